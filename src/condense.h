#line 94 "paper/condense.nw"
#ifndef CONTACTOPT_CONDENSE_H
#define CONTACTOPT_CONDENSE_H
/* The state problem condensed onto its contact unknowns: the state
   solver's files include this header, no other module does. */
#include "sparse.h"
#include "status.h"

#line 118 "paper/condense.nw"
/* free at the lower end of its force's interval, held, free at the upper */
enum { CONDENSE_LO = 0, CONDENSE_HELD = 1, CONDENSE_HI = 2 };
#define CONDENSE_SINGULAR (-1) /* K is singular (not a Status_code) */

#line 131 "paper/condense.nw"
typedef struct Condense {
  const cholmod_sparse *A; /* the problem's A (borrowed): its pattern, and
                            its values at each condensation */
  cholmod_common *cm;    /* the caller's CHOLMOD environment */
  int n;                 /* A is n x n */
  int nk;                /* the number of unknowns condensed onto */
  const int *ik;         /* nk: which they are (borrowed) */
  int nc;                /* the first nc of them are bounded, the others slip */
  const double *b;       /* n: the load (borrowed) */
  const double *d;       /* n: the diagonal A_ii (borrowed) */
  const double *pos;     /* nk: where each sits when held (borrowed) */
  const double *flo, *fhi; /* nk: the interval of its force (borrowed) */
  int *at;               /* n: k when unknown i = ik[k], -1 otherwise */
  Sparse_index *perm;    /* n: P, the unknown at each place of the factor,
                            the condensed unknowns last */
  cholmod_sparse *K;     /* n x n: P (A + D_c) P', its lower triangle
                            (stype -1, sorted), own pattern and values */
  Sparse_index *src;     /* nnz(K): the entry of A's lower triangle that
                            each entry of K takes its value from */
  cholmod_factor *Ls;    /* n x n: the symbolic analysis of K */
  cholmod_factor *L;     /* n x n: the factor LL' of K at the current values */
  int first;             /* n - nk: where the condensed unknowns start in L */
  int *tc;               /* nk: the condensed unknown c at position first + t */
  double *Lcc;           /* nk x nk, row-major: the trailing block of L */
  double *S;             /* nk x nk, row-major: the Schur complement of A */
  double *f;             /* nk: the condensed load */
  double *y;             /* nk: the condensed iterate x[ik] */
  double *M;             /* nk x nk: L_cc L_cc' while condensing, then its
                            user's (the matrix of an active-set step of
                            pdas, the factor of S for cgssor with friction) */
  double bu2;            /* ||b_u||^2, for the residual */
  cholmod_dense *rhs;    /* n x 1: the vector that two solves overwrite */
  cholmod_dense *sol;    /* n x 1: the vector between the two solves */
  cholmod_dense *solve_Y, *solve_E; /* cholmod_solve2's scratch Y, E, sized by CHOLMOD */
  cholmod_dense *Lb;     /* n x 1: z = L \ P b */
  char *act;             /* nk: the state of each, CONDENSE_HELD, _LO, _HI */
  int stepped;           /* y, T come from an active-set step (not a guess) */
  int condensed;         /* S, f belong to the current values of A and b */
} Condense;

#line 178 "paper/condense.nw"
/* what the condensed problem reads besides A, borrowed: their values may
   change between condensations, their places may not */
typedef struct {
  int nc;                  /* the first nc condensed unknowns are bounded */
  const double *b;         /* n: the load */
  const double *d;         /* n: the diagonal A_ii */
  const double *pos;       /* nk: where each sits when held */
  const double *flo, *fhi; /* nk: the interval of its force */
} Condense_contact;

/* the condensation of A onto its unknowns ik[0..nk-1], analysed; ct
   (may be NULL: the analysis alone) lent; NULL (and st) on failure */
Condense *condense_alloc(const cholmod_sparse *A, int nk, const int *ik,
                         const Condense_contact *ct, cholmod_common *cm,
                         Status *st);
/* S, f and the factor of K at the current values of A, b and d;
   CONDENSE_SINGULAR when K is singular */
int condense_factor(Condense *cd, Status *st);
/* frees the numeric factor of K (the analysis stays): the next
   condense_factor factorises anew, and nothing reads S or the factor
   before it (NULL: nothing) */
void condense_release(Condense *cd);
/* frees cd and all it owns (NULL: nothing) */
void condense_free(Condense *cd);

#line 209 "paper/condense.nw"
/* T (nk) = S y - f */
void condense_forces(const Condense *cd, double *T);
/* the relative KKT residual of y and T; normA and gamma: the bound of
   ||A|| and the relative rounding of a residual (qp_kkt_eval) */
double condense_kkt(const Condense *cd, const double *T, double normA,
                    double gamma);
/* act = the states that y and T call for; 1 if none changed */
int condense_predict(Condense *cd, const double *T);
/* y from x (n), T = S y - f, and the states they call for (no step
   behind) */
void condense_states_at(Condense *cd, const double *x, double *T);

#line 227 "paper/condense.nw"
/* *v = L \ P *v (back = 0), or P' (L' \ *v) (back = 1): the triangular
   solves with the factor of K, through cd->sol */
int condense_solve(Condense *cd, int back, cholmod_dense **v, Status *st);
/* x (n) from y by back substitution */
int condense_expand(Condense *cd, double *x, Status *st);
/* x_u refined by one step with the factor, grad = A x - b at x */
int condense_refine(Condense *cd, const double *grad, double *x, Status *st);

#line 239 "paper/condense.nw"
/* S (nc x nc) of the condensation cd, its diagonal raised by shift A_ii;
   with friction, the sticking unknowns held and the sliding ones
   eliminated */
int condense_schur(const Condense *cd, double shift, double *S,
                   Status *st);

#line 1010 "paper/condense.nw"
/* lam (n) = the adjoint of the state x (n) with the factor of cd: lam_H
   = 0 on the held unknowns, A_FF lam_F = g_F; held (nk, may be NULL)
   receives 1 at each held unknown, in the order of ik */
int condense_adjoint(Condense *cd, const double *x, const double *grad,
                     double *lam, char *held, Status *st);
#line 114 "paper/condense.nw"
#endif
