#line 207 "paper/qp.nw"
#ifndef CONTACTOPT_QP_PRIVATE_H
#define CONTACTOPT_QP_PRIVATE_H
/* The state solver's own header: qp.c, condense.c, pdas.c, mprgp.c and
   psor.c include it, no other module does. */
#include <float.h>
#include <math.h>
#include "qp.h"

#line 277 "paper/qp.nw"
typedef struct {
  double *s, *t;         /* nk: its gaps y - lo and forces, both > 0;
                            with friction, the slide y - pos = s - b and
                            the force inside (flo, fhi) */
  double *b;             /* nk: with friction, the slide the other way, > 0
                            (0 on a bounded unknown) */
  double *ds, *dt, *db;  /* nk: its step */
  double *as, *at, *ab;  /* nk: its affine (predictor) step */
  double *h;             /* nk: S lo - f, the forces with every unknown
                            at its bound */
  char *pred;            /* nk: the active set it predicted last */
  char *own;             /* nk: the Newton method's own next set, kept
                            while the guide's is tried */
  int state;             /* GUIDE_OFF, GUIDE_ON or GUIDE_STOPPED */
  int guided;            /* act is the guide's prediction in this step */
} Pdas_guide;

typedef struct {
  double *r;             /* nk: a right-hand side on the free set */
  int *fr;               /* nk: the free set, listed */
  int warm;              /* the first active set is to be guessed from x0 */
  char *prev;            /* nk: the active set of the last step */
  char *moved;           /* nk: 1 where a step past kkt <= tol changed the
                            state (pdas.nw, the forces' set) */
  Pdas_guide ip;         /* the interior point that guides the steps */
} Pdas_workspace;

#line 309 "paper/qp.nw"
typedef struct {
  double *p;             /* n: the conjugate direction */
  double *q;             /* n: A p, or A beta in a proportioning step */
  double *z;             /* n: the preconditioned free gradient, or beta */
  double abar;           /* the expansion step length 1.9 / normA
                            (friction: 1.9 / ||S^-1||) */
  int restart;           /* 1: p must restart from z (the face changed) */
  int factored;          /* friction: S is condensed and factored for the
                            values of the last qp_set */
} Mprgp_workspace;

#line 243 "paper/qp.nw"
struct Qp_workspace {
  const Qp *qp;          /* the problem: its pattern fixed, values may change */
  Qp_options opt;        /* a copy of the caller's options */
  cholmod_common *cm;    /* the caller's CHOLMOD environment */
  int n;                 /* the number of unknowns: A is n x n */
  int nc;                /* the number of bounded unknowns, |I| */
  int nk;                /* nc + nt: the unknowns the Newton method condenses */
  int *ik;               /* nk: ic, then it */
  double *pos;           /* nk: where each sits when held: lo, or 0 (stick) */
  double *flo, *fhi;     /* nk: the interval of its force: [0, inf) on a
                            bound, [-s, s] with friction */
  int *bnd;              /* n: k when unknown i = ik[k], -1 otherwise */
  double *lo;            /* n: the lower bound of each unknown, -INFINITY if none */
  double *d;             /* n: the diagonal A_ii > 0 */
  double normA;          /* max row sum of |A|: an upper bound of ||A||_2 */
  double gamma;          /* gamma_{m+2}, m the longest column of A: the
                            relative rounding of a residual (qp_kkt_eval) */
  double *x;             /* n: the iterate */
  double *g;             /* n: the gradient A x - b at x */
  double *T;             /* nk: the contact forces g[ik[k]] (4.6) */
  double kkt;            /* qp_kkt at x */
  int iter;              /* iterations since qp_set */
  struct Condense *cond; /* the condensation (condense.c): pdas, and
                            cgssor with friction; NULL otherwise */
  Pdas_workspace pdas;   /* method pdas only (pdas.c), zero otherwise */
  Mprgp_workspace mprgp; /* method cgssor only (mprgp.c), zero otherwise */
};

#line 511 "paper/qp.nw"
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
   g of a displacement, relative; over the scales sf and su.  A NaN
   anywhere gives NaN, which fmax would drop. */
static inline double qp_kkt_combine(double rf, double tn, double inf,
                                    double comp, double sf, double su,
                                    double rho_f, double g)
{
  double k = fmax(fmax(qp_ratio(qp_excess(rf, rho_f), sf),
                       qp_ratio(qp_excess(tn, rho_f), sf)),
                  fmax(qp_ratio(qp_excess(inf, g * su), su),
                       qp_ratio(qp_ratio(qp_excess(comp, (rho_f + g * sf) * su),
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

#line 663 "paper/qp.nw"
/* unknown i is off its bound */
static inline int qp_is_free(const Qp_workspace *w, int i)
{
  return w->x[i] > w->lo[i];
}

/* the projection of value y of unknown i onto x_i >= lo_i */
static inline double qp_proj(const Qp_workspace *w, int i, double y)
{
  return y < w->lo[i] ? w->lo[i] : y;
}

#line 683 "paper/qp.nw"
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

#line 326 "paper/qp.nw"
/* the relative KKT residual of x; normA = max_j sum_i |A_ij|; g = Ax - b
   if known, else NULL; T (nc, may be NULL) receives the contact forces */
double qp_kkt_eval(const Qp *qp, double normA, const double *x,
                   const double *g, double *T);
/* g = A x - b, then kkt and T at x */
void qp_refresh(Qp_workspace *w);
/* bounded unknowns at their bound */
int qp_count_active(const Qp_workspace *w);
/* (4.3) has no solution: why, with how many bounds active */
int qp_not_held(const Qp_workspace *w, Status *st, const char *why,
                int active);

#line 344 "paper/qp.nw"
/* pdas.c: the primal-dual active set method */
int pdas_alloc(Qp_workspace *w, Status *st);
void pdas_set(Qp_workspace *w, int warm);
int pdas_iterate(Qp_workspace *w, Status *st);
void pdas_free(Qp_workspace *w);
/* mprgp.c: MPRGP, CG-SSOR with projection */
int mprgp_alloc(Qp_workspace *w, Status *st);
void mprgp_set(Qp_workspace *w);
int mprgp_iterate(Qp_workspace *w, Status *st);
void mprgp_free(Qp_workspace *w);
int mprgp_end(Qp_workspace *w, Status *st);
/* psor.c: projected SOR */
int psor_iterate(Qp_workspace *w, Status *st);
#line 230 "paper/qp.nw"
#endif
