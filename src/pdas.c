#line 242 "paper/pdas.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "qp_private.h"
#include "pdas.h"
#line 331 "paper/pdas.nw"
#define SINGULAR (-1)    /* a step matrix is singular (not a Status_code) */
#line 336 "paper/pdas.nw"
enum { GUIDE_OFF = 0, GUIDE_ON = 1, GUIDE_STOPPED = 2 };
#line 236 "paper/pdas.nw"
static int pdas_step(Qp_workspace *w);
static int hold_stopping(Qp_workspace *w);
static void guide(Qp_workspace *w);
#line 258 "paper/pdas.nw"
/* the first active set: all of I; a warm start guesses after condensing */
void pdas_set(Qp_workspace *w, int warm)
{
  Pdas_workspace *pd = &w->pdas;
  Condense *cd = w->cond;
  pd->warm = warm, cd->condensed = 0, cd->stepped = 1;
  pd->gd.state = GUIDE_OFF, pd->gd.guided = 0;
  for (int c = 0; c < w->nk; c++) cd->act[c] = CONDENSE_HELD, pd->moved[c] = 0;
}

/* the size of the active set */
static int count_act(const Qp_workspace *w)
{
  int m = 0;
  for (int c = 0; c < w->nk; c++) m += w->cond->act[c] == CONDENSE_HELD;
  return m;
}
#line 282 "paper/pdas.nw"
/* the guide's vectors, nc each; nonzero when out of memory */
static int alloc_guide(Pdas_guide *gd, size_t nc)
{
  gd->s = malloc(nc * sizeof *gd->s), gd->t = malloc(nc * sizeof *gd->t);
  gd->ds = malloc(nc * sizeof *gd->ds), gd->dt = malloc(nc * sizeof *gd->dt);
  gd->as = malloc(nc * sizeof *gd->as), gd->at = malloc(nc * sizeof *gd->at);
  gd->b = malloc(nc * sizeof *gd->b), gd->db = malloc(nc * sizeof *gd->db);
  gd->ab = malloc(nc * sizeof *gd->ab);
  gd->h = malloc(nc * sizeof *gd->h);
  gd->pred = malloc(nc), gd->own = malloc(nc);
  return !gd->s || !gd->t || !gd->ds || !gd->dt || !gd->as || !gd->at
         || !gd->b || !gd->db || !gd->ab || !gd->h || !gd->pred || !gd->own;
}

int pdas_alloc(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  size_t nc = (size_t) w->nk + 1;
  pd->fr = malloc(nc * sizeof *pd->fr), pd->r = malloc(nc * sizeof *pd->r);
  pd->prev = malloc(nc), pd->moved = malloc(nc);
  if (!pd->fr || !pd->r || !pd->prev || !pd->moved || alloc_guide(&pd->gd, nc))
    return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (pdas, "
                      "nc = %d)", w->nk);
  return STATUS_OK;
}
#line 310 "paper/pdas.nw"
void pdas_free(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  free(pd->fr), free(pd->r), free(pd->prev), free(pd->moved);
  free(pd->gd.s), free(pd->gd.t), free(pd->gd.ds), free(pd->gd.dt);
  free(pd->gd.as), free(pd->gd.at), free(pd->gd.h), free(pd->gd.pred), free(pd->gd.own);
  free(pd->gd.b), free(pd->gd.db), free(pd->gd.ab);
}
#line 340 "paper/pdas.nw"
/* 1 if a step past kkt <= tol is to be taken to the set that the state
   calls for (below): room for it, a change called for by more than the
   rounding rho_f of a force, none changed back, none tangential */
static int settle(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  const Condense *cd = w->cond;
  const char *act = cd->act;
  double yy = 0, bb = cd->bu2, beyond = 0;
  if (w->iter + 2 >= w->opt.max_iter) return 0;
  for (int c = 0; c < w->nk; c++) {
    double bc = w->qp->b[w->ik[c]];
    yy += cd->y[c] * cd->y[c], bb += bc * bc;
    if (act[c] == pd->prev[c]) continue;
    if (pd->moved[c] || c >= w->nc) return 0;
    double z = w->T[c] + w->d[w->ik[c]] * (w->pos[c] - cd->y[c]);
    beyond = fmax(beyond, fmin(fabs(z - w->flo[c]), fabs(z - w->fhi[c])));
  }
  if (!(beyond > w->gamma * (w->normA * sqrt(yy) + sqrt(bb)))) return 0;
  for (int c = 0; c < w->nk; c++) pd->moved[c] |= act[c] != pd->prev[c];
  return 1;
}

int pdas_iterate(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  int code;
  if (!w->cond->condensed) {
    
#line 391 "paper/pdas.nw"
if ((code = qp_condense(w, st))) return code;
if (pd->warm) condense_states_at(w->cond, w->x, w->T);
#line 369 "paper/pdas.nw"
  }
  if (w->qp->slides) hold_stopping(w);
  if (w->iter > 0) guide(w);
  if (w->qp->slides && pd->gd.guided) hold_stopping(w);
  if ((code = pdas_step(w)) == SINGULAR && pd->gd.guided) {
    memcpy(w->cond->act, pd->gd.own, (size_t) w->nk); /* the guide's set: retake */
    pd->gd.guided = 0;
    code = pdas_step(w);
  }
  if (code == SINGULAR && w->iter == 0 && pd->warm) {
    pdas_set(w, 0), w->cond->condensed = 1; /* the guess holds nothing: cold */
    code = pdas_step(w);
  }
  if (code == SINGULAR)
    return qp_not_held(w, st, "the step matrix is singular", count_act(w));
  condense_forces(w->cond, w->T);
  w->kkt = condense_kkt(w->cond, w->T, w->normA, w->gamma);
  
#line 437 "paper/pdas.nw"
memcpy(pd->prev, w->cond->act, (size_t) w->nk);
int same = condense_predict(w->cond, w->T), solved = w->kkt <= w->opt.tol;
if (solved && !same && settle(w)) {
  w->iter++;                           /* a step more, to the forces' set */
  return pdas_iterate(w, st);
}
if (!same && !solved && w->iter + 1 < w->opt.max_iter) return STATUS_OK;
if ((code = qp_expand(w, st))) return code;
if (w->kkt > w->opt.tol && (same || solved) && (code = qp_refine(w, st)))
  return code;
if (!same || w->kkt <= w->opt.tol) return STATUS_OK;
return status_set(st, STATUS_NUMERIC, "pdas: the active set repeated at "
  "active-set step %d, and its state, refined once, has kkt = %.3g > tol = "
  "%.3g", w->iter + 1, w->kkt, w->opt.tol);
#line 387 "paper/pdas.nw"
}
#line 471 "paper/pdas.nw"
/* y = lo on the active set, the solution of the step system off it */
static int pdas_step(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Condense *cd = w->cond;
  int nk = w->nk, m = 0;
  const double *lo = w->pos;
  
#line 495 "paper/pdas.nw"
for (int c = 0; c < nk; c++)
  if (cd->act[c] == CONDENSE_HELD) cd->y[c] = lo[c];
  else pd->fr[m++] = c;
for (int a = 0; a < m; a++) {
  int c0 = pd->fr[a];
  const double *Sa = cd->S + (size_t) c0 * nk;
  double s = cd->f[c0] + (cd->act[c0] == CONDENSE_HI ? w->fhi[c0] : w->flo[c0]);
  for (int c = 0; c < nk; c++) if (cd->act[c] == CONDENSE_HELD) s -= Sa[c] * lo[c];
  pd->r[a] = s;
  for (int b = 0; b < m; b++) cd->M[(size_t) a * m + b] = Sa[pd->fr[b]];
}
#line 479 "paper/pdas.nw"
  if (m == 0) return STATUS_OK;
  gsl_matrix_view M = gsl_matrix_view_array(cd->M, m, m);
  gsl_vector_view r = gsl_vector_view_array(pd->r, m);
  if (gsl_linalg_cholesky_decomp1(&M.matrix) || !qp_factor_regular(cd->M, m))
    return SINGULAR;
  gsl_linalg_cholesky_svx(&M.matrix, &r.vector);
  for (int a = 0; a < m; a++) cd->y[pd->fr[a]] = pd->r[a];
  return STATUS_OK;
}
#line 576 "paper/pdas.nw"
/* 1 if every tangential unknown is free (and there is one): N = the sum
   of their right-hand sides, noise = the rounding it may carry */
static int slide_imbalance(const Qp_workspace *w, double *N, double *noise)
{
  const Condense *cd = w->cond;
  double sum = 0, size = 0;
  for (int t = w->nc; t < w->nk; t++) {
    if (cd->act[t] == CONDENSE_HELD) return 0;
    const double *St = cd->S + (size_t) t * w->nk;
    double F = cd->act[t] == CONDENSE_HI ? w->fhi[t] : w->flo[t];
    sum += cd->f[t] + F, size += fabs(cd->f[t]) + fabs(F);
    for (int c = 0; c < w->nk; c++)
      if (cd->act[c] == CONDENSE_HELD)
        sum -= St[c] * w->pos[c], size += fabs(St[c] * w->pos[c]);
  }
  *N = sum, *noise = (w->nk + 2) * DBL_EPSILON * size;
  return w->nk > w->nc;
}
#line 598 "paper/pdas.nw"
/* the free tangential unknown with an interval, its force of the sign of
   push (any if push is 0), that slides least: the first within TIE of
   the least; -1 if none */
static int least_slide(const Qp_workspace *w, int push)
{
  const double TIE = 1e-6;
  const Condense *cd = w->cond;
  int least = -1;
  for (int t = w->nc; t < w->nk; t++) {
    double F = cd->act[t] == CONDENSE_HI ? w->fhi[t] : w->flo[t];
    if (cd->act[t] == CONDENSE_HELD || !(w->fhi[t] > w->flo[t])
        || (push && !(F * push > 0)))
      continue;
    double slide = fabs(cd->y[t] - w->pos[t]);
    if (least < 0 || slide < (1 - TIE) * fabs(cd->y[least] - w->pos[least]))
      least = t;
  }
  return least;
}

#line 557 "paper/pdas.nw"
/* where every tangential unknown is free, hold those that stop first
   as the net force N pushes the body; 1 if it held any */
static int hold_stopping(Qp_workspace *w)
{
  double N, noise, absorbed = 0;
  int t, held = 0;
  if (!slide_imbalance(w, &N, &noise)) return 0;
  int push = fabs(N) <= noise ? 0 : N > 0 ? 1 : -1;
  while ((t = least_slide(w, push)) >= 0) {
    w->cond->act[t] = CONDENSE_HELD, held++;
    if ((absorbed += 2 * w->fhi[t]) >= fabs(N) - noise) break;
  }
  return held > 0;
}
#line 628 "paper/pdas.nw"
/* c has an interval of positive width for its force: a slip bound */
static int slips(const Qp_workspace *w, int c)
{
  return c >= w->nc && w->fhi[c] > w->flo[c];
}

/* s, t (and b) from (y, T) shifted inside by 1.5 times the largest
   violation, as forces; 0 when there is none (or a value is not finite) */
static int guide_start(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Condense *cd = w->cond;
  Pdas_guide *gd = &pd->gd;
  int nk = w->nk;
  double worst = 0;
  for (int c = 0; c < nk; c++) {
    double gap = w->d[w->ik[c]] * (cd->y[c] - w->pos[c]);   /* as a force */
    worst = c < w->nc ? fmax(worst, fmax(-gap, -w->T[c]))
          : fmax(worst, fmax(w->T[c] - w->fhi[c], w->flo[c] - w->T[c]));
  }
  double delta = 1.5 * worst;
  if (!(delta > 0 && isfinite(delta))) return 0;
  for (int c = 0; c < nk; c++) {
    const double *Sc = cd->S + (size_t) c * nk;
    double h = -cd->f[c], slide = cd->y[c] - w->pos[c];
    for (int e = 0; e < nk; e++) h += Sc[e] * w->pos[e];
    gd->h[c] = h, gd->b[c] = 0;
    if (c < w->nc) {
      gd->s[c] = slide + delta / w->d[w->ik[c]];
      gd->t[c] = w->T[c] + delta;
      if (!(gd->s[c] > 0 && gd->t[c] > 0)) return 0;
    } else if (!slips(w, c)) {
      gd->s[c] = slide, gd->t[c] = w->flo[c];
    } else {
      
#line 677 "paper/pdas.nw"
double quarter = 0.25 * (w->fhi[c] - w->flo[c]);
gd->s[c] = fmax(slide, 0) + delta / w->d[w->ik[c]];
gd->b[c] = fmax(-slide, 0) + delta / w->d[w->ik[c]];
gd->t[c] = fmin(fmax(w->T[c], w->flo[c] + quarter), w->fhi[c] - quarter);
if (!(gd->s[c] > 0 && gd->b[c] > 0 && isfinite(gd->t[c]))) return 0;
#line 663 "paper/pdas.nw"
    }
  }
  memcpy(gd->pred, cd->act, (size_t) nk);   /* its first prediction */
  gd->state = GUIDE_ON;
  return 1;
}
#line 723 "paper/pdas.nw"
/* e_s and e_b of a slipping unknown c, and its u, v and D */
static void slip_pair(const Qp_workspace *w, int c, double sm, const double *cs,
                      const double *ct, const double *cb, double *es,
                      double *eb, double *u, double *v, double *D)
{
  const Pdas_guide *gd = &w->pdas.gd;
  *u = gd->t[c] - w->flo[c], *v = w->fhi[c] - gd->t[c];
  *es = sm - gd->s[c] * *u - (cs ? cs[c] * ct[c] : 0);
  *eb = sm - gd->b[c] * *v + (cs ? cb[c] * ct[c] : 0);
  *D = 1 / (gd->s[c] / *u + gd->b[c] / *v);
}

/* the largest alpha in (0, 1] that keeps the gaps and slides (primal)
   or the forces' distances to their ends (dual) >= 0 along the step */
static double guide_to_bound(const Qp_workspace *w, const double *ds,
                             const double *dt, const double *db, int dual)
{
  const Pdas_guide *gd = &w->pdas.gd;
  double a = 1;
  for (int c = 0; c < w->nk; c++) {
    if (c >= w->nc && !slips(w, c)) continue;
    if (!dual) {
      if (ds[c] < 0) a = fmin(a, -gd->s[c] / ds[c]);
      if (c >= w->nc && db[c] < 0) a = fmin(a, -gd->b[c] / db[c]);
    } else if (c < w->nc) {
      if (dt[c] < 0) a = fmin(a, -gd->t[c] / dt[c]);
    } else {
      if (dt[c] < 0) a = fmin(a, -(gd->t[c] - w->flo[c]) / dt[c]);
      if (dt[c] > 0) a = fmin(a, (w->fhi[c] - gd->t[c]) / dt[c]);
    }
  }
  return a;
}

/* ds = (S + D)^-1 (-r + D E), dt and db from it; M holds the factor of
   S + D; the corrections from (cs, ct, cb), or 0 when cs is NULL */
static void guide_direction(Qp_workspace *w, double sm, const double *cs,
                            const double *ct, const double *cb, double *ds,
                            double *dt, double *db)
{
  Pdas_guide *gd = &w->pdas.gd;
  int nk = w->nk;
  double es, eb, u, v, D;
  for (int c = 0; c < nk; c++) {
    if (c < w->nc) {
      double e = (sm - (cs ? cs[c] * ct[c] : 0)) / gd->s[c];
      ds[c] = -w->pdas.r[c] - gd->t[c] + e, dt[c] = e;
    } else if (!slips(w, c)) ds[c] = -w->pdas.r[c], dt[c] = 0;
    else {
      slip_pair(w, c, sm, cs, ct, cb, &es, &eb, &u, &v, &D);
      dt[c] = es / u - eb / v;                     /* E, for now */
      ds[c] = -w->pdas.r[c] + D * dt[c];
    }
  }
  gsl_matrix_view M = gsl_matrix_view_array(w->cond->M, nk, nk);
  gsl_vector_view x = gsl_vector_view_array(ds, nk);
  gsl_linalg_cholesky_svx(&M.matrix, &x.vector);
  for (int c = 0; c < nk; c++) {
    db[c] = 0;
    if (c < w->nc) dt[c] += -gd->t[c] - gd->t[c] / gd->s[c] * ds[c];
    else if (slips(w, c)) {
      slip_pair(w, c, sm, cs, ct, cb, &es, &eb, &u, &v, &D);
      dt[c] = D * (dt[c] - ds[c]);
      ds[c] = (es - gd->s[c] * dt[c]) / u, db[c] = (eb + gd->b[c] * dt[c]) / v;
    }
  }
}

/* the sum of the complementarity products at (s, t, b) + alpha (ds, dt, db)
   (alpha_p for the slides, alpha_d for the forces; at (s, t, b) when ds
   is NULL), and their number */
static double guide_products(const Qp_workspace *w, double ap, double ad,
                             const double *ds, const double *dt,
                             const double *db, int *pairs)
{
  const Pdas_guide *gd = &w->pdas.gd;
  double sum = 0;
  *pairs = 0;
  for (int c = 0; c < w->nk; c++) {
    double s = ds ? gd->s[c] + ap * ds[c] : gd->s[c];
    double t = ds ? gd->t[c] + ad * dt[c] : gd->t[c];
    double b = ds ? gd->b[c] + ap * db[c] : gd->b[c];
    if (c < w->nc) sum += s * t, ++*pairs;
    else if (slips(w, c))
      sum += s * (t - w->flo[c]) + b * (w->fhi[c] - t),
      *pairs += 2;
  }
  return sum;
}

/* one step; nonzero when the factorisation fails or the new point is not
   strictly inside */
static int guide_step(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Condense *cd = w->cond;
  Pdas_guide *gd = &pd->gd;
  int nk = w->nk, pairs;
  double es, eb, u, v, D;
  for (int c = 0; c < nk; c++) {
    const double *Sc = cd->S + (size_t) c * nk;
    double r = gd->h[c] - gd->t[c];
    for (int e = 0; e < nk; e++) r += Sc[e] * (gd->s[e] - gd->b[e]);
    pd->r[c] = r;
    memcpy(cd->M + (size_t) c * nk, Sc, (size_t) nk * sizeof *cd->M);
    if (c < w->nc) cd->M[(size_t) c * nk + c] += gd->t[c] / gd->s[c];
    else if (slips(w, c)) {
      slip_pair(w, c, 0, NULL, NULL, NULL, &es, &eb, &u, &v, &D);
      cd->M[(size_t) c * nk + c] += D;
    }
  }
  double mu = guide_products(w, 0, 0, NULL, NULL, NULL, &pairs) / pairs;
  gsl_matrix_view M = gsl_matrix_view_array(cd->M, nk, nk);
  if (gsl_linalg_cholesky_decomp1(&M.matrix)) return 1;
  guide_direction(w, 0, NULL, NULL, NULL, gd->as, gd->at, gd->ab);
  double ap = guide_to_bound(w, gd->as, gd->at, gd->ab, 0);
  double ad = guide_to_bound(w, gd->as, gd->at, gd->ab, 1);
  double mua = guide_products(w, ap, ad, gd->as, gd->at, gd->ab, &pairs);
  double sigma = pow(mua / pairs / mu, 3);
  guide_direction(w, sigma * mu, gd->as, gd->at, gd->ab, gd->ds, gd->dt, gd->db);
  double a = fmin(1, 0.995 * fmin(guide_to_bound(w, gd->ds, gd->dt, gd->db, 0),
                                  guide_to_bound(w, gd->ds, gd->dt, gd->db, 1)));
  int inside = 1;
  for (int c = 0; c < nk; c++) {
    gd->s[c] += a * gd->ds[c], gd->t[c] += a * gd->dt[c], gd->b[c] += a * gd->db[c];
    inside &= isfinite(gd->s[c] + gd->t[c] + gd->b[c]);
    if (c < w->nc) inside &= gd->s[c] > 0 && gd->t[c] > 0;
    else if (slips(w, c))
      inside &= gd->s[c] > 0 && gd->b[c] > 0 && gd->t[c] > w->flo[c] && gd->t[c] < w->fhi[c];
  }
  return !inside;
}
#line 864 "paper/pdas.nw"
static void guide(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Condense *cd = w->cond;
  Pdas_guide *gd = &pd->gd;
  int nk = w->nk, changed = 0;
  gd->guided = 0;
  if (gd->state == GUIDE_STOPPED) return;
  if (gd->state == GUIDE_OFF && !guide_start(w)) return;
  if (guide_step(w)) { gd->state = GUIDE_STOPPED; return; }
  for (int c = 0; c < nk; c++) {
    double z = gd->t[c] - w->d[w->ik[c]] * (gd->s[c] - gd->b[c]);
    char a = c < w->nc
             ? (gd->t[c] > w->d[w->ik[c]] * gd->s[c] ? CONDENSE_HELD : CONDENSE_LO)
           : !slips(w, c) || z <= w->flo[c] ? CONDENSE_LO
           : z > w->fhi[c] ? CONDENSE_HI : CONDENSE_HELD;
    changed |= a != gd->pred[c];
    gd->pred[c] = a;
  }
  if (!changed) return;
  memcpy(gd->own, cd->act, (size_t) nk);
  memcpy(cd->act, gd->pred, (size_t) nk);
  gd->guided = 1;
}
