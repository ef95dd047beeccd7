#line 84 "paper/newton.nw"
#ifndef CONTACTOPT_NEWTON_H
#define CONTACTOPT_NEWTON_H
#include "status.h"
#include "design.h"

#line 102 "paper/newton.nw"
typedef struct {
  int n;               /* design nodes, N+1 */
  int m;               /* contact unknowns, nc (may be 0) */
  const int *col;      /* m: the design node i(c) of each, increasing */
  const double *X;     /* n: the design, in B */
  const Design_set *B; /* box, slopes and area of (4.4) */
  const double *grad;  /* n: the gradient of E but for the contact, G + P'T */
  const double *r;     /* n: the curvature R of the design step, > 0 */
  const double *S;     /* m x m, row-major: the contact Schur complement */
  const double *f;     /* m: its load, S Q_c - T */
  const double *v0;    /* m: the state's contact displacements Q_c */
} Newton_model;
#line 117 "paper/newton.nw"
typedef struct {
  double pred;         /* m(0) - m(d) >= 0, J/m */
  double rounding;     /* of pred: eps times the magnitudes of its terms, J/m */
  int iterations;      /* of the interior point */
  double residual;     /* its largest relative residual at the end */
} Newton_report;

#line 92 "paper/newton.nw"
typedef struct Newton_workspace Newton_workspace;
Newton_workspace *newton_alloc(int n, int m, Status *st);
void newton_free(Newton_workspace *w);
/* (d, v) = the minimiser of the model; pred = m(0) - m(d) */
int newton_solve(Newton_workspace *w, const Newton_model *mdl, double *d,
                 double *v, Newton_report *rep, Status *st);
#endif
