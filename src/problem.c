#line 278 "paper/problem.nw"
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "problem.h"

#line 286 "paper/problem.nw"
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
#line 312 "paper/problem.nw"
double problem_node_x(const Problem *p, int i)
{
  double t = (double)i / p->N;
  return (1 - t) * p->a + t * p->b;
}
#line 321 "paper/problem.nw"
void problem_supports(const Problem *p, char *buf, size_t size)
{
  int n = snprintf(buf, size, "left.bc = %s, right.bc = %s",
                   problem_bc_name(p->side[0].kind), problem_bc_name(p->side[1].kind));
  if (n < 0 || (size_t) n >= size) return;
  if (!p->part.geometry[0]) {
    snprintf(buf + n, size - n, ", top.bc = %s", problem_bc_name(p->side[2].kind));
    return;
  }
  for (int s = 0; s < p->part.ncurve; s++) {
    const Problem_curve *c = &p->part.curve[s];
    if (c->kind != BC_CLAMPED && c->kind != BC_ROLLER) continue;
    int k = snprintf(buf + n, size - n, ", boundary.%s.bc = %s", c->name,
                     problem_bc_name(c->kind));
    if (k < 0 || (size_t) (n += k) >= size) return;
  }
  if (strstr(buf, "boundary.") == NULL)
    snprintf(buf + n, size - n, ", boundary.* free or loaded");
}

int problem_curve_slot(const Problem *p, const char *name)
{
  for (int s = 0; s < p->part.ncurve; s++)
    if (strcmp(p->part.curve[s].name, name) == 0) return s;
  return -1;
}

int problem_region_slot(const Problem *p, const char *name)
{
  for (int s = 0; s < p->part.nregion; s++)
    if (strcmp(p->part.region[s].name, name) == 0) return s;
  return -1;
}
