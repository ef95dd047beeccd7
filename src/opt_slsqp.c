#line 360 "paper/opt.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <nlopt.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "opt_private.h"
#line 855 "paper/opt.nw"
typedef struct {
  int n;                  /* N+1 */
  double *X0;             /* n: the start */
  double *R;              /* n x n, row-major: X = X0 + C0 R y */
  double scale;           /* sigma: the objective is E / sigma */
} Metric;
#line 1007 "paper/opt.nw"
typedef struct {
  Opt_evaluator *ev;
  nlopt_opt opt;
  Metric metric;
  double best;            /* the lowest E evaluated */
  double best_band;       /* delta E + C0 v |grad E|_1 there */
  double *bestX;          /* n: where; the last accepted iterate */
  int k;                  /* accepted iterates so far */
  int stalled;            /* evaluations since the last accepted one */
  int fresh;              /* iterates accepted since SLSQP (re)started */
  double outside;         /* seconds in this file's callbacks, this start */
} Slsqp;
enum { STALL = 10 };
static const double OPT_IN_B = 1e-12;   /* a violation of B that is rounding */
#line 864 "paper/opt.nw"
/* X = X0 + C0 R y, unclipped: the design the constraints see */
static void metric_design(const Metric *mt, double C0, const double *y,
                          double *X)
{
  int n = mt->n;
  for (int i = 0; i < n; i++) {
    double s = 0;
    for (int j = 0; j < n; j++) s += mt->R[(size_t) i * n + j] * y[j];
    X[i] = mt->X0[i] + C0 * s;
  }
}
#line 879 "paper/opt.nw"
static void linear_constraints(unsigned m, double *c, unsigned n,
                               const double *y, double *grad, void *data)
{
  Slsqp *q = data;
  const Design_set *B = q->ev->B;
  const double *R = q->metric.R;
  double X[n], start = resources_clock();
  metric_design(&q->metric, B->C0, y, X);
  opt_constraints(B, X, n, c);
  if (grad) opt_constraints_gradient(R, n, n, grad);
  q->outside += resources_clock() - start;
  (void) m;
}
#line 935 "paper/opt.nw"
static double area_constraint(unsigned n, const double *y, double *grad,
                              void *data)
{
  Slsqp *q = data;
  const Design_set *B = q->ev->B;
  double L = B->h * B->N, X[n], sum = 0, start = resources_clock();
  metric_design(&q->metric, B->C0, y, X);
  for (unsigned i = 0; i < n; i++) sum += (i == 0 || i + 1 == n ? 0.5 : 1.0) * X[i];
  if (grad)
    for (unsigned j = 0; j < n; j++) {
      double g = 0;
      for (unsigned i = 0; i < n; i++)
        g += (i == 0 || i + 1 == n ? 0.5 : 1.0) * q->metric.R[i * n + j];
      grad[j] = g * B->h / L;
    }
  q->outside += resources_clock() - start;
  return (B->h * sum - B->area) / (B->C0 * L);
}
#line 1025 "paper/opt.nw"
static void slsqp_stop(Slsqp *q, const char *why)
{
  snprintf(q->ev->rep->stop_reason, sizeof q->ev->rep->stop_reason, "%s", why);
  nlopt_force_stop(q->opt);
}
#line 1034 "paper/opt.nw"
/* delta E + C0 v |grad E|_1 at the evaluator's design, v its violation of B */
static double slsqp_band(const Opt_evaluator *ev, double v)
{
  double g1 = 0;
  for (int i = 0; i < ev->n; i++) g1 += fabs(ev->G[i]);
  return ev->noise + ev->B->C0 * v * g1;
}

static void slsqp_accept(Slsqp *q, double band);
/* E(X(y)) / sigma, and its gradient in y */
static double slsqp_value(Slsqp *q, unsigned n, const double *y, double *grad)
{
  Opt_evaluator *ev = q->ev;
  const double *R = q->metric.R;
  double X[n], C0 = ev->B->C0;
  metric_design(&q->metric, C0, y, X);
  for (unsigned i = 0; i < n; i++) X[i] = fmin(fmax(X[i], 0), C0);
  if ((ev->failed = opt_evaluate(ev, X))) { nlopt_force_stop(q->opt); return HUGE_VAL; }
  if (grad)
    
#line 1074 "paper/opt.nw"
for (unsigned j = 0; j < n; j++) {
  double g = 0;
  for (unsigned i = 0; i < n; i++) g += R[i * n + j] * ev->G[i];
  grad[j] = C0 * g / q->metric.scale;
}
#line 1054 "paper/opt.nw"
  double v = design_violation(ev->B, X), band = slsqp_band(ev, v);
  if (ev->J <= q->best + q->best_band + band && v <= OPT_IN_B
      && (q->k == 0 || memcmp(X, q->bestX, n * sizeof *X))) slsqp_accept(q, band);
  else if (++q->stalled >= STALL) nlopt_force_stop(q->opt);    /* restart */
  return ev->J / q->metric.scale;
}

/* NLopt's objective: the value, timed as the callbacks' */
static double slsqp_objective(unsigned n, const double *y, double *grad,
                              void *data)
{
  Slsqp *q = data;
  double start = resources_clock(), J = slsqp_value(q, n, y, grad);
  q->outside += resources_clock() - start;
  return J;
}
#line 1084 "paper/opt.nw"
static void slsqp_accept(Slsqp *q, double band)
{
  Opt_evaluator *ev = q->ev;
  if (ev->J < q->best) q->best = ev->J, q->best_band = band;
  q->stalled = 0;
  q->fresh += q->k > 0;
  const char *why = opt_nlopt_iterate(ev, q->k, q->bestX);
  if (ev->failed) { nlopt_force_stop(q->opt); return; }
  if (why) slsqp_stop(q, why);
  q->k++;
}
#line 1101 "paper/opt.nw"
static int metric_setup(Opt_evaluator *ev, Metric *mt)
{
  int n = ev->n, rc = STATUS_OK;
  double C0 = ev->B->C0, Gmax = 0;
  memset(mt->R, 0, (size_t) n * n * sizeof *mt->R);
  for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev->G[i]));
  if (ev->o->metric == OPT_METRIC_EUCLIDEAN) {
    for (int i = 0; i < n; i++) mt->R[(size_t) i * n + i] = 1;
    mt->scale = C0 * (Gmax > 0 ? Gmax : 1.0);
    return STATUS_OK;
  }
  double start = resources_clock();
  if ((rc = model_contact_stiffness(ev->md, mt->R, ev->st))) return rc;
  
#line 1121 "paper/opt.nw"
gsl_matrix_view S = gsl_matrix_view_array(mt->R, n, n);
gsl_matrix *Linv = gsl_matrix_alloc(n, n);
gsl_vector *g = gsl_vector_alloc(n);
if (!Linv || !g) rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
else if (gsl_linalg_cholesky_decomp1(&S.matrix))
  rc = status_set(ev->st, STATUS_NUMERIC, "optimiser: the contact stiffness "
                  "is not positive definite");
else {
  for (int i = 0; i < n; i++) gsl_vector_set(g, i, ev->G[i]);
  gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, &S.matrix, g);
  double sigma = pow(gsl_blas_dnrm2(g), 2);
  mt->scale = sigma > 0 ? sigma : 1.0;
  gsl_matrix_set_identity(Linv);                    /* Linv = L^{-T} */
  gsl_blas_dtrsm(CblasLeft, CblasLower, CblasTrans, CblasNonUnit, 1.0,
                 &S.matrix, Linv);
  double c = sqrt(mt->scale) / C0;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) mt->R[(size_t) i * n + j] = c * gsl_matrix_get(Linv, i, j);
}
gsl_matrix_free(Linv);
gsl_vector_free(g);
#line 1115 "paper/opt.nw"
  ev->rep->metric_seconds += resources_clock() - start;
  return rc;
}
#line 1151 "paper/opt.nw"
int opt_slsqp(Opt_evaluator *ev, double *X)
{
  int n = ev->n, m = 2 * n + 2 * (n - 1), rc;
  double *scratch = malloc(((size_t) n * n + 2 * n + m) * sizeof *scratch);
  Slsqp q = { ev, NULL, { n, NULL, NULL, 1 }, HUGE_VAL, 0, X, 0, 0, 0, 0 };
  if (!scratch) return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  q.metric.R = scratch, q.metric.X0 = scratch + (size_t) n * n;
  double *y = q.metric.X0 + n, *tol = y + n, f;
  for (int more = 1; more; ) {
    memcpy(q.metric.X0, X, n * sizeof *X);
    if ((rc = opt_evaluate(ev, X)) || (rc = metric_setup(ev, &q.metric))) break;
    if (!(q.opt = nlopt_create(NLOPT_LD_SLSQP, n))) {
      rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
      break;
    }
    
#line 1174 "paper/opt.nw"
for (int i = 0; i < m; i++) tol[i] = 1e-14;
for (int i = 0; i < n; i++) y[i] = 0;
nlopt_result r = nlopt_add_inequality_mconstraint(q.opt, m, linear_constraints, &q, tol);
if (r > 0) r = nlopt_add_equality_constraint(q.opt, area_constraint, &q, 1e-14);
if (r > 0) r = nlopt_set_min_objective(q.opt, slsqp_objective, &q);
if (r > 0) r = nlopt_set_maxeval(q.opt, 50 * (ev->o->max_iter + 1) - ev->rep->evaluations + 1);
double start = resources_clock();
q.outside = 0;
if (r > 0) r = nlopt_optimize(q.opt, y, &f);
ev->rep->subproblem_seconds += resources_clock() - start - q.outside;
nlopt_destroy(q.opt);
#line 1194 "paper/opt.nw"
if (!(rc = ev->failed) && r == NLOPT_OUT_OF_MEMORY)
  rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
more = !rc && !ev->rep->stop_reason[0]
       && r != NLOPT_MAXEVAL_REACHED && q.fresh > 0;
if (!rc && !more && !ev->rep->stop_reason[0]) {
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s",
           r == NLOPT_MAXEVAL_REACHED ? "max_iter" : "no_progress");
  
#line 1211 "paper/opt.nw"
if (r != NLOPT_MAXEVAL_REACHED)
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "SLSQP, %s, found no "
           "new iterate: %s%s", ev->rep->iterations ? "restarted from its last iterate"
           : "from the start", r == NLOPT_FORCED_STOP ? "its line search found no design "
           "in B with a lower value of the objective" : "NLopt ended it as ",
           r == NLOPT_FORCED_STOP ? "" : nlopt_result_to_string(r));
#line 1202 "paper/opt.nw"
}
if (!rc) rc = opt_evaluate(ev, X);
q.fresh = q.stalled = 0;
(void) f;
#line 1167 "paper/opt.nw"
  }
  free(scratch);
  return rc;
}
