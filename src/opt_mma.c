#line 341 "paper/opt.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <nlopt.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "opt_private.h"
#line 1148 "paper/opt.nw"
typedef struct {
  Evaluator *ev;
  nlopt_opt opt;
  int n;                  /* N+1; MMA's variables y are n - 1 */
  double *X0;             /* n: the design at y = 0, in B */
  double *R;              /* n x (n-1), row-major: X = X0 + C0 R y */
  double scale;           /* sigma: the objective is J / sigma */
  double *S, *Z;          /* n x n, n x (n-1): work of the metric */
  double *X, *w;          /* n each: work */
  double best, best_noise;  /* the lowest J of an iterate, its rounding */
  double *bestX;          /* n: the last accepted iterate */
  int k;                  /* accepted iterates so far */
  int stalled;            /* evaluations since the last accepted one */
  int fresh;              /* iterates accepted since MMA (re)started */
} Mma;
enum { MMA_STALL = 20 };
#line 1167 "paper/opt.nw"
/* X = X0 + C0 R y */
static void mma_design(const Mma *q, const double *y, double *X)
{
  int n = q->n;
  for (int i = 0; i < n; i++) {
    double s = 0;
    for (int j = 0; j < n - 1; j++) s += q->R[(size_t) i * (n - 1) + j] * y[j];
    X[i] = q->X0[i] + q->ev->B->C0 * s;
  }
}

/* grad = C0 R' G / sigma */
static void mma_gradient(const Mma *q, const double *G, double *grad)
{
  int n = q->n;
  for (int j = 0; j < n - 1; j++) grad[j] = 0;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n - 1; j++) grad[j] += q->R[(size_t) i * (n - 1) + j] * G[i];
  for (int j = 0; j < n - 1; j++) grad[j] *= q->ev->B->C0 / q->scale;
}
#line 1191 "paper/opt.nw"
static void mma_constraints(unsigned m, double *c, unsigned ny,
                            const double *y, double *grad, void *data)
{
  Mma *q = data;
  const Design_set *B = q->ev->B;
  const double *R = q->R;
  unsigned n = ny + 1;
  double *X = q->w;
  mma_design(q, y, X);
  opt_constraints(B, X, n, c);
  if (grad) opt_constraints_gradient(R, n, ny, grad);
  (void) m;
}
#line 1216 "paper/opt.nw"
static void mma_accept(Mma *q);
static double mma_objective(unsigned ny, const double *y, double *grad,
                            void *data)
{
  Mma *q = data;
  Evaluator *ev = q->ev;
  mma_design(q, y, q->X);
  if (design_violation(ev->B, q->X) > 0
      && (ev->failed = design_project(ev->B, q->X, q->X, NULL, ev->st))) {
    nlopt_force_stop(q->opt);
    return HUGE_VAL;
  }
  if ((ev->failed = opt_evaluate(ev, q->X))) { nlopt_force_stop(q->opt); return HUGE_VAL; }
  if (grad) mma_gradient(q, ev->G, grad);
  if (ev->E <= q->best + q->best_noise + ev->noise
      && (q->k == 0 || memcmp(ev->X, q->bestX, q->n * sizeof *ev->X))) mma_accept(q);
  else if (++q->stalled >= MMA_STALL) nlopt_force_stop(q->opt);    /* restart */
  (void) ny;
  return ev->E / q->scale;
}
#line 1239 "paper/opt.nw"
static void mma_stop(Mma *q, const char *why)
{
  snprintf(q->ev->rep->stop_reason, sizeof q->ev->rep->stop_reason, "%s", why);
  nlopt_force_stop(q->opt);
}

static void mma_accept(Mma *q)
{
  Evaluator *ev = q->ev;
  if (ev->E < q->best) q->best = ev->E, q->best_noise = ev->noise;
  q->stalled = 0;
  q->fresh += q->k > 0;
  const char *why = opt_nlopt_iterate(ev, q->k, q->bestX);
  if (ev->failed) { nlopt_force_stop(q->opt); return; }
  if (why) mma_stop(q, why);
  q->k++;
}
#line 1261 "paper/opt.nw"
static int mma_schur(Mma *q);
/* Z, R and sigma at X, the evaluator's design */
static int mma_setup(Mma *q, const double *X)
{
  int n = q->n, m = n - 1;
  double norm = sqrt(n - 1.5), vv = 0, Gmax = 0, *v = q->w;   /* |a| / h */
  for (int i = 0; i < n; i++) v[i] = (i == 0 || i == n - 1 ? 0.5 : 1.0) / norm;
  v[0] += 1;
  for (int i = 0; i < n; i++) vv += v[i] * v[i];
  for (int i = 0; i < n; i++)
    for (int j = 0; j < m; j++)
      q->Z[(size_t) i * m + j] = (i == j + 1) - 2 * v[i] * v[j + 1] / vv;
  memcpy(q->X0, X, n * sizeof *X);
  if (q->ev->o->metric == OPT_METRIC_SCHUR) return mma_schur(q);
  for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(q->ev->G[i]));
  memcpy(q->R, q->Z, (size_t) n * m * sizeof *q->R);
  q->scale = q->ev->B->C0 * (Gmax > 0 ? Gmax : 1.0);
  return STATUS_OK;
}
#line 1286 "paper/opt.nw"
static int mma_schur(Mma *q)
{
  Evaluator *ev = q->ev;
  int n = q->n, m = n - 1, rc;
  double start = resources_clock();
  if ((rc = model_contact_stiffness(ev->md, q->S, ev->st))) return rc;
  gsl_matrix_view S = gsl_matrix_view_array(q->S, n, n);
  gsl_matrix_view Z = gsl_matrix_view_array(q->Z, n, m), R = gsl_matrix_view_array(q->R, n, m);
  gsl_matrix *K = gsl_matrix_alloc(m, m);
  gsl_vector *g = gsl_vector_alloc(m);
  if (!K || !g) rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  else {
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &S.matrix, &Z.matrix, 0.0, &R.matrix);
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, &Z.matrix, &R.matrix, 0.0, K);
    
#line 1310 "paper/opt.nw"
if (gsl_linalg_cholesky_decomp1(K))
  rc = status_set(ev->st, STATUS_NUMERIC, "optimiser: the contact stiffness "
                  "is not positive definite");
else {
  gsl_vector_const_view G = gsl_vector_const_view_array(ev->G, n);
  gsl_blas_dgemv(CblasTrans, 1.0, &Z.matrix, &G.vector, 0.0, g);
  gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, K, g);
  double sigma = pow(gsl_blas_dnrm2(g), 2);
  q->scale = sigma > 0 ? sigma : 1.0;
  gsl_matrix_memcpy(&R.matrix, &Z.matrix);                  /* R = Z L^{-T} */
  gsl_blas_dtrsm(CblasRight, CblasLower, CblasTrans, CblasNonUnit, 1.0, K, &R.matrix);
  gsl_matrix_scale(&R.matrix, sqrt(q->scale) / ev->B->C0);
}
#line 1301 "paper/opt.nw"
  }
  gsl_matrix_free(K);
  gsl_vector_free(g);
  ev->rep->metric_seconds += resources_clock() - start;
  return rc;
}
#line 1330 "paper/opt.nw"
static int mma_run(Mma *q, double *y, double *tol, int *more);
int opt_mma(Evaluator *ev, double *X)
{
  int n = ev->n, rc = STATUS_OK;
  size_t nn = (size_t) n * n;
  double *work = malloc((3 * nn + 8 * (size_t) n + 2) * sizeof *work);
  Mma q = { .ev = ev, .n = n, .best = HUGE_VAL, .bestX = X };
  if (!work) return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  q.S = work, q.Z = q.S + nn, q.R = q.Z + nn, q.X0 = q.R + nn;
  q.X = q.X0 + n, q.w = q.X + n;
  double *y = q.w + n, *tol = y + n;            /* n - 1 and 4n - 2 */
  for (int more = 1; more && !rc; ) {
    if ((rc = opt_evaluate(ev, X)) || (rc = mma_setup(&q, X))) break;
    rc = mma_run(&q, y, tol, &more);
  }
  free(work);
  return rc;
}
#line 1352 "paper/opt.nw"
static int mma_run(Mma *q, double *y, double *tol, int *more)
{
  Evaluator *ev = q->ev;
  int n = q->n, m = 2 * n + 2 * (n - 1), rc = STATUS_OK;
  double f;
  if (!(q->opt = nlopt_create(NLOPT_LD_MMA, n - 1)))
    return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
  for (int i = 0; i < m; i++) tol[i] = 0;
  for (int i = 0; i < n - 1; i++) y[i] = 0;
  nlopt_result r = nlopt_add_inequality_mconstraint(q->opt, m, mma_constraints, q, tol);
  if (r > 0) r = nlopt_set_min_objective(q->opt, mma_objective, q);
  if (r > 0) r = nlopt_set_maxeval(q->opt, 50 * (ev->o->max_iter + 1) - ev->rep->evaluations + 1);
  if (r > 0) r = nlopt_optimize(q->opt, y, &f);
  nlopt_destroy(q->opt);
  
#line 1374 "paper/opt.nw"
if (!(rc = ev->failed) && r == NLOPT_OUT_OF_MEMORY)
  rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
*more = !rc && !ev->rep->stop_reason[0] && r != NLOPT_MAXEVAL_REACHED && q->fresh > 0;
if (!rc && !*more && !ev->rep->stop_reason[0]) {
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s",
           r == NLOPT_MAXEVAL_REACHED ? "max_iter" : "no_progress");
  if (r != NLOPT_MAXEVAL_REACHED)
    snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "MMA, %s, found no "
             "new iterate in %d evaluations (NLopt: %s)", ev->rep->iterations
             ? "restarted from its last iterate" : "from the start", q->stalled,
             nlopt_result_to_string(r));
}
if (!rc) rc = opt_evaluate(ev, q->bestX);
q->fresh = q->stalled = 0;
(void) f;
#line 1367 "paper/opt.nw"
  return rc;
}
