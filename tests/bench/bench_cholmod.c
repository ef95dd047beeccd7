/* bench_cholmod: what a state solve costs against one sparse Cholesky
   factorisation of the same stiffness matrix, and what the gradient (4.8)
   costs against a state solve.  Run by tests/bench/performance.sh (make
   bench); not a test.

     bench_cholmod SCENE [section.key=value ...]
     bench_cholmod --limit SCENE [section.key=value ...]

   With --limit it prints only the reference (analyse, factor_solve,
   below) of the stiffness at alpha0, which the accuracy sweep draws as
   the limit of each N: "N dofs analyse factor_solve residual".

   On the scene (with the overrides, as -s gives them) at its initial
   shape alpha0 it times, wall-clock (CLOCK_MONOTONIC):
     setup    model_new: mesh, pattern of A, CHOLMOD's symbolic analysis
              (the program analyses once per mesh, here);
     cold     the first model_solve: assembly of A and b and the state
              problem (4.3) from nothing, as `contactopt solve` does it;
   and reads the peak resident set of the process after it.  Then on a
   copy of the lower triangle of the same A and the same b (no contact):
     analyse       cholmod_analyze;
     factor_solve  cholmod_factorize and one cholmod_solve;
   the normalised residual |b - Ax| / (|A||x| + |b|) proves that solve.
   Then at X1 = P_B(alpha0) (solved, not timed: alpha0 need not be in B)
   and its neighbour X2 = P_B(X1 - tG(X1)), t = 1e-3 C0 / |G|_inf, a step
   the size of an optimiser's late step:
     warm     model_solve at X2 from the state at X1 (then back to X1, ...);
     grad     grad_energy after each of those solves.
   At small N one solve takes microseconds and one sample is noise, so
   each of the two groups (cold solve and CHOLMOD; warm solve and gradient)
   is repeated while it took less than a second in all, at most 10 times,
   and the least time of each kind is kept; at large N (N = 1024) each is
   done once.  Prints one line:
     N dofs setup cold cold_steps analyse factor_solve ratio maxrss_MiB
       warm warm_steps grad grad/warm residual adjoint_compliance
       adjoint_spread adjoint_peak
   the last three the times of objective_gradient_fixed (the adjoint) of the
   three objectives besides the energy, after the same warm solves.
   with ratio = (setup + cold) / (analyse + factor_solve).  Any failure:
   a message on stderr and exit status 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "scene.h"
#include "model.h"
#include "grad.h"
#include "design.h"
#include "mesh.h"
#include "fem.h"
#include "objective.h"

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void die(const char *what, const char *why)
{
  fprintf(stderr, "bench_cholmod: %s: %s\n", what, why);
  exit(1);
}

/* peak resident set of this process so far, MiB (Linux: ru_maxrss in KiB) */
static double maxrss_mib(void)
{
  struct rusage ru;
  if (getrusage(RUSAGE_SELF, &ru)) die("getrusage", "failed");
  return ru.ru_maxrss / 1024.0;
}

/* x = A\b by CHOLMOD from scratch (A both triangles, b its load);
   *analyse, *factor_solve its times; returns |b - Ax| / (|A||x| + |b|) */
static double cholmod_reference(const cholmod_sparse *A, const double *bx,
                                cholmod_common *cm, double *analyse,
                                double *factor_solve)
{
  int n = (int) A->nrow;
  double one[2] = { 1, 0 }, minus_one[2] = { -1, 0 };
  cholmod_sparse *C = cholmod_l_copy((cholmod_sparse *) A, -1, 1, cm);   /* lower triangle */
  cholmod_dense *b = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, cm), *x, *r;
  if (!C || !b) die("CHOLMOD", "out of memory for the copy of A");
  memcpy(b->x, bx, n * sizeof(double));
  double t0 = now();
  cholmod_factor *L = cholmod_l_analyze(C, cm);
  double t1 = now();
  if (!L) die("cholmod_analyze", "failed");
  if (!cholmod_l_factorize(C, L, cm) || cm->status != CHOLMOD_OK || L->minor < L->n)
    die("cholmod_factorize", "failed (A not positive definite?)");
  x = cholmod_l_solve(CHOLMOD_A, L, b, cm);
  double t2 = now();
  if (!x) die("cholmod_solve", "failed");
  *analyse = t1 - t0, *factor_solve = t2 - t1;
  if (!(r = cholmod_l_copy_dense(b, cm))
      || !cholmod_l_sdmult(C, 0, minus_one, one, x, r, cm))   /* r = b - Ax */
    die("cholmod_sdmult", "failed");
  double res = cholmod_l_norm_dense(r, 0, cm)
    / (cholmod_l_norm_sparse(C, 0, cm) * cholmod_l_norm_dense(x, 0, cm)
       + cholmod_l_norm_dense(b, 0, cm));
  cholmod_l_free_dense(&r, cm);
  cholmod_l_free_dense(&x, cm);
  cholmod_l_free_dense(&b, cm);
  cholmod_l_free_factor(&L, cm);
  cholmod_l_free_sparse(&C, cm);
  return res;
}

/* model_solve at X, timed; its PDAS steps in *steps */
static double timed_solve(Model *md, const double *X, int *steps)
{
  Status st;
  double t = now();
  if (model_solve(md, X, &st)) die("model_solve", st.msg);
  *steps = md->report.iterations;
  return now() - t;
}

/* the adjoint gradient of objective kind k (energy, q = 8 otherwise), timed */
static double timed_adjoint(Model *md, Objective_kind k, double *G)
{
  Status st;
  Objective o = objective_default();
  o.kind = k;
  double t = now();
  if (objective_gradient_fixed(md, &o, NULL, NULL, NULL, G, NULL, &st))
    die("objective_gradient_fixed", st.msg);
  return now() - t;
}

static double timed_gradient(const Model *md, double *G)
{
  Status st;
  double t = now();
  if (grad_energy(md, G, &st)) die("grad_energy", st.msg);
  return now() - t;
}

typedef struct {
  double setup, cold;          /* model_new, first model_solve (s) */
  int cold_steps;              /* PDAS steps of that solve */
  double analyse, factor_solve;/* CHOLMOD on the same A, b (s) */
  double residual;             /* of CHOLMOD's solve, normalised */
  double rss;                  /* peak resident set after the cold solve, MiB */
  double warm, grad;           /* warm model_solve, grad_energy (s) */
  double adjoint[3];           /* objective_gradient of compliance,
                                  pressure_spread, pressure_peak (s) */
  int warm_steps;              /* PDAS steps of that warm solve */
} Times;

/* fresh model, cold solve at alpha0, CHOLMOD on its matrix: least times
   of the repetitions into T; returns the last model, solved at alpha0 */
static Model *measure_cold(const Scene *s, cholmod_common *cm, Times *T)
{
  Status st;
  Model *md = NULL;
  double spent = 0, a, f;
  T->setup = T->cold = T->analyse = T->factor_solve = HUGE_VAL;
  for (int k = 0; k < 10 && (k == 0 || spent < 1.0); k++) {
    model_free(md);
    double t = now(), setup, cold;
    if (!(md = model_new(&s->problem, &s->solver, cm, &st))) die("model_new", st.msg);
    setup = now() - t;
    cold = timed_solve(md, s->alpha0, &T->cold_steps);
    if (k == 0) T->rss = maxrss_mib();    /* before CHOLMOD's own factor */
    T->residual = cholmod_reference(md->A, md->b, cm, &a, &f);
    if (!(T->residual < 1e-10)) die("CHOLMOD", "the residual of its solve is not small");
    T->setup = fmin(T->setup, setup), T->cold = fmin(T->cold, cold);
    T->analyse = fmin(T->analyse, a), T->factor_solve = fmin(T->factor_solve, f);
    spent += setup + cold + a + f;
  }
  return md;
}

/* warm solves between the neighbours X1 = P_B(alpha0), X2 of B, and the
   gradient after each: least times into T */
static void measure_warm(const Scene *s, Model *md, Times *T)
{
  Status st;
  Design_set B = design_set(&s->problem);
  int n = s->problem.N + 1, steps;
  double *X1 = malloc(n * sizeof *X1), *X2 = malloc(n * sizeof *X2),
         *G = malloc(n * sizeof *G), gmax = 0, spent = 0;
  if (!X1 || !X2 || !G) die("malloc", "out of memory");
  if (design_project(&B, s->alpha0, X1, NULL, &st)) die("design_project", st.msg);
  timed_solve(md, X1, &steps);
  T->grad = timed_gradient(md, G);
  for (int i = 0; i < n; i++) gmax = fmax(gmax, fabs(G[i]));
  if (!(gmax > 0)) die("grad_energy", "zero gradient: no direction to step in");
  for (int i = 0; i < n; i++) G[i] = X1[i] - 1e-3 * s->problem.C0 / gmax * G[i];
  if (design_project(&B, G, X2, NULL, &st)) die("design_project", st.msg);
  T->warm = HUGE_VAL;
  const Objective_kind kinds[3] = { OBJECTIVE_COMPLIANCE, OBJECTIVE_SPREAD, OBJECTIVE_PEAK };
  for (int j = 0; j < 3; j++) T->adjoint[j] = HUGE_VAL;
  for (int k = 0; k < 10 && (k == 0 || spent < 1.0); k++) {
    double w = timed_solve(md, k % 2 ? X1 : X2, &steps), g = timed_gradient(md, G);
    if (w < T->warm) T->warm = w, T->warm_steps = steps;
    T->grad = fmin(T->grad, g);
    spent += w + g;
    for (int j = 0; j < 3; j++) {
      double a = timed_adjoint(md, kinds[j], G);
      T->adjoint[j] = fmin(T->adjoint[j], a), spent += a;
    }
  }
  free(X1), free(X2), free(G);
}

/* --limit: the stiffness A and load b at alpha0 assembled by the fem
   module alone (no model, no state solve), then only the reference, the
   least of its repetitions: "N dofs analyse factor_solve residual" */
static void measure_limit(const Scene *s, cholmod_common *cm)
{
  Status st;
  Mesh *m = mesh_new(&s->problem, &st);
  if (!m || mesh_move(m, s->alpha0, &st)) die("mesh", st.msg);
  Dofs *d = fem_dofs_new(m, &s->problem, &st);
  if (!d) die("fem_dofs_new", st.msg);
  Hooke H = fem_hooke(&s->problem);
  cholmod_sparse *A = fem_stiffness_new(m, d, cm, &st);
  if (!A || fem_stiffness_fill(A, m, d, &H, &st)) die("fem_stiffness", st.msg);
  double *b = malloc(A->nrow * sizeof *b), an = HUGE_VAL, fs = HUGE_VAL, res = 0, spent = 0;
  if (!b) die("bench_cholmod", "out of memory");
  fem_load(m, d, &s->problem, b);
  for (int k = 0; k < 10 && (k == 0 || spent < 1.0); k++) {
    double a, f;
    res = cholmod_reference(A, b, cm, &a, &f);
    an = fmin(an, a), fs = fmin(fs, f), spent += a + f;
  }
  printf("%d %d %.6f %.6f %.1e\n", s->problem.N, (int) A->nrow, an, fs, res);
  free(b);
  cholmod_l_free_sparse(&A, cm);
  fem_dofs_free(d);
  mesh_free(m);
}

int main(int argc, char **argv)
{
  Scene s;
  Status st;
  Times T = { 0 };
  cholmod_common cm;
  int limit = argc > 1 && !strcmp(argv[1], "--limit");
  if (argc < 2 + limit) die("usage", "bench_cholmod [--limit] SCENE [section.key=value ...]");
  if (scene_load(&s, argv[1 + limit], argc - 2 - limit, argv + 2 + limit, &st))
    die(argv[1 + limit], st.msg);
  cholmod_l_start(&cm);
  gsl_set_error_handler_off();   /* failures come back as codes */
  cm.print = 0;
  if (limit) {
    measure_limit(&s, &cm);
    cholmod_l_finish(&cm);
    scene_free(&s);
    return 0;
  }
  Model *md = measure_cold(&s, &cm, &T);
  measure_warm(&s, md, &T);
  printf("%d %d %.6f %.6f %d %.6f %.6f %.3f %.1f %.6f %d %.3e %.4f %.1e %.3e %.3e %.3e\n",
         s.problem.N, (int) md->A->nrow, T.setup, T.cold, T.cold_steps, T.analyse,
         T.factor_solve, (T.setup + T.cold) / (T.analyse + T.factor_solve),
         T.rss, T.warm, T.warm_steps, T.grad, T.grad / T.warm, T.residual,
         T.adjoint[0], T.adjoint[1], T.adjoint[2]);
  model_free(md);
  cholmod_l_finish(&cm);
  scene_free(&s);
  return 0;
}
