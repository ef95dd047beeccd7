#line 92 "paper/condense.nw"
#ifndef CONTACTOPT_CONDENSE_H
#define CONTACTOPT_CONDENSE_H
/* The state problem condensed onto its contact unknowns: qp.c, pdas.c,
   mprgp.c and condense.c include this header, no other file does. */
#include "sparse.h"
#include "qp.h"

#line 116 "paper/condense.nw"
/* free at the lower end of its force's interval, held, free at the upper */
enum { CONDENSE_LO = 0, CONDENSE_HELD = 1, CONDENSE_HI = 2 };

#line 128 "paper/condense.nw"
typedef struct Condense {
  const cholmod_sparse *A; /* the problem's A (borrowed): its pattern, and
                            its values at each condensation */
  cholmod_common *cm;    /* the caller's CHOLMOD environment */
  int n;                 /* A is n x n */
  int nk;                /* the number of unknowns condensed onto */
  const int *ik;         /* nk: which they are (borrowed) */
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
                            user's (the Newton matrix of pdas, the factor
                            of S for MPRGP with friction) */
  double bu2;            /* ||b_u||^2, for the residual */
  cholmod_dense *rhs;    /* n x 1: the vector that two solves overwrite */
  cholmod_dense *sol;    /* n x 1: the vector between the two solves */
  cholmod_dense *solve_Y, *solve_E; /* cholmod_solve2's workspace Y, E, sized by CHOLMOD */
  cholmod_dense *Lb;     /* n x 1: z = L \ P b */
  char *act;             /* nk: the state of each, CONDENSE_HELD, _LO, _HI */
  int stepped;           /* y, T come from a Newton step (not a guess) */
  int condensed;         /* S, f belong to the current values of A and b */
} Condense;

#line 170 "paper/condense.nw"
/* the condensation of A onto its unknowns ik[0..nk-1], analysed; NULL
   (and st) on failure */
Condense *condense_alloc(const cholmod_sparse *A, int nk, const int *ik,
                         cholmod_common *cm, Status *st);
/* S, f and the factor of K at w's current values */
int condense_factor(Qp_workspace *w, Status *st);
/* frees the numeric factor of K (the analysis stays): the next
   condense_factor factorises anew, and nothing reads S or the factor
   before it (NULL: nothing) */
void condense_release(Condense *cd);
/* frees cd and all it owns (NULL: nothing) */
void condense_free(Condense *cd);

#line 188 "paper/condense.nw"
/* T = S y - f */
void condense_forces(Qp_workspace *w);
/* the relative KKT residual of y and T */
double condense_kkt(const Qp_workspace *w);
/* act = the states that y and T call for; 1 if none changed */
int condense_predict(Qp_workspace *w);
/* y from x, T = S y - f, and the states they call for (no step behind) */
void condense_states_at_x(Qp_workspace *w);

#line 203 "paper/condense.nw"
/* *v = L \ P *v (back = 0), or P' (L' \ *v) (back = 1): the triangular
   solves with the factor of K, through cd->sol */
int condense_solve(Condense *cd, int back, cholmod_dense **v, Status *st);
/* x from y by back substitution; g, kkt and T recomputed at x */
int condense_expand(Qp_workspace *w, Status *st);
/* x_u refined by one step with the factor; g, kkt, T recomputed */
int condense_refine(Qp_workspace *w, Status *st);
/* the states that (y, T) call for, then x, refined once if kkt > tol */
int condense_end(Qp_workspace *w, Status *st);

#line 217 "paper/condense.nw"
/* what qp_schur hands over: S of the last condensation (with friction,
   sticking held and sliding eliminated), or of one made apart */
int condense_schur(const Qp_workspace *w, double shift, double *S,
                   Status *st);

#line 944 "paper/condense.nw"
/* w's problem without friction condensed onto its bounded unknowns at
   the values of the last qp_set; who names the caller in a message */
Condense *condense_apart(const Qp_workspace *w, const char *who, Status *st);
#line 112 "paper/condense.nw"
#endif
