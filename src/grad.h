#line 38 "paper/grad.nw"
#ifndef CONTACTOPT_GRAD_H
#define CONTACTOPT_GRAD_H
#include "status.h"
#include "model.h"
#include "objective.h"

/* G (N+1 values) = grad E(X) by (4.8), at the design and state that the
   model solved last, without Coulomb friction (objective_evaluate gives
   J_F's through the fixed point).  It is a checked error to call it
   before a solve or at a Coulomb state. */
int grad_energy(const Model *md, double *G, Status *st);
#line 77 "paper/grad.nw"
typedef struct {
  int N;          /* the design has N+1 nodes */
  int ncheck;     /* the nodes checked: all N+1 unless the caller lowers it */
  int *check;     /* ncheck: their indices, ascending (0..N as made) */
  double *G;      /* N+1: dE/dX_i by (4.8) at X */
  double *fd;     /* N+1: the finite difference closest to G_i (NaN at a
                     node not checked) */
  double *err;    /* N+1: |fd_i - G_i| / max_k |G_k| (/ 1 when G = 0; NaN
                     at a node not checked) */
  int worst;      /* the node checked of the largest err, the first of equals */
  double *X;      /* N+1: scratch, the perturbed design */
  const Objective *objective; /* NULL (as made) or energy: E and (4.8);
                     another: its J and its gradient by the adjoint */
  char *crossed;  /* N+1: 1 where a difference met other held sets than
                     the design's (another objective, or Coulomb), else 0 */
  char *held;     /* the held sets at X while checking (scratch) */
} Grad_check;

/* called once per node i, when fd[i] and err[i] are known */
typedef void (*Grad_check_progress)(int i, const Grad_check *gc, void *data);

Grad_check *grad_check_new(int N, Status *st);
void grad_check_free(Grad_check *gc);
/* gc->G = grad E(X) by (4.8), gc->fd its best finite differences at the
   steps C0 1e-2 .. 1e-6; leaves the model solved at X.  progress may be
   NULL. */
int grad_check(Model *md, const double *X, Grad_check *gc,
               Grad_check_progress progress, void *data, Status *st);
/* the state solves that grad_check(md, X, gc, ...) takes, md's problem's */
long grad_check_solves(const Grad_check *gc, const Problem *p, const double *X);
#line 50 "paper/grad.nw"
#endif
