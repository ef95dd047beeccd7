#line 140 "paper/newton.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "newton_private.h"
#line 230 "paper/newton.nw"
Newton_workspace *newton_alloc(int n, int m, Status *st)
{
  Newton_workspace *w = calloc(1, sizeof *w);
  int p = 2 * n + 2 * (n - 1) + m, nm = n + m, mm = m > 0 ? m : 1;
  if (!w || n < 2 || m < 0) {
    free(w);
    status_set(st, n < 2 || m < 0 ? STATUS_INPUT : STATUS_MEMORY, "newton: %s",
               n < 2 || m < 0 ? "needs n >= 2 design nodes and m >= 0" : "out of memory");
    return NULL;
  }
  w->n = n, w->m = m, w->p = p;
  double **a[] = { &w->z, &w->q, &w->rd, &w->dz, &w->az, &w->t1, &w->t2,
                   &w->y2, &w->zf, &w->rdf };
  double **c[] = { &w->s, &w->lam, &w->b, &w->W, &w->rp, &w->ds, &w->dl,
                   &w->as, &w->al, &w->rc, &w->lf, &w->rpf };
  int ok = 1;
  for (size_t k = 0; k < sizeof a / sizeof a[0]; k++)
    ok &= !!(*a[k] = malloc(nm * sizeof(double)));
  for (size_t k = 0; k < sizeof c / sizeof c[0]; k++)
    ok &= !!(*c[k] = malloc(p * sizeof(double)));
  ok &= !!(w->Hd = malloc(n * sizeof(double))) && !!(w->w = malloc(n * sizeof(double)))
     && !!(w->Td = malloc(n * sizeof(double))) && !!(w->Te = malloc(n * sizeof(double)))
     && !!(w->c0 = malloc(n * sizeof(double)))
     && !!(w->act = calloc(p, 1)) && !!(w->tried = calloc(p, 1))
     && !!(w->Hv = malloc((size_t) mm * mm * sizeof(double)))
     && !!(w->Y = malloc((size_t) n * mm * sizeof(double)))
     && !!(w->Sig = gsl_matrix_alloc(mm, mm));
  if (!ok) {
    newton_free(w);
    status_set(st, STATUS_MEMORY, "newton: out of memory for n = %d, m = %d", n, m);
    return NULL;
  }
  return w;
}

void newton_free(Newton_workspace *w)
{
  if (!w) return;
  double *all[] = { w->z, w->q, w->rd, w->dz, w->az, w->t1, w->t2, w->y2, w->zf,
                    w->rdf, w->s, w->lam, w->b, w->W, w->rp, w->ds, w->dl, w->as,
                    w->al, w->rc, w->lf, w->rpf, w->Hd, w->w, w->Td, w->Te, w->c0,
                    w->Hv, w->Y };
  for (size_t k = 0; k < sizeof all / sizeof all[0]; k++) free(all[k]);
  free(w->act), free(w->tried);
  if (w->Sig) gsl_matrix_free(w->Sig);
  free(w);
}
#line 284 "paper/newton.nw"
/* phi: the largest of |grad|, |f|, R_ii C0 and S_ii C0; 0 if all are */
static double force_scale(const Newton_model *mdl)
{
  double C0 = mdl->B->C0, phi = 0;
  for (int i = 0; i < mdl->n; i++)
    phi = fmax(phi, fmax(fabs(mdl->grad[i]), mdl->r[i] * C0));
  for (int c = 0; c < mdl->m; c++)
    phi = fmax(phi, fmax(fabs(mdl->f[c]), mdl->S[(size_t) c * mdl->m + c] * C0));
  return phi;
}

static void scale_by(Newton_workspace *w, const Newton_model *mdl, double phi)
{
  int n = w->n, m = w->m, N = n - 1;
  const Design_set *B = mdl->B;
  double C0 = B->C0, dlt = B->delta / C0;
  for (int i = 0; i < n; i++) {
    w->q[i] = mdl->grad[i] / phi, w->Hd[i] = mdl->r[i] * C0 / phi;
    w->w[i] = i == 0 || i == N ? 0.5 : 1.0;
    w->b[i] = mdl->X[i] / C0;                     /* -d_i <= X_i */
    w->b[n + i] = 1 - mdl->X[i] / C0;             /*  d_i <= C0 - X_i */
  }
  for (int i = 0; i < N; i++) {
    double rise = (mdl->X[i + 1] - mdl->X[i]) / C0;
    w->b[2 * n + i] = dlt - rise;                 /*  d_{i+1} - d_i <= ... */
    w->b[2 * n + N + i] = dlt + rise;             /* -d_{i+1} + d_i <= ... */
  }
  for (int c = 0; c < m; c++) {
    w->q[n + c] = -mdl->f[c] / phi;
    w->b[2 * n + 2 * N + c] = mdl->X[mdl->col[c]] / C0; /* -v_c - d_i <= X_i */
    for (int e = 0; e < m; e++)
      w->Hv[(size_t) c * m + e] = mdl->S[(size_t) c * m + e] * C0 / phi;
  }
}
#line 700 "paper/newton.nw"
enum { NEWTON_FACE_STEPS = 10, NEWTON_FACE_ROUNDS = 3 };
static const double NEWTON_FACE_SOFT = 1e-4;   /* the weight of a soft face */

/* how far a point is from the KKT conditions, each relative to its scale:
   the rows of the design and their constraints (bounds, slopes) to the
   largest term of the design rows, those of the contact to the contact's */
typedef struct {
  double dual;     /* |rd| over the largest term of its kind of rows */
  double primal;   /* |rp| (on the face, if one is given) over max |b| */
  double outside;  /* the largest violation off the face, over max |b| */
  double negative; /* the most negative multiplier on the face, over its kind's scale */
  double area;     /* |w'd| over max |b| times the sum of w */
  double mu;       /* the complementarity s'lam of each kind over its count, max |b| and scale */
  double scale[2]; /* the multipliers' scales: the largest term of the design and contact rows */
  int finite;      /* whether every residual is a number */
} Newton_quality;

/* the scale of the multiplier of constraint j */
static double kind_scale(const Newton_workspace *w, const Newton_quality *q, int j)
{
  return q->scale[j >= 2 * w->n + 2 * (w->n - 1)];
}

/* q at (rd, rp, lam) and the slacks s (NULL on a face act) */
static void measure(const Newton_workspace *w, const double *rd, const double *rp,
                    const double *lam, const double *s, const unsigned char *act,
                    double re, const double scale[2], double bmax, Newton_quality *q)
{
  int n = w->n, m = w->m, p = w->p, pd = 2 * n + 2 * (n - 1);
  double rdd = 0, rdv = 0, wsum = 0, all = re, gap[2] = { 0, 0 };  /* all: NaN if any is */
  *q = (Newton_quality) { 0, 0, 0, 0, 0, 0,
                          { fmax(scale[0], DBL_MIN), fmax(scale[1], DBL_MIN) }, 1 };
  for (int i = 0; i < n; i++) rdd = fmax(rdd, fabs(rd[i])), all += rd[i], wsum += w->w[i];
  for (int c = 0; c < m; c++) rdv = fmax(rdv, fabs(rd[n + c])), all += rd[n + c];
  q->dual = fmax(rdd / q->scale[0], rdv / q->scale[1]);
  q->area = fabs(re) / (bmax * wsum);
  for (int j = 0; j < p; j++) {
    all += rp[j] + lam[j];
    if (s) gap[j >= pd] += s[j] * lam[j];
    if (!act || act[j]) q->primal = fmax(q->primal, fabs(rp[j]) / bmax);
    else q->outside = fmax(q->outside, rp[j] / bmax);
    if (act && act[j]) q->negative = fmax(q->negative, -lam[j] / kind_scale(w, q, j));
  }
  q->mu = fmax(gap[0] / (pd * bmax * q->scale[0]), m ? gap[1] / (m * bmax * q->scale[1]) : 0);
  q->finite = isfinite(all);
}

/* the weight of the face: 1e6 times the largest curvature of H^, or the
   multipliers' scale over the bounds' if that is larger */
static double face_weight(const Newton_workspace *w, double lscale, double bmax)
{
  double h = lscale / bmax;
  for (int i = 0; i < w->n; i++) h = fmax(h, w->Hd[i]);
  for (int c = 0; c < w->m; c++) h = fmax(h, w->Hv[(size_t) c * w->m + c]);
  return 1e6 * h;
}

/* one refinement of (zf, lf, muf) on the face act, from its residuals */
static void face_step(Newton_workspace *w, const int *col, double om, double re)
{
  int p = w->p, nm = w->n + w->m;
  double dmu, *dz = w->az, *adz = w->as, *t = w->ds;
  for (int j = 0; j < p; j++) t[j] = w->act[j] ? om * w->rpf[j] : 0;
  newton_constraints_transposed(w, col, t, w->t2);
  for (int k = 0; k < nm; k++) w->t2[k] = -w->rdf[k] - w->t2[k];
  newton_bordered_solve(w, col, w->t2, re, dz, &dmu);
  newton_constraints_times(w, col, dz, adz);
  for (int k = 0; k < nm; k++) w->zf[k] += dz[k];
  for (int j = 0; j < p; j++)
    if (w->act[j]) w->lf[j] += om * (adz[j] + w->rpf[j]);
  w->muf += dmu;
}

/* the point of the face act at the weight om, refined from the iterate
   until two steps in a row halve none of its residuals; q: how far it is
   from the KKT conditions; -1 if the Newton matrix of the face is not
   positive definite */
static int face_point(Newton_workspace *w, const int *col, double bmax,
                      double om, Newton_quality *q)
{
  int p = w->p, nm = w->n + w->m, strikes = 0;
  double re, sc[2];
  double best[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
  for (int j = 0; j < p; j++)               /* off the face: a contact's proximal weight */
    w->W[j] = w->act[j] ? om : j >= 2 * w->n + 2 * (w->n - 1) ? 1e-14 * om : 0;
  if (newton_factor_with_area(w, col)) return -1;
  memcpy(w->zf, w->z, nm * sizeof *w->zf);
  for (int j = 0; j < p; j++) w->lf[j] = w->act[j] ? w->lam[j] : 0;
  w->muf = w->mu;
  for (int k = 0;; k++) {
    newton_residuals(w, col, w->zf, w->lf, NULL, w->muf, w->rdf, w->rpf, &re, sc);
    measure(w, w->rdf, w->rpf, w->lf, NULL, w->act, re, sc, bmax, q);
    double e[3] = { q->dual, q->primal, q->area };
    int better = 0;
    for (int i = 0; i < 3; i++)
      if (e[i] < 0.5 * best[i]) best[i] = e[i], better = 1;
    if (better) strikes = 0;
    else if (!q->finite || ++strikes == 2) break;
    if (k == NEWTON_FACE_STEPS) break;
    face_step(w, col, om, re);
  }
  return 0;
}
#line 903 "paper/newton.nw"
/* the point of the face act at the weight of face_weight and, if its
   dual, primal or area residual stays above tol, once more at
   NEWTON_FACE_SOFT times that weight; -1 as face_point */
static int face_point_soft(Newton_workspace *w, const int *col, double bmax,
                           double lscale, double tol, Newton_quality *q)
{
  double om = face_weight(w, lscale, bmax);
  if (face_point(w, col, bmax, om, q)) return -1;
  if (!q->finite || fmax(fmax(q->dual, q->primal), q->area) <= tol) return 0;
  return face_point(w, col, bmax, NEWTON_FACE_SOFT * om, q);
}
#line 917 "paper/newton.nw"
/* 1 if the point of the face passes; else the face takes the constraints
   its point violates and gives up those of negative multipliers, up to
   NEWTON_FACE_ROUNDS times, while that changes it; *singular counts the
   faces whose Newton matrix was not positive definite */
static int face_solve(Newton_workspace *w, const int *col, double bmax, double tol,
                      Newton_quality *q, int *singular)
{
  double lscale = fmax(q->scale[0], q->scale[1]);   /* the interior point's */
  for (int r = 0; r < NEWTON_FACE_ROUNDS; r++) {
    if (face_point_soft(w, col, bmax, lscale, tol, q)) return ++*singular, 0;
    if (!q->finite || !(fmax(fmax(q->dual, q->primal), q->area) <= tol)) return 0;
    if (q->outside <= tol && q->negative <= tol) return 1;
    int changed = 0;
    for (int j = 0; j < w->p; j++) {
      unsigned char a = w->act[j] ? !(w->lf[j] < -tol * kind_scale(w, q, j))
                                  : w->rpf[j] > tol * bmax;
      changed |= a != w->act[j], w->act[j] = a;
    }
    if (!changed) return 0;
  }
  return 0;
}
#line 1000 "paper/newton.nw"
enum { NEWTON_MAX_ITER = 60 };
static const double NEWTON_TOL = 1e-12, NEWTON_FACE_MU = 1e-7,
                    NEWTON_MU_ROUND = 4 * DBL_EPSILON;

/* m(0) - m(d) = -(grad'd + d'Rd/2) - (T'dv + dv'S dv/2), dv = v - v0 and
   T = S v0 - f: from the step, so that its rounding is the step's;
   *round = eps times the sum of the magnitudes of its terms and of T's */
static double model_decrease(const Newton_model *mdl, const double *d, const double *v,
                             double *round)
{
  int m = mdl->m;
  double dec = 0, sum = 0;
  for (int i = 0; i < mdl->n; i++) {
    dec -= (mdl->grad[i] + 0.5 * mdl->r[i] * d[i]) * d[i];
    sum += (fabs(mdl->grad[i]) + 0.5 * mdl->r[i] * fabs(d[i])) * fabs(d[i]);
  }
  for (int c = 0; c < m; c++) {
    double T = -mdl->f[c], sdv = 0, Tabs = fabs(mdl->f[c]), sabs = 0;
    for (int e = 0; e < m; e++) {
      double t = mdl->S[(size_t) c * m + e] * mdl->v0[e];
      double u = mdl->S[(size_t) c * m + e] * (v[e] - mdl->v0[e]);
      T += t, sdv += u, Tabs += fabs(t), sabs += fabs(u);
    }
    dec -= (T + 0.5 * sdv) * (v[c] - mdl->v0[c]);
    sum += (Tabs + 0.5 * sabs) * fabs(v[c] - mdl->v0[c]);
  }
  *round = DBL_EPSILON * sum;
  return dec;
}

static int check_model(const Newton_workspace *w, const Newton_model *mdl, Status *st)
{
  if (mdl->n != w->n || mdl->m != w->m)
    return status_set(st, STATUS_INPUT, "newton: a model of n = %d, m = %d for a "
                      "workspace of n = %d, m = %d", mdl->n, mdl->m, w->n, w->m);
  for (int i = 0; i < mdl->n; i++)
    if (!(mdl->r[i] > 0) || !isfinite(mdl->r[i]) || !isfinite(mdl->grad[i]) || !isfinite(mdl->X[i]))
      return status_set(st, STATUS_INPUT, "newton: r, grad or X at node %d is not "
                        "finite, or r <= 0", i);
  for (int c = 0; c < mdl->m; c++)     /* one contact unknown a node, in order */
    if (mdl->col[c] < (c ? mdl->col[c - 1] + 1 : 0) || mdl->col[c] >= mdl->n)
      return status_set(st, STATUS_INPUT, "newton: the design nodes col of the "
                        "contact unknowns are not increasing in [0, n) at %d", c);
  for (int c = 0; c < mdl->m; c++)
    if (!isfinite(mdl->f[c]) || !isfinite(mdl->v0[c]))
      return status_set(st, STATUS_INPUT, "newton: f or v0 at contact %d is not finite", c);
  for (size_t k = 0; k < (size_t) mdl->m * mdl->m; k++)
    if (!isfinite(mdl->S[k]))
      return status_set(st, STATUS_INPUT, "newton: S at (%d, %d) is not finite",
                        (int) (k / mdl->m), (int) (k % mdl->m));
  return STATUS_OK;
}

/* the start: d = 0, v = v0, slacks at least 1, multipliers 1 */
static void interior_start(Newton_workspace *w, const Newton_model *mdl)
{
  int n = w->n, m = w->m, p = w->p;
  memset(w->z, 0, n * sizeof *w->z);
  for (int c = 0; c < m; c++) w->z[n + c] = mdl->v0[c] / mdl->B->C0;
  newton_constraints_times(w, mdl->col, w->z, w->s);
  for (int j = 0; j < p; j++) w->s[j] = fmax(w->b[j] - w->s[j], 1), w->lam[j] = 1;
  w->mu = 0;
}

int newton_solve(Newton_workspace *w, const Newton_model *mdl, double *d,
                 double *v, Newton_report *rep, Status *st)
{
  int rc = check_model(w, mdl, st), n = w->n, m = w->m, p = w->p, k;
  if (rc) return rc;
  double phi = force_scale(mdl), C0 = mdl->B->C0, re;
  double tol = fmax(NEWTON_TOL, (n + m) * DBL_EPSILON), bmax = 1, scale[2];
  if (!(phi > 0)) phi = 1;
  scale_by(w, mdl, phi);
  interior_start(w, mdl);
  for (int j = 0; j < p; j++) bmax = fmax(bmax, fabs(w->b[j]));
  Newton_quality q, fq = { 0 };
  int found = 0, faces = 0, singular = 0;
  const char *why = "reached its iteration limit";
  for (k = 0; k < NEWTON_MAX_ITER; k++) {
    double gap = newton_residuals(w, mdl->col, w->z, w->lam, w->s, w->mu, w->rd, w->rp, &re,
                                  scale);
    measure(w, w->rd, w->rp, w->lam, w->s, NULL, re, scale, bmax, &q);
    if (!q.finite) { why = "reached residuals that are not finite"; break; }
    
#line 1111 "paper/newton.nw"
if (k > 0 && q.dual <= NEWTON_FACE_MU && q.primal <= NEWTON_FACE_MU
    && q.mu <= NEWTON_FACE_MU) {
  int same = faces > 0;
  for (int j = 0; j < p; j++) {
    w->act[j] = w->s[j] * kind_scale(w, &q, j) < w->lam[j] * bmax;
    same &= w->act[j] == w->tried[j];
  }
  if (!same) {
    memcpy(w->tried, w->act, p);
    faces++;
    fq = q;
    if ((found = face_solve(w, mdl->col, bmax, tol, &fq, &singular))) break;
  }
}
#line 1084 "paper/newton.nw"
    
#line 1101 "paper/newton.nw"
if (q.mu <= NEWTON_MU_ROUND) {
  if ((found = q.dual <= tol && q.primal <= tol && q.area <= tol)) {
    memcpy(w->zf, w->z, (size_t) (n + m) * sizeof *w->z);
    fq = q;
  } else why = "reached a complementarity at rounding, but not its residuals";
  break;
}
#line 1085 "paper/newton.nw"
    if (newton_predictor_corrector(w, mdl->col, gap, re)) {
      why = "met a Newton matrix whose contact block is not positive definite";
      break;
    }
  }
  if (rep) rep->iterations = k, rep->residual = found || faces ? fmax(fmax(fmax(fq.dual,
                           fq.primal), fmax(fq.outside, fq.negative)), fq.area) : HUGE_VAL;
  if (!found) 
#line 1130 "paper/newton.nw"
return faces ? status_set(st, STATUS_NUMERIC, "newton: the interior point %s after %d "
                          "iterations (complementarity %.1e of its scale); the last of %d "
                          "faces tried (%d not positive definite) has stationarity %.1e, "
                          "violation %.1e on and %.1e off it, multiplier %.1e, area %.1e "
                          "(relative; tolerance %.0e)", why, k, q.mu, faces, singular,
                          fq.dual, fq.primal, fq.outside,
                          fq.negative > 0 ? -fq.negative : 0.0, fq.area, tol)
  : status_set(st, STATUS_NUMERIC, "newton: the interior point %s after %d iterations "
               "(complementarity %.1e, dual residual %.1e, primal %.1e, each relative "
               "to its scale) before its active set could be tried", why, k, q.mu,
               q.dual, q.primal);
#line 1093 "paper/newton.nw"
  for (int i = 0; i < n; i++) d[i] = C0 * w->zf[i];
  for (int c = 0; c < m; c++) v[c] = C0 * w->zf[n + c];
  if (rep) rep->pred = model_decrease(mdl, d, v, &rep->rounding);
  return STATUS_OK;
}
