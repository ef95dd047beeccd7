#line 222 "paper/qp.nw"
#ifndef CONTACTOPT_QP_INLINE_H
#define CONTACTOPT_QP_INLINE_H
/* The state solver's inline helpers that need no workspace: its files
   include this header, no other module does. */
#include <float.h>
#include <math.h>
#include "sparse.h"

#line 543 "paper/qp.nw"
/* gamma_m = m u / (1 - m u): the relative rounding of a sum of m terms */
static inline double qp_gamma(int m)
{
  double mu = m * (DBL_EPSILON / 2);
  return mu / (1 - mu);
}

/* v less the allowance a for rounding, and 0 if no more */
static inline double qp_excess(double v, double a)
{
  return v > a ? v - a : 0;
}

/* a slipping unknown with bound s, force r, value x: the squared excess
   |r| - s > 0 to tn (more than friction holds), the Fenchel-Young gap
   s|x| + r x to comp (slip not against r); the whole state's residual and
   the active set method's condensed one both add them */
static inline void qp_slip_terms(double s, double r, double x, double *tn,
                                 double *comp)
{
  double excess = fabs(r) - s;
  if (excess > 0) *tn += excess * excess;
  *comp += fabs(s * fabs(x) + r * x);
}

/* num/den, and 0 whenever num is 0 (den may then be 0 too) */
static inline double qp_ratio(double num, double den)
{
  return num == 0 ? 0 : num / den;
}

/* the relative KKT residual from the norms of its four terms (rf, tn,
   inf; comp a sum), each less what rounding may explain: rho_f of a force,
   rho_u of a displacement, relative; over the scales sf and su.  A NaN
   anywhere gives NaN, which fmax would drop. */
static inline double qp_kkt_combine(double rf, double tn, double inf,
                                    double comp, double sf, double su,
                                    double rho_f, double rho_u)
{
  double k = fmax(fmax(qp_ratio(qp_excess(rf, rho_f), sf),
                       qp_ratio(qp_excess(tn, rho_f), sf)),
                  fmax(qp_ratio(qp_excess(inf, rho_u * su), su),
                       qp_ratio(qp_ratio(qp_excess(comp, (rho_f + rho_u * sf) * su),
                                         sf), su)));
  return isfinite(rf + tn + inf + comp + sf + su + rho_f) ? k : NAN;
}

/* (Ax)_j: column j of A, which is also its row j */
static inline double qp_row_dot(const cholmod_sparse *A, int j,
                                const double *x)
{
  const Sparse_index *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x;
  double s = 0;
  for (Sparse_index k = Ap[j]; k < Ap[j + 1]; k++) s += Ax[k] * x[Ai[k]];
  return s;
}

#line 715 "paper/qp.nw"
#define QP_RCOND_MIN (100 * DBL_EPSILON) /* smaller: taken to be singular */

/* the squared pivots of the Cholesky factor L (m x m, row-major) spread
   by at least QP_RCOND_MIN (min/max) */
static inline int qp_factor_regular(const double *L, int m)
{
  double dmin = INFINITY, dmax = 0;
  for (int a = 0; a < m; a++) {
    double p = L[(size_t) a * m + a] * L[(size_t) a * m + a];
    if (p < dmin || isnan(p)) dmin = p;    /* a NaN stays */
    if (p > dmax) dmax = p;
  }
  return dmin >= QP_RCOND_MIN * dmax;
}
#line 233 "paper/qp.nw"
#endif
