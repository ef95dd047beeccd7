#line 289 "paper/grad.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grad.h"
#line 297 "paper/grad.nw"
Grad_check *grad_check_new(int N, Status *st)
{
  if (N < 1) {
    status_set(st, STATUS_INPUT, "gradcheck: N = %d < 1", N);
    return NULL;
  }
  Grad_check *gc = malloc(sizeof *gc);
  double *v = malloc(4 * ((size_t) N + 1) * sizeof *v + ((size_t) N + 1) * (sizeof (int) + 1));
  if (!gc || !v) {
    free(gc);
    free(v);
    status_set(st, STATUS_MEMORY, "gradcheck: out of memory");
    return NULL;
  }
  gc->N = N;
  gc->worst = 0;
  gc->G = v;
  gc->fd = gc->G + N + 1;
  gc->err = gc->fd + N + 1;
  gc->X = gc->err + N + 1;
  gc->check = (int *) (gc->X + N + 1);
  gc->ncheck = N + 1;
  for (int i = 0; i <= N; i++) gc->check[i] = i;
  gc->crossed = (char *) (gc->check + N + 1);
  memset(gc->crossed, 0, (size_t) N + 1);
  gc->objective = NULL;
  gc->held = NULL;
  return gc;
}

void grad_check_free(Grad_check *gc)
{
  if (!gc) return;
  free(gc->held);
  free(gc->G);
  free(gc);
}
#line 340 "paper/grad.nw"
/* the objective checked: gc's, E where it names none */
static Objective grad_objective(const Grad_check *gc)
{
  return gc->objective ? *gc->objective : objective_default();
}

/* E (or gc's objective) at the design X with X_i = x; where the objective
   has a kink at a change of the held sets (objective_has_kinks), such a
   change is marked at i */
static int energy_with(Model *md, Grad_check *gc, int i, double x, double *E,
                       Status *st)
{
  double *X = gc->X;
  Objective o = grad_objective(gc);
  X[i] = x;
  int rc = model_solve_to_rounding(md, X, st);
  *E = model_energy(md);
  if (!rc) rc = objective_value(md, &o, E, st);
  if (!rc && objective_has_kinks(md, &o) && !objective_same_sets(md, gc->held, 0))
    gc->crossed[i] = 1;
  return rc;
}

/* fd = dE/dX_i by a difference with step s; X is restored */
static int grad_difference(Model *md, Grad_check *gc, int i, double s,
                           double *fd, Status *st)
{
  double *X = gc->X, x0 = X[i];
  int rc;
  if (x0 - s >= 0) {
    
#line 380 "paper/grad.nw"
double Em, Ep;
if (!(rc = energy_with(md, gc, i, x0 - s, &Em, st))
    && !(rc = energy_with(md, gc, i, x0 + s, &Ep, st)))
  *fd = (Ep - Em) / (2 * s);
#line 371 "paper/grad.nw"
  } else {
    
#line 387 "paper/grad.nw"
double E0, E1, E2;
if (!(rc = energy_with(md, gc, i, x0, &E0, st))
    && !(rc = energy_with(md, gc, i, x0 + s, &E1, st))
    && !(rc = energy_with(md, gc, i, x0 + 2 * s, &E2, st)))
  *fd = (-3 * E0 + 4 * E1 - E2) / (2 * s);
#line 373 "paper/grad.nw"
  }
  X[i] = x0;
  return rc;
}
#line 395 "paper/grad.nw"
/* the steps of the differences, relative to C0: 1e-2, 1e-3, ..., 1e-6 */
#define FOR_EACH_STEP(step) \
  for (double step = 1e-2; step >= 1e-6 * 0.999; step /= 10)

static int grad_check_node(Model *md, Grad_check *gc, int i, double Gmax,
                           Status *st)
{
  gc->err[i] = INFINITY;
  gc->fd[i] = NAN;
  FOR_EACH_STEP(step) {
    double fd;
    int rc = grad_difference(md, gc, i, step * model_problem(md)->C0, &fd, st);
    if (rc) return rc;
    double e = fabs(fd - gc->G[i]) / (Gmax > 0 ? Gmax : 1);
    if (e < gc->err[i]) { gc->err[i] = e; gc->fd[i] = fd; }
  }
  return STATUS_OK;
}
#line 417 "paper/grad.nw"
long grad_check_solves(const Grad_check *gc, const Problem *p, const double *X)
{
  long n = 2;
  for (int k = 0; k < gc->ncheck; k++)
    FOR_EACH_STEP(step) n += X[gc->check[k]] - step * p->C0 >= 0 ? 2 : 3;
  return n;
}
#line 431 "paper/grad.nw"
/* gc->G at the design just solved by the objective's front door: (4.8),
   or another objective's gradient with the held sets it belongs to */
static int grad_at(Model *md, Grad_check *gc, Status *st)
{
  Objective o = grad_objective(gc);
  if (objective_has_kinks(md, &o)) {
    free(gc->held);
    gc->held = malloc((size_t) model_dofs(md)->nc + model_dofs(md)->nt + 1);
    if (!gc->held) return status_set(st, STATUS_MEMORY, "gradcheck: out of memory");
    memset(gc->crossed, 0, (size_t) gc->N + 1);
    objective_same_sets(md, gc->held, 1);
  }
  return objective_evaluate(md, &o, NULL, gc->G, NULL, st);
}

int grad_check(Model *md, const double *X, Grad_check *gc,
               Grad_check_progress progress, void *data, Status *st)
{
  int rc, n = gc->N + 1;
  double Gmax = 0;
  if (gc->N != model_problem(md)->N)
    return status_set(st, STATUS_INPUT, "gradcheck: made for N = %d, the "
                      "model has N = %d", gc->N, model_problem(md)->N);
  if (gc->ncheck < 1 || gc->ncheck > n)
    return status_set(st, STATUS_INPUT, "gradcheck: %d nodes to check", gc->ncheck);
  for (int k = 0; k < gc->ncheck; k++)
    if (gc->check[k] < (k ? gc->check[k - 1] + 1 : 0) || gc->check[k] > gc->N)
      return status_set(st, STATUS_INPUT, "gradcheck: the nodes to check are "
                        "not ascending in 0..%d (node %d)", gc->N, gc->check[k]);
  if ((rc = model_solve_to_rounding(md, X, st)) || (rc = grad_at(md, gc, st)))
    return rc;
  for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(gc->G[i]));
  for (int i = 0; i < n; i++) gc->fd[i] = gc->err[i] = NAN;
  memcpy(gc->X, X, n * sizeof *X);
  for (int k = 0; k < gc->ncheck; k++) {
    if ((rc = grad_check_node(md, gc, gc->check[k], Gmax, st))) return rc;
    if (progress) progress(gc->check[k], gc, data);
  }
  gc->worst = gc->check[0];
  for (int k = 1; k < gc->ncheck; k++)
    if (gc->err[gc->check[k]] > gc->err[gc->worst]) gc->worst = gc->check[k];
  free(gc->held);
  gc->held = NULL;
  return model_solve_to_rounding(md, X, st);
}
