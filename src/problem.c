#line 260 "paper/problem.nw"
#include <stddef.h>
#include "problem.h"

#line 266 "paper/problem.nw"
const char *const problem_model_names[] = {"plane_stress", "plane_strain",
                                           NULL};
const char *const problem_bc_names[] = {"free", "clamped", "roller",
                                        "traction", "pressure", NULL};
const char *const problem_contact_names[] = {"frictionless", "tresca",
                                             "coulomb", NULL};

const char *problem_model_name(Problem_plane_model m)
{
  return (unsigned)m <= MODEL_PLANE_STRAIN ? problem_model_names[m] : "?";
}

const char *problem_bc_name(Problem_bc_kind k)
{
  return (unsigned)k <= BC_PRESSURE ? problem_bc_names[k] : "?";
}

const char *problem_contact_name(Problem_contact_law law)
{
  return (unsigned)law <= CONTACT_COULOMB ? problem_contact_names[law] : "?";
}
#line 292 "paper/problem.nw"
double problem_node_x(const Problem *p, int i)
{
  double t = (double)i / p->N;
  return (1 - t) * p->a + t * p->b;
}
