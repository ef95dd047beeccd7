#line 844 "paper/model.nw"
#include <math.h>
#include <stdio.h>
#include "friction.h"
#include "held.h"
#line 852 "paper/model.nw"
int held_lift_free(const Problem *p)
{
  return !friction_side_holds(p, 1);
}
#line 861 "paper/model.nw"
static void node_load(const Fem_dofs *d, const double *b, int k, double f[2])
{
  for (int c = 0; c < 2; c++)
    f[c] = d->unknown[2 * k + c] >= 0 ? b[d->unknown[2 * k + c]] : 0;
}
#line 869 "paper/model.nw"
static double lift_work(const Mesh *m, const Fem_dofs *d, const double *b,
                        double *scale)
{
  double L2 = 0, f[2];
  *scale = 0;
  for (int k = 0; k < m->nnodes; k++) {
    node_load(d, b, k, f);
    L2 += f[1], *scale += fabs(f[1]);
  }
  return L2;
}
#line 889 "paper/model.nw"
typedef struct {
  double W0, L1;        /* W(0), and the horizontal load: W(y) = W0 + sigma y L1 */
  double scale0, scale1; /* the scale of W(y)'s terms: scale0 + |y| scale1 */
} Tip;

static Tip tip_work(const Mesh *m, const Fem_dofs *d, const double *b, double p,
                    double sigma)
{
  Tip w = {0, 0, 0, 0};
  double f[2];
  for (int k = 0; k < m->nnodes; k++) {
    double dx = m->xy[2 * k] - p, x2 = m->xy[2 * k + 1];
    node_load(d, b, k, f);
    w.W0 += sigma * (dx * f[1] - x2 * f[0]), w.L1 += f[0];
    w.scale0 += fabs(dx * f[1]) + fabs(x2 * f[0]), w.scale1 += fabs(f[0]);
  }
  return w;
}
#line 913 "paper/model.nw"
static double friction_on_tip(const Mesh *m, const Fem_dofs *d,
                              const double *slip, double y)
{
  double w = 0;
  for (int t = 0; t < d->nt; t++)
    w += slip[t] * fabs(y - m->xy[2 * d->tangent_col[t] + 1]);
  return w;
}
#line 928 "paper/model.nw"
static double tip_excess(const Mesh *m, const Fem_dofs *d, const double *b,
                         const double *slip, int end, double *scale)
{
  double p = end ? m->b : m->a, sigma = end ? -1 : 1;
  int pivot = end ? m->N : 0, heights = slip ? d->nt : 1;
  double worst = -INFINITY;
  Tip w = tip_work(m, d, b, p, sigma);
  *scale = 0;
  for (int t = 0; t < heights; t++) {
    double y = m->xy[2 * (slip ? d->tangent_col[t] : pivot) + 1];
    double fr = slip ? friction_on_tip(m, d, slip, y) : 0;
    double excess = w.W0 + sigma * y * w.L1 - fr;
    if (excess > worst) worst = excess, *scale = w.scale0 + fabs(y) * w.scale1 + fr;
  }
  return worst;
}
#line 953 "paper/model.nw"
#define HELD_ROUNDING 1e-12
static int held(double work, double scale)
{
  return work < -HELD_ROUNDING * scale;
}

int held_check(const Problem *p, const Mesh *m, const Fem_dofs *d,
               const double *b, const double *slip, Status_code code,
               Status *st)
{
  double scale = 0, w;
  char sides[256];
  problem_supports(p, sides, sizeof sides);
  if (!held_lift_free(p)) return 0;
  if (!held(w = lift_work(m, d, b, &scale), scale))
    
#line 979 "paper/model.nw"
return status_set(st, code, "the body is not held: the loads do not press "
                  "it onto the foundation (their vertical resultant is %.6g N/m, "
                  "not downward), and no side holds u2 (%s): nothing stops it "
                  "lifting off", w, sides);
#line 969 "paper/model.nw"
  if (friction_side_holds(p, 0)) return 0;
  for (int end = 0; end < 2; end++)
    if (!held(w = tip_excess(m, d, b, slip, end, &scale), scale))
      
#line 986 "paper/model.nw"
return status_set(st, code, "the body is not held: the loads tip it about "
                  "the %s end of its contact (x1 = %g): their moment about it%s "
                  "turns the body off the foundation with %.6g N m/m, and no side "
                  "holds it (%s)", end ? "right" : "left", end ? m->b : m->a,
                  slip ? ", less what friction resists," : "", w, sides);
#line 973 "paper/model.nw"
  return 0;
}
