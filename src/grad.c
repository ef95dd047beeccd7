#line 108 "paper/grad.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grad.h"
#include "coulomb.h"
#line 166 "paper/grad.nw"
static void grad_element(const Model *md, int t, double *G);
static double grad_element_height(const double gy[3], const double q[6],
                                  const double e[3], const double De[3],
                                  double d, int m);
static double grad_body_force(const double F[2], const double q[6],
                              double gy_m);

int grad_energy(const Model *md, double *G, Status *st)
{
  if (!md->solved)
    return status_set(st, STATUS_INPUT, "gradient: no state has been solved");
  if (md->problem->contact == CONTACT_COULOMB)
    return coulomb_gradient(md, &(Objective) { OBJECTIVE_ENERGY, 8 }, G, st);
  memset(G, 0, md->mesh->ncol * sizeof *G);
  for (int c = 0; c < md->dofs->nc; c++)          /* -sum T_i V_i of (4.8) */
    G[md->dofs->contact_col[c]] -= md->T[c];
  int moving = 2 * md->mesh->N * md->mesh->M;      /* triangles below C0' */
  for (int t = 0; t < moving; t++) grad_element(md, t, G);
  if (md->problem->contact == CONTACT_TRESCA)      /* Section friction */
    friction_gradient(md->problem, md->mesh, md->dofs, md->Q, G);
  return STATUS_OK;
}
#line 205 "paper/grad.nw"
static void grad_element(const Model *md, int t, double *G)
{
  const Mesh *m = md->mesh;
  double xy[6], q[6], gx[3], gy[3], e[3], De[3];
  long double el[3];
  fem_element_xy(m, t, xy);
  fem_element_q(m, md->dofs, md->Q, t, q);
  fem_element_gradients(xy, gx, gy);
  double d = xy[0] * gx[0] + xy[2] * gx[1] + xy[4] * gx[2];   /* 2|T| */
  fem_element_strain(gx, gy, q, el);
  for (int r = 0; r < 3; r++) e[r] = (double) el[r];
  for (int r = 0; r < 3; r++)
    De[r] = md->hooke.D[r][0] * e[0] + md->hooke.D[r][1] * e[1]
          + md->hooke.D[r][2] * e[2];
  for (int v = 0; v < 3; v++) {
    int node = m->tri[3 * t + v];
    double rate = mesh_motion(m, node);
    if (rate == 0) continue;
    double de_dy = grad_element_height(gy, q, e, De, d, v);
    if (md->problem->has_body_force)
      de_dy -= grad_body_force(md->problem->F, q, gy[v]);
    G[node % m->ncol] += rate * de_dy;
  }
}
#line 234 "paper/grad.nw"
static double grad_element_height(const double gy[3], const double q[6],
                                  const double e[3], const double De[3],
                                  double d, int m)
{
  int up = (m + 2) % 3, down = (m + 1) % 3;     /* k with k+1 = m, k+2 = m */
  double de0 = q[2 * up] - q[2 * down];          /* d e~_11 / d y_m */
  double de2 = q[2 * up + 1] - q[2 * down + 1];  /* d e~_12 / d y_m */
  double energy2 = e[0] * De[0] + e[1] * De[1] + e[2] * De[2];
  return (De[0] * de0 + De[2] * de2) / (2 * d) - energy2 * gy[m] / (4 * d * d);
}
#line 248 "paper/grad.nw"
static double grad_body_force(const double F[2], const double q[6],
                              double gy_m)
{
  double work = 0;
  for (int v = 0; v < 3; v++) work += F[0] * q[2 * v] + F[1] * q[2 * v + 1];
  return work * gy_m / 6;
}
#line 279 "paper/grad.nw"
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
#line 322 "paper/grad.nw"
/* another objective than E: gc's */
static int grad_other(const Grad_check *gc)
{
  return gc->objective && gc->objective->kind != OBJECTIVE_ENERGY;
}

/* the held sets matter: another objective, or a Coulomb state, whose
   J_F has a kink where its sets change */
static int grad_sets_matter(const Model *md, const Grad_check *gc)
{
  return grad_other(gc) || md->problem->contact == CONTACT_COULOMB;
}

/* E (or gc's objective) at the design X with X_i = x; a change of the
   held sets is marked at i */
static int energy_with(Model *md, Grad_check *gc, int i, double x, double *E,
                       Status *st)
{
  double *X = gc->X;
  X[i] = x;
  int rc = model_solve(md, X, st);
  *E = md->energy;
  if (!rc && grad_other(gc)) rc = objective_value(md, gc->objective, E, st);
  if (!rc && grad_sets_matter(md, gc) && !objective_same_sets(md, gc->held, 0))
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
    
#line 367 "paper/grad.nw"
double Em, Ep;
if (!(rc = energy_with(md, gc, i, x0 - s, &Em, st))
    && !(rc = energy_with(md, gc, i, x0 + s, &Ep, st)))
  *fd = (Ep - Em) / (2 * s);
#line 358 "paper/grad.nw"
  } else {
    
#line 374 "paper/grad.nw"
double E0, E1, E2;
if (!(rc = energy_with(md, gc, i, x0, &E0, st))
    && !(rc = energy_with(md, gc, i, x0 + s, &E1, st))
    && !(rc = energy_with(md, gc, i, x0 + 2 * s, &E2, st)))
  *fd = (-3 * E0 + 4 * E1 - E2) / (2 * s);
#line 360 "paper/grad.nw"
  }
  X[i] = x0;
  return rc;
}
#line 382 "paper/grad.nw"
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
    int rc = grad_difference(md, gc, i, step * md->problem->C0, &fd, st);
    if (rc) return rc;
    double e = fabs(fd - gc->G[i]) / (Gmax > 0 ? Gmax : 1);
    if (e < gc->err[i]) { gc->err[i] = e; gc->fd[i] = fd; }
  }
  return STATUS_OK;
}
#line 404 "paper/grad.nw"
long grad_check_solves(const Grad_check *gc, const Problem *p, const double *X)
{
  long n = 2;
  for (int k = 0; k < gc->ncheck; k++)
    FOR_EACH_STEP(step) n += X[gc->check[k]] - step * p->C0 >= 0 ? 2 : 3;
  return n;
}
#line 416 "paper/grad.nw"
/* gc->G at the design just solved: (4.8), or another objective's
   gradient by its adjoint and the held sets it belongs to */
static int grad_at(Model *md, Grad_check *gc, Status *st)
{
  if (!grad_sets_matter(md, gc)) return grad_energy(md, gc->G, st);
  free(gc->held);
  gc->held = malloc((size_t) md->dofs->nc + md->dofs->nt + 1);
  if (!gc->held) return status_set(st, STATUS_MEMORY, "gradcheck: out of memory");
  memset(gc->crossed, 0, (size_t) gc->N + 1);
  objective_same_sets(md, gc->held, 1);
  return grad_other(gc) ? objective_gradient(md, gc->objective, gc->G, st)
                        : grad_energy(md, gc->G, st);
}

int grad_check(Model *md, const double *X, Grad_check *gc,
               Grad_check_progress progress, void *data, Status *st)
{
  int rc, n = gc->N + 1;
  double Gmax = 0;
  if (gc->N != md->problem->N)
    return status_set(st, STATUS_INPUT, "gradcheck: made for N = %d, the "
                      "model has N = %d", gc->N, md->problem->N);
  if (gc->ncheck < 1 || gc->ncheck > n)
    return status_set(st, STATUS_INPUT, "gradcheck: %d nodes to check", gc->ncheck);
  for (int k = 0; k < gc->ncheck; k++)
    if (gc->check[k] < (k ? gc->check[k - 1] + 1 : 0) || gc->check[k] > gc->N)
      return status_set(st, STATUS_INPUT, "gradcheck: the nodes to check are "
                        "not ascending in 0..%d (node %d)", gc->N, gc->check[k]);
  md->fixed_point_rounding = 1;        /* Coulomb: forces to rounding */
  if ((rc = model_solve(md, X, st)) || (rc = grad_at(md, gc, st))) return rc;
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
  return model_solve(md, X, st);
}
