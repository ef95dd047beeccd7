#line 139 "paper/cgssor.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "qp_private.h"
#include "cgssor.h"
#line 150 "paper/cgssor.nw"
#define MPRGP_GAMMA 1.0  /* proportioning: ||beta||^2 <= Gamma^2 phi~'phi */
#define MPRGP_ABAR 1.9   /* expansion step length abar = 1.9 / ||A|| */
#line 372 "paper/cgssor.nw"
#define TIE (4 * DBL_EPSILON)  /* blocking steps this close are equal */
#line 129 "paper/cgssor.nw"
static int proportional(const Qp_workspace *w);
static int proportioning_step(Qp_workspace *w, Status *st);
static double feasible_step(const Qp_workspace *w);
static void cg_step(Qp_workspace *w, double acg, double pap);
static void expansion_step(Qp_workspace *w, double af);
static int cg_or_expansion_step(Qp_workspace *w, Status *st);
static int dual_iterate(Qp_workspace *w, Status *st);
#line 156 "paper/cgssor.nw"
static double dot(int n, const double *u, const double *v)
{
  double s = 0;
  for (int i = 0; i < n; i++) s += u[i] * v[i];
  return s;
}
#line 167 "paper/cgssor.nw"
int cgssor_alloc(Qp_workspace *w, Status *st)
{
  Cgssor_workspace *mp = &w->cgssor;
  size_t n = (size_t) w->n + 1;
  mp->p = malloc(n * sizeof *mp->p), mp->q = malloc(n * sizeof *mp->q);
  mp->z = malloc(n * sizeof *mp->z);
  if (!mp->p || !mp->q || !mp->z)
    return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (cgssor)");
  return STATUS_OK;
}
#line 181 "paper/cgssor.nw"
void cgssor_set(Qp_workspace *w)
{
  w->cgssor.abar = MPRGP_ABAR / w->normA;   /* with friction: at the first step */
  w->cgssor.restart = 1, w->cgssor.factored = 0;
  if (w->cond) w->cond->condensed = 0;   /* S is the last values' */
}

void cgssor_free(Qp_workspace *w)
{
  free(w->cgssor.p), free(w->cgssor.q), free(w->cgssor.z);
}
#line 208 "paper/cgssor.nw"
/* z = SSOR(omega) of A restricted to the free set, applied to phi */
static void ssor_free(Qp_workspace *w)
{
  const Sparse_index *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  const double *Ax = w->qp->A->x;
  double *z = w->cgssor.z, om = w->opt.omega;
  for (int i = 0; i < w->n; i++) {          /* (D + omega L) y = phi */
    double s = w->grad[i];
    for (Sparse_index k = Ap[i]; k < Ap[i + 1] && Ai[k] < i; k++) s -= om * Ax[k] * z[Ai[k]];
    z[i] = qp_is_free(w, i) ? s / w->d[i] : 0;
  }
  for (int i = w->n - 1; i >= 0; i--) {     /* (D + omega U) z = D y */
    double s = 0;
    if (!qp_is_free(w, i)) continue;
    for (Sparse_index k = Ap[i + 1] - 1; k >= Ap[i] && Ai[k] > i; k--) s += Ax[k] * z[Ai[k]];
    z[i] -= om * s / w->d[i];
  }
}
#line 237 "paper/cgssor.nw"
int cgssor_iterate(Qp_workspace *w, Status *st)
{
  if (w->nk > w->nc) return dual_iterate(w, st);   /* friction */
  int code = proportional(w) ? cg_or_expansion_step(w, st)
                             : proportioning_step(w, st);
  if (code) return code;
  w->kkt = qp_kkt_eval(w->qp, w->normA, w->x, w->grad, w->T);
  if (w->kkt <= w->opt.tol) qp_refresh(w);   /* confirm from scratch */
  return STATUS_OK;
}
#line 250 "paper/cgssor.nw"
/* ||beta||^2 <= Gamma^2 phi~' phi */
static int proportional(const Qp_workspace *w)
{
  double bb = 0, fp = 0;
  for (int i = 0; i < w->n; i++) {
    double gi = w->grad[i];
    if (qp_is_free(w, i))
      fp += fmin((w->x[i] - w->lo[i]) / w->cgssor.abar, gi) * gi;
    else if (gi < 0)
      bb += gi * gi;
  }
  return bb <= MPRGP_GAMMA * MPRGP_GAMMA * fp;
}
#line 271 "paper/cgssor.nw"
/* x <- x - alpha beta, the exact minimiser along the chopped gradient */
static int proportioning_step(Qp_workspace *w, Status *st)
{
  Cgssor_workspace *mp = &w->cgssor;
  for (int i = 0; i < w->n; i++)
    mp->z[i] = !qp_is_free(w, i) && w->grad[i] < 0 ? w->grad[i] : 0;
  qp_matvec(w->qp->A, mp->z, mp->q);
  double bb = dot(w->n, mp->z, mp->z), bab = dot(w->n, mp->z, mp->q);
  if (!(bab > DBL_EPSILON * w->normA * bb))
    return qp_not_held(w, st, "A does not resist the chopped gradient",
                       qp_count_active(w));
  double alpha = bb / bab;
  for (int i = 0; i < w->n; i++)
    w->x[i] -= alpha * mp->z[i], w->grad[i] -= alpha * mp->q[i];
  mp->restart = 1;
  return STATUS_OK;
}
#line 303 "paper/cgssor.nw"
static int cg_or_expansion_step(Qp_workspace *w, Status *st)
{
  Cgssor_workspace *mp = &w->cgssor;
  int n = w->n;
  if (mp->restart || !(dot(n, w->grad, mp->p) > 0)) {
    ssor_free(w);
    memcpy(mp->p, mp->z, (size_t) n * sizeof *mp->p);
    mp->restart = 0;
  }
  double pp = dot(n, mp->p, mp->p);
  if (pp == 0) { qp_refresh(w); return STATUS_OK; }
  qp_matvec(w->qp->A, mp->p, mp->q);
  double pap = dot(n, mp->p, mp->q), af = feasible_step(w);
  double acg = pap > DBL_EPSILON * w->normA * pp ? dot(n, w->grad, mp->p) / pap
                                                 : INFINITY;
  if (acg == INFINITY && af == INFINITY)
    return qp_not_held(w, st, "neither A nor a bound resists the CG direction",
                       qp_count_active(w));
  if (acg <= af) cg_step(w, acg, pap);
  else expansion_step(w, af);
  return STATUS_OK;
}
#line 328 "paper/cgssor.nw"
/* the largest alpha with x - alpha p >= lo */
static double feasible_step(const Qp_workspace *w)
{
  double af = INFINITY;
  for (int i = 0; i < w->n; i++)
    if (w->cgssor.p[i] > 0 && w->bnd[i] >= 0)
      af = fmin(af, (w->x[i] - w->lo[i]) / w->cgssor.p[i]);
  return af;
}
#line 345 "paper/cgssor.nw"
/* x <- x - acg p; p <- z - gamma p, A-conjugate to the old p */
static void cg_step(Qp_workspace *w, double acg, double pap)
{
  Cgssor_workspace *mp = &w->cgssor;
  for (int i = 0; i < w->n; i++) {
    w->x[i] = qp_proj(w, i, w->x[i] - acg * mp->p[i]);
    w->grad[i] -= acg * mp->q[i];
  }
  ssor_free(w);
  double gamma = dot(w->n, mp->z, mp->q) / pap;
  for (int i = 0; i < w->n; i++) mp->p[i] = mp->z[i] - gamma * mp->p[i];
}
#line 376 "paper/cgssor.nw"
/* x <- P(x_half - abar phi(x_half)), x_half = x - af p */
static void expansion_step(Qp_workspace *w, double af)
{
  Cgssor_workspace *mp = &w->cgssor;
  for (int i = 0; i < w->n; i++) {
    int tie = mp->p[i] > 0 && w->x[i] - w->lo[i] <= af * mp->p[i] * (1 + TIE);
    w->x[i] = tie ? w->lo[i] : qp_proj(w, i, w->x[i] - af * mp->p[i]);
    w->grad[i] -= af * mp->q[i];
  }
  for (int i = 0; i < w->n; i++)
    if (qp_is_free(w, i)) w->x[i] = qp_proj(w, i, w->x[i] - mp->abar * w->grad[i]);
  qp_refresh(w);
  mp->restart = 1;
}
#line 512 "paper/cgssor.nw"
/* T_k strictly inside its interval (a width 0 never is) */
static int dual_free(const Qp_workspace *w, int k)
{
  return w->T[k] > w->flo[k] && w->T[k] < w->fhi[k];
}

/* the gradient of q at T_k: y_k - pos_k */
static double dual_grad(const Qp_workspace *w, int k)
{
  return w->cond->y[k] - w->pos[k];
}

/* the chopped gradient: what pulls T_k inward from an end; 0 inside and
   on an interval of width 0 */
static double dual_chopped(const Qp_workspace *w, int k)
{
  double grad = dual_grad(w, k);
  if (w->flo[k] == w->fhi[k] || dual_free(w, k)) return 0;
  return w->T[k] <= w->flo[k] ? fmin(grad, 0) : fmax(grad, 0);
}

/* v projected onto [flo_k, fhi_k]; a NaN stays */
static double dual_proj(const Qp_workspace *w, int k, double v)
{
  return v < w->flo[k] ? w->flo[k] : v > w->fhi[k] ? w->fhi[k] : v;
}
#line 542 "paper/cgssor.nw"
/* u = S^-1 v = L^-T L^-1 v (u and v distinct) */
static void dual_hessian(const Qp_workspace *w, const double *v, double *u)
{
  gsl_matrix_const_view L = gsl_matrix_const_view_array(w->cond->M, w->nk, w->nk);
  gsl_vector_view x = gsl_vector_view_array(u, w->nk);
  memcpy(u, v, (size_t) w->nk * sizeof *u);
  gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, &L.matrix, &x.vector);
  gsl_blas_dtrsv(CblasLower, CblasTrans, CblasNonUnit, &L.matrix, &x.vector);
}

/* y = S^-1 (f + T), from scratch */
static void dual_state(Qp_workspace *w)
{
  double *r = w->cgssor.z;
  for (int k = 0; k < w->nk; k++) r[k] = w->cond->f[k] + w->T[k];
  dual_hessian(w, r, w->cond->y);
}
#line 506 "paper/cgssor.nw"
#define POWER_TOL 1e-2   /* stop when ||S^-1 v - rho v|| <= POWER_TOL rho */
#define POWER_MAX 100    /* power iterations at most */

#line 564 "paper/cgssor.nw"
/* M = L, S = L L' by dense Cholesky; STATUS_NUMERIC if S is singular */
static int factor_schur(Qp_workspace *w, Status *st)
{
  int nk = w->nk;
  gsl_matrix_view M = gsl_matrix_view_array(w->cond->M, nk, nk);
  memcpy(w->cond->M, w->cond->S, (size_t) nk * nk * sizeof *w->cond->M);
  if (!gsl_linalg_cholesky_decomp1(&M.matrix) && qp_factor_regular(w->cond->M, nk))
    return STATUS_OK;
  return status_set(st, STATUS_NUMERIC, "cgssor with friction needs S, the "
    "Schur complement onto the %d contact unknowns, positive definite: it is "
    "its Cholesky factor's squared pivots spread by less than 100 epsilon, "
    "which is taken for singular; use solver.state = pdas",
    nk);
}

/* rho + ||r||: above the eigenvalue of S^-1 that the power iteration
   from the ones vector reaches, ||r|| <= POWER_TOL rho */
static double norm_inverse(Qp_workspace *w)
{
  double *v = w->cgssor.p, *u = w->cgssor.q, rho = 0, res = INFINITY;
  int nk = w->nk;
  for (int k = 0; k < nk; k++) v[k] = 1 / sqrt(nk);
  for (int it = 0; it < POWER_MAX && !(res <= POWER_TOL * rho); it++) {
    dual_hessian(w, v, u);
    rho = dot(nk, v, u), res = 0;
    for (int k = 0; k < nk; k++) res += (u[k] - rho * v[k]) * (u[k] - rho * v[k]);
    res = sqrt(res);
    double nu = sqrt(dot(nk, u, u));
    for (int k = 0; k < nk; k++) v[k] = u[k] / nu;
  }
  return rho + res;
}
#line 600 "paper/cgssor.nw"
static int dual_setup(Qp_workspace *w, Status *st)
{
  int code = qp_condense(w, st);
  if (!code) code = factor_schur(w, st);
  if (code) return code;
  w->cgssor.abar = MPRGP_ABAR / norm_inverse(w);
  for (int k = 0; k < w->nk; k++) w->T[k] = dual_proj(w, k, w->T[k]);
  dual_state(w);
  w->cgssor.restart = 1, w->cgssor.factored = 1;
  return STATUS_OK;
}
#line 615 "paper/cgssor.nw"
/* ||beta||^2 <= Gamma^2 phi~' phi on the box */
static int dual_proportional(const Qp_workspace *w)
{
  double bb = 0, fp = 0, a = w->cgssor.abar;
  for (int k = 0; k < w->nk; k++) {
    double grad = dual_grad(w, k), b = dual_chopped(w, k);
    if (dual_free(w, k))
      fp += (grad > 0 ? fmin((w->T[k] - w->flo[k]) / a, grad)
                   : fmax((w->T[k] - w->fhi[k]) / a, grad)) * grad;
    bb += b * b;
  }
  return bb <= MPRGP_GAMMA * MPRGP_GAMMA * fp;
}
#line 631 "paper/cgssor.nw"
/* the largest alpha with flo <= T - alpha d <= fhi */
static double dual_feasible_step(const Qp_workspace *w, const double *d)
{
  double af = INFINITY;
  for (int k = 0; k < w->nk; k++)
    if (d[k] > 0) af = fmin(af, (w->T[k] - w->flo[k]) / d[k]);
    else if (d[k] < 0) af = fmin(af, (w->T[k] - w->fhi[k]) / d[k]);
  return af;
}
#line 645 "paper/cgssor.nw"
/* T <- T - alpha beta, y <- y - alpha H beta */
static void dual_proportioning_step(Qp_workspace *w)
{
  Cgssor_workspace *mp = &w->cgssor;
  int nk = w->nk;
  for (int k = 0; k < nk; k++) mp->z[k] = dual_chopped(w, k);
  dual_hessian(w, mp->z, mp->q);
  double alpha = fmin(dot(nk, mp->z, mp->z) / dot(nk, mp->z, mp->q),
                      dual_feasible_step(w, mp->z));
  for (int k = 0; k < nk; k++) {
    w->T[k] = dual_proj(w, k, w->T[k] - alpha * mp->z[k]);
    w->cond->y[k] -= alpha * mp->q[k];
  }
  mp->restart = 1;
}
#line 665 "paper/cgssor.nw"
/* p <- the free gradient, where the face changed */
static void dual_restart(Qp_workspace *w, double *p)
{
  for (int k = 0; k < w->nk; k++) p[k] = dual_free(w, k) ? dual_grad(w, k) : 0;
}

/* grad' p, grad = y - pos */
static double dual_slope(const Qp_workspace *w, const double *p)
{
  double s = 0;
  for (int k = 0; k < w->nk; k++) s += dual_grad(w, k) * p[k];
  return s;
}

#line 699 "paper/cgssor.nw"
/* T <- T - acg p, y <- y - acg Hp; p <- z - gamma p */
static void dual_cg_step(Qp_workspace *w, double acg, double php)
{
  Cgssor_workspace *mp = &w->cgssor;
  for (int k = 0; k < w->nk; k++) {
    w->T[k] = dual_proj(w, k, w->T[k] - acg * mp->p[k]);
    w->cond->y[k] -= acg * mp->q[k];
  }
  dual_restart(w, mp->z);
  double gamma = dot(w->nk, mp->z, mp->q) / php;
  for (int k = 0; k < w->nk; k++) mp->p[k] = mp->z[k] - gamma * mp->p[k];
}

#line 717 "paper/cgssor.nw"
/* T <- P(T_half - abar phi(T_half)), T_half = T - af p; y from scratch */
static void dual_expansion_step(Qp_workspace *w, double af)
{
  Cgssor_workspace *mp = &w->cgssor;
  for (int k = 0; k < w->nk; k++) {
    double p = mp->p[k], end = p > 0 ? w->flo[k] : w->fhi[k];
    int tie = p != 0 && fabs(w->T[k] - end) <= af * fabs(p) * (1 + TIE);
    w->T[k] = tie ? end : dual_proj(w, k, w->T[k] - af * p);
    w->cond->y[k] -= af * mp->q[k];
  }
  for (int k = 0; k < w->nk; k++)
    if (dual_free(w, k)) w->T[k] = dual_proj(w, k, w->T[k] - mp->abar * dual_grad(w, k));
  dual_state(w);
  mp->restart = 1;
}

#line 683 "paper/cgssor.nw"
static void dual_cg_or_expansion_step(Qp_workspace *w)
{
  Cgssor_workspace *mp = &w->cgssor;
  int nk = w->nk;
  if (mp->restart || !(dual_slope(w, mp->p) > 0))
    dual_restart(w, mp->p), mp->restart = 0;
  if (dot(nk, mp->p, mp->p) == 0) { dual_state(w); return; }
  dual_hessian(w, mp->p, mp->q);
  double php = dot(nk, mp->p, mp->q), af = dual_feasible_step(w, mp->p);
  double acg = dual_slope(w, mp->p) / php;
  if (acg <= af) dual_cg_step(w, acg, php);
  else dual_expansion_step(w, af);
}
#line 741 "paper/cgssor.nw"
/* y_k = pos_k where T_k is inside; y_k on the allowed side at an end */
static void dual_snap(Qp_workspace *w)
{
  double *y = w->cond->y;
  for (int k = 0; k < w->nk; k++)
    if (w->flo[k] == w->fhi[k]) continue;
    else if (dual_free(w, k)) y[k] = w->pos[k];
    else if (w->T[k] <= w->flo[k]) y[k] = fmax(y[k], w->pos[k]);
    else y[k] = fmin(y[k], w->pos[k]);
}

/* the residual of (y snapped, T = S y - f), left in place if <= tol */
static double dual_snapped_kkt(Qp_workspace *w)
{
  Condense *cd = w->cond;
  size_t size = (size_t) w->nk * sizeof *cd->y;
  gsl_matrix_const_view S = gsl_matrix_const_view_array(cd->S, w->nk, w->nk);
  gsl_vector_view y = gsl_vector_view_array(cd->y, w->nk),
                  T = gsl_vector_view_array(w->T, w->nk);
  memcpy(w->cgssor.z, cd->y, size), memcpy(w->cgssor.q, w->T, size);
  dual_snap(w);
  memcpy(w->T, cd->f, size);
  gsl_blas_dgemv(CblasNoTrans, 1.0, &S.matrix, &y.vector, -1.0, &T.vector);
  double kkt = condense_kkt(cd, w->T, w->normA, w->gamma);
  if (!(kkt <= w->opt.tol))
    memcpy(cd->y, w->cgssor.z, size), memcpy(w->T, w->cgssor.q, size);
  return kkt;
}
#line 779 "paper/cgssor.nw"
static int dual_finish(Qp_workspace *w, Status *st)
{
  int met = w->kkt <= w->opt.tol, code;
  w->cond->stepped = 0;
  condense_predict(w->cond, w->T);
  w->cond->stepped = 1;
  if (!(code = qp_expand(w, st)) && w->kkt > w->opt.tol) code = qp_refine(w, st);
  if (code || !met || w->kkt <= w->opt.tol) return code;
  return status_set(st, STATUS_NUMERIC, "cgssor: the dual's pair met the "
    "tolerance at step %d, and the whole state formed from it, refined once, "
    "has kkt = %.3g > tol = %.3g", w->iter + 1, w->kkt, w->opt.tol);
}
#line 798 "paper/cgssor.nw"
static int dual_iterate(Qp_workspace *w, Status *st)
{
  int code;
  if (!w->cgssor.factored && (code = dual_setup(w, st))) return code;
  if (dual_proportional(w)) dual_cg_or_expansion_step(w);
  else dual_proportioning_step(w);
  w->kkt = condense_kkt(w->cond, w->T, w->normA, w->gamma);
  if (w->kkt <= w->opt.tol)
    dual_state(w), w->kkt = condense_kkt(w->cond, w->T, w->normA, w->gamma);
  if (w->kkt <= w->opt.tol) w->kkt = dual_snapped_kkt(w);
  if (w->kkt <= w->opt.tol || w->iter + 1 >= w->opt.max_iter)
    return dual_finish(w, st);
  return STATUS_OK;
}
#line 820 "paper/cgssor.nw"
int cgssor_end(Qp_workspace *w, Status *st)
{
  int code = STATUS_OK;
  if (w->nk > w->nc && !w->cond->condensed && !(code = qp_condense(w, st)))
    condense_states_at(w->cond, w->x, w->T);
  return code;
}
