#line 173 "paper/design.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design_private.h"
#line 220 "paper/design.nw"
Design_set design_set(const Problem *p)
{
  Design_set B;
  double width = p->b - p->a, slack = 1e-12 * p->gamma * width;
  B.N = p->N;
  B.h = width / p->N;
  B.C0 = p->C0;
  B.delta = p->C1 * B.h;
  B.area = p->gamma * width - p->C2;
  if (B.area < 0 && B.area >= -slack) B.area = 0;
  if (B.area > B.C0 * (B.N * B.h) && B.area <= B.C0 * (B.N * B.h) + slack)
    B.area = B.C0 * (B.N * B.h);
  return B;
}
#line 237 "paper/design.nw"
double design_weight(const Design_set *B, int i)
{
  return i == 0 || i == B->N ? 0.5 * B->h : B->h;
}

double design_area(const Design_set *B, const double *X)
{
  double sum = 0.5 * (X[0] + X[B->N]);
  for (int i = 1; i < B->N; i++) sum += X[i];
  return B->h * sum;
}
#line 252 "paper/design.nw"
double design_violation(const Design_set *B, const double *X)
{
  double v = 0;
  for (int i = 0; i <= B->N; i++) {
    if (!isfinite(X[i])) return HUGE_VAL;
    v = fmax(v, fmax(-X[i], X[i] - B->C0) / B->C0);
  }
  for (int i = 0; i < B->N; i++)
    v = fmax(v, (fabs(X[i + 1] - X[i]) - B->delta) / B->C0);
  return fmax(v, fabs(design_area(B, X) - B->area) / (B->C0 * B->N * B->h));
}
#line 917 "paper/design.nw"
int design_check_set(const Design_set *B, Status *st)
{
  if (!B || B->N < 1)
    return status_set(st, STATUS_INPUT, "design: N = %d < 1", B ? B->N : 0);
  if (!(B->h > 0 && isfinite(B->h)))
    return status_set(st, STATUS_INPUT, "design: h = %g is not positive", B->h);
  if (!(B->C0 > 0 && isfinite(B->C0)))
    return status_set(st, STATUS_INPUT, "design: C0 = %g is not positive",
                      B->C0);
  if (!(B->delta >= 0 && isfinite(B->delta)))
    return status_set(st, STATUS_INPUT, "design: the slope bound C1 h = %g "
                      "is negative", B->delta);
  double top = B->C0 * (B->N * B->h), slack = (B->N + 1) * DBL_EPSILON * top;
  if (!(B->area >= -slack && B->area <= top + slack))
    return status_set(st, STATUS_INPUT, "design: B is empty: the area S = "
                      "%.17g is outside [0, C0 (b-a)] = [0, %.17g]",
                      B->area, top);
  return STATUS_OK;
}

int design_check_point(const Design_set *B, const double *Y,
                       const char *what, Status *st)
{
  for (int i = 0; i <= B->N; i++)
    if (!isfinite(Y[i]))
      return status_set(st, STATUS_NUMERIC, "design: component %d of %s "
                        "is %g", i, what, Y[i]);
  return STATUS_OK;
}
#line 997 "paper/design.nw"
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
#line 1051 "paper/design.nw"
static double default_step(const Design_set *B, const double *G)
{
  double Gmax = 0;
  for (int i = 0; i <= B->N; i++) Gmax = fmax(Gmax, fabs(G[i]));
  return Gmax > 0 ? B->C0 / Gmax : 1;
}
#line 1061 "paper/design.nw"
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
#line 1087 "paper/design.nw"
static void scale_multipliers(Design_multipliers *m, double f)
{
  for (int i = 0; i <= m->N; i++) { m->lower[i] *= f; m->upper[i] *= f; }
  for (int i = 0; i < m->N; i++) { m->up[i] *= f; m->down[i] *= f; }
  m->mu *= f;
}
#line 1105 "paper/design.nw"
/* alpha0 at x1 by the formula of sh; 0 if the arc does not reach x1 */
static int shape_at(const Shape *sh, double x1, double t, double *alpha)
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
#line 1122 "paper/design.nw"
int design_shape(const Problem *p, const Shape *sh, double *X, Status *st)
{
  for (int i = 0; i <= p->N; i++)
    if (!shape_at(sh, problem_node_x(p, i), (double)i / p->N, &X[i]))
      return status_set(st, STATUS_INPUT, "the arc does not reach node %d "
                        "(x1 = %g): it lies farther than the radius from the "
                        "centre", i,
                        problem_node_x(p, i));
  return STATUS_OK;
}
#line 1145 "paper/design.nw"
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
  
#line 1167 "paper/design.nw"
double d2 = 0;
for (int i = 0; i <= B->N; i++) d2 += (X[i] - alpha0[i]) * (X[i] - alpha0[i]);
if (moved) *moved = sqrt(d2);
#line 1161 "paper/design.nw"
  if (violation) *violation = v;
  return STATUS_OK;
}
