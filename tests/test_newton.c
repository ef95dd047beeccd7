/* test_newton: the model problem of a Newton step (paper/newton.nw).
   References independent of the module: (1) on tiny problems, every
   active set of the 4n - 2 + m inequalities, each equality-constrained
   problem solved by GSL's LU, the one that satisfies every KKT condition
   kept; (2) an interior solution in closed form; (3) NLopt's SLSQP on
   problems of 13 design nodes; (4) the scale of the data (E times 1e7)
   changes neither the step nor the iteration count; (5) every documented
   error provoked once. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <nlopt.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "newton.h"

static uint64_t seed = 0x9E3779B97F4A7C15ULL;

static double uniform(void)          /* xorshift64, in [0, 1) */
{
  seed ^= seed << 13; seed ^= seed >> 7; seed ^= seed << 17;
  return (seed >> 11) * 0x1.0p-53;
}

/* one random model: n design nodes, contact at nodes 1..m, X in B */
typedef struct {
  int n, m, col[16];
  double X[16], g[16], r[16], S[256], f[16], v0[16];
  Design_set B;
  Newton_model mdl;
} Case;

static void make_case(Case *k, int n, int m, double scale)
{
  memset(k, 0, sizeof *k);
  k->n = n, k->m = m;
  k->B = (Design_set) { n - 1, 1.0 / (n - 1), 1.0, 0.3 / (n - 1), 0 };
  double area = 0;
  for (int i = 0; i < n; i++) {
    k->X[i] = 0.2 + 0.6 * uniform();
    area += (i == 0 || i == n - 1 ? 0.5 : 1.0) * k->X[i] * k->B.h;
  }
  for (int i = 0; i + 1 < n; i++)        /* slopes within C1 h */
    if (fabs(k->X[i + 1] - k->X[i]) > k->B.delta)
      k->X[i + 1] = k->X[i] + copysign(k->B.delta * 0.9, k->X[i + 1] - k->X[i]);
  area = 0;
  for (int i = 0; i < n; i++) area += (i == 0 || i == n - 1 ? 0.5 : 1.0) * k->X[i] * k->B.h;
  k->B.area = area;
  double L[256] = { 0 };
  for (int c = 0; c < m; c++) {
    k->col[c] = 1 + c;
    for (int e = 0; e <= c; e++) L[c * m + e] = uniform() - 0.5 + (c == e ? 1.5 : 0);
  }
  for (int c = 0; c < m; c++)            /* S = L L' */
    for (int e = 0; e < m; e++) {
      double s = 0;
      for (int j = 0; j < m; j++) s += L[c * m + j] * L[e * m + j];
      k->S[c * m + e] = scale * s;
    }
  for (int i = 0; i < n; i++) k->g[i] = scale * (uniform() - 0.5), k->r[i] = scale * (0.1 + uniform());
  for (int c = 0; c < m; c++) {           /* a state: v0 >= -X, touching on some */
    k->v0[c] = uniform() < 0.5 ? -k->X[k->col[c]] : -k->X[k->col[c]] + 0.1 * uniform();
    k->f[c] = 0;
  }
  for (int c = 0; c < m; c++) {           /* f = S v0 - T, T >= 0 where touching */
    double sv = 0;
    for (int e = 0; e < m; e++) sv += k->S[c * m + e] * k->v0[e];
    double T = k->v0[c] == -k->X[k->col[c]] ? scale * uniform() : 0;
    k->f[c] = sv - T;
  }
  k->mdl = (Newton_model) { n, m, k->col, k->X, &k->B, k->g, k->r, k->S, k->f, k->v0 };
}

/* the model's objective at (d, v) */
static double objective(const Case *k, const double *d, const double *v)
{
  double val = 0;
  for (int i = 0; i < k->n; i++) val += (k->g[i] + 0.5 * k->r[i] * d[i]) * d[i];
  for (int c = 0; c < k->m; c++) {
    double sv = 0;
    for (int e = 0; e < k->m; e++) sv += k->S[c * k->m + e] * v[e];
    val += (0.5 * sv - k->f[c]) * v[c];
  }
  return val;
}

/* the largest violation of the constraints at (d, v) */
static double violation(const Case *k, const double *d, const double *v)
{
  double worst = 0, area = 0;
  for (int i = 0; i < k->n; i++) {
    double x = k->X[i] + d[i];
    worst = fmax(worst, fmax(-x, x - k->B.C0));
    area += (i == 0 || i == k->n - 1 ? 0.5 : 1.0) * d[i];
  }
  for (int i = 0; i + 1 < k->n; i++)
    worst = fmax(worst, fabs(k->X[i + 1] + d[i + 1] - k->X[i] - d[i]) - k->B.delta);
  for (int c = 0; c < k->m; c++) worst = fmax(worst, -(v[c] + k->X[k->col[c]] + d[k->col[c]]));
  return fmax(worst, fabs(area));
}

/* ---- (1) every active set ------------------------------------------------ */

/* row j of A z <= b, as (coefficients over z, bound) */
static double row(const Case *k, int j, double *a)
{
  int n = k->n, N = n - 1;
  memset(a, 0, (n + k->m) * sizeof *a);
  if (j < n) { a[j] = -1; return k->X[j]; }
  if (j < 2 * n) { a[j - n] = 1; return k->B.C0 - k->X[j - n]; }
  if (j < 2 * n + N) { int i = j - 2 * n; a[i + 1] = 1, a[i] = -1; return k->B.delta - (k->X[i + 1] - k->X[i]); }
  if (j < 2 * n + 2 * N) { int i = j - 2 * n - N; a[i] = 1, a[i + 1] = -1; return k->B.delta + (k->X[i + 1] - k->X[i]); }
  int c = j - 2 * n - 2 * N;
  a[n + c] = -1, a[k->col[c]] = -1;
  return k->X[k->col[c]];
}

/* the KKT point of the active set 'set' (bits), or 0 */
static int kkt_of_set(const Case *k, unsigned set, int p, double *z)
{
  int n = k->n, m = k->m, nz = n + m, na = 0, rows[32];
  for (int j = 0; j < p; j++) if (set >> j & 1) rows[na++] = j;
  int K = nz + na + 1;
  if (na > nz) return 0;
  gsl_matrix *M = gsl_matrix_calloc(K, K);
  gsl_vector *rhs = gsl_vector_calloc(K), *sol = gsl_vector_alloc(K);
  gsl_permutation *P = gsl_permutation_alloc(K);
  double a[32];
  for (int i = 0; i < n; i++) gsl_matrix_set(M, i, i, k->r[i]), gsl_vector_set(rhs, i, -k->g[i]);
  for (int c = 0; c < m; c++) {
    for (int e = 0; e < m; e++) gsl_matrix_set(M, n + c, n + e, k->S[c * m + e]);
    gsl_vector_set(rhs, n + c, k->f[c]);
  }
  for (int q = 0; q < na; q++) {
    double bq = row(k, rows[q], a);
    for (int t = 0; t < nz; t++)
      gsl_matrix_set(M, nz + q, t, a[t]), gsl_matrix_set(M, t, nz + q, a[t]);
    gsl_vector_set(rhs, nz + q, bq);
  }
  for (int i = 0; i < n; i++) {
    double w = i == 0 || i == n - 1 ? 0.5 : 1.0;
    gsl_matrix_set(M, K - 1, i, w), gsl_matrix_set(M, i, K - 1, w);
  }
  int sign, ok = !gsl_linalg_LU_decomp(M, P, &sign)
                 && fabs(gsl_matrix_get(M, K - 1, K - 1)) > 1e-13
                 && !gsl_linalg_LU_solve(M, P, rhs, sol);
  for (int q = 0; ok && q < na; q++) ok = gsl_vector_get(sol, nz + q) >= -1e-12;
  for (int t = 0; ok && t < nz; t++) z[t] = gsl_vector_get(sol, t);
  for (int j = 0; ok && j < p; j++) {
    double bj = row(k, j, a), az = 0;
    for (int t = 0; t < nz; t++) az += a[t] * z[t];
    ok = az <= bj + 1e-12;
  }
  gsl_matrix_free(M), gsl_vector_free(rhs), gsl_vector_free(sol), gsl_permutation_free(P);
  return ok;
}

static void test_enumeration(void)
{
  int agree = 1, found = 1, trials = 0;
  double worst = 0;
  for (int t = 0; t < 12; t++) {
    int n = 3 + t % 2, m = t % 3 == 0 ? 1 : 2, p = 4 * n - 2 + m;
    Case k;
    make_case(&k, n, m, 1.0);
    for (int i = 0; i < n; i++) k.g[i] *= 40;      /* steps that reach bounds */
    double z[16], d[16], v[16];
    int have = 0;
    for (unsigned set = 0; !have && set < 1u << p; set++) have = kkt_of_set(&k, set, p, z);
    found &= have;
    Newton_workspace *w = newton_alloc(n, m, NULL);
    Newton_report rep;
    Status st = { STATUS_OK, "" };
    if (!have || !w || newton_solve(w, &k.mdl, d, v, &rep, &st)) { agree = 0; newton_free(w); continue; }
    for (int i = 0; i < n; i++) worst = fmax(worst, fabs(d[i] - z[i]));
    for (int c = 0; c < m; c++) worst = fmax(worst, fabs(v[c] - z[n + c]));
    trials++;
    newton_free(w);
  }
  check(found, "every tiny problem (n = 3, 4; m = 1, 2) has one active set that meets the KKT conditions");
  check(agree && worst <= 1e-9, "the interior point finds the enumerated solution of %d problems "
        "to %.1e <= 1e-9 (C0 = 1)", trials, worst);
}

/* ---- (2) an interior solution in closed form ----------------------------- */

static void test_interior(void)
{
  Case k;
  make_case(&k, 9, 0, 1.0);
  for (int i = 0; i < 9; i++) k.g[i] *= 1e-3;       /* a tiny step: no bound active */
  /* d = -R^-1 (g + mu w), mu from w'd = 0 */
  double a = 0, b = 0, want[9], d[9];
  for (int i = 0; i < 9; i++) {
    double w = i == 0 || i == 8 ? 0.5 : 1.0;
    a += w * k.g[i] / k.r[i], b += w * w / k.r[i];
  }
  double worst = 0;
  for (int i = 0; i < 9; i++) want[i] = -(k.g[i] - a / b * (i == 0 || i == 8 ? 0.5 : 1.0)) / k.r[i];
  Newton_workspace *w = newton_alloc(9, 0, NULL);
  Newton_report rep;
  Status st = { STATUS_OK, "" };
  int rc = newton_solve(w, &k.mdl, d, NULL, &rep, &st);
  for (int i = 0; rc == 0 && i < 9; i++) worst = fmax(worst, fabs(d[i] - want[i]));
  double pred = 0;
  for (int i = 0; i < 9; i++) pred -= (k.g[i] + 0.5 * k.r[i] * want[i]) * want[i];
  check(rc == 0 && worst <= 1e-10 * 1e-3, "no contact, no bound active: d = -R^-1(g + mu w) "
        "to %.1e <= 1e-13 (|d| ~ 1e-3)", worst);
  check(rc == 0 && fabs(rep.pred - pred) <= 1e-9 * pred, "the predicted decrease %.6e is "
        "the model's own, %.6e", rep.pred, pred);
  newton_free(w);
}

/* ---- (3) SLSQP on 13 design nodes ---------------------------------------- */

typedef struct { const Case *k; } Ref;

static double ref_objective(unsigned nz, const double *z, double *grad, void *data)
{
  const Case *k = ((const Ref *) data)->k;
  int n = k->n, m = k->m;
  if (grad) {
    for (int i = 0; i < n; i++) grad[i] = k->g[i] + k->r[i] * z[i];
    for (int c = 0; c < m; c++) {
      double sv = 0;
      for (int e = 0; e < m; e++) sv += k->S[c * m + e] * z[n + e];
      grad[n + c] = sv - k->f[c];
    }
  }
  (void) nz;
  return objective(k, z, z + n);
}

static void ref_constraints(unsigned p, double *out, unsigned nz, const double *z,
                            double *grad, void *data)
{
  const Case *k = ((const Ref *) data)->k;
  double a[32];
  for (unsigned j = 0; j < p; j++) {
    double bj = row(k, (int) j, a), az = 0;
    for (unsigned t = 0; t < nz; t++) az += a[t] * z[t];
    out[j] = az - bj;
    if (grad) memcpy(grad + j * nz, a, nz * sizeof *a);
  }
}

static double ref_area(unsigned nz, const double *z, double *grad, void *data)
{
  const Case *k = ((const Ref *) data)->k;
  double s = 0;
  for (unsigned t = 0; t < nz; t++) {
    double w = (int) t < k->n ? (t == 0 || (int) t == k->n - 1 ? 0.5 : 1.0) : 0.0;
    s += w * z[t];
    if (grad) grad[t] = w;
  }
  return s;
}

static void test_slsqp(void)
{
  double worst_obj = 0, worst_viol = 0;
  int ok = 1;
  for (int t = 0; t < 5; t++) {
    Case k;
    make_case(&k, 13, 12, 1.0);
    for (int i = 0; i < 13; i++) k.g[i] *= 20;
    int nz = 25, p = 4 * 13 - 2 + 12;
    double z[25], tol[64], f, d[13], v[12];
    for (int i = 0; i < 13; i++) z[i] = 0;
    for (int c = 0; c < 12; c++) z[13 + c] = k.v0[c];
    for (int j = 0; j < p; j++) tol[j] = 1e-13;
    Ref ref = { &k };
    nlopt_opt o = nlopt_create(NLOPT_LD_SLSQP, nz);
    nlopt_add_inequality_mconstraint(o, p, ref_constraints, &ref, tol);
    nlopt_add_equality_constraint(o, ref_area, &ref, 1e-13);
    nlopt_set_min_objective(o, ref_objective, &ref);
    nlopt_set_ftol_abs(o, 1e-15), nlopt_set_maxeval(o, 10000);
    nlopt_result r = nlopt_optimize(o, z, &f);
    nlopt_destroy(o);
    ok &= (r > 0 || r == NLOPT_ROUNDOFF_LIMITED) && violation(&k, z, z + 13) <= 1e-10;
    Newton_workspace *w = newton_alloc(13, 12, NULL);
    Newton_report rep;
    Status st = { STATUS_OK, "" };
    ok &= w && !newton_solve(w, &k.mdl, d, v, &rep, &st);
    newton_free(w);
    double mine = objective(&k, d, v);
    worst_obj = fmax(worst_obj, (mine - f) / fmax(fabs(f), 1));
    worst_viol = fmax(worst_viol, violation(&k, d, v));
  }
  check(ok && worst_obj <= 1e-9, "13 nodes, 12 contact unknowns (5 problems): the objective "
        "is not above SLSQP's (a feasible point) by more than %.1e <= 1e-9 (relative)", worst_obj);
  check(ok && worst_viol <= 1e-12, "its step is feasible to %.1e <= 1e-12", worst_viol);
}

/* ---- (4) scale-free ------------------------------------------------------- */

static void test_scale(void)
{
  Case a, b;
  uint64_t s0 = seed;
  make_case(&a, 13, 12, 1.0);
  seed = s0;
  make_case(&b, 13, 12, 1e7);
  for (int i = 0; i < 13; i++) a.g[i] *= 20, b.g[i] *= 20;
  double da[13], va[12], db[13], vb[12], worst = 0;
  Newton_report ra, rb;
  Newton_workspace *w = newton_alloc(13, 12, NULL);
  int rc = newton_solve(w, &a.mdl, da, va, &ra, NULL) || newton_solve(w, &b.mdl, db, vb, &rb, NULL);
  for (int i = 0; !rc && i < 13; i++) worst = fmax(worst, fabs(da[i] - db[i]));
  check(!rc && worst <= 1e-12 && ra.iterations == rb.iterations, "the data times 1e7: the "
        "same step to %.1e and the same iterations (%d, %d)", worst, ra.iterations,
        rc ? -1 : rb.iterations);
  newton_free(w);
}

/* ---- (5) errors ----------------------------------------------------------- */

static void test_errors(void)
{
  Case k;
  make_case(&k, 5, 2, 1.0);
  Newton_workspace *w = newton_alloc(5, 3, NULL);
  double d[5], v[3];
  Status st = { STATUS_OK, "" };
  check(newton_solve(w, &k.mdl, d, v, NULL, &st) == STATUS_INPUT && strstr(st.msg, "workspace"),
        "a model of other sizes than the workspace: STATUS_INPUT \"%s\"", st.msg);
  newton_free(w);
  w = newton_alloc(5, 2, NULL);
  k.r[3] = 0;
  check(newton_solve(w, &k.mdl, d, v, NULL, &st) == STATUS_INPUT && strstr(st.msg, "node 3"),
        "r = 0 at a node: STATUS_INPUT \"%s\"", st.msg);
  k.r[3] = 1, k.f[1] = NAN;
  check(newton_solve(w, &k.mdl, d, v, NULL, &st) == STATUS_INPUT && strstr(st.msg, "contact 1"),
        "a NaN in f: STATUS_INPUT \"%s\"", st.msg);
  k.f[1] = 0, k.col[0] = 2, k.col[1] = 1;
  check(newton_solve(w, &k.mdl, d, v, NULL, &st) == STATUS_INPUT && strstr(st.msg, "increasing"),
        "contact unknowns out of order (col = 2, 1): STATUS_INPUT \"%s\"", st.msg);
  k.col[0] = 1, k.col[1] = 5;
  check(newton_solve(w, &k.mdl, d, v, NULL, &st) == STATUS_INPUT && strstr(st.msg, "increasing"),
        "a contact unknown at node 5 of 5: STATUS_INPUT \"%s\"", st.msg);
  newton_free(w);
  check(newton_alloc(1, 0, &st) == NULL && st.code == STATUS_INPUT,
        "one design node: STATUS_INPUT \"%s\"", st.msg);
}

int main(void)
{
  gsl_set_error_handler_off();
  test_enumeration();
  test_interior();
  test_slsqp();
  test_scale();
  test_errors();
  return check_done();
}
