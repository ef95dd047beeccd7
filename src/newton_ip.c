#line 181 "paper/newton.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "newton_private.h"

#line 325 "paper/newton.nw"
/* out = A z (p values) */
void newton_constraints_times(const Newton_workspace *w, const int *col,
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
void newton_constraints_transposed(const Newton_workspace *w, const int *col,
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
#line 418 "paper/newton.nw"
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
#line 503 "paper/newton.nw"
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
void newton_bordered_solve(Newton_workspace *w, const int *col, const double *r,
                           double re, double *dz, double *dmu)
{
  double wy1 = 0, wy2 = 0;
  newton_matrix_solve(w, col, r, dz);
  for (int i = 0; i < w->n; i++) wy1 += w->w[i] * dz[i], wy2 += w->w[i] * w->y2[i];
  *dmu = (wy1 + re) / wy2;
  for (int k = 0; k < w->n + w->m; k++) dz[k] -= *dmu * w->y2[k];
}
#line 547 "paper/newton.nw"
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
  newton_constraints_transposed(w, col, ds, w->t2);
  for (int k = 0; k < nm; k++) w->t2[k] = -w->rd[k] - w->t2[k];
  newton_bordered_solve(w, col, w->t2, re, dz, dmu);
  newton_constraints_times(w, col, dz, ds);
  for (int j = 0; j < p; j++) {
    ds[j] = -w->rp[j] - ds[j];
    dl[j] = (rc[j] - w->lam[j] * ds[j]) / w->s[j];
  }
}

/* at (z, lam, s, mu): rd, rp = A z + s - b (s NULL: A z - b) and *re =
   w'd; scale[0], scale[1] receive the largest term of rd's design and
   contact rows (of S v, the sum of the magnitudes of its terms); returns
   the complementarity s'lam/p (0 if s is NULL) */
double newton_residuals(const Newton_workspace *w, const int *col, const double *z,
                        const double *lam, const double *s, double mu, double *rd,
                        double *rp, double *re, double scale[2])
{
  int n = w->n, m = w->m, p = w->p;
  newton_constraints_transposed(w, col, lam, rd);
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
  newton_constraints_times(w, col, z, rp);
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
int newton_factor_with_area(Newton_workspace *w, const int *col)
{
  int nm = w->n + w->m;
  if (factor_newton_matrix(w, col)) return -1;
  memset(w->t1, 0, nm * sizeof *w->t1);
  for (int i = 0; i < w->n; i++) w->t1[i] = w->w[i];
  newton_matrix_solve(w, col, w->t1, w->y2);
  return 0;
}

int newton_predictor_corrector(Newton_workspace *w, const int *col, double gap,
                               double re)
{
  int p = w->p, nm = w->n + w->m;
  double dmu, *rc = w->rc;
  for (int j = 0; j < p; j++) w->W[j] = w->lam[j] / w->s[j];
  if (newton_factor_with_area(w, col)) return -1;
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
