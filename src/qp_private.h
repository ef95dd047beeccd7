#line 237 "paper/qp.nw"
#ifndef CONTACTOPT_QP_PRIVATE_H
#define CONTACTOPT_QP_PRIVATE_H
/* The state solver's workspace, and what qp_base.c gives the methods:
   qp.c, qp_base.c, pdas.c, cgssor.c and psor.c include it, no other
   module does. */
#include "qp.h"
#include "qp_inline.h"
#include "condense.h"

#line 302 "paper/qp.nw"
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
  char *own;             /* nk: the active-set step's own next set, kept
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
  Pdas_guide gd;         /* the path-following guide of the steps */
} Pdas_workspace;

#line 334 "paper/qp.nw"
typedef struct {
  double *p;             /* n: the conjugate direction */
  double *q;             /* n: A p, or A beta in a proportioning step */
  double *z;             /* n: the preconditioned free gradient, or beta */
  double abar;           /* the expansion step length 1.9 / normA
                            (friction: 1.9 / ||S^-1||) */
  int restart;           /* 1: p must restart from z (the face changed) */
  int factored;          /* friction: S is condensed and factored for the
                            values of the last qp_set */
} Cgssor_workspace;

#line 268 "paper/qp.nw"
struct Qp_workspace {
  const Qp *qp;          /* the problem: its pattern fixed, values may change */
  Qp_options opt;        /* a copy of the caller's options */
  cholmod_common *cm;    /* the caller's CHOLMOD environment */
  int n;                 /* the number of unknowns: A is n x n */
  int nc;                /* the number of bounded unknowns, |I| */
  int nk;                /* nc + nt: the unknowns that PDAS condenses */
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
  double *grad;             /* n: the gradient A x - b at x */
  double *T;             /* nk: the contact forces grad[ik[k]] (4.6) */
  double kkt;            /* qp_kkt at x */
  int iter;              /* iterations since qp_set */
  struct Condense *cond; /* the condensation (condense.c): pdas, and
                            cgssor with friction; NULL otherwise */
  Pdas_workspace pdas;   /* method pdas only (pdas.c), zero otherwise */
  Cgssor_workspace cgssor; /* method cgssor only (cgssor.c), zero otherwise */
};

#line 695 "paper/qp.nw"
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

#line 356 "paper/qp.nw"
/* the relative KKT residual of x; normA = max_j sum_i |A_ij|; grad = Ax - b
   if known, else NULL; T (nc, may be NULL) receives the contact forces */
double qp_kkt_eval(const Qp *qp, double normA, const double *x,
                   const double *grad, double *T);
/* grad = A x - b, then kkt and T at x */
void qp_refresh(Qp_workspace *w);
/* bounded unknowns at their bound */
int qp_count_active(const Qp_workspace *w);
/* (4.3) has no solution: why, with how many bounds active */
int qp_not_held(const Qp_workspace *w, Status *st, const char *why,
                int active);
/* S, f and the factor of K at w's current values (condense_factor); a
   singular K is a body that nothing holds */
int qp_condense(Qp_workspace *w, Status *st);
/* x from the condensed y (condense_expand); grad, kkt and T at x */
int qp_expand(Qp_workspace *w, Status *st);
/* x_u refined by one step with the factor (condense_refine); grad, kkt, T */
int qp_refine(Qp_workspace *w, Status *st);
#line 255 "paper/qp.nw"
#endif
