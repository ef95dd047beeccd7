#line 98 "paper/mprgp.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qp_private.h"

#line 106 "paper/mprgp.nw"
#define MPRGP_GAMMA 1.0  /* proportioning: ||beta||^2 <= Gamma^2 phi~'phi */
#define MPRGP_ABAR 1.9   /* expansion step length abar = 1.9 / ||A|| */
#line 326 "paper/mprgp.nw"
#define TIE (4 * DBL_EPSILON)  /* blocking steps this close are equal */

#line 112 "paper/mprgp.nw"
static double dot(int n, const double *u, const double *v)
{
  double s = 0;
  for (int i = 0; i < n; i++) s += u[i] * v[i];
  return s;
}

#line 123 "paper/mprgp.nw"
int mprgp_alloc(Qp_workspace *w, Status *st)
{
  Mprgp_workspace *mp = &w->mprgp;
  size_t n = (size_t) w->n + 1;
  mp->p = malloc(n * sizeof *mp->p), mp->q = malloc(n * sizeof *mp->q);
  mp->z = malloc(n * sizeof *mp->z);
  if (!mp->p || !mp->q || !mp->z)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory (cgssor)");
  return STATUS_OK;
}

#line 137 "paper/mprgp.nw"
void mprgp_set(Qp_workspace *w)
{
  w->mprgp.abar = MPRGP_ABAR / w->normA;
  w->mprgp.restart = 1;
}

void mprgp_free(Qp_workspace *w)
{
  free(w->mprgp.p), free(w->mprgp.q), free(w->mprgp.z);
}

#line 163 "paper/mprgp.nw"
/* z = SSOR(omega) of A restricted to the free set, applied to phi */
static void ssor_free(Qp_workspace *w)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  const double *Ax = w->qp->A->x;
  double *z = w->mprgp.z, om = w->opt.omega;
  for (int i = 0; i < w->n; i++) {          /* (D + omega L) y = phi */
    double s = w->g[i];
    for (int k = Ap[i]; k < Ap[i + 1] && Ai[k] < i; k++) s -= om * Ax[k] * z[Ai[k]];
    z[i] = qp_is_free(w, i) ? s / w->d[i] : 0;
  }
  for (int i = w->n - 1; i >= 0; i--) {     /* (D + omega U) z = D y */
    double s = 0;
    if (!qp_is_free(w, i)) continue;
    for (int k = Ap[i + 1] - 1; k >= Ap[i] && Ai[k] > i; k--) s += Ax[k] * z[Ai[k]];
    z[i] -= om * s / w->d[i];
  }
}

#line 204 "paper/mprgp.nw"
/* ||beta||^2 <= Gamma^2 phi~' phi */
static int proportional(const Qp_workspace *w)
{
  double bb = 0, fp = 0;
  for (int i = 0; i < w->n; i++) {
    double gi = w->g[i];
    if (qp_is_free(w, i))
      fp += fmin((w->x[i] - w->lo[i]) / w->mprgp.abar, gi) * gi;
    else if (gi < 0)
      bb += gi * gi;
  }
  return bb <= MPRGP_GAMMA * MPRGP_GAMMA * fp;
}

#line 225 "paper/mprgp.nw"
/* x <- x - alpha beta, the exact minimiser along the chopped gradient */
static int proportioning_step(Qp_workspace *w, Status *st)
{
  Mprgp_workspace *mp = &w->mprgp;
  for (int i = 0; i < w->n; i++)
    mp->z[i] = !qp_is_free(w, i) && w->g[i] < 0 ? w->g[i] : 0;
  qp_matvec(w->qp->A, mp->z, mp->q);
  double bb = dot(w->n, mp->z, mp->z), bab = dot(w->n, mp->z, mp->q);
  if (!(bab > DBL_EPSILON * w->normA * bb))
    return qp_not_held(w, st, "A does not resist the chopped gradient",
                       qp_count_active(w));
  double alpha = bb / bab;
  for (int i = 0; i < w->n; i++)
    w->x[i] -= alpha * mp->z[i], w->g[i] -= alpha * mp->q[i];
  mp->restart = 1;
  return STATUS_OK;
}

#line 282 "paper/mprgp.nw"
/* the largest alpha with x - alpha p >= lo */
static double feasible_step(const Qp_workspace *w)
{
  double af = INFINITY;
  for (int i = 0; i < w->n; i++)
    if (w->mprgp.p[i] > 0 && w->bnd[i] >= 0)
      af = fmin(af, (w->x[i] - w->lo[i]) / w->mprgp.p[i]);
  return af;
}

#line 299 "paper/mprgp.nw"
/* x <- x - acg p; p <- z - gamma p, A-conjugate to the old p */
static void cg_step(Qp_workspace *w, double acg, double pap)
{
  Mprgp_workspace *mp = &w->mprgp;
  for (int i = 0; i < w->n; i++) {
    w->x[i] = qp_proj(w, i, w->x[i] - acg * mp->p[i]);
    w->g[i] -= acg * mp->q[i];
  }
  ssor_free(w);
  double gamma = dot(w->n, mp->z, mp->q) / pap;
  for (int i = 0; i < w->n; i++) mp->p[i] = mp->z[i] - gamma * mp->p[i];
}

#line 330 "paper/mprgp.nw"
/* x <- P(x_half - abar phi(x_half)), x_half = x - af p */
static void expansion_step(Qp_workspace *w, double af)
{
  Mprgp_workspace *mp = &w->mprgp;
  for (int i = 0; i < w->n; i++) {
    int tie = mp->p[i] > 0 && w->x[i] - w->lo[i] <= af * mp->p[i] * (1 + TIE);
    w->x[i] = tie ? w->lo[i] : qp_proj(w, i, w->x[i] - af * mp->p[i]);
    w->g[i] -= af * mp->q[i];
  }
  for (int i = 0; i < w->n; i++)
    if (qp_is_free(w, i)) w->x[i] = qp_proj(w, i, w->x[i] - mp->abar * w->g[i]);
  qp_refresh(w);
  mp->restart = 1;
}

#line 257 "paper/mprgp.nw"
static int cg_or_expansion_step(Qp_workspace *w, Status *st)
{
  Mprgp_workspace *mp = &w->mprgp;
  int n = w->n;
  if (mp->restart || !(dot(n, w->g, mp->p) > 0)) {
    ssor_free(w);
    memcpy(mp->p, mp->z, (size_t) n * sizeof *mp->p);
    mp->restart = 0;
  }
  double pp = dot(n, mp->p, mp->p);
  if (pp == 0) { qp_refresh(w); return STATUS_OK; }
  qp_matvec(w->qp->A, mp->p, mp->q);
  double pap = dot(n, mp->p, mp->q), af = feasible_step(w);
  double acg = pap > DBL_EPSILON * w->normA * pp ? dot(n, w->g, mp->p) / pap
                                                 : INFINITY;
  if (acg == INFINITY && af == INFINITY)
    return qp_not_held(w, st, "neither A nor a bound resists the CG direction",
                       qp_count_active(w));
  if (acg <= af) cg_step(w, acg, pap);
  else expansion_step(w, af);
  return STATUS_OK;
}

#line 192 "paper/mprgp.nw"
int mprgp_iterate(Qp_workspace *w, Status *st)
{
  int code = proportional(w) ? cg_or_expansion_step(w, st)
                             : proportioning_step(w, st);
  if (code) return code;
  w->kkt = qp_kkt_eval(w->qp, w->x, w->g, w->T);
  if (w->kkt <= w->opt.tol) qp_refresh(w);   /* confirm from scratch */
  return STATUS_OK;
}
