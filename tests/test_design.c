/* test_design: the design set B (4.4) and the projection onto it.
   References independent of the module: (1) the KKT conditions of the
   projection, checked densely from the returned multipliers; (2) for
   N <= 6, brute force over every active set, each equality-constrained
   least-squares problem solved by GSL's SVD, on random data and on data
   tied on purpose (multiples of 1/8); (3) the properties of a
   projection (fixed points, idempotence, non-expansiveness); (4) Example
   5.1's data; (5) N = 1024, timed; (6) degenerate and empty sets; (7) the
   stationarity measure of the shape problem; (8) the feasible start. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "design.h"
#include "opt.h"

static uint64_t seed = 88172645463325252ULL;

static double uniform(void)          /* xorshift64, in [0, 1) */
{
  seed ^= seed << 13; seed ^= seed >> 7; seed ^= seed << 17;
  return (seed >> 11) * 0x1.0p-53;
}

static Design_set make_set(int N, double width, double C0, double C1, double S)
{
  Design_set B = { N, width / N, C0, C1 * width / N, S };
  return B;
}

static double w_of(const Design_set *B, int i)
{
  return i == 0 || i == B->N ? B->h / 2 : B->h;
}

static double norm_inf(const double *v, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
  return m;
}

static double scale_of(const Design_set *B, const double *Y)
{
  return fmax(norm_inf(Y, B->N + 1), B->C0);
}

/* ---- (1) the KKT conditions of X = P_B(Y), computed here, not by design.c.
   Feasibility is relative to C0 (area: C0 (b-a)); signs to s = max(|Y|, C0);
   complementarity to s C0; stationarity to the largest term of a row (s or
   a multiplier), since a multiplier that sums the forces along a chain of
   N steps is N times larger than any one of them. */

typedef struct { double feas, sign, comp, stat; } Kkt;

static double area_of(const Design_set *B, const double *X)
{
  double a = 0;
  for (int i = 0; i < B->N; i++) a += B->h * (X[i] + X[i + 1]) / 2;
  return a;
}

static Kkt kkt(const Design_set *B, const double *Y, const double *X,
               const Design_multipliers *m)
{
  int N = B->N;
  double s = scale_of(B, Y), big = s;   /* big: the largest term of a row */
  Kkt k = { 0, 0, 0, 0 };
  for (int i = 0; i <= N; i++) {
    double r = X[i] - Y[i] - m->lower[i] + m->upper[i] + m->mu * w_of(B, i);
    big = fmax(big, fmax(fmax(m->lower[i], m->upper[i]), fabs(m->mu) * B->h));
    if (i < N) r += m->down[i] - m->up[i];
    if (i < N) big = fmax(big, fmax(m->down[i], m->up[i]));
    if (i > 0) r += m->up[i - 1] - m->down[i - 1];
    k.stat = fmax(k.stat, fabs(r));
    k.feas = fmax(k.feas, fmax(-X[i], X[i] - B->C0) / B->C0);
    k.sign = fmax(k.sign, fmax(-m->lower[i], -m->upper[i]) / s);
    k.comp = fmax(k.comp, fmax(m->lower[i] * X[i],
                               m->upper[i] * (B->C0 - X[i])) / (s * B->C0));
  }
  for (int i = 0; i < N; i++) {
    double d = X[i + 1] - X[i];
    k.feas = fmax(k.feas, (fabs(d) - B->delta) / B->C0);
    k.sign = fmax(k.sign, fmax(-m->up[i], -m->down[i]) / s);
    k.comp = fmax(k.comp, fmax(m->up[i] * fabs(B->delta - d),
                               m->down[i] * fabs(B->delta + d)) / (s * B->C0));
  }
  k.feas = fmax(k.feas, fabs(area_of(B, X) - B->area) / (B->C0 * N * B->h));
  k.stat /= big;
  return k;
}

static int kkt_ok(Kkt k, double tol)
{
  return k.feas <= tol && k.sign <= tol && k.comp <= tol && k.stat <= tol;
}

/* project and check the KKT conditions; returns the KKT errors */
static Kkt project_checked(const Design_set *B, const double *Y, double *X,
                           int *rc)
{
  Status st = { 0, "" };
  Design_multipliers *m = design_multipliers_new(B, &st);
  Kkt k = { 1, 1, 1, 1 };
  *rc = design_project(B, Y, X, m, &st);
  if (!*rc) k = kkt(B, Y, X, m);
  design_multipliers_free(m);
  return k;
}

/* ---- (2) brute force over active sets -------------------------------- */

/* Rows of the active set coded by code: node i is free, at 0 or at C0;
   step i is free, at +delta or at -delta; the area is always a row. */
static int active_rows(const Design_set *B, long code, gsl_matrix *At,
                       double *b)
{
  int n = B->N + 1, m = 0;
  gsl_matrix_set_zero(At);
  for (int i = 0; i < n; i++, code /= 3) {
    if (code % 3 == 0) continue;
    if (m == n) return -1;
    gsl_matrix_set(At, i, m, 1);
    b[m++] = code % 3 == 1 ? 0 : B->C0;
  }
  for (int i = 0; i < B->N; i++, code /= 3) {
    if (code % 3 == 0) continue;
    if (m == n) return -1;
    double sgn = code % 3 == 1 ? 1 : -1;
    gsl_matrix_set(At, i + 1, m, sgn);
    gsl_matrix_set(At, i, m, -sgn);
    b[m++] = B->delta;
  }
  if (m == n) return -1;
  for (int i = 0; i < n; i++) gsl_matrix_set(At, i, m, w_of(B, i));
  b[m++] = B->area;
  return m;
}

/* X = Y + A^+ (b - A Y) for A of full row rank m; 0 if rank deficient.
   Vf, Sf, scratchf: room for m = n. */
static int affine_projection(gsl_matrix *At, int m, const double *b,
                             const double *Y, double *X, gsl_matrix *Vf,
                             gsl_vector *Sf, gsl_vector *scratchf)
{
  int n = At->size1;
  gsl_matrix_view U = gsl_matrix_submatrix(At, 0, 0, n, m);
  gsl_matrix_view Vv = gsl_matrix_submatrix(Vf, 0, 0, m, m);
  gsl_vector_view Sv = gsl_vector_subvector(Sf, 0, m);
  gsl_vector_view wv = gsl_vector_subvector(scratchf, 0, m);
  gsl_matrix *V = &Vv.matrix;
  gsl_vector *S = &Sv.vector, *scratch = &wv.vector;
  double r[16], c[16];
  for (int k = 0; k < m; k++) {
    r[k] = b[k];
    for (int i = 0; i < n; i++) r[k] -= gsl_matrix_get(&U.matrix, i, k) * Y[i];
  }
  gsl_linalg_SV_decomp(&U.matrix, V, S, scratch);
  int ok = gsl_vector_get(S, m - 1) > 1e-10 * gsl_vector_get(S, 0);
  for (int k = 0; ok && k < m; k++) {
    c[k] = 0;
    for (int l = 0; l < m; l++) c[k] += gsl_matrix_get(V, l, k) * r[l];
    c[k] /= gsl_vector_get(S, k);
  }
  for (int i = 0; ok && i < n; i++) {
    X[i] = Y[i];
    for (int k = 0; k < m; k++) X[i] += gsl_matrix_get(&U.matrix, i, k) * c[k];
  }
  return ok;
}

static int feasible(const Design_set *B, const double *X, double tol)
{
  for (int i = 0; i <= B->N; i++)
    if (X[i] < -tol || X[i] > B->C0 + tol) return 0;
  for (int i = 0; i < B->N; i++)
    if (fabs(X[i + 1] - X[i]) > B->delta + tol) return 0;
  return fabs(area_of(B, X) - B->area) <= tol * B->N * B->h;
}

static double brute_force(const Design_set *B, const double *Y, double *best)
{
  int n = B->N + 1;
  long total = 1;
  for (int k = 0; k < n + B->N; k++) total *= 3;
  gsl_matrix *At = gsl_matrix_alloc(n, n), *V = gsl_matrix_alloc(n, n);
  gsl_vector *S = gsl_vector_alloc(n), *scratch = gsl_vector_alloc(n);
  double b[16], X[16], dbest = HUGE_VAL, tol = 1e-13 * scale_of(B, Y);
  for (long code = 0; code < total; code++) {
    int m = active_rows(B, code, At, b);
    if (m < 0 || !affine_projection(At, m, b, Y, X, V, S, scratch)
        || !feasible(B, X, tol))
      continue;
    double d = 0;
    for (int i = 0; i < n; i++) d += (X[i] - Y[i]) * (X[i] - Y[i]);
    if (d < dbest) { dbest = d; memcpy(best, X, n * sizeof *X); }
  }
  gsl_matrix_free(At);
  gsl_matrix_free(V);
  gsl_vector_free(S);
  gsl_vector_free(scratch);
  return dbest;
}

/* a random set with every constraint likely to matter, and a random Y */
static Design_set random_case(int N, double *Y)
{
  double C0 = 0.5 + uniform(), width = 1 + 3 * uniform();
  double C1 = uniform() < 0.15 ? 0 : (0.2 + uniform()) * C0 / width * 2;
  double S = uniform() * C0 * width;
  Design_set B = make_set(N, width, C0, C1, S);
  for (int i = 0; i <= N; i++) Y[i] = C0 * (2.6 * uniform() - 0.8);
  return B;
}

/* degenerate on purpose: every number a multiple of 1/8, exact in binary,
   so that C0 is a multiple of delta, Y sits on bounds and on slope bounds,
   and S is often an end of its range */
static Design_set tied_case(int N, double *Y)
{
  Design_set B = { N, 0.25, 1, 0.125 * (1 << (int) (4 * uniform())), 0 };
  B.area = 0.125 * (int) ((2 * N + 1) * uniform());
  for (int i = 0; i <= N; i++) Y[i] = 0.125 * (int) (20 * uniform() - 6);
  return B;
}

static void test_brute_force(int tied)
{
  double Y[16], X[16], R[16];
  for (int N = 1; N <= (tied ? 5 : 6); N++) {
    int cases = N <= 4 ? 40 : N == 5 ? 4 : 1, bad = 0, notkkt = 0, rc;
    double worst = 0;
    for (int t = 0; t < cases; t++) {
      Design_set B = tied ? tied_case(N, Y) : random_case(N, Y);
      Kkt k = project_checked(&B, Y, X, &rc);
      brute_force(&B, Y, R);
      double e = 0;
      for (int i = 0; i <= N; i++) e = fmax(e, fabs(X[i] - R[i]));
      e /= scale_of(&B, Y);
      worst = fmax(worst, e);
      bad += rc != 0 || e > 1e-12;
      notkkt += !kkt_ok(k, 1e-12);
    }
    check(bad == 0, "N = %d: %d %s projections onto B (4.4) equal the brute-force "
          "least distance over all active sets (worst %.1e relative)",
          N, cases, tied ? "tied" : "random", worst);
    check(notkkt == 0, "N = %d: their multipliers satisfy the KKT conditions of B (4.4) "
          "to 1e-12", N);
  }
}

/* ---- (3) properties of a projection ---------------------------------- */

static void test_properties(void)
{
  enum { N = 64, n = N + 1 };
  double Y[n], Y2[n], X[n], X2[n], XX[n];
  Status st = { 0, "" };
  int idem = 1, nonexp = 1, alias = 1;
  double fixed = 0;
  for (int t = 0; t < 200; t++) {
    Design_set B = random_case(N, Y);
    for (int i = 0; i < n; i++) Y2[i] = Y[i] + B.C0 * (uniform() - 0.5);
    design_project(&B, Y, X, NULL, &st);
    design_project(&B, Y2, X2, NULL, &st);
    design_project(&B, X, XX, NULL, &st);
    double d = 0, dy = 0, dx = 0;
    for (int i = 0; i < n; i++) {
      d = fmax(d, fabs(XX[i] - X[i]));
      dy += (Y[i] - Y2[i]) * (Y[i] - Y2[i]);
      dx += (X[i] - X2[i]) * (X[i] - X2[i]);
    }
    idem &= d <= 1e-13 * scale_of(&B, Y);
    nonexp &= sqrt(dx) <= sqrt(dy) * (1 + 1e-12);
    memcpy(XX, Y, sizeof Y);
    design_project(&B, XX, XX, NULL, &st);
    alias &= !memcmp(XX, X, sizeof X);
    for (int i = 0; i < n; i++) XX[i] = B.area / (N * B.h);
    design_project(&B, XX, X2, NULL, &st);
    for (int i = 0; i < n; i++) fixed = fmax(fixed, fabs(X2[i] - XX[i]) / B.C0);
  }
  check(fixed <= 1e-14, "P(X) = X for the constant X = S/(b-a) in B (4.4) (200 sets, "
        "N = 64; worst %.1e relative to C0)", fixed);
  check(idem, "P(P(Y)) = P(Y) to 1e-13 (200 random Y)");
  check(nonexp, "||P(Y1) - P(Y2)|| <= ||Y1 - Y2|| (200 random pairs)");
  check(alias, "X may alias Y: the same result, bit for bit");
}

/* ---- (4) Example 5.1 -------------------------------------------------- */

static void test_example_51(void)
{
  Problem p;
  memset(&p, 0, sizeof p);
  p.a = 0; p.b = 4; p.gamma = 1; p.N = 16;
  p.C0 = 0.05; p.C1 = 0.025; p.C2 = 3.91;
  Design_set B = design_set(&p);
  check(B.N == 16 && B.h == 0.25 && B.C0 == 0.05
        && fabs(B.delta - 0.00625) < 1e-18 && fabs(B.area - 0.09) < 1e-15,
        "design_set of Example 5.1: N = 16, "
        "h = 0.25, delta = C1 h = 0.00625, S = 0.09 (%.17g)", B.area);
  double Y[17], X[17], R1 = 160.025;
  for (int i = 0; i <= 16; i++) {
    double x = 0.25 * i;
    Y[i] = R1 - sqrt(R1 * R1 - (x - 4) * (x - 4));
  }
  check(fabs(area_of(&B, Y) - 0.0667) < 1e-3 && design_violation(&B, Y) > 0.1,
        "the arc of Example 5.1 has area %.6f, not 0.09: not in B (4.4)",
        area_of(&B, Y));
  int rc;
  Kkt k = project_checked(&B, Y, X, &rc);
  check(rc == 0 && kkt_ok(k, 1e-12), "its projection onto B (4.4) satisfies the KKT "
        "conditions (feas %.1e, sign %.1e, comp %.1e, stat %.1e)",
        k.feas, k.sign, k.comp, k.stat);
  check(fabs(design_area(&B, X) - 0.09) <= 1e-12
        && design_violation(&B, X) <= 1e-12,
        "its projection is in B (4.4), with area 0.09 (%.17g)", design_area(&B, X));
  check(X[0] == 0.05 && X[16] > 0, "the projection keeps alpha_0 = C0 and "
        "lifts alpha_16 off the foundation (%.6f)", X[16]);
}

/* ---- (5) N = 1024 ------------------------------------------------------ */

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void test_large(void)
{
  enum { N = 1024, n = N + 1, reps = 20 };
  static double Y[n], X[n], G[n];
  int rc, ok = 1;
  Kkt worst = { 0, 0, 0, 0 };
  double seconds = 0;
  Design_set B = make_set(N, 4, 0.05, 0.025, 0.09);
  for (int t = 0; t < reps; t++) {
    for (int i = 0; i < n; i++)
      Y[i] = 0.05 * (0.5 + 0.8 * sin(0.02 * i * (1 + t))
                     + 0.4 * (uniform() - 0.5));
    double t0 = now();
    Kkt k = project_checked(&B, Y, X, &rc);
    seconds += now() - t0;
    ok &= rc == 0 && kkt_ok(k, 1e-12);
    worst.feas = fmax(worst.feas, k.feas);
    worst.sign = fmax(worst.sign, k.sign);
    worst.comp = fmax(worst.comp, k.comp);
    worst.stat = fmax(worst.stat, k.stat);
  }
  check(ok, "N = 1024, %d random Y: feasible and KKT to 1e-12 (feas %.1e, sign "
        "%.1e, comp %.1e, stat %.1e)", reps, worst.feas, worst.sign,
        worst.comp, worst.stat);
  printf("# N = 1024: design_project with multipliers %.3f ms per call\n",
         1e3 * seconds / reps);
  Status st = { 0, "" };
  double r, t0 = now();
  for (int i = 0; i < n; i++) G[i] = cos(0.01 * i);
  for (int t = 0; t < reps; t++) design_kkt(&B, X, G, 0, NULL, NULL, &r, &st);
  printf("# N = 1024: design_kkt %.3f ms per call\n",
         1e3 * (now() - t0) / reps);
}

/* ---- (6) degenerate and empty sets ------------------------------------ */

static void test_degenerate(void)
{
  enum { N = 10, n = N + 1 };
  double Y[n], X[n];
  int rc;
  for (int i = 0; i < n; i++) Y[i] = 0.05 * (2 * uniform() - 0.5);
  Design_set B = make_set(N, 4, 0.05, 0, 0.07);
  Kkt k = project_checked(&B, Y, X, &rc);
  double e = 0;
  for (int i = 0; i < n; i++) e = fmax(e, fabs(X[i] - 0.07 / 4));
  check(rc == 0 && e <= 1e-15 && kkt_ok(k, 1e-12), "C1 = 0: X = S/(b-a) "
        "(error %.1e), KKT to 1e-12", e);
  B = make_set(N, 4, 0.05, 0.025, 0);
  k = project_checked(&B, Y, X, &rc);
  check(rc == 0 && norm_inf(X, n) == 0 && kkt_ok(k, 1e-12),
        "S = 0: X = 0 exactly, KKT to 1e-12");
  B = make_set(N, 4, 0.05, 0.025, 0.05 * (N * B.h));
  k = project_checked(&B, Y, X, &rc);
  e = 0;
  for (int i = 0; i < n; i++) e = fmax(e, fabs(X[i] - 0.05));
  check(rc == 0 && e == 0 && kkt_ok(k, 1e-12),
        "S = C0 (b-a): X = C0 exactly, KKT to 1e-12");
}

static void test_errors(void)
{
  enum { N = 8, n = N + 1 };
  double Y[n], X[n], G[n], r;
  Status st = { 0, "" };
  for (int i = 0; i < n; i++) { Y[i] = 0.01; X[i] = -7; G[i] = 1; }
  Design_set B = make_set(N, 4, 0.05, 0.025, -1e-9);
  int rc = design_project(&B, Y, X, NULL, &st);
  check(rc == STATUS_INPUT && strstr(st.msg, "empty") && X[0] == -7,
        "S < 0: STATUS_INPUT, X untouched (%s)", st.msg);
  B.area = 0.2 * (1 + 1e-12);
  rc = design_project(&B, Y, X, NULL, &st);
  check(rc == STATUS_INPUT && strstr(st.msg, "empty") && X[0] == -7,
        "S > C0 (b-a): STATUS_INPUT (%s)", st.msg);
  B.area = 0.2 * (1 + 1e-15);
  rc = design_project(&B, Y, X, NULL, &st);
  check(rc == 0 && X[0] == 0.05 && X[N] == 0.05, "S = C0 (b-a) (1 + 1e-15), "
        "within rounding of the end: X = C0");
  X[0] = -7;
  Design_set good = make_set(N, 4, 0.05, 0.025, 0.09), bad = good;
  bad.N = 0;
  check(design_project(&bad, Y, X, NULL, &st) == STATUS_INPUT,
        "N = 0: STATUS_INPUT (%s)", st.msg);
  bad = good; bad.C0 = 0;
  check(design_project(&bad, Y, X, NULL, &st) == STATUS_INPUT,
        "C0 = 0: STATUS_INPUT (%s)", st.msg);
  bad = good; bad.delta = -1;
  check(design_project(&bad, Y, X, NULL, &st) == STATUS_INPUT,
        "delta < 0: STATUS_INPUT (%s)", st.msg);
  bad = good; bad.h = NAN;
  check(design_project(&bad, Y, X, NULL, &st) == STATUS_INPUT,
        "h = NaN: STATUS_INPUT (%s)", st.msg);
  Y[3] = NAN;
  check(design_project(&good, Y, X, NULL, &st) == STATUS_NUMERIC && X[0] == -7,
        "a NaN in Y: STATUS_NUMERIC, X untouched (%s)", st.msg);
  Y[3] = 0.01;
  Design_set other = make_set(N + 1, 4, 0.05, 0.025, 0.09);
  Design_multipliers *m = design_multipliers_new(&other, &st);
  check(design_project(&good, Y, X, m, &st) == STATUS_INPUT,
        "multipliers of another N: STATUS_INPUT (%s)", st.msg);
  design_multipliers_free(m);
  check(design_multipliers_new(&bad, &st) == NULL,
        "multipliers of an invalid set: refused (%s)", st.msg);
  G[2] = INFINITY;
  check(design_kkt(&good, Y, G, 0, NULL, NULL, &r, &st) == STATUS_NUMERIC,
        "design_kkt with an infinite gradient: STATUS_NUMERIC (%s)", st.msg);
  B = make_set(N, 4, 0.05, 0.025, 0.3);
  check(design_kkt(&B, Y, Y, 0, NULL, NULL, &r, &st) == STATUS_INPUT,
        "design_kkt on an empty set: STATUS_INPUT (%s)", st.msg);
}

/* ---- (7) the stationarity measure of the shape problem ---------------- */

/* ||G + J' lambda||_inf with the multipliers of design_kkt */
static double nlp_stationarity(const Design_set *B, const double *G,
                               const Design_multipliers *m)
{
  double e = 0;
  for (int i = 0; i <= B->N; i++) {
    double r = G[i] - m->lower[i] + m->upper[i] + m->mu * w_of(B, i);
    if (i < B->N) r += m->down[i] - m->up[i];
    if (i > 0) r += m->up[i - 1] - m->down[i - 1];
    e = fmax(e, fabs(r));
  }
  return e;
}

static void test_kkt(void)
{
  enum { N = 32, n = N + 1 };
  double X[n], G[n], P[n], Y[n], r, r2;
  Status st = { 0, "" };
  Design_set B = make_set(N, 4, 0.05, 0.025, 0.09);
  Design_multipliers *m = design_multipliers_new(&B, &st);
  for (int i = 0; i < n; i++) { X[i] = 0.09 / 4; G[i] = 1e9 * w_of(&B, i); }
  int rc = design_kkt(&B, X, G, 0, P, m, &r, &st);
  check(rc == 0 && r <= 1e-15 * norm_inf(G, n) && fabs(m->mu + 1e9) <= 1e-6,
        "G = 1e9 w (the area normal) at an interior X: stationary on B (4.4), residual "
        "%.1e, mu = %.15g", r, m->mu);
  for (int i = 0; i < n; i++) G[i] = i == 7 ? -1 : 0;
  rc = design_kkt(&B, X, G, 0, P, m, &r, &st);
  check(rc == 0 && r > 0.1 && nlp_stationarity(&B, G, m) <= r * (1 + 1e-12),
        "G = -e_7 at the same X: not stationary, residual %.3g = ||G + J'l||",
        r);
  for (int i = 0; i < n; i++) G[i] = 0;
  rc = design_kkt(&B, X, G, 0, P, m, &r, &st);
  check(rc == 0 && r == 0, "G = 0: residual 0");
  B = random_case(N, Y);
  design_project(&B, Y, X, NULL, &st);
  for (int i = 0; i < n; i++) G[i] = 3e10 * (X[i] - Y[i]);
  rc = design_kkt(&B, X, G, 0, P, m, &r, &st);
  double s = nlp_stationarity(&B, G, m);
  check(rc == 0 && r <= 1e-12 * norm_inf(G, n) && s <= 1e-12 * norm_inf(G, n),
        "X = P_B(Y), G = 3e10 (X - Y): residual %.1e, ||G + J'l|| %.1e "
        "(relative to ||G||)", r / norm_inf(G, n), s / norm_inf(G, n));
  for (int i = 0; i < n; i++) { X[i] = B.area / (N * B.h); G[i] = sin(i); }
  design_kkt(&B, X, G, 0, NULL, NULL, &r, &st);
  for (int i = 0; i < n; i++) G[i] *= 1e-7;
  design_kkt(&B, X, G, 0, NULL, NULL, &r2, &st);
  check(fabs(r2 / 1e-7 - r) <= 1e-12 * r, "the default step is scale-free: "
        "residual(1e-7 G) = 1e-7 residual(G) (%.15g, %.15g)", r, r2 / 1e-7);
  design_kkt(&B, X, G, 0, P, m, &r, &st);
  check(nlp_stationarity(&B, G, m) <= r * (1 + 1e-12) + 1e-15,
        "its multipliers have ||G + J'l|| = residual (%.3g, %.3g)",
        nlp_stationarity(&B, G, m), r);
  design_multipliers_free(m);
}

/* ---- (8) the feasible start ------------------------------------------- */

static void test_feasible_start(void)
{
  Design_set B = make_set(16, 4, 0.05, 0.025, 0.09);
  double Y[17], X[17], P[17], v = -1, moved = -1, d2 = 0, R1 = 160.025;
  for (int i = 0; i <= 16; i++)
    Y[i] = R1 - sqrt(R1 * R1 - (0.25 * i - 4) * (0.25 * i - 4));
  int rc = design_feasible_start(&B, Y, 1e-12, X, &v, &moved, NULL);
  design_project(&B, Y, P, NULL, NULL);
  for (int i = 0; i <= 16; i++) d2 += (P[i] - Y[i]) * (P[i] - Y[i]);
  check(rc == 0 && !memcmp(X, P, sizeof X) && v == design_violation(&B, Y)
        && moved == sqrt(d2) && moved > 0.02,
        "feasible start: Example 5.1's arc (violation %.3g) moves to its "
        "projection, bit for bit, by %.6g m", v, moved);
  memcpy(Y, P, sizeof Y);
  v = design_violation(&B, Y);
  rc = design_feasible_start(&B, Y, v, X, NULL, &moved, NULL);
  check(rc == 0 && !memcmp(X, Y, sizeof X) && moved == 0,
        "feasible start: a point of B (4.4) (violation %.1e = tol) is kept, bit "
        "for bit, moved 0", v);
  Y[3] += 1e-3;
  v = design_violation(&B, Y);
  rc = design_feasible_start(&B, Y, 0.99 * v, X, NULL, &moved, NULL);
  check(rc == 0 && design_violation(&B, X) <= 1e-12 && moved > 0,
        "feasible start: a violation %.2e above the tolerance moves the "
        "start into B (by %.3g m)", v, moved);
  Status st;
  double keep = X[0];
  check(design_feasible_start(&B, Y, -1, X, NULL, NULL, &st) == STATUS_INPUT
        && X[0] == keep, "feasible start: a negative tolerance is refused, "
        "X not written: %s", st.msg);
  check(design_feasible_start(&B, Y, NAN, X, NULL, NULL, &st) == STATUS_INPUT,
        "feasible start: a NaN tolerance is refused: %s", st.msg);
  check(design_feasible_start(&B, Y, 0, Y, NULL, NULL, &st) == STATUS_INPUT,
        "feasible start: X aliasing alpha0 is refused: %s", st.msg);
  Y[5] = NAN;
  check(design_feasible_start(&B, Y, 0, X, NULL, NULL, &st) == STATUS_NUMERIC,
        "feasible start: a NaN in alpha0 is refused: %s", st.msg);
  Y[5] = 0.01;
  B.area = 1;
  check(design_feasible_start(&B, Y, 0, X, NULL, NULL, &st) == STATUS_INPUT,
        "feasible start: an empty B is refused: %s", st.msg);
}

/* the linear interpolation of a design of B onto the mesh refined by 2
   (opt_interpolate, the coarse-to-fine start of paper/opt.nw) stays in B:
   the bounds, the slope bound C1 h of the finer mesh, the area */
static void test_interpolation(void)
{
  Design_set B = make_set(16, 4, 0.05, 0.025, 0.09), F = make_set(32, 4, 0.05, 0.025, 0.09);
  double Y[17], X[33], worst = 0, area = 0, slope = 0;
  int inside = 1;
  srand(27);
  for (int t = 0; t < 200; t++) {
    for (int i = 0; i <= 16; i++)
      Y[i] = t == 0 ? 160.025 - sqrt(160.025 * 160.025 - (0.25 * i - 4) * (0.25 * i - 4))
                    : -0.05 + 0.15 * rand() / (double) RAND_MAX;
    design_project(&B, Y, X, NULL, NULL);
    double a = design_area(&B, X);
    opt_interpolate(X, 16);
    for (int i = 0; i <= 32; i++) inside &= X[i] >= 0 && X[i] <= F.C0;
    for (int i = 0; i < 32; i++) slope = fmax(slope, fabs(X[i + 1] - X[i]) / F.delta);
    area = fmax(area, fabs(design_area(&F, X) - a) / a);
    worst = fmax(worst, design_violation(&F, X));
  }
  check(inside && slope <= 1 + 1e-12 && area <= 1e-14 && worst <= 1e-12,
        "interpolation onto the mesh refined by 2 stays in B (4.4): 200 designs, bounds "
        "kept, slope at most %.15g of C1 h, area kept to %.1e, violation %.1e", slope, area, worst);
}

int main(void)
{
  test_brute_force(0);
  test_brute_force(1);
  test_properties();
  test_example_51();
  test_large();
  test_degenerate();
  test_errors();
  test_kkt();
  test_feasible_start();
  test_interpolation();
  return check_done();
}
