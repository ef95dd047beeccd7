#line 154 "paper/newton.nw"
#ifndef CONTACTOPT_NEWTON_PRIVATE_H
#define CONTACTOPT_NEWTON_PRIVATE_H
#include <gsl/gsl_matrix.h>
#include "newton.h"
#line 203 "paper/newton.nw"
struct Newton_workspace {
  int n, m, p;         /* design nodes, contact unknowns, inequalities */
  double *z, *s, *lam; /* n+m, p, p: the iterate, slacks, multipliers */
  double mu;           /* the multiplier of the area equality */
  double *q, *b;       /* n+m, p: the scaled linear term and bounds */
  double *Hd;          /* n: the scaled R */
  double *Hv;          /* m x m: the scaled S */
  double *w;           /* n: the weights of the area equality */
  double *W;           /* p: lambda / s */
  double *Td, *Te;     /* n, n-1: T's pivots and L's subdiagonal */
  double *c0;          /* n: T's grounding without the contact, T~ 1 */
  double *Y;           /* n x m: T^-1 P', T^-1 at the contact columns */
  gsl_matrix *Sig;     /* m x m: Sigma, then its Cholesky factor */
  double *rd, *rp;     /* n+m, p: dual and primal residuals */
  double *dz, *ds, *dl;     /* n+m, p, p: the step */
  double *az, *as, *al;     /* n+m, p, p: the affine step */
  double *rc;          /* p: the complementarity target of a step */
  double *t1, *t2;     /* n+m each: scratch of the solves */
  double *y2;          /* n+m: K^-1 (w, 0), for the area equality */
  double *zf, *lf;     /* n+m, p: the point of the face and its multipliers */
  double muf;          /* its multiplier of the area equality */
  double *rdf, *rpf;   /* n+m, p: its residuals */
  unsigned char *act, *tried; /* p: the face now indicated, the last tried */
};
#line 159 "paper/newton.nw"
/* out = A z, the constraints at z (columns col of the contact) */
void newton_constraints_times(const Newton_workspace *w, const int *col,
                              const double *z, double *out);
/* out = A' y */
void newton_constraints_transposed(const Newton_workspace *w, const int *col,
                                   const double *y, double *out);
/* factor K = H + A'WA with the area equality beside it */
int newton_factor_with_area(Newton_workspace *w, const int *col);
/* (dz, dmu) from K and the area equality for the residuals r, re */
void newton_bordered_solve(Newton_workspace *w, const int *col, const double *r,
                           double re, double *dz, double *dmu);
/* the residuals of (z, lam, s, mu) into rd, rp, re; their largest scaled */
double newton_residuals(const Newton_workspace *w, const int *col, const double *z,
                        const double *lam, const double *s, double mu, double *rd,
                        double *rp, double *re, double scale[2]);
/* one predictor-corrector step of the interior point */
int newton_predictor_corrector(Newton_workspace *w, const int *col, double gap,
                               double re);
#endif
