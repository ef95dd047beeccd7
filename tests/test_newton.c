/* test_newton: the model problem of a Newton step (paper/newton.nw).
   References independent of the module: (1) on tiny problems, every
   active set of the 4n - 2 + m inequalities, each equality-constrained
   problem solved by GSL's LU, the one that satisfies every KKT condition
   kept, for random problems and for the optimiser's end game (tiny steps
   against active constraints); (2) an interior solution in closed form;
   (3) NLopt's SLSQP on problems of 13 design nodes; (4) the scale of the
   data (E times 1e7 and 1e-7) does not change the step; (5) hundreds of
   random problems, down to a curvature of 1e-10 of the contact's, all
   solved; (6) every documented error provoked once; (7) models of a
   strip that bends, whose forces are far below the stiffness's terms,
   all solved.  No comparison reads
   the result of a solve that failed. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <nlopt.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "setup.h"
#include "newton.h"

static uint64_t seed = 0x9E3779B97F4A7C15ULL;
enum { MSG = sizeof ((Status) { 0 }).msg };   /* the first failure's message */

static double uniform(void)          /* xorshift64, in [0, 1) */
{
  seed ^= seed << 13; seed ^= seed >> 7; seed ^= seed << 17;
  return (seed >> 11) * 0x1.0p-53;
}

/* one random model: n design nodes, contact at nodes 1..m, X in B */
typedef struct {
  int n, m, col[16];
  double X[16], grad[16], r[16], S[256], f[16], v0[16];
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
  for (int i = 0; i < n; i++) k->grad[i] = scale * (uniform() - 0.5), k->r[i] = scale * (0.1 + uniform());
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
  k->mdl = (Newton_model) { n, m, k->col, k->X, &k->B, k->grad, k->r, k->S, k->f, k->v0 };
}

/* the optimiser's end game, n = 4: node 0 on its lower bound and the
   slope from node 0 to 1 at C1 h, both pushed into by a gradient of O(1);
   nodes 2 and 3 free with a tiny gradient, so that the step, one degree
   of freedom left by the area, is about tiny / rho; every contact node
   (1 .. m) touching, with a tiny force on nodes 2 and 3 */
static void make_endgame(Case *k, int m, double tiny, double rho)
{
  make_case(k, 4, m, 1.0);
  double dl = k->B.delta, area = 0;
  k->X[0] = 0, k->X[1] = dl;
  k->X[2] = dl * (1 + 0.8 * (uniform() - 0.5)), k->X[3] = k->X[2] + dl * 0.8 * (uniform() - 0.5);
  for (int i = 0; i < 4; i++) area += (i == 0 || i == 3 ? 0.5 : 1.0) * k->X[i] * k->B.h;
  k->B.area = area;
  k->grad[0] = 2 + uniform(), k->grad[1] = -(0.5 + uniform());   /* grad[0] + grad[1] > 0 */
  k->grad[2] = tiny * (uniform() - 0.5), k->grad[3] = tiny * (uniform() - 0.5);
  for (int i = 0; i < 4; i++) k->r[i] = rho * (0.1 + uniform());
  for (int c = 0; c < m; c++) k->v0[c] = -k->X[k->col[c]];
  for (int c = 0; c < m; c++) {           /* f = S v0 - T, T tiny on 2, 3 */
    double sv = 0;
    for (int e = 0; e < m; e++) sv += k->S[c * m + e] * k->v0[e];
    k->f[c] = sv - (k->col[c] < 2 ? 0.5 + uniform() : tiny * uniform());
  }
}

/* the model's objective at (d, v) */
static double objective(const Case *k, const double *d, const double *v)
{
  double val = 0;
  for (int i = 0; i < k->n; i++) val += (k->grad[i] + 0.5 * k->r[i] * d[i]) * d[i];
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
  for (int i = 0; i < n; i++) gsl_matrix_set(M, i, i, k->r[i]), gsl_vector_set(rhs, i, -k->grad[i]);
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

/* the first active set that meets the KKT conditions: z, or 0 */
static int enumerate(const Case *k, double *z)
{
  int p = 4 * k->n - 2 + k->m;
  for (unsigned set = 0; set < 1u << p; set++)
    if (kkt_of_set(k, set, p, z)) return 1;
  return 0;
}

/* solve k; 0 and d, v, or the status (its message in msg if none yet) */
static int solve(const Case *k, double *d, double *v, Newton_report *rep, char *msg)
{
  Newton_workspace *w = newton_alloc(k->n, k->m, NULL);
  Status st = { STATUS_OK, "" };
  int rc = w ? newton_solve(w, &k->mdl, d, v, rep, &st) : STATUS_MEMORY;
  if (rc && !*msg) snprintf(msg, MSG, "%s", w ? st.msg : "out of memory");
  newton_free(w);
  return rc;
}

/* m(0) - m(d) at (d, v) in long double (64 bits of mantissa on x86-64,
   113 on arm64), a reference for the predicted decrease: from the step,
   -(grad'd + d'Rd/2) - (T'dv + dv'S dv/2), T = S v0 - f and dv = v - v0
   (exact algebra; a difference of two values of m would lose the tiny
   steps even in long double) */
static long double decrease_long(const Case *k, const double *d, const double *v)
{
  long double dec = 0;
  for (int i = 0; i < k->n; i++) dec -= (k->grad[i] + 0.5L * k->r[i] * d[i]) * d[i];
  for (int c = 0; c < k->m; c++) {
    long double T = -(long double) k->f[c], sdv = 0;
    for (int e = 0; e < k->m; e++) {
      T += (long double) k->S[c * k->m + e] * k->v0[e];
      sdv += (long double) k->S[c * k->m + e] * ((long double) v[e] - k->v0[e]);
    }
    dec -= (T + 0.5L * sdv) * ((long double) v[c] - k->v0[c]);
  }
  return dec;
}

/* the largest difference of (d, v) from the enumerated z */
static double distance(const Case *k, const double *z, const double *d, const double *v)
{
  double worst = 0;
  for (int i = 0; i < k->n; i++) worst = fmax(worst, fabs(d[i] - z[i]));
  for (int c = 0; c < k->m; c++) worst = fmax(worst, fabs(v[c] - z[k->n + c]));
  return worst;
}

static void test_enumeration(void)
{
  int found = 1, solved = 0, trials = 12;
  double worst = 0;
  char msg[MSG] = "";
  for (int t = 0; t < trials; t++) {
    int n = 3 + t % 2, m = t % 3 == 0 ? 1 : 2;
    Case k;
    make_case(&k, n, m, 1.0);
    for (int i = 0; i < n; i++) k.grad[i] *= 40;      /* steps that reach bounds */
    double z[16], d[16], v[16];
    Newton_report rep;
    int have = enumerate(&k, z);
    found &= have;
    if (!have || solve(&k, d, v, &rep, msg)) continue;
    worst = fmax(worst, distance(&k, z, d, v)), solved++;
  }
  check(found, "every tiny problem (n = 3, 4; m = 1, 2) has one active set that meets the KKT conditions");
  check(solved == trials, "the interior point solves all %d of them (%d) %s", trials, solved, msg);
  check(solved > 0 && worst <= 1e-12, "it finds the enumerated solution of the %d solved to %.1e "
        "<= 1e-12 (C0 = 1)", solved, worst);
}

/* tiny steps (1e-10 .. 1e-4 of C0) against active constraints: the step
   to rounding, absolute and relative to its own size */
static void test_endgame(void)
{
  int found = 1, solved = 0, trials = 24;
  double worst = 0, worst_rel = 0, smallest = HUGE_VAL, worst_pred = 0;
  double worst_round = 0, noisiest = 0;
  char msg[MSG] = "";
  for (int t = 0; t < trials; t++) {
    int n = 4, m = 1 + t % 3;
    Case k;
    make_endgame(&k, m, pow(10, -10 + 6 * uniform()), pow(10, -3 + 3 * uniform()));
    double z[16], d[16], v[16], step = 0;
    Newton_report rep;
    int have = enumerate(&k, z);
    found &= have;
    if (!have || solve(&k, d, v, &rep, msg)) continue;
    for (int i = 0; i < n; i++) step = fmax(step, fabs(z[i]));
    double dist = distance(&k, z, d, v), pred = (double) decrease_long(&k, d, v);
    worst = fmax(worst, dist), solved++;
    worst_pred = fmax(worst_pred, fabs(rep.pred - pred) / pred);
    worst_round = fmax(worst_round, fabs(rep.pred - pred) / rep.rounding);
    noisiest = fmax(noisiest, rep.rounding / pred);
    if (step > 0) worst_rel = fmax(worst_rel, dist / step), smallest = fmin(smallest, step);
  }
  check(found, "the end game (n = 4 on a bound and a slope, tiny gradients): one active set meets the KKT conditions");
  check(solved == trials, "the interior point solves all %d of them (%d) %s", trials, solved, msg);
  check(solved > 0 && worst <= 1e-14, "it finds the enumerated step to %.1e <= 1e-14 C0", worst);
  check(solved > 0 && worst_rel <= 1e-4, "steps down to %.1e C0 to %.1e <= 1e-4 of their size",
        smallest, worst_rel);
  check(solved > 0 && worst_pred <= 1e-6, "their predicted decreases, down to 1e-20, are those "
        "of the steps (in long double) to %.1e <= 1e-6 of themselves", worst_pred);
  check(solved > 0 && worst_round <= 1 && noisiest <= 1e-4, "their reported rounding bounds "
        "that difference (%.2f of it at most) and shrinks with the step (at most %.1e of the "
        "decrease <= 1e-4)", worst_round, noisiest);
}

/* ---- (2) an interior solution in closed form ----------------------------- */

static void test_interior(void)
{
  Case k;
  make_case(&k, 9, 0, 1.0);
  for (int i = 0; i < 9; i++) k.grad[i] *= 1e-3;       /* a tiny step: no bound active */
  /* d = -R^-1 (grad + mu w), mu from w'd = 0 */
  double a = 0, b = 0, want[9], d[9];
  for (int i = 0; i < 9; i++) {
    double w = i == 0 || i == 8 ? 0.5 : 1.0;
    a += w * k.grad[i] / k.r[i], b += w * w / k.r[i];
  }
  double worst = 0;
  for (int i = 0; i < 9; i++) want[i] = -(k.grad[i] - a / b * (i == 0 || i == 8 ? 0.5 : 1.0)) / k.r[i];
  Newton_workspace *w = newton_alloc(9, 0, NULL);
  Newton_report rep;
  Status st = { STATUS_OK, "" };
  int rc = newton_solve(w, &k.mdl, d, NULL, &rep, &st);
  for (int i = 0; rc == 0 && i < 9; i++) worst = fmax(worst, fabs(d[i] - want[i]));
  double pred = 0;
  for (int i = 0; i < 9; i++) pred -= (k.grad[i] + 0.5 * k.r[i] * want[i]) * want[i];
  check(rc == 0 && worst <= 1e-10 * 1e-3, "no contact, no bound active: d = -R^-1(grad + mu w) "
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
    for (int i = 0; i < n; i++) grad[i] = k->grad[i] + k->r[i] * z[i];
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
  int refs = 0, solved = 0, trials = 5;
  char msg[MSG] = "";
  for (int t = 0; t < trials; t++) {
    Case k;
    make_case(&k, 13, 12, 1.0);
    for (int i = 0; i < 13; i++) k.grad[i] *= 20;
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
    Newton_report rep;
    int good_ref = (r > 0 || r == NLOPT_ROUNDOFF_LIMITED) && violation(&k, z, z + 13) <= 1e-10;
    refs += good_ref;
    if (solve(&k, d, v, &rep, msg)) continue;        /* d, v not written */
    solved++;
    worst_viol = fmax(worst_viol, violation(&k, d, v));
    if (good_ref) worst_obj = fmax(worst_obj, (objective(&k, d, v) - f) / fmax(fabs(f), 1));
  }
  check(refs == trials, "13 nodes, 12 contact unknowns: SLSQP reaches a feasible point of all "
        "%d problems (%d)", trials, refs);
  check(solved == trials, "the interior point solves all %d (%d) %s", trials, solved, msg);
  check(solved > 0 && refs > 0 && worst_obj <= 1e-9, "its objective is not above SLSQP's by more "
        "than %.1e <= 1e-9 (relative)", worst_obj);
  check(solved > 0 && worst_viol <= 1e-12, "its step is feasible to %.1e <= 1e-12", worst_viol);
}

/* ---- (4) scale-free ------------------------------------------------------- */

/* The data times s: every comparison of the method is between scale-free
   quantities, so the step is the same to rounding.  Multiplying by s is
   not exact in binary, and a comparison that falls within rounding of
   its threshold (when to try the face, which side of the indicator a
   constraint is on) may go the other way: the iterations may differ by
   one, no more in these problems. */
static void test_scale(void)
{
  double worst = 0, worst_pred = 0;
  int rc = 0, most = 0, trials = 0;
  char msg[MSG] = "";
  for (int t = 0; t < 6; t++) {
    double s = t % 2 ? 1e-7 : 1e7;
    Case a, b;
    uint64_t s0 = seed;
    make_case(&a, 13, 12, 1.0);
    seed = s0;
    make_case(&b, 13, 12, s);
    for (int i = 0; i < 13; i++) a.grad[i] *= 20, b.grad[i] *= 20;
    double da[13], va[12], db[13], vb[12];
    Newton_report ra, rb;
    if (solve(&a, da, va, &ra, msg) || solve(&b, db, vb, &rb, msg)) { rc = 1; continue; }
    for (int i = 0; i < 13; i++) worst = fmax(worst, fabs(da[i] - db[i]));
    for (int c = 0; c < 12; c++) worst = fmax(worst, fabs(va[c] - vb[c]));
    worst_pred = fmax(worst_pred, fabs(rb.pred / s - ra.pred) / ra.pred);
    most = fmax(most, abs(ra.iterations - rb.iterations)), trials++;
  }
  check(!rc, "the data times 1e7 and 1e-7 (6 problems): every solve succeeds %s", msg);
  check(trials > 0 && worst <= 1e-13, "the same step to %.1e <= 1e-13 C0", worst);
  check(trials > 0 && worst_pred <= 1e-12, "the same predicted decrease, times the factor, to "
        "%.1e <= 1e-12 (relative)", worst_pred);
  check(trials > 0 && most <= 1, "iterations that differ by at most one (%d)", most);
}

/* ---- (5) robustness -------------------------------------------------------- */

/* a design that walks flat or at C1 h between the bounds, every contact
   node touching, a gradient that pushes into the active constraints and a
   part of size tiny, curvature rho (down to 1e-10 of the contact's: the
   optimiser's rho ranges from 1e-15 to 1e12) */
static void make_walk(Case *k, int n, int m, double tiny, double rho)
{
  make_case(k, n, m, 1.0);
  double dl = k->B.delta, x = 0, area = 0;
  int mode = 0;
  for (int i = 0; i < n; i++) {
    if (uniform() < 0.3) mode = (int) (uniform() * 3);
    k->X[i] = x;
    x = fmin(fmax(mode == 0 ? x : mode == 1 ? x + dl : x - dl, 0), 1);
  }
  for (int i = 0; i < n; i++) area += (i == 0 || i == n - 1 ? 0.5 : 1.0) * k->X[i] * k->B.h;
  k->B.area = area;
  for (int i = 0; i < n; i++) {
    double gi = k->X[i] == 0 ? 0.5 + uniform() : 0;
    if (i + 1 < n && k->X[i + 1] - k->X[i] == dl) gi += 0.5 + uniform();
    if (i > 0 && k->X[i] - k->X[i - 1] == dl) gi -= 0.5 + uniform();
    k->grad[i] = gi + tiny * (uniform() - 0.5), k->r[i] = rho * (0.1 + uniform());
  }
  for (int c = 0; c < m; c++) k->v0[c] = -k->X[k->col[c]];
  for (int c = 0; c < m; c++) {
    double sv = 0;
    for (int e = 0; e < m; e++) sv += k->S[c * m + e] * k->v0[e];
    k->f[c] = sv - (0.5 + uniform());
  }
}

/* S made singular, P S P with P = I - u u'/u'u and u the indicator of
   the contact unknowns that do not touch and of the first that does (a
   body held in that direction by one contact alone: T'u > 0, so that the
   model has one minimiser; on a face without that contact its Newton
   matrix is singular), the forces T = S v0 - f kept; 0 if all or none
   touch */
static int make_singular(Case *k)
{
  int m = k->m, nu = 0, holder = -1;
  double T[16], u[16], Su[16], uSu = 0;
  for (int c = 0; c < m; c++) {
    int touches = k->v0[c] == -k->X[k->col[c]];
    if (touches && holder < 0) holder = c;
    u[c] = !touches || c == holder, nu += u[c] > 0;
    T[c] = -k->f[c];
    for (int e = 0; e < m; e++) T[c] += k->S[c * m + e] * k->v0[e];
  }
  if (holder < 0 || nu < 2) return 0;
  for (int c = 0; c < m; c++) {
    Su[c] = 0;
    for (int e = 0; e < m; e++) Su[c] += k->S[c * m + e] * u[e] / nu;
    uSu += u[c] * Su[c];
  }
  for (int c = 0; c < m; c++)            /* P S P = S - Su u' - u Su' + uSu u u' (u'u = nu) */
    for (int e = 0; e < m; e++)
      k->S[c * m + e] += -Su[c] * u[e] - u[c] * Su[e] + uSu * u[c] * u[e] / nu;
  for (int c = 0; c < m; c++) {
    k->f[c] = -T[c];
    for (int e = 0; e < m; e++) k->f[c] += k->S[c * m + e] * k->v0[e];
  }
  return 1;
}

static void test_robust(void)
{
  int solved = 0, trials = 400, singular = 0;
  double worst_viol = 0, worst_pred = 0;
  char msg[MSG] = "";
  for (int t = 0; t < trials; t++) {
    int n = 3 + (int) (uniform() * 14), m = (int) (uniform() * n);
    Case k;
    if (t % 2) make_walk(&k, n, m, pow(10, -12 + 10 * uniform()), pow(10, -10 + 10 * uniform()));
    else {
      make_case(&k, n, m, 1.0);
      for (int i = 0; i < n; i++) k.grad[i] *= 40, k.r[i] *= pow(10, -10 + 10 * uniform());
    }
    if (t % 4 == 2) singular += make_singular(&k);   /* a make_case: some not touching */
    double scale = pow(10, -8 + 16 * uniform()), d[16], v[16], zero[16] = { 0 }, terms = 0;
    for (int i = 0; i < n; i++) k.grad[i] *= scale, k.r[i] *= scale, terms += fabs(k.grad[i]) + k.r[i];
    for (int c = 0; c < m * m; c++) k.S[c] *= scale;
    for (int c = 0; c < m; c++) k.f[c] *= scale, terms += fabs(k.f[c] * k.v0[c]);
    Newton_report rep;
    if (solve(&k, d, v, &rep, msg)) continue;
    solved++;
    worst_viol = fmax(worst_viol, violation(&k, d, v));
    double pred = objective(&k, zero, k.v0) - objective(&k, d, v);
    worst_pred = fmax(worst_pred, fabs(rep.pred - pred) / terms);
    worst_pred = fmax(worst_pred, -pred / terms);
  }
  check(solved == trials, "%d random problems (n = 3 .. 16, curvature 1e-10 .. 1 of the contact's, "
        "data 1e-8 .. 1e8, half of them on bounds and slopes with tiny gradients, %d with S "
        "singular): all solved (%d) %s", trials, singular, solved, msg);
  check(solved > 0 && worst_viol <= 1e-12, "their steps are feasible to %.1e <= 1e-12 C0", worst_viol);
  check(solved > 0 && worst_pred <= 1e-14, "their predicted decreases are the model's own and "
        "not negative to %.1e <= 1e-14 of the model's terms", worst_pred);
}

/* ---- (6) errors ----------------------------------------------------------- */

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
  k.col[1] = 2, k.S[1] = INFINITY;
  check(newton_solve(w, &k.mdl, d, v, NULL, &st) == STATUS_INPUT && strstr(st.msg, "(0, 1)"),
        "an infinite entry of S: STATUS_INPUT \"%s\"", st.msg);
  for (int c = 0; c < 4; c++) k.S[c] = c == 0 || c == 3 ? -1 : 0;   /* S = -I */
  for (int i = 0; i < 5; i++) d[i] = 12345;
  int rc = newton_solve(w, &k.mdl, d, v, NULL, &st), same = 1;
  for (int i = 0; i < 5; i++) same &= d[i] == 12345;
  check(rc == STATUS_NUMERIC && strstr(st.msg, "not positive definite") && same,
        "S = -I, a model that is not convex: STATUS_NUMERIC, d not written: \"%s\"", st.msg);
  newton_free(w);
  check(newton_alloc(1, 0, &st) == NULL && st.code == STATUS_INPUT,
        "one design node: STATUS_INPUT \"%s\"", st.msg);
}

/* ---- (7) a strip that bends (paper/newton.nw, "A soft face") ----------- */

/* n design nodes, C0 = 1, a contact unknown at each inner node, all of
   them touching: S the fourth difference of a beam clamped at both ends
   over 6 (diagonal 1, softest mode about (pi / n)^4), forces T of `load`
   to 1.5 load, the design's curvature rho and gradient within +-load:
   the forces are those of S v's terms less by the factor load, as on a
   thin strip in contact (its design rows that much below its contact
   rows) */
static int bending_solve(int n, double rho, double load, Newton_report *rep, char *msg)
{
  int m = n - 2, rc = STATUS_MEMORY;
  int *col = malloc(m * sizeof *col);
  double *a = malloc(((size_t) 4 * n + 3 * m + (size_t) m * m) * sizeof *a);
  Newton_workspace *w = newton_alloc(n, m, NULL);
  if (!col || !a || !w) {
    if (!*msg) snprintf(msg, MSG, "out of memory");
    goto done;
  }
  double *X = a, *grad = X + n, *r = grad + n, *d = r + n, *f = d + n, *v0 = f + m, *v = v0 + m, *S = v + m;
  Design_set B = { n - 1, 1.0 / (n - 1), 1.0, 1.0 / (n - 1), 0 };
  double phase = 6.28 * uniform();
  for (int i = 0; i < n; i++) X[i] = 0.5 + 0.2 * sin(M_PI * i / (n - 1) + phase);
  for (int i = 0; i + 1 < n; i++) B.area += B.h * (X[i] + X[i + 1]) / 2;
  memset(S, 0, (size_t) m * m * sizeof *S);
  for (int c = 0; c < m; c++) {
    const double st[5] = { 1, -4, 6, -4, 1 };
    for (int k = -2; k <= 2; k++)
      if (c + k >= 0 && c + k < m) S[(size_t) c * m + c + k] = st[k + 2] / 6;
    col[c] = c + 1, v0[c] = -X[c + 1];
  }
  for (int c = 0; c < m; c++) {            /* f = S v0 - T */
    double sv = 0;
    for (int e = 0; e < m; e++) sv += S[(size_t) c * m + e] * v0[e];
    f[c] = sv - load * (1 + 0.5 * uniform());
  }
  for (int i = 0; i < n; i++) grad[i] = load * (2 * uniform() - 1), r[i] = rho;
  for (int c = 0; c < m; c++) grad[col[c]] += load;
  Newton_model mdl = { n, m, col, X, &B, grad, r, S, f, v0 };
  Status st = { STATUS_OK, "" };
  rc = newton_solve(w, &mdl, d, v, rep, &st);
  if (rc && !*msg) snprintf(msg, MSG, "%s", st.msg);
done:
  newton_free(w), free(col), free(a);
  return rc;
}

static void test_bending(void)
{
  int solved = 0, trials = 20;
  double worst = 0;
  char msg[MSG] = "";
  for (int t = 0; t < trials; t++) {
    Newton_report rep;
    if (bending_solve(201, 1e-9, 1e-9, &rep, msg)) continue;
    solved++, worst = fmin(worst, rep.pred + rep.rounding);
  }
  check(solved == trials, "a strip that bends (n = 201, 199 contact unknowns, forces 1e-9 of "
        "the stiffness, rho = 1e-9): all %d models solved (%d) %s", trials, solved, msg);
  check(solved > 0 && worst >= 0, "their predicted decreases are not negative beyond their "
        "rounding (%.1e)", worst);
}

int main(void)
{
  test_start_gsl();
  test_enumeration();
  test_endgame();
  test_interior();
  test_slsqp();
  test_scale();
  test_robust();
  test_errors();
  test_bending();
  return check_done();
}
