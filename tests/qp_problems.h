/* qp_problems.h: small bound-constrained QPs of the form of the state
   problem (4.3), min 1/2 x'Ax - b'x, x[ic] >= lo, built with
   cholmod_triplet, and the checks that every state solver passes on them
   (tests/test_qp.c, test_pdas.c, test_psor.c, test_cgssor.c):
   (a) 1D obstacle problems, (b) a semidefinite 1D Neumann problem held only
   by the bounds, (c) 2D grid Laplacians with mixed contact, (d) a small
   elastic body of Example 5.1 (not an M-matrix).  The reference
   for the tiny ones enumerates every active set and solves each linear
   system with GSL's Cholesky factorisation: independent of the solvers. */
#ifndef CONTACTOPT_TEST_QP_PROBLEMS_H
#define CONTACTOPT_TEST_QP_PROBLEMS_H
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "sparse.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "qp.h"

#define TOL 1e-10

/* a test problem: dense copy for the reference, sparse for the solvers */
typedef struct {
  const char *name;
  int n, nc;
  double *D;          /* n*n, row major: the dense A */
  double *b, *lo;     /* n, nc */
  int *ic;            /* nc */
  cholmod_sparse *A;
  Qp qp;
} Qp_problem;

static cholmod_common cm;
static const Qp_method methods[3] = { QP_PDAS, QP_PSOR, QP_CGSSOR };
static const char *names[3] = { "pdas", "psor", "cgssor" };

/* ---- building problems ---------------------------------------------------- */

static inline Qp_problem *problem_new(const char *name, int n, int nc)
{
  Qp_problem *P = calloc(1, sizeof *P);
  P->name = name, P->n = n, P->nc = nc;
  P->D = calloc((size_t) n * n, sizeof *P->D);
  P->b = calloc(n, sizeof *P->b);
  P->lo = calloc(nc + 1, sizeof *P->lo);
  P->ic = calloc(nc + 1, sizeof *P->ic);
  return P;
}

/* the sparse A of the dense one, both triangles, via a triplet matrix */
static inline void problem_finish(Qp_problem *P)
{
  int n = P->n, k = 0;
  cholmod_triplet *t = cholmod_l_allocate_triplet(n, n, (size_t) n * n, 0,
                                                CHOLMOD_REAL, &cm);
  Sparse_index *ti = t->i, *tj = t->j;
  double *tx = t->x;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      if (P->D[i * n + j] != 0 || i == j)
        ti[k] = i, tj[k] = j, tx[k] = P->D[i * n + j], k++;
  t->nnz = k;
  P->A = cholmod_l_triplet_to_sparse(t, k, &cm);
  cholmod_l_free_triplet(&t, &cm);
  P->qp = (Qp) { P->A, P->b, P->nc, P->ic, P->lo, 0, NULL, NULL, 0 };
}

static inline void problem_free(Qp_problem *P)
{
  cholmod_l_free_sparse(&P->A, &cm);
  free(P->D), free(P->b), free(P->lo), free(P->ic), free(P);
}

/* add k * (e_i - e_j)(e_i - e_j)' to D; j < 0: k e_i e_i' (a spring to 0) */
static inline void spring(Qp_problem *P, int i, int j, double k)
{
  int n = P->n;
  P->D[i * n + i] += k;
  if (j < 0) return;
  P->D[j * n + j] += k;
  P->D[i * n + j] -= k, P->D[j * n + i] -= k;
}

/* (a) -u'' = -f on (0,1), u(0) = u(1) = 0, u >= psi at every "every"-th node */
static inline Qp_problem *obstacle_1d(const char *name, int n, int every)
{
  Qp_problem *P = problem_new(name, n, (n + every - 1) / every);
  double h = 1.0 / (n + 1);
  for (int i = 0; i < n; i++) {
    spring(P, i, i + 1 < n ? i + 1 : -1, 1 / h);
    if (i == 0) spring(P, 0, -1, 1 / h);
    P->b[i] = -10 * h;
  }
  for (int c = 0; c < P->nc; c++) {
    double x = (c * every + 1) * h;
    P->ic[c] = c * every;
    P->lo[c] = -0.3 + (x - 0.5) * (x - 0.5);
  }
  problem_finish(P);
  return P;
}

/* (b) a free 1D chain (A singular: constants) held only by 3 bounds;
   up = 1: the load lifts it off and nothing holds it */
static inline Qp_problem *neumann_1d(const char *name, int up, double k)
{
  static const int ic[3] = { 1, 4, 8 };
  static const double lo[3] = { -0.5, -0.05, -0.12 };
  Qp_problem *P = problem_new(name, 10, 3);
  for (int i = 0; i + 1 < 10; i++) spring(P, i, i + 1, k);
  for (int i = 0; i < 10; i++) P->b[i] = (up ? 1 : -1) * (1 + i % 3) * 0.01;
  memcpy(P->ic, ic, sizeof ic), memcpy(P->lo, lo, sizeof lo);
  problem_finish(P);
  return P;
}

/* (c) a membrane on an nx x ny grid, held above its top row, resting with
   its bottom row on a curved obstacle, under a uniform downward load;
   loose = 1: not held above (A singular), and the load lifts it off */
static inline Qp_problem *grid_2d(const char *name, int nx, int ny, int loose)
{
  Qp_problem *P = problem_new(name, nx * ny, nx);
  for (int j = 0; j < ny; j++)
    for (int i = 0; i < nx; i++) {
      int v = j * nx + i;
      if (i + 1 < nx) spring(P, v, v + 1, 1);
      if (j + 1 < ny) spring(P, v, v + nx, 1);
      else if (!loose) spring(P, v, -1, 1);
      P->b[v] = (loose ? 0.3 : -1.25) / (ny * ny);
    }
  for (int c = 0; c < nx; c++) {
    double s = (c + 0.5) / nx - 0.5;
    P->ic[c] = c, P->lo[c] = -0.4 + 2 * s * s;
  }
  problem_finish(P);
  return P;
}

/* (d) the elastic body of Example 5.1 on N x ny cells cut by diagonals:
   plane stress, E = 2.15e11, nu = 0.29, x1 in (0,4), clamped at x1 = 0,
   u1 = 0 at x1 = 4, P2 = -5.75e8 on the top for x1 in (2,4), the bottom on
   the arc alpha(x1) = R1 - sqrt(R1^2 - (x1-4)^2) above the foundation:
   u2 >= -alpha at the N bottom nodes that are not clamped */
static inline void element(const double *xy, const int *v, double K[6][6])
{
  const double E = 2.15e11, nu = 0.29, f = E / (1 - nu * nu);
  const double D[3][3] = { { f, f * nu, 0 }, { f * nu, f, 0 }, { 0, 0, f * (1 - nu) / 2 } };
  double x[3], y[3];
  for (int a = 0; a < 3; a++) x[a] = xy[2 * v[a]], y[a] = xy[2 * v[a] + 1];
  double A2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  double B[3][6] = { { y[1] - y[2], 0, y[2] - y[0], 0, y[0] - y[1], 0 },
                     { 0, x[2] - x[1], 0, x[0] - x[2], 0, x[1] - x[0] },
                     { x[2] - x[1], y[1] - y[2], x[0] - x[2], y[2] - y[0],
                       x[1] - x[0], y[0] - y[1] } };
  for (int a = 0; a < 6; a++)
    for (int b = a; b < 6; b++) {
      double s = 0;
      for (int p = 0; p < 3; p++)
        for (int r = 0; r < 3; r++) s += B[p][a] * D[p][r] * B[r][b];
      K[a][b] = K[b][a] = s / (2 * A2);
    }
}

static inline Qp_problem *elastic_2d(const char *name, int N, int ny)
{
  int nn = (N + 1) * (ny + 1), n = 0, *u = malloc(2 * nn * sizeof *u);
  double *xy = malloc(2 * nn * sizeof *xy), R1 = 160.025;
  for (int v = 0; v < nn; v++) {
    int i = v % (N + 1), j = v / (N + 1);
    double x1 = 4.0 * i / N, al = R1 - sqrt(R1 * R1 - (x1 - 4) * (x1 - 4));
    xy[2 * v] = x1, xy[2 * v + 1] = al + (1 - al) * j / ny;
    u[2 * v] = i == 0 || i == N ? -1 : n++;
    u[2 * v + 1] = i == 0 ? -1 : n++;
  }
  Qp_problem *P = problem_new(name, n, N);
  for (int j = 0; j < ny; j++)
    for (int i = 0; i < N; i++) {
      int v0 = j * (N + 1) + i;
      int tri[2][3] = { { v0, v0 + 1, v0 + N + 2 }, { v0, v0 + N + 2, v0 + N + 1 } };
      for (int e = 0; e < 2; e++) {
        double K[6][6];
        element(xy, tri[e], K);
        for (int a = 0; a < 6; a++)
          for (int b = 0; b < 6; b++) {
            int ua = u[2 * tri[e][a / 2] + a % 2], ub = u[2 * tri[e][b / 2] + b % 2];
            if (ua >= 0 && ub >= 0) P->D[ua * n + ub] += K[a][b];
          }
      }
    }
  for (int i = N / 2; i < N; i++)                 /* the load on (2,4) */
    for (int s = 0; s < 2; s++)
      P->b[u[2 * (ny * (N + 1) + i + s) + 1]] += -5.75e8 * (4.0 / N) / 2;
  for (int c = 0; c < N; c++)
    P->ic[c] = u[2 * (c + 1) + 1], P->lo[c] = -xy[2 * (c + 1) + 1];
  problem_finish(P);
  free(u), free(xy);
  return P;
}

/* ---- the independent reference: enumerate active sets --------------------- */

/* solve with the bounds in mask active; 1 if the result satisfies KKT */
static inline int try_active_set(const Qp_problem *P, unsigned mask, double *x)
{
  int n = P->n, ok = 1;
  gsl_matrix *M = gsl_matrix_alloc(n, n);
  gsl_vector *r = gsl_vector_alloc(n), *y = gsl_vector_alloc(n);
  char *act = calloc(n, 1);
  for (int c = 0; c < P->nc; c++) act[P->ic[c]] = (mask >> c) & 1;
  for (int i = 0, c = 0; i < n; i++) {
    double rhs = P->b[i];
    for (int j = 0; j < n; j++) {
      double a = P->D[i * n + j];
      gsl_matrix_set(M, i, j, act[i] || act[j] ? (i == j) : a);
      if (act[j] && !act[i]) {
        int cj = 0;
        while (P->ic[cj] != j) cj++;
        rhs -= a * P->lo[cj];
      }
    }
    if (act[i]) { while (P->ic[c] != i) c++; rhs = P->lo[c]; }
    gsl_vector_set(r, i, rhs);
  }
  ok = gsl_linalg_cholesky_decomp1(M) == GSL_SUCCESS
       && gsl_linalg_cholesky_solve(M, r, y) == GSL_SUCCESS;
  for (int i = 0; ok && i < n; i++) x[i] = gsl_vector_get(y, i);
  for (int i = 0, c = 0; ok && i < n; i++) {   /* the KKT conditions, densely */
    double ri = -P->b[i], scale = fabs(P->b[i]);
    for (int j = 0; j < n; j++)
      ri += P->D[i * n + j] * x[j], scale += fabs(P->D[i * n + j] * x[j]);
    int bounded = c < P->nc && P->ic[c] == i;
    if (!bounded || !act[i]) ok = fabs(ri) <= 1e-9 * scale;
    if (bounded && act[i]) ok = ri >= -1e-9 * scale;
    if (bounded && !act[i]) ok = ok && x[i] >= P->lo[c] - 1e-12;
    c += bounded;
  }
  gsl_matrix_free(M), gsl_vector_free(r), gsl_vector_free(y), free(act);
  return ok;
}

/* the solution by enumeration (nc <= 12); 0 if no active set satisfies KKT */
static inline int reference(const Qp_problem *P, double *x)
{
  for (unsigned mask = 0; mask < (1u << P->nc); mask++)
    if (try_active_set(P, mask, x)) return 1;
  return 0;
}

/* ---- running the solvers ---------------------------------------------------- */

typedef struct {
  int code;
  Qp_report rep;
  Status st;
} Run;

static inline Qp_options options(Qp_method m)
{
  Qp_options o = { m, TOL, 100000, 1.5 };
  return o;
}

/* one cold (x0 NULL) or warm solve in a fresh workspace */
static inline Run run(const Qp_problem *P, Qp_options o, const double *x0, double *x,
               double *T)
{
  Run r = { 0, { 0, 0, 0, 0 }, { STATUS_OK, "" } };
  Qp_workspace *w = qp_alloc(&P->qp, &o, &cm, &r.st);
  if (!w) { r.code = r.st.code; return r; }
  r.code = qp_solve(w, x0, x, T, &r.rep, &r.st);
  qp_free(w);
  return r;
}

static inline double rel_diff(int n, const double *u, const double *v)
{
  double d = 0, s = 0;
  for (int i = 0; i < n; i++) d = fmax(d, fabs(u[i] - v[i])), s = fmax(s, fabs(v[i]));
  return d / (s > 0 ? s : 1);
}

static inline int count_touching(const Qp_problem *P, const double *x)
{
  int m = 0;
  for (int c = 0; c < P->nc; c++) m += x[P->ic[c]] <= P->lo[c] + 1e-9;
  return m;
}

static inline int has(const char *msg, const char *what) { return strstr(msg, what) != NULL; }

static inline int all_finite(int n, const double *x)
{
  for (int i = 0; i < n; i++) if (!isfinite(x[i])) return 0;
  return 1;
}

/* the six problems every method solves */
static inline void problems_new(Qp_problem *P[6])
{
  P[0] = obstacle_1d("obstacle 1D, all bounded", 12, 1);
  P[1] = obstacle_1d("obstacle 1D, every 3rd bounded", 30, 3);
  P[2] = neumann_1d("neumann 1D (semidefinite)", 0, 1);
  P[3] = grid_2d("grid 8x5", 8, 5, 0);
  P[4] = elastic_2d("elastic body 10x3", 10, 3);
  P[5] = grid_2d("grid 30x20", 30, 20, 0);
}

static inline void problems_free(Qp_problem *P[6])
{
  for (int k = 0; k < 6; k++) problem_free(P[k]);
}

/* ---- the checks of one method m (0 pdas, 1 psor, 2 cgssor) ---------------- */

/* method m against the reference xr (or, if NULL, against pdas: for m = 0
   against its own solution, as it was when the three ran in one loop) */
static inline void check_solver(const Qp_problem *P, const double *xr, int m)
{
  int n = P->n;
  double *x = malloc(n * sizeof *x), *T = malloc((P->nc + 1) * sizeof *T);
  double *x0 = malloc(n * sizeof *x0);
  if (!xr && m != 0) {                     /* pdas's solution, the reference */
    run(P, options(QP_PDAS), NULL, x0, T);
    xr = x0;
  }
  Run r = run(P, options(methods[m]), NULL, x, T);
  check(r.code == STATUS_OK && r.rep.converged && r.rep.kkt <= TOL,
        "%s %s: converged in %d iterations, kkt %.2g, %d of %d bounds active%s",
        P->name, names[m], r.rep.iterations, r.rep.kkt, r.rep.active, P->nc,
        r.st.msg);
  check(qp_kkt(&P->qp, x, NULL) <= TOL, "%s %s: recomputed kkt %.2g <= tol (4.3)",
        P->name, names[m], qp_kkt(&P->qp, x, NULL));
  if (m == 0 && !xr) memcpy(x0, x, n * sizeof *x), xr = x0;
  check(rel_diff(n, x, xr) < 1e-7, "%s %s: x of (4.3) agrees with %s to %.2g",
        P->name, names[m], xr == x0 ? "pdas" : "the enumeration",
        rel_diff(n, x, xr));
  free(x), free(T), free(x0);
}

/* method m on the five small problems against the enumeration, and on the
   large one against pdas */
static inline void check_solvers(Qp_problem *P[6], int m)
{
  for (int k = 0; k < 5; k++) {
    double *xr = malloc(P[k]->n * sizeof *xr);
    if (reference(P[k], xr)) check_solver(P[k], xr, m);
    free(xr);
  }
  check_solver(P[5], NULL, m);
}

/* ---- invariance and warm starts ------------------------------------------- */

/* A and b times s leave x and the iteration count of method m unchanged */
static inline void check_scaling(Qp_problem *P, int m)
{
  int n = P->n, nz = ((Sparse_index *) P->A->p)[n];
  double *x0 = malloc(n * sizeof *x0), *x = malloc(n * sizeof *x);
  double *Ax0 = malloc(nz * sizeof *Ax0), *b0 = malloc(n * sizeof *b0);
  double *Ax = P->A->x, scales[2] = { 2.15e11, 1e-9 };
  memcpy(Ax0, Ax, nz * sizeof *Ax), memcpy(b0, P->b, n * sizeof *b0);
  Run r0 = run(P, options(methods[m]), NULL, x0, NULL);
  for (int s = 0; s < 2; s++) {
    for (int k = 0; k < nz; k++) Ax[k] = scales[s] * Ax0[k];
    for (int i = 0; i < n; i++) P->b[i] = scales[s] * b0[i];
    Run r = run(P, options(methods[m]), NULL, x, NULL);
    check(r.code == STATUS_OK && r.rep.iterations == r0.rep.iterations
          && rel_diff(n, x, x0) < 1e-9, "%s %s: A, b times %g: %d iterations "
          "as unscaled (%d), x the same to %.2g", P->name, names[m], scales[s],
          r.rep.iterations, r0.rep.iterations, rel_diff(n, x, x0));
    memcpy(Ax, Ax0, nz * sizeof *Ax), memcpy(P->b, b0, n * sizeof *b0);
  }
  free(x0), free(x), free(Ax0), free(b0);
}

/* a warm start from the solution converges at once; after new values of A
   and b, qp_set re-reads them: a warm re-solve in the same workspace
   agrees with a cold solve in a fresh one */
static inline void check_warm(Qp_problem *P, int m)
{
  int n = P->n, nz = ((Sparse_index *) P->A->p)[n];
  double *x = malloc(n * sizeof *x), *x2 = malloc(n * sizeof *x2);
  double *x3 = malloc(n * sizeof *x3), *Ax = P->A->x;
  double *Ax0 = malloc(nz * sizeof *Ax0), *b0 = malloc(n * sizeof *b0);
  memcpy(Ax0, Ax, nz * sizeof *Ax), memcpy(b0, P->b, n * sizeof *b0);
  Qp_options o = options(methods[m]);
  Status st = { STATUS_OK, "" };
  Qp_report r1, r2;
  Qp_workspace *w = qp_alloc(&P->qp, &o, &cm, &st);
  int code = qp_solve(w, NULL, x, NULL, &r1, &st);
  code |= qp_solve(w, x, x2, NULL, &r2, &st);
  check(!code && r2.iterations <= 1 && rel_diff(n, x2, x) < 1e-12,
        "%s %s: warm start from the solution: %d iterations (cold: %d)",
        P->name, names[m], r2.iterations, r1.iterations);
  for (int j = 0; j < n; j++)            /* stiffer diagonal, more load */
    for (Sparse_index k = ((Sparse_index *) P->A->p)[j]; k < ((Sparse_index *) P->A->p)[j + 1]; k++)
      if (((Sparse_index *) P->A->i)[k] == j) Ax[k] *= 1.25;
  for (int i = 0; i < n; i++) P->b[i] *= 1.5;
  code = qp_solve(w, x, x2, NULL, &r2, &st);
  Run r3 = run(P, o, NULL, x3, NULL);
  check(!code && !r3.code && rel_diff(n, x2, x3) < 1e-7, "%s %s: new values "
        "of A and b: warm re-solve (%d iterations) = cold solve (%d), to %.2g",
        P->name, names[m], r2.iterations, r3.rep.iterations, rel_diff(n, x2, x3));
  memcpy(Ax, Ax0, nz * sizeof *Ax), memcpy(P->b, b0, n * sizeof *b0);
  qp_free(w);
  free(x), free(x2), free(x3), free(Ax0), free(b0);
}

/* ---- failures, each provoked once ------------------------------------------- */

/* max_iter = 1 on a problem that needs more: not converged, with what was
   measured (the residual, the bounds active) */
static inline void check_not_converged(Qp_problem *P, int m)
{
  double *x = malloc(P->n * sizeof *x);
  Qp_options o = options(methods[m]);
  o.max_iter = 1;
  Run r = run(P, o, NULL, x, NULL);
  check(r.code == STATUS_NUMERIC && has(r.st.msg, "not converged")
        && has(r.st.msg, names[m]) && has(r.st.msg, "bounds active")
        && r.rep.iterations == 1,
        "%s %s, max_iter 1: STATUS_NUMERIC \"%s\"", P->name, names[m], r.st.msg);
  free(x);
}

/* tol = 1e-300, below any rounding: the residual counts only what exceeds
   the rounding of its terms, so method m converges when its state is
   exact to rounding (kkt 0), and agrees with its solution at TOL */
static inline void check_below_rounding(const Qp_problem *P, int m)
{
  double *x = malloc(P->n * sizeof *x), *x0 = malloc(P->n * sizeof *x0);
  Qp_options o = options(methods[m]);
  Run r0 = run(P, o, NULL, x0, NULL);
  o.tol = 1e-300;
  Run r = run(P, o, NULL, x, NULL);
  check(r.code == STATUS_OK && r0.code == STATUS_OK && r.rep.kkt == 0
        && qp_kkt(&P->qp, x, NULL) == 0 && rel_diff(P->n, x, x0) < 1e-7,
        "%s %s, tol 1e-300: converged in %d iterations (%d at tol %g), kkt "
        "0, x the same to %.2g%s", P->name, names[m], r.rep.iterations,
        r0.rep.iterations, TOL, rel_diff(P->n, x, x0), r.st.msg);
  free(x), free(x0);
}

/* a body held only by the bounds, under a load that lifts it off */
static inline void check_not_held(int m)
{
  Qp_problem *P[3] = { neumann_1d("neumann 1D, load up", 1, 1),
                       neumann_1d("neumann 1D, k = 2.15e11/3, load up", 1, 2.15e11 / 3),
                       grid_2d("free grid 12x6, load up", 12, 6, 1) };
  for (int k = 0; k < 3; k++) {
    double *x = malloc(P[k]->n * sizeof *x);
    Qp_options o = options(methods[m]);
    o.max_iter = 2000;
    Run r = run(P[k], o, NULL, x, NULL);
    /* pdas and cgssor find it (a singular step matrix, a direction
       that nothing resists); psor runs out of sweeps and says what it
       measured: none of the bounds is active */
    int said = methods[m] == QP_PSOR
             ? has(r.st.msg, "not converged") && has(r.st.msg, ", 0 of ")
             : has(r.st.msg, "not held with 0 of ");
    check(r.code == STATUS_NUMERIC && said
          && !has(r.st.msg, "nan") && all_finite(P[k]->n, x),
          "%s %s: STATUS_NUMERIC \"%s\"", P[k]->name, names[m], r.st.msg);
    free(x), problem_free(P[k]);
  }
}

/* the checks common to the three methods, on the problems above, in the
   order test_qp.c ran them before they were parted by method */
static inline void check_method(int m)
{
  Qp_problem *P[6];
  problems_new(P);
  check_solvers(P, m);
  for (int k = 0; k < 6; k++) check_scaling(P[k], m), check_warm(P[k], m);
  check_not_converged(P[1], m);
  for (int k = 0; k < 6; k++) check_below_rounding(P[k], m);
  check_not_held(m);
  problems_free(P);
}
#endif
