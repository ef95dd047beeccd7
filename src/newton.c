#line 135 "paper/newton.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "newton.h"

#line 161 "paper/newton.nw"
struct Newton_workspace {
  int n, m, p;         /* design nodes, contact unknowns, inequalities */
  double *z, *s, *lam; /* n+m, p, p: the iterate, slacks, multipliers */
  double mu;           /* the multiplier of the area equality */
  double *q, *b;       /* n+m, p: the scaled linear term and bounds */
  double *Hd;          /* n: the scaled R */
  double *Hv;          /* m x m: the scaled S */
  double *w;           /* n: the weights of the area equality */
  double *W;           /* p: lambda / s */
  double *Td, *Te;     /* n, n-1: T's diagonal and off-diagonal, factored */
  double *T0;          /* n: T's diagonal without the contact weights */
  double *Y;           /* n x m: T^-1 at the contact columns */
  gsl_matrix *Sig;     /* m x m: Sigma, then its Cholesky factor */
  double *rd, *rp;     /* n+m, p: dual and primal residuals */
  double *dz, *ds, *dl;     /* n+m, p, p: the step */
  double *az, *as, *al;     /* n+m, p, p: the affine step */
  double *rc;          /* p: the complementarity target of a step */
  double *t1, *t2;     /* n+m each: scratch of the solves */
  double *y2;          /* n+m: K^-1 (w, 0), for the area equality */
  double *zbest;       /* n+m: the iterate of the smallest residual */
};
#line 185 "paper/newton.nw"
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
                   &w->y2, &w->zbest };
  double **c[] = { &w->s, &w->lam, &w->b, &w->W, &w->rp, &w->ds, &w->dl,
                   &w->as, &w->al, &w->rc };
  int ok = 1;
  for (size_t k = 0; k < sizeof a / sizeof a[0]; k++)
    ok &= !!(*a[k] = malloc(nm * sizeof(double)));
  for (size_t k = 0; k < sizeof c / sizeof c[0]; k++)
    ok &= !!(*c[k] = malloc(p * sizeof(double)));
  ok &= !!(w->Hd = malloc(n * sizeof(double))) && !!(w->w = malloc(n * sizeof(double)))
     && !!(w->Td = malloc(n * sizeof(double))) && !!(w->Te = malloc(n * sizeof(double)))
     && !!(w->T0 = malloc(n * sizeof(double)))
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
  double *all[] = { w->z, w->q, w->rd, w->dz, w->az, w->t1, w->t2, w->y2, w->zbest,
                    w->s, w->lam, w->b, w->W, w->rp, w->ds, w->dl, w->as, w->al, w->rc,
                    w->Hd, w->w, w->Td, w->Te, w->T0, w->Hv, w->Y };
  for (size_t k = 0; k < sizeof all / sizeof all[0]; k++) free(all[k]);
  if (w->Sig) gsl_matrix_free(w->Sig);
  free(w);
}
#line 236 "paper/newton.nw"
/* phi: the largest of |g|, |f|, R_ii C0 and S_ii C0; 0 if all are */
static double model_scale(const Newton_model *mdl)
{
  double C0 = mdl->B->C0, phi = 0;
  for (int i = 0; i < mdl->n; i++)
    phi = fmax(phi, fmax(fabs(mdl->g[i]), mdl->r[i] * C0));
  for (int c = 0; c < mdl->m; c++)
    phi = fmax(phi, fmax(fabs(mdl->f[c]), mdl->S[(size_t) c * mdl->m + c] * C0));
  return phi;
}

static void scale_model(Newton_workspace *w, const Newton_model *mdl, double phi)
{
  int n = w->n, m = w->m, N = n - 1;
  const Design_set *B = mdl->B;
  double C0 = B->C0, dlt = B->delta / C0;
  for (int i = 0; i < n; i++) {
    w->q[i] = mdl->g[i] / phi, w->Hd[i] = mdl->r[i] * C0 / phi;
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
#line 274 "paper/newton.nw"
/* out = A z (p values) */
static void constraints_times(const Newton_workspace *w, const int *col,
                              const double *z, double *out)
{
  int n = w->n, m = w->m, N = n - 1;
  const double *v = z + n;
  for (int i = 0; i < n; i++) out[i] = -z[i], out[n + i] = z[i];
  for (int i = 0; i < N; i++) {
    out[2 * n + i] = z[i + 1] - z[i];
    out[2 * n + N + i] = z[i] - z[i + 1];
  }
  for (int c = 0; c < m; c++) out[2 * n + 2 * N + c] = -v[c] - z[col[c]];
}

/* out = A' y (n+m values) */
static void constraints_transposed(const Newton_workspace *w, const int *col,
                                   const double *y, double *out)
{
  int n = w->n, m = w->m, N = n - 1;
  for (int i = 0; i < n; i++) out[i] = y[n + i] - y[i];
  for (int i = 0; i < N; i++) {
    double up = y[2 * n + i] - y[2 * n + N + i];
    out[i + 1] += up, out[i] -= up;
  }
  for (int c = 0; c < m; c++) {
    double yc = y[2 * n + 2 * N + c];
    out[n + c] = -yc, out[col[c]] -= yc;
  }
}
#line 342 "paper/newton.nw"
/* x = T^-1 x, T factored as L D L' by factor_tridiagonal */
static void tridiagonal_solve(const Newton_workspace *w, double *x)
{
  int n = w->n;
  for (int i = 1; i < n; i++) x[i] -= w->Te[i - 1] * x[i - 1];
  for (int i = 0; i < n; i++) x[i] /= w->Td[i];
  for (int i = n - 2; i >= 0; i--) x[i] -= w->Te[i] * x[i + 1];
}

static void factor_tridiagonal(Newton_workspace *w, const int *col)
{
  int n = w->n, m = w->m, N = n - 1;
  const double *W = w->W;
  for (int i = 0; i < n; i++) w->Td[i] = w->Hd[i] + W[i] + W[n + i];
  for (int i = 0; i < N; i++) {
    double ws = W[2 * n + i] + W[2 * n + N + i];
    w->Td[i] += ws, w->Td[i + 1] += ws, w->Te[i] = -ws;
  }
  memcpy(w->T0, w->Td, n * sizeof *w->T0);
  for (int c = 0; c < m; c++) w->Td[col[c]] += W[2 * n + 2 * N + c];
  for (int i = 0; i < N; i++) {            /* L D L': Te becomes L's subdiagonal */
    double l = w->Te[i] / w->Td[i];
    w->Td[i + 1] -= l * w->Te[i];
    w->Te[i] = l;
  }
}

/* Y = T^-1 T~ P' (n x m, row-major) by the substitutions of
   tridiagonal_solve, a row of all m columns at a time; off is T~'s
   off-diagonal */
static void contact_columns(Newton_workspace *w, const int *col,
                            const double *off)
{
  int n = w->n, m = w->m;
  double *Y = w->Y;
  memset(Y, 0, (size_t) n * m * sizeof *Y);
  for (int e = 0; e < m; e++) {            /* T~ e_{i(e)}: three entries */
    int i = col[e];
    Y[(size_t) i * m + e] = w->T0[i];
    if (i > 0) Y[(size_t) (i - 1) * m + e] = off[i - 1];
    if (i < n - 1) Y[(size_t) (i + 1) * m + e] = off[i];
  }
  for (int k = 1, live = 0; k < n; k++) {  /* L: columns with i(e) <= k */
    double *y = Y + (size_t) k * m, l = w->Te[k - 1];
    const double *above = y - m;
    while (live < m && col[live] <= k) live++;
    for (int e = 0; e < live; e++) y[e] -= l * above[e];
  }
  for (int k = n - 1; k >= 0; k--) {       /* D, then L' from below */
    double *y = Y + (size_t) k * m, d = w->Td[k];
    for (int e = 0; e < m; e++) y[e] /= d;
    if (k == n - 1) continue;
    const double *below = y + m, l = w->Te[k];
    for (int e = 0; e < m; e++) y[e] -= l * below[e];
  }
}

static int factor_newton_matrix(Newton_workspace *w, const int *col)
{
  int n = w->n, m = w->m, N = n - 1;
  const double *Wc = w->W + 2 * n + 2 * N;
  double *off = w->t2;                     /* T's off-diagonal, before factoring */
  for (int i = 0; i < N; i++) off[i] = -(w->W[2 * n + i] + w->W[2 * n + N + i]);
  factor_tridiagonal(w, col);
  if (m == 0) return 0;
  contact_columns(w, col, off);
  for (int c = 0; c < m; c++) {            /* the lower triangle of Sigma */
    double *sig = gsl_matrix_ptr(w->Sig, c, 0);
    const double *hv = w->Hv + (size_t) c * m, *y = w->Y + (size_t) col[c] * m;
    for (int e = 0; e <= c; e++) sig[e] = hv[e] + Wc[c] * y[e];
  }
  gsl_matrix_view Sv = gsl_matrix_submatrix(w->Sig, 0, 0, m, m);
  return gsl_linalg_cholesky_decomp1(&Sv.matrix) ? -1 : 0;
}
#line 424 "paper/newton.nw"
/* y = K^-1 r (n+m values); r and y may not alias */
static void newton_matrix_solve(const Newton_workspace *w, const int *col,
                                const double *r, double *y)
{
  int n = w->n, m = w->m;
  const double *Wc = w->W + 2 * n + 2 * (n - 1);
  memcpy(y, r, n * sizeof *y);
  tridiagonal_solve(w, y);
  if (m == 0) return;
  gsl_vector_view yv = gsl_vector_view_array(y + n, m);
  for (int c = 0; c < m; c++) y[n + c] = r[n + c] - Wc[c] * y[col[c]];
  gsl_matrix_const_view Sv = gsl_matrix_const_submatrix(w->Sig, 0, 0, m, m);
  gsl_linalg_cholesky_svx(&Sv.matrix, &yv.vector);
  memcpy(y, r, n * sizeof *y);
  for (int c = 0; c < m; c++) y[col[c]] -= Wc[c] * y[n + c];
  tridiagonal_solve(w, y);
}

/* dz, dmu: K dz + (w,0) dmu = r, w' dz_d = -re */
static void bordered_solve(Newton_workspace *w, const int *col, const double *r,
                           double re, double *dz, double *dmu)
{
  double wy1 = 0, wy2 = 0;
  newton_matrix_solve(w, col, r, dz);
  for (int i = 0; i < w->n; i++) wy1 += w->w[i] * dz[i], wy2 += w->w[i] * w->y2[i];
  *dmu = (wy1 + re) / wy2;
  for (int k = 0; k < w->n + w->m; k++) dz[k] -= *dmu * w->y2[k];
}
#line 468 "paper/newton.nw"
/* the largest alpha <= 1 with x + alpha dx >= (1 - 0.995) x, x > 0 */
static double step_to_boundary(const double *x, const double *dx, int k)
{
  double a = 1;
  for (int j = 0; j < k; j++)
    if (dx[j] < 0) a = fmin(a, -0.995 * x[j] / dx[j]);
  return a;
}

/* dz, ds, dl, dmu for the complementarity target rc (p values) */
static void direction(Newton_workspace *w, const int *col, const double *rc,
                      double re, double *dz, double *ds, double *dl, double *dmu)
{
  int p = w->p, nm = w->n + w->m;
  for (int j = 0; j < p; j++) ds[j] = (rc[j] + w->lam[j] * w->rp[j]) / w->s[j];
  constraints_transposed(w, col, ds, w->t2);
  for (int k = 0; k < nm; k++) w->t2[k] = -w->rd[k] - w->t2[k];
  bordered_solve(w, col, w->t2, re, dz, dmu);
  constraints_times(w, col, dz, ds);
  for (int j = 0; j < p; j++) {
    ds[j] = -w->rp[j] - ds[j];
    dl[j] = (rc[j] - w->lam[j] * ds[j]) / w->s[j];
  }
}

/* the residuals of the current iterate; returns the complementarity s'l/p */
/* the residuals of the current iterate; scale[0], scale[1] receive the
   largest term of the dual residual's design and contact rows (of S v,
   the sum of the magnitudes of its terms); returns
   the complementarity s'l/p */
static double residuals(Newton_workspace *w, const int *col, double *re,
                        double scale[2])
{
  int n = w->n, m = w->m, p = w->p;
  constraints_transposed(w, col, w->lam, w->rd);
  scale[0] = scale[1] = 0;
  for (int i = 0; i < n; i++) {
    double hz = w->Hd[i] * w->z[i], mw = w->mu * w->w[i];
    scale[0] = fmax(scale[0], fmax(fmax(fabs(w->rd[i]), fabs(hz)),
                                   fmax(fabs(w->q[i]), fabs(mw))));
    w->rd[i] += hz + w->q[i] + mw;
  }
  for (int c = 0; c < m; c++) {
    double hv = 0, habs = 0;
    for (int e = 0; e < m; e++) {
      double t = w->Hv[(size_t) c * m + e] * w->z[n + e];
      hv += t, habs += fabs(t);
    }
    scale[1] = fmax(scale[1], fmax(fmax(fabs(w->rd[n + c]), habs), fabs(w->q[n + c])));
    w->rd[n + c] += hv + w->q[n + c];
  }
  constraints_times(w, col, w->z, w->rp);
  double gap = 0;
  for (int j = 0; j < p; j++) w->rp[j] += w->s[j] - w->b[j], gap += w->s[j] * w->lam[j];
  *re = 0;
  for (int i = 0; i < n; i++) *re += w->w[i] * w->z[i];
  return gap / p;
}

static int predictor_corrector(Newton_workspace *w, const int *col, double gap,
                               double re)
{
  int p = w->p, nm = w->n + w->m;
  double dmu, *rc = w->rc;
  for (int j = 0; j < p; j++) w->W[j] = w->lam[j] / w->s[j];
  if (factor_newton_matrix(w, col)) return -1;
  memset(w->t1, 0, nm * sizeof *w->t1);
  for (int i = 0; i < w->n; i++) w->t1[i] = w->w[i];
  newton_matrix_solve(w, col, w->t1, w->y2);
  for (int j = 0; j < p; j++) rc[j] = -w->s[j] * w->lam[j];   /* affine */
  direction(w, col, rc, re, w->az, w->as, w->al, &dmu);
  double a = fmin(step_to_boundary(w->s, w->as, p), step_to_boundary(w->lam, w->al, p));
  double gap_a = 0;
  for (int j = 0; j < p; j++) gap_a += (w->s[j] + a * w->as[j]) * (w->lam[j] + a * w->al[j]);
  double sigma = pow(gap_a / p / gap, 3);
  for (int j = 0; j < p; j++) rc[j] = -w->s[j] * w->lam[j] + sigma * gap - w->as[j] * w->al[j];
  direction(w, col, rc, re, w->dz, w->ds, w->dl, &dmu);
  a = fmin(step_to_boundary(w->s, w->ds, p), step_to_boundary(w->lam, w->dl, p));
  for (int k = 0; k < nm; k++) w->z[k] += a * w->dz[k];
  for (int j = 0; j < p; j++) w->s[j] += a * w->ds[j], w->lam[j] += a * w->dl[j];
  w->mu += a * dmu;
  return 0;
}
#line 558 "paper/newton.nw"
enum { NEWTON_MAX_ITER = 60 };
static const double NEWTON_TOL = 1e-12, NEWTON_GAP = 1e-18, NEWTON_ACCEPT = 1e-9;

/* m(d) - E(X) + Phi(X), at d and v; d NULL: d = 0 */
static double model_value(const Newton_model *mdl, const double *d, const double *v)
{
  double val = 0;
  for (int i = 0; d && i < mdl->n; i++) val += (mdl->g[i] + 0.5 * mdl->r[i] * d[i]) * d[i];
  for (int c = 0; c < mdl->m; c++) {
    double sv = 0;
    for (int e = 0; e < mdl->m; e++) sv += mdl->S[(size_t) c * mdl->m + e] * v[e];
    val += (0.5 * sv - mdl->f[c]) * v[c];
  }
  return val;
}

static int check_model(const Newton_workspace *w, const Newton_model *mdl, Status *st)
{
  if (mdl->n != w->n || mdl->m != w->m)
    return status_set(st, STATUS_INPUT, "newton: a model of n = %d, m = %d for a "
                      "workspace of n = %d, m = %d", mdl->n, mdl->m, w->n, w->m);
  for (int i = 0; i < mdl->n; i++)
    if (!(mdl->r[i] > 0) || !isfinite(mdl->r[i]) || !isfinite(mdl->g[i]) || !isfinite(mdl->X[i]))
      return status_set(st, STATUS_INPUT, "newton: r, g or X at node %d is not "
                        "finite, or r <= 0", i);
  for (int c = 0; c < mdl->m; c++)     /* one contact unknown a node, in order */
    if (mdl->col[c] < (c ? mdl->col[c - 1] + 1 : 0) || mdl->col[c] >= mdl->n)
      return status_set(st, STATUS_INPUT, "newton: the design nodes col of the "
                        "contact unknowns are not increasing in [0, n) at %d", c);
  for (int c = 0; c < mdl->m; c++)
    if (!isfinite(mdl->f[c]) || !isfinite(mdl->v0[c]))
      return status_set(st, STATUS_INPUT, "newton: f or v0 at contact %d is not finite", c);
  return STATUS_OK;
}

int newton_solve(Newton_workspace *w, const Newton_model *mdl, double *d,
                 double *v, Newton_report *rep, Status *st)
{
  int rc = check_model(w, mdl, st), n = w->n, m = w->m, p = w->p, k;
  if (rc) return rc;
  double phi = model_scale(mdl), C0 = mdl->B->C0, re, gap = 0, res = HUGE_VAL;
  if (!(phi > 0)) phi = 1;
  scale_model(w, mdl, phi);
  memset(w->z, 0, n * sizeof *w->z);
  for (int c = 0; c < m; c++) w->z[n + c] = mdl->v0[c] / C0;
  constraints_times(w, mdl->col, w->z, w->s);
  for (int j = 0; j < p; j++) w->s[j] = fmax(w->b[j] - w->s[j], 1), w->lam[j] = 1;
  w->mu = 0;
  double bmax = 1, scale[2];
  for (int j = 0; j < p; j++) bmax = fmax(bmax, fabs(w->b[j]));
  double best = HUGE_VAL;
  int worse = 0, singular = 0;
  for (k = 0; k < NEWTON_MAX_ITER; k++) {
    gap = residuals(w, mdl->col, &re, scale);
    
#line 630 "paper/newton.nw"
double rdd = 0, rdv = 0, rpmax = 0, all = re + gap;   /* all: NaN if any is */
for (int i = 0; i < n; i++) rdd = fmax(rdd, fabs(w->rd[i])), all += w->rd[i];
for (int c = 0; c < m; c++) rdv = fmax(rdv, fabs(w->rd[n + c])), all += w->rd[n + c];
for (int j = 0; j < p; j++) rpmax = fmax(rpmax, fabs(w->rp[j])), all += w->rp[j];
res = fmax(fmax(rdd / fmax(scale[0], DBL_MIN), rdv / fmax(scale[1], DBL_MIN)),
           fmax(rpmax / bmax, fabs(re)));
res = fmax(res, gap / (fmax(scale[0], DBL_MIN) * NEWTON_GAP) * NEWTON_TOL);
if (!isfinite(all)) break;                    /* rounding has broken it: the best */
#line 613 "paper/newton.nw"
    
#line 650 "paper/newton.nw"
if (res < best) {
  best = res, worse = 0;
  memcpy(w->zbest, w->z, (size_t) (n + m) * sizeof *w->z);
} else worse++;
if (best <= NEWTON_TOL || (worse >= 3 && best <= NEWTON_ACCEPT)) break;
#line 614 "paper/newton.nw"
    if ((singular = predictor_corrector(w, mdl->col, gap, re))) break;
  }
  if (rep) rep->iterations = k, rep->residual = best;
  if (best > NEWTON_ACCEPT)
    return status_set(st, STATUS_NUMERIC, "newton: the interior point %s after %d "
                      "iterations (relative residual %.2e > %.0e)", singular ?
                      "met a Newton matrix that is not positive definite (is S "
                      "semidefinite?)" : "did not converge", k, best, NEWTON_ACCEPT);
  for (int i = 0; i < n; i++) d[i] = C0 * w->zbest[i];
  for (int c = 0; c < m; c++) v[c] = C0 * w->zbest[n + c];
  if (rep) rep->pred = model_value(mdl, NULL, mdl->v0) - model_value(mdl, d, v);
  return STATUS_OK;
}
