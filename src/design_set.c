#line 190 "paper/design.nw"
#include <float.h>
#include <math.h>
#include "design_private.h"
#line 231 "paper/design.nw"
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
#line 248 "paper/design.nw"
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
#line 263 "paper/design.nw"
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
#line 282 "paper/design.nw"
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
