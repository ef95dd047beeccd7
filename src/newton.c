#line 139 "paper/newton.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "newton.h"

#line 166 "paper/newton.nw"
struct Newton_workspace {
  int n, m, p;         /* design nodes, contact unknowns, inequalities */
  double *z, *s, *lam; /* n+m, p, p: the iterate, slacks, multipliers */
  double mu;           /* the multiplier of the area equality */
  double *q, *b;       /* n+m, p: the scaled linear term and bounds */
  double *Hd;          /* n: the scaled R */
  double *Hv;          /* m x m: the scaled S */
  double *w;           /* n: the weights of the area equality */
  double *W;           /* p: lambda / s */
  double *Td, *Te;     /* n, n-1: T's pivots and L's subdiagonal */
  double *c0;          /* n: T's grounding without the contact, T~ 1 */
  double *Y;           /* n x m: T^-1 P', T^-1 at the contact columns */
  gsl_matrix *Sig;     /* m x m: Sigma, then its Cholesky factor */
  double *rd, *rp;     /* n+m, p: dual and primal residuals */
  double *dz, *ds, *dl;     /* n+m, p, p: the step */
  double *az, *as, *al;     /* n+m, p, p: the affine step */
  double *rc;          /* p: the complementarity target of a step */
  double *t1, *t2;     /* n+m each: scratch of the solves */
  double *y2;          /* n+m: K^-1 (w, 0), for the area equality */
  double *zf, *lf;     /* n+m, p: the point of the face and its multipliers */
  double muf;          /* its multiplier of the area equality */
  double *rdf, *rpf;   /* n+m, p: its residuals */
  unsigned char *act, *tried; /* p: the face now indicated, the last tried */
};
#line 193 "paper/newton.nw"
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
#line 247 "paper/newton.nw"
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
#line 285 "paper/newton.nw"
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
#line 378 "paper/newton.nw"
/* x = T^-1 x, T factored as L D L' by factor_tridiagonal */
static void tridiagonal_solve(const Newton_workspace *w, double *x)
{
  int n = w->n;
  for (int i = 1; i < n; i++) x[i] -= w->Te[i - 1] * x[i - 1];
  for (int i = 0; i < n; i++) x[i] /= w->Td[i];
  for (int i = n - 2; i >= 0; i--) x[i] -= w->Te[i] * x[i + 1];
}

/* T = L D L' from the grounding g of each node and the springs between
   neighbours: D_i = g_i + w_i, g_{i+1} = c_{i+1} + w_i g_i / D_i */
static void factor_tridiagonal(Newton_workspace *w, const int *col)
{
  int n = w->n, m = w->m, N = n - 1;
  const double *W = w->W;
  for (int i = 0; i < n; i++) w->c0[i] = w->Hd[i] + W[i] + W[n + i];
  memcpy(w->Td, w->c0, n * sizeof *w->Td);  /* c: with the contact */
  for (int c = 0; c < m; c++) w->Td[col[c]] += W[2 * n + 2 * N + c];
  double g = w->Td[0];
  for (int i = 0; i < N; i++) {
    double ws = W[2 * n + i] + W[2 * n + N + i];
    w->Td[i] = g + ws, w->Te[i] = -ws / w->Td[i];
    g = w->Td[i + 1] + ws * (g / w->Td[i]);
  }
  w->Td[N] = g;
}

/* Y = T^-1 P' (n x m, row-major) by the substitutions of
   tridiagonal_solve, a row of all m columns at a time */
static void contact_columns(Newton_workspace *w, const int *col)
{
  int n = w->n, m = w->m;
  double *Y = w->Y;
  memset(Y, 0, (size_t) n * m * sizeof *Y);
  for (int e = 0; e < m; e++) Y[(size_t) col[e] * m + e] = 1;
  for (int k = 1, live = 0; k < n; k++) {  /* L: columns with i(e) < k */
    double *y = Y + (size_t) k * m, l = w->Te[k - 1];
    const double *above = y - m;
    while (live < m && col[live] < k) live++;
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

/* Sigma's lower triangle: S^ + M, M's diagonal from its row sums */
static void fill_sigma(Newton_workspace *w, const int *col, const double *r)
{
  int n = w->n, m = w->m;
  const double *Wc = w->W + 2 * n + 2 * (n - 1);
  for (int c = 0; c < m; c++) {
    double *sig = gsl_matrix_ptr(w->Sig, c, 0), sum = 0;
    const double *hv = w->Hv + (size_t) c * m, *y = w->Y + (size_t) col[c] * m;
    for (int e = 0; e < m; e++) sum += e == c ? 0 : Wc[e] * y[e];
    for (int e = 0; e < c; e++) sig[e] = hv[e] - Wc[c] * (Wc[e] * y[e]);
    sig[c] = hv[c] + Wc[c] * (r[col[c]] + sum);
  }
}

static int factor_newton_matrix(Newton_workspace *w, const int *col)
{
  int n = w->n, m = w->m;
  double *r = w->t2;                       /* T^-1 c0 */
  factor_tridiagonal(w, col);
  if (m == 0) return 0;
  contact_columns(w, col);
  memcpy(r, w->c0, n * sizeof *r);
  tridiagonal_solve(w, r);
  fill_sigma(w, col, r);
  gsl_matrix_view Sv = gsl_matrix_submatrix(w->Sig, 0, 0, m, m);
  return gsl_linalg_cholesky_decomp1(&Sv.matrix) ? -1 : 0;
}
#line 463 "paper/newton.nw"
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
#line 507 "paper/newton.nw"
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

/* at (z, lam, s, mu): rd, rp = A z + s - b (s NULL: A z - b) and *re =
   w'd; scale[0], scale[1] receive the largest term of rd's design and
   contact rows (of S v, the sum of the magnitudes of its terms); returns
   the complementarity s'lam/p (0 if s is NULL) */
static double residuals(const Newton_workspace *w, const int *col, const double *z,
                        const double *lam, const double *s, double mu, double *rd,
                        double *rp, double *re, double scale[2])
{
  int n = w->n, m = w->m, p = w->p;
  constraints_transposed(w, col, lam, rd);
  scale[0] = scale[1] = 0;
  for (int i = 0; i < n; i++) {
    double hz = w->Hd[i] * z[i], mw = mu * w->w[i];
    scale[0] = fmax(scale[0], fmax(fmax(fabs(rd[i]), fabs(hz)),
                                   fmax(fabs(w->q[i]), fabs(mw))));
    rd[i] += hz + w->q[i] + mw;
  }
  for (int c = 0; c < m; c++) {
    double hv = 0, habs = 0;
    for (int e = 0; e < m; e++) {
      double t = w->Hv[(size_t) c * m + e] * z[n + e];
      hv += t, habs += fabs(t);
    }
    scale[1] = fmax(scale[1], fmax(fmax(fabs(rd[n + c]), habs), fabs(w->q[n + c])));
    rd[n + c] += hv + w->q[n + c];
  }
  constraints_times(w, col, z, rp);
  double gap = 0;
  for (int j = 0; j < p; j++) {
    rp[j] += (s ? s[j] : 0) - w->b[j];
    gap += s ? s[j] * lam[j] : 0;
  }
  *re = 0;
  for (int i = 0; i < n; i++) *re += w->w[i] * z[i];
  return gap / p;
}

/* factor K for the weights W and find y2 = K^-1 (w, 0); -1 if Sigma
   is not positive definite */
static int factor_with_area(Newton_workspace *w, const int *col)
{
  int nm = w->n + w->m;
  if (factor_newton_matrix(w, col)) return -1;
  memset(w->t1, 0, nm * sizeof *w->t1);
  for (int i = 0; i < w->n; i++) w->t1[i] = w->w[i];
  newton_matrix_solve(w, col, w->t1, w->y2);
  return 0;
}

static int predictor_corrector(Newton_workspace *w, const int *col, double gap,
                               double re)
{
  int p = w->p, nm = w->n + w->m;
  double dmu, *rc = w->rc;
  for (int j = 0; j < p; j++) w->W[j] = w->lam[j] / w->s[j];
  if (factor_with_area(w, col)) return -1;
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
#line 661 "paper/newton.nw"
enum { NEWTON_FACE_STEPS = 10, NEWTON_FACE_ROUNDS = 3 };

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
  *q = (Newton_quality) { 0, 0, 0, 0, 0, 0, { fmax(scale[0], DBL_MIN), fmax(scale[1], DBL_MIN) }, 1 };
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
  constraints_transposed(w, col, t, w->t2);
  for (int k = 0; k < nm; k++) w->t2[k] = -w->rdf[k] - w->t2[k];
  bordered_solve(w, col, w->t2, re, dz, &dmu);
  constraints_times(w, col, dz, adz);
  for (int k = 0; k < nm; k++) w->zf[k] += dz[k];
  for (int j = 0; j < p; j++)
    if (w->act[j]) w->lf[j] += om * (adz[j] + w->rpf[j]);
  w->muf += dmu;
}

/* the point of the face act, refined from the iterate until two steps in
   a row halve none of its residuals; q: how far it is from the KKT
   conditions; -1 if the Newton matrix of the face is not positive definite */
static int face_point(Newton_workspace *w, const int *col, double bmax,
                      double lscale, Newton_quality *q)
{
  int p = w->p, nm = w->n + w->m, strikes = 0;
  double om = face_weight(w, lscale, bmax), re, sc[2];
  double best[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
  for (int j = 0; j < p; j++)               /* off the face: a contact's proximal weight */
    w->W[j] = w->act[j] ? om : j >= 2 * w->n + 2 * (w->n - 1) ? 1e-14 * om : 0;
  if (factor_with_area(w, col)) return -1;
  memcpy(w->zf, w->z, nm * sizeof *w->zf);
  for (int j = 0; j < p; j++) w->lf[j] = w->act[j] ? w->lam[j] : 0;
  w->muf = w->mu;
  for (int k = 0;; k++) {
    residuals(w, col, w->zf, w->lf, NULL, w->muf, w->rdf, w->rpf, &re, sc);
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

/* 1 if the point of the face passes; else the face takes the constraints
   its point violates and gives up those of negative multipliers, up to
   NEWTON_FACE_ROUNDS times, while that changes it; *singular counts the
   faces whose Newton matrix was not positive definite */
static int face_solve(Newton_workspace *w, const int *col, double bmax, double tol,
                      Newton_quality *q, int *singular)
{
  double lscale = fmax(q->scale[0], q->scale[1]);   /* the interior point's */
  for (int r = 0; r < NEWTON_FACE_ROUNDS; r++) {
    if (face_point(w, col, bmax, lscale, q)) return ++*singular, 0;
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
#line 844 "paper/newton.nw"
enum { NEWTON_MAX_ITER = 60 };
static const double NEWTON_TOL = 1e-12, NEWTON_FACE_MU = 1e-7,
                    NEWTON_MU_ROUND = 4 * DBL_EPSILON;

/* m(0) - m(d) = -(g'd + d'Rd/2) - (T'dv + dv'S dv/2), dv = v - v0 and
   T = S v0 - f: from the step, so that its rounding is the step's */
static double model_decrease(const Newton_model *mdl, const double *d, const double *v)
{
  int m = mdl->m;
  double dec = 0;
  for (int i = 0; i < mdl->n; i++) dec -= (mdl->g[i] + 0.5 * mdl->r[i] * d[i]) * d[i];
  for (int c = 0; c < m; c++) {
    double T = -mdl->f[c], sdv = 0;
    for (int e = 0; e < m; e++) {
      T += mdl->S[(size_t) c * m + e] * mdl->v0[e];
      sdv += mdl->S[(size_t) c * m + e] * (v[e] - mdl->v0[e]);
    }
    dec -= (T + 0.5 * sdv) * (v[c] - mdl->v0[c]);
  }
  return dec;
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
  constraints_times(w, mdl->col, w->z, w->s);
  for (int j = 0; j < p; j++) w->s[j] = fmax(w->b[j] - w->s[j], 1), w->lam[j] = 1;
  w->mu = 0;
}

int newton_solve(Newton_workspace *w, const Newton_model *mdl, double *d,
                 double *v, Newton_report *rep, Status *st)
{
  int rc = check_model(w, mdl, st), n = w->n, m = w->m, p = w->p, k;
  if (rc) return rc;
  double phi = model_scale(mdl), C0 = mdl->B->C0, re;
  double tol = fmax(NEWTON_TOL, (n + m) * DBL_EPSILON), bmax = 1, scale[2];
  if (!(phi > 0)) phi = 1;
  scale_model(w, mdl, phi);
  interior_start(w, mdl);
  for (int j = 0; j < p; j++) bmax = fmax(bmax, fabs(w->b[j]));
  Newton_quality q, fq = { 0 };
  int found = 0, faces = 0, singular = 0;
  const char *why = "reached its iteration limit";
  for (k = 0; k < NEWTON_MAX_ITER; k++) {
    double gap = residuals(w, mdl->col, w->z, w->lam, w->s, w->mu, w->rd, w->rp, &re, scale);
    measure(w, w->rd, w->rp, w->lam, w->s, NULL, re, scale, bmax, &q);
    if (!q.finite) { why = "reached residuals that are not finite"; break; }
    
#line 946 "paper/newton.nw"
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
#line 919 "paper/newton.nw"
    
#line 936 "paper/newton.nw"
if (q.mu <= NEWTON_MU_ROUND) {
  if ((found = q.dual <= tol && q.primal <= tol && q.area <= tol)) {
    memcpy(w->zf, w->z, (size_t) (n + m) * sizeof *w->z);
    fq = q;
  } else why = "reached a complementarity at rounding, but not its residuals";
  break;
}
#line 920 "paper/newton.nw"
    if (predictor_corrector(w, mdl->col, gap, re)) {
      why = "met a Newton matrix whose contact block is not positive definite";
      break;
    }
  }
  if (rep) rep->iterations = k, rep->residual = found || faces ? fmax(fmax(fmax(fq.dual,
                           fq.primal), fmax(fq.outside, fq.negative)), fq.area) : HUGE_VAL;
  if (!found) 
#line 965 "paper/newton.nw"
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
#line 928 "paper/newton.nw"
  for (int i = 0; i < n; i++) d[i] = C0 * w->zf[i];
  for (int c = 0; c < m; c++) v[c] = C0 * w->zf[n + c];
  if (rep) rep->pred = model_decrease(mdl, d, v);
  return STATUS_OK;
}
