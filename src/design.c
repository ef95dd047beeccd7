#line 173 "paper/design.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design_private.h"
#line 1010 "paper/design.nw"
Design_multipliers *design_multipliers_new(const Design_set *B, Status *st)
{
  if (design_check_set(B, st)) return NULL;
  Design_multipliers *m = calloc(1, sizeof *m);
  double *v = malloc((4 * (size_t) B->N + 2) * sizeof *v);
  if (!m || !v) {
    free(m);
    free(v);
    status_set(st, STATUS_MEMORY, "design: out of memory for multipliers");
    return NULL;
  }
  m->N = B->N;
  m->lower = v;
  m->upper = v + B->N + 1;
  m->up = m->upper + B->N + 1;
  m->down = m->up + B->N;
  return m;
}

void design_multipliers_free(Design_multipliers *m)
{
  if (!m) return;
  free(m->lower);
  free(m);
}
#line 1064 "paper/design.nw"
static double default_step(const Design_set *B, const double *G)
{
  double Gmax = 0;
  for (int i = 0; i <= B->N; i++) Gmax = fmax(Gmax, fabs(G[i]));
  return Gmax > 0 ? B->C0 / Gmax : 1;
}
#line 1074 "paper/design.nw"
static void scale_multipliers(Design_multipliers *m, double f);

int design_kkt(const Design_set *B, const double *X, const double *G,
               double t, double *P, Design_multipliers *mult,
               double *residual, Status *st)
{
  int rc, n = B->N + 1;
  if ((rc = design_check_set(B, st)) || (rc = design_check_point(B, X, "the design", st))
      || (rc = design_check_point(B, G, "the gradient", st))) return rc;
  if (!(t > 0) || !isfinite(t)) t = default_step(B, G);
  double *Y = malloc(2 * (size_t) n * sizeof *Y), *Q = P ? P : Y + n;
  if (!Y) return status_set(st, STATUS_MEMORY, "design: out of memory");
  for (int i = 0; i < n; i++) Y[i] = X[i] - t * G[i];
  if (!(rc = design_project(B, Y, Q, mult, st))) {
    double r = 0;
    for (int i = 0; i < n; i++) r = fmax(r, fabs(X[i] - Q[i]));
    if (residual) *residual = r / t;
    if (mult) scale_multipliers(mult, 1 / t);
  }
  free(Y);
  return rc;
}
#line 1100 "paper/design.nw"
static void scale_multipliers(Design_multipliers *m, double f)
{
  for (int i = 0; i <= m->N; i++) { m->lower[i] *= f; m->upper[i] *= f; }
  for (int i = 0; i < m->N; i++) { m->up[i] *= f; m->down[i] *= f; }
  m->mu *= f;
}
#line 1118 "paper/design.nw"
/* alpha0 at x1 by the formula of sh; 0 if the arc does not reach x1 */
static int shape_at(const Design_shape *sh, double x1, double t, double *alpha)
{
  double d = x1 - sh->centre[0], r = sh->radius;
  switch (sh->kind) {
  case SHAPE_ARC:
    if (!(fabs(d) <= r)) return 0;
    *alpha = (sh->centre[1] - r) + d * d / (r + sqrt((r - d) * (r + d)));
    return 1;
  case SHAPE_LINE: *alpha = (1 - t) * sh->start + t * sh->end; return 1;
  default: *alpha = sh->value; return 1;
  }
}
#line 1135 "paper/design.nw"
int design_shape(const Problem *p, const Design_shape *sh, double *X, Status *st)
{
  for (int i = 0; i <= p->N; i++)
    if (!shape_at(sh, problem_node_x(p, i), (double)i / p->N, &X[i]))
      return status_set(st, STATUS_INPUT, "the arc does not reach node %d "
                        "(x1 = %g): it lies farther than the radius from the "
                        "centre", i,
                        problem_node_x(p, i));
  return STATUS_OK;
}
#line 1158 "paper/design.nw"
int design_feasible_start(const Design_set *B, const double *alpha0,
                          double tol, double *X, double *violation,
                          double *moved, Status *st)
{
  int rc;
  if ((rc = design_check_set(B, st))
      || (rc = design_check_point(B, alpha0, "the start alpha0", st))) return rc;
  if (!(tol >= 0))
    return status_set(st, STATUS_INPUT, "design: the tolerance %g of the "
                      "start is not >= 0", tol);
  if (X == alpha0)
    return status_set(st, STATUS_INPUT, "design: the start X aliases alpha0");
  double v = design_violation(B, alpha0);
  if (v <= tol) memcpy(X, alpha0, (B->N + 1) * sizeof *X);
  else if ((rc = design_project(B, alpha0, X, NULL, st))) return rc;
  
#line 1180 "paper/design.nw"
double d2 = 0;
for (int i = 0; i <= B->N; i++) d2 += (X[i] - alpha0[i]) * (X[i] - alpha0[i]);
if (moved) *moved = sqrt(d2);
#line 1174 "paper/design.nw"
  if (violation) *violation = v;
  return STATUS_OK;
}
