/* test_problem.c: the plain problem description (paper/problem.nw):
   the names of the boundary conditions and plane models, and those of the
   state solvers and optimisers beside them, are the scene's words, with
   '?' out of range; the end nodes of the partition are a and b exactly. */
#include <string.h>
#include "check.h"
#include "problem.h"
#include "qp.h"
#include "opt.h"

static void test_names(void)
{
  check(strcmp(problem_bc_name(BC_ROLLER), "roller") == 0
        && strcmp(qp_method_name(QP_CGSSOR), "cgssor") == 0
        && strcmp(problem_model_name(MODEL_PLANE_STRAIN), "plane_strain") == 0
        && strcmp(problem_bc_name((Problem_bc_kind)9), "?") == 0
        && strcmp(opt_method_name(OPT_PROJGRAD), "projgrad") == 0
        && strcmp(opt_metric_name((Opt_metric)-1), "?") == 0,
        "names of conditions, methods, models, and '?' out of range");
  Problem p = {0};
  p.a = -0.3; p.b = 0.7; p.N = 3;
  check(problem_node_x(&p, 0) == -0.3 && problem_node_x(&p, 3) == 0.7,
        "the end nodes are a and b exactly (a = -0.3, b = 0.7, N = 3)");
}

int main(void)
{
  test_names();
  return check_done();
}
