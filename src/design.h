#line 74 "paper/design.nw"
#ifndef CONTACTOPT_DESIGN_H
#define CONTACTOPT_DESIGN_H
#include "status.h"
#include "problem.h"

typedef struct {
  int N;          /* X has N+1 components */
  double h;       /* (b-a)/N */
  double C0;      /* box 0 <= X_i <= C0 */
  double delta;   /* slope bound C1*h on |X_{i+1} - X_i| */
  double area;    /* S = gamma (b-a) - C2: h sum (X_i + X_{i+1})/2 = S */
} Design_set;

typedef struct {
  int N;          /* of the design set they were made for */
  double *lower;  /* N+1: of -X_i <= 0, >= 0 */
  double *upper;  /* N+1: of X_i - C0 <= 0, >= 0 */
  double *up;     /* N: of X_{i+1} - X_i - delta <= 0, >= 0 */
  double *down;   /* N: of X_i - X_{i+1} - delta <= 0, >= 0 */
  double mu;      /* of h sum (X_i + X_{i+1})/2 - S = 0, free */
} Design_multipliers;

#line 133 "paper/design.nw"
typedef enum { SHAPE_ARC, SHAPE_LINE, SHAPE_CONSTANT } Design_shape_kind;
typedef struct {
  Design_shape_kind kind;
  double centre[2];  /* SHAPE_ARC: the centre (x1, x2) of the circle, */
  double radius;     /*   its radius > 0: alpha0 is its lower half */
  double start, end; /* SHAPE_LINE: alpha0 at x1 = a and at x1 = b */
  double value;      /* SHAPE_CONSTANT: alpha0 */
} Design_shape;

#line 109 "paper/design.nw"
Design_set design_set(const Problem *p);
/* h sum_{i<N} (X_i + X_{i+1})/2, the trapezoid rule */
double design_area(const Design_set *B, const double *X);
/* largest violation, relative to C0 (area: C0 (b-a)); HUGE_VAL on a NaN */
double design_violation(const Design_set *B, const double *X);
/* X = argmin ||X - Y||_2 over B; mult (may be NULL) its multipliers */
int design_project(const Design_set *B, const double *Y, double *X,
                   Design_multipliers *mult, Status *st);
/* P = P_B(X - tG), residual = ||X - P||_inf / t, mult = multipliers / t;
   t <= 0 chooses t = C0 / ||G||_inf.  P, mult, residual may be NULL. */
int design_kkt(const Design_set *B, const double *X, const double *G,
               double t, double *P, Design_multipliers *mult,
               double *residual, Status *st);
Design_multipliers *design_multipliers_new(const Design_set *B, Status *st);
void design_multipliers_free(Design_multipliers *m);
#line 148 "paper/design.nw"
/* X_i = alpha0(x_i), i = 0..N, for the shape sh */
int design_shape(const Problem *p, const Design_shape *sh, double *X, Status *st);
#line 163 "paper/design.nw"
/* X = alpha0 if design_violation(alpha0) <= tol, else P_B(alpha0);
   violation = design_violation(alpha0), moved = ||X - alpha0||_2 */
int design_feasible_start(const Design_set *B, const double *alpha0,
                          double tol, double *X, double *violation,
                          double *moved, Status *st);
#line 101 "paper/design.nw"
#endif
