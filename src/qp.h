#line 60 "paper/qp.nw"
#ifndef CONTACTOPT_QP_H
#define CONTACTOPT_QP_H
#include "sparse.h"
#include "status.h"

#line 74 "paper/qp.nw"
/* The discrete state problem (4.3): minimise 1/2 x'Ax - b'x subject to
   x[ic[c]] >= lo[c], c = 0..nc-1; with given friction, plus
   sum_k s_k |x[it[k]]|.  A is symmetric positive semidefinite, and
   positive definite on the subspace x[ic] = 0, x[it] = 0; on x[ic] = 0
   too unless slides. */
typedef struct {
  const cholmod_sparse *A; /* n x n, both triangles stored, sorted, packed */
  const double *b;         /* n: the load vector F + P */
  int nc;                  /* number of bounded unknowns, |I| */
  const int *ic;           /* nc: their indices, increasing */
  const double *lo;        /* nc: their lower bounds, -X_i */
  int nt;                  /* number of slipping unknowns; 0: frictionless */
  const int *it;           /* nt: their indices, increasing, none in ic */
  const double *slip;      /* nt: their slip bounds s_k >= 0 (forces) */
  int slides;              /* 1: A e = 0 for an e that is 1 at every
                              slipping unknown and 0 at every bounded one
                              (only friction holds the body sideways) */
} Qp;
#line 95 "paper/qp.nw"
typedef enum { QP_PDAS, QP_PSOR, QP_CGSSOR } Qp_method;

typedef struct {
  Qp_method method;        /* pdas, psor or cgssor */
  double tol;              /* stop when qp_kkt <= tol */
  int max_iter;            /* fail when not converged after this many */
  double omega;            /* relaxation, 0 < omega < 2 (psor, cgssor) */
} Qp_options;

/* the defaults: tol 1e-10, max_iter 100 (pdas) or 100000, omega 1.5 */
Qp_options qp_options_default(Qp_method method);
/* "pdas", "psor", "cgssor", or "?" */
const char *qp_method_name(Qp_method method);
#line 111 "paper/qp.nw"
typedef struct {
  int iterations;          /* sweeps, CG steps or active-set steps used */
  double kkt;              /* qp_kkt at the returned x */
  int active;              /* bounded unknowns at their bound */
  int converged;           /* kkt <= tol */
} Qp_report;

typedef struct Qp_workspace Qp_workspace;
#line 127 "paper/qp.nw"
/* set / iterate / test, GSL style: the caller may own the loop */
Qp_workspace *qp_alloc(const Qp *qp, const Qp_options *opt,
                       cholmod_common *cm, Status *st);
int qp_set(Qp_workspace *w, const double *x0, Status *st); /* x0 NULL: cold */
int qp_iterate(Qp_workspace *w, Status *st);
int qp_test(const Qp_workspace *w);          /* 1 when kkt <= tol */
const double *qp_x(const Qp_workspace *w);   /* the current iterate */
/* frees the factorisation of the last solve, which the next solve
   makes anew; the analysis and the iterate stay */
void qp_release(Qp_workspace *w);
void qp_free(Qp_workspace *w);
#line 141 "paper/qp.nw"
/* The whole loop: from x0 (NULL: cold start) to x, with the contact forces
   T[c] = (Ax - b)[ic[c]], then (friction) T[nc + k] = (Ax - b)[it[k]];
   STATUS_NUMERIC when not converged. */
int qp_solve(Qp_workspace *w, const double *x0, double *x, double *T,
             Qp_report *rep, Status *st);

/* The relative KKT residual of x (scale-free; what the rounding of its
   terms may explain is not counted); T (nc + nt, may be NULL)
   receives the contact forces, normal then tangential. */
double qp_kkt(const Qp *qp, const double *x, double *T);

/* S (nc x nc, row-major, in the order of ic): the Schur complement of A
   onto the bounded unknowns, A_cc - A_cu A_uu^-1 A_uc (slipping unknowns
   among the u, as if frictionless), with its diagonal
   raised by shift A_ii (the Schur complement of A with those diagonals
   raised), at the values the last qp_set read; from PDAS's
   own S when it has one.  Needs GSL's error handler off
   (gsl_set_error_handler_off), as PDAS needs too. */
int qp_schur(const Qp_workspace *w, double shift, double *S, Status *st);

/* lam (n) = the adjoint of the last state solved: A_FF lam_F = g_F and
   lam_H = 0, H the unknowns that the state holds (a bound touched,
   friction sticking), F the others, solved with the state's own factor
   (Section sec:condense-adjoint); held (nc + nt, may be NULL) receives 1
   at each held unknown, in the order of ic then it.  STATUS_NUMERIC when
   A_FF is singular. */
int qp_adjoint(const Qp_workspace *w, const double *grad, double *lam,
               char *held, Status *st);

/* y = A x, A stored with both triangles (as a Qp's); the package's one
   sparse product, which the tests use too */
void qp_matvec(const cholmod_sparse *A, const double *x, double *y);
#line 70 "paper/qp.nw"
#endif
