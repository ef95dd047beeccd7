#line 283 "paper/opt.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <nlopt.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "opt.h"
#include "grad.h"
#include "newton.h"

#line 300 "paper/opt.nw"
const char *const opt_method_names[] = {"slsqp", "projgrad", "newton", NULL};
const char *const opt_metric_names[] = {"schur", "euclidean", NULL};

Opt_options opt_options_default(Opt_method method)
{
  return (Opt_options) { method, method == OPT_PROJGRAD ? OPT_METRIC_EUCLIDEAN
                                                       : OPT_METRIC_SCHUR,
                         1e-6, 200 };
}

const char *opt_method_name(Opt_method m)
{
  return (unsigned)m <= OPT_NEWTON ? opt_method_names[m] : "?";
}

const char *opt_metric_name(Opt_metric m)
{
  return (unsigned)m <= OPT_METRIC_EUCLIDEAN ? opt_metric_names[m] : "?";
}
#line 328 "paper/opt.nw"
typedef struct {
  Model *md;              /* the state at the last design evaluated */
  const Design_set *B;
  const Opt_options *o;
  int n;                  /* N+1 */
  double *X;              /* n: the last design evaluated */
  double *G;              /* n: grad E there */
  double E;               /* E there */
  double noise;           /* the rounding of E there (below) */
  int have;               /* X, G, E are valid */
  int solves;             /* state solves so far */
  double tau;             /* the step of pi, fixed at the start */
  double start;           /* clock at the start */
  Opt_monitor monitor;
  void *data;
  Opt_report *rep;
  Status *st;
  int failed;             /* a status to return after NLopt stops */
  double last_E, last_noise; /* E and its rounding at the last accepted iterate */
  double pg_best;         /* the smallest pi of the accepted iterates */
  int idle;               /* accepted iterates in a row without measured progress */
} Evaluator;
enum { OPT_FEW = 3 };     /* so many such iterates in a row: no progress */
#line 633 "paper/opt.nw"
typedef struct {
  int n;                  /* N+1 */
  double *X0;             /* n: the start */
  double *R;              /* n x n, row-major: X = X0 + C0 R y */
  double scale;           /* sigma: the objective is E / sigma */
} Metric;
#line 765 "paper/opt.nw"
typedef struct {
  Evaluator *ev;
  nlopt_opt opt;
  Metric metric;
  double best;            /* the lowest E evaluated */
  double best_noise;      /* the rounding of E there */
  double *bestX;          /* n: where; the last accepted iterate */
  int k;                  /* accepted iterates so far */
  int stalled;            /* evaluations since the last accepted one */
  int fresh;              /* iterates accepted since SLSQP (re)started */
} Slsqp;
enum { STALL = 10 };
static const double OPT_IN_B = 1e-12;   /* a violation of B that is rounding */
#line 404 "paper/opt.nw"
/* eps (U + sum_i |b_i Q_i| + friction), E = U - b'Q + friction, U >= 0 */
static double energy_rounding(const Model *md)
{
  long double W = 0, Wabs = 0;
  for (int i = 0; i < md->dofs->n; i++) {
    long double bq = (long double) md->b[i] * md->Q[i];
    W += bq, Wabs += fabsl(bq);
  }
  long double U = md->energy - md->friction_energy + W;
  return DBL_EPSILON * (double) (fabsl(U) + Wabs + fabs(md->friction_energy));
}
#line 356 "paper/opt.nw"
static int evaluate(Evaluator *ev, const double *X)
{
  if (ev->have && !memcmp(ev->X, X, ev->n * sizeof *X)) return STATUS_OK;
  ev->have = 0;
  double start = model_clock();
  int rc = model_solve(ev->md, X, ev->st);
  ev->solves++;
  if (!rc) rc = grad_energy(ev->md, ev->G, ev->st);
  if (ev->rep)
    ev->rep->evaluations++, ev->rep->state_seconds += model_clock() - start;
  if (rc) return rc;
  memcpy(ev->X, X, ev->n * sizeof *X);
  ev->E = ev->md->energy;
  ev->noise = energy_rounding(ev->md);
  ev->have = 1;
  return STATUS_OK;
}
#line 418 "paper/opt.nw"
int opt_pgnorm(const Design_set *B, const double *X, const double *G,
               double tau, double *pg, Status *st)
{
  double residual;                      /* ||X - P_B(X - tau G)|| / tau */
  int rc = design_kkt(B, X, G, tau, NULL, NULL, &residual, st);
  *pg = residual * tau / B->C0;
  return rc;
}
#line 429 "paper/opt.nw"
/* 1 if the monitor asks to stop here; its time is the caller's */
static int report_iterate(Evaluator *ev, int iteration, double pg)
{
  double start = model_clock();
  Opt_progress p = { iteration, ev->E, pg, ev->solves, ev->md->report.active,
                     ev->md->report.iterations, start - ev->start };
  int stop = ev->monitor && ev->monitor(&p, ev->X, ev->data);
  ev->rep->monitor_seconds += model_clock() - start;
  return stop;
}
#line 460 "paper/opt.nw"
/* after the accepted iterate k, at the evaluator's design, with pi = pg:
   the iterates in a row without measured progress; judged: the method
   measured the step by its own test */
static int idle_iterates(Evaluator *ev, int k, double pg, int judged)
{
  int measured = k == 0 || judged || pg < 0.5 * ev->pg_best
              || ev->E < ev->last_E - (ev->noise + ev->last_noise);
  ev->idle = measured ? 0 : ev->idle + 1;
  if (k == 0 || pg < ev->pg_best) ev->pg_best = pg;
  ev->last_E = ev->E, ev->last_noise = ev->noise;
  return ev->idle;
}

/* the stop_detail of a run stopped by OPT_FEW idle iterates */
static void idle_detail(Evaluator *ev)
{
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "%d iterates in a row "
           "lowered E by no more than its rounding (%.1e J/m) and did not halve pi: "
           "the rounding of E allows no smaller pi", ev->idle, ev->noise);
}
#line 511 "paper/opt.nw"
typedef struct {
  double *trial;          /* n: P_B(X - tG) */
  double *Y;              /* n: X - tG */
  double *X, *G;          /* n each: the iterate and its gradient */
} Projgrad_work;

#line 521 "paper/opt.nw"
static int projgrad_step(Evaluator *ev, double *t, Projgrad_work *w,
                         int *accepted)
{
  int n = ev->n, rc;
  double E0 = ev->E, *Xn = w->trial, *Y = w->Y, *X = w->X, *G = w->G;
  memcpy(X, ev->X, n * sizeof *X);
  memcpy(G, ev->G, n * sizeof *G);
  *accepted = 0;
  for (int halving = 0; halving < 50 && !*accepted; halving++, *t /= 2) {
    
#line 540 "paper/opt.nw"
for (int i = 0; i < n; i++) Y[i] = X[i] - *t * G[i];
if ((rc = design_project(ev->B, Y, Xn, NULL, ev->st))) return rc;
double descent = 0;
for (int i = 0; i < n; i++) descent += G[i] * (Xn[i] - X[i]);
if (descent >= 0) continue;                /* the arc has collapsed */
if ((rc = evaluate(ev, Xn))) return rc;
*accepted = ev->E <= E0 + 1e-4 * descent;
#line 531 "paper/opt.nw"
  }
  if (*accepted) *t *= 4;                      /* undo the last halving, then double */
  else if ((rc = evaluate(ev, X))) return rc;  /* back to the last iterate */
  return STATUS_OK;
}
#line 552 "paper/opt.nw"
static int projgrad(Evaluator *ev, double *X)
{
  int n = ev->n, rc, accepted = 1, k = 0;
  double t = ev->tau, pg;
  double *work = malloc(4 * n * sizeof *work);
  Projgrad_work w = { work, work + n, work + 2 * n, work + 3 * n };
  if (!work) return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  for (;; k++) {
    if ((rc = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))) break;
    int stop = report_iterate(ev, k, pg);
    ev->rep->pgnorm = pg;
    
#line 574 "paper/opt.nw"
int idle = idle_iterates(ev, k, pg, 0);
const char *why = pg <= ev->o->tol ? "converged"
                : stop ? "interrupted"
                : !accepted ? "no_progress"
                : k >= ev->o->max_iter ? "max_iter"
                : idle >= OPT_FEW ? "no_progress" : NULL;
if (why) {
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s", why);
  if (!accepted)
    snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "fifty halvings of "
             "the step found no point of the projection arc that meets the Armijo "
             "condition");
  else if (!strcmp(why, "no_progress")) idle_detail(ev);
  break;
}
#line 564 "paper/opt.nw"
    if ((rc = projgrad_step(ev, &t, &w, &accepted))) break;
  }
  ev->rep->iterations = k;
  memcpy(X, ev->X, n * sizeof *X);
  free(work);
  return rc;
}
#line 642 "paper/opt.nw"
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
#line 657 "paper/opt.nw"
static void linear_constraints(unsigned m, double *c, unsigned n,
                               const double *y, double *grad, void *data)
{
  const Slsqp *q = data;
  const Design_set *B = q->ev->B;
  const double *R = q->metric.R;
  double X[n], d = B->delta / B->C0;
  metric_design(&q->metric, B->C0, y, X);
  
#line 677 "paper/opt.nw"
for (unsigned i = 0; i < n; i++) {
  c[2 * i] = -X[i] / B->C0;                       /* X_i >= 0 */
  c[2 * i + 1] = X[i] / B->C0 - 1;                /* X_i <= C0 */
}
for (unsigned i = 0; i + 1 < n; i++) {
  double rise = (X[i + 1] - X[i]) / B->C0;
  c[2 * n + 2 * i] = rise - d;                    /* rising at most C1 h */
  c[2 * n + 2 * i + 1] = -rise - d;               /* falling at most C1 h */
}
#line 666 "paper/opt.nw"
  if (grad)
    for (unsigned j = 0; j < n; j++) {
      
#line 690 "paper/opt.nw"
for (unsigned i = 0; i < n; i++) {
  grad[2 * i * n + j] = -R[i * n + j];
  grad[(2 * i + 1) * n + j] = R[i * n + j];
}
for (unsigned i = 0; i + 1 < n; i++) {
  double rise = R[(i + 1) * n + j] - R[i * n + j];
  grad[(2 * n + 2 * i) * n + j] = rise;
  grad[(2 * n + 2 * i + 1) * n + j] = -rise;
}
#line 669 "paper/opt.nw"
    }
  (void) m;
}
#line 703 "paper/opt.nw"
static double area_constraint(unsigned n, const double *y, double *grad,
                              void *data)
{
  const Slsqp *q = data;
  const Design_set *B = q->ev->B;
  double L = B->h * B->N, X[n], sum = 0;
  metric_design(&q->metric, B->C0, y, X);
  for (unsigned i = 0; i < n; i++) sum += (i == 0 || i + 1 == n ? 0.5 : 1.0) * X[i];
  if (grad)
    for (unsigned j = 0; j < n; j++) {
      double g = 0;
      for (unsigned i = 0; i < n; i++)
        g += (i == 0 || i + 1 == n ? 0.5 : 1.0) * q->metric.R[i * n + j];
      grad[j] = g * B->h / L;
    }
  return (B->h * sum - B->area) / (B->C0 * L);
}
#line 782 "paper/opt.nw"
static void slsqp_stop(Slsqp *q, const char *why)
{
  snprintf(q->ev->rep->stop_reason, sizeof q->ev->rep->stop_reason, "%s", why);
  nlopt_force_stop(q->opt);
}
#line 791 "paper/opt.nw"
static void slsqp_accept(Slsqp *q);
static double slsqp_objective(unsigned n, const double *y, double *grad,
                              void *data)
{
  Slsqp *q = data;
  Evaluator *ev = q->ev;
  const double *R = q->metric.R;
  double X[n], C0 = ev->B->C0;
  metric_design(&q->metric, C0, y, X);
  for (unsigned i = 0; i < n; i++) X[i] = fmin(fmax(X[i], 0), C0);
  if ((ev->failed = evaluate(ev, X))) { nlopt_force_stop(q->opt); return HUGE_VAL; }
  if (grad)
    
#line 814 "paper/opt.nw"
for (unsigned j = 0; j < n; j++) {
  double g = 0;
  for (unsigned i = 0; i < n; i++) g += R[i * n + j] * ev->G[i];
  grad[j] = C0 * g / q->metric.scale;
}
#line 804 "paper/opt.nw"
  if (ev->E <= q->best + q->best_noise + ev->noise
      && design_violation(ev->B, X) <= OPT_IN_B
      && (q->k == 0 || memcmp(X, q->bestX, n * sizeof *X))) slsqp_accept(q);
  else if (++q->stalled >= STALL) nlopt_force_stop(q->opt);    /* restart */
  return ev->E / q->metric.scale;
}
#line 823 "paper/opt.nw"
static void slsqp_accept(Slsqp *q)
{
  Evaluator *ev = q->ev;
  double pg;
  if (ev->E < q->best) q->best = ev->E, q->best_noise = ev->noise;
  q->stalled = 0;
  q->fresh += q->k > 0;
  if ((ev->failed = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))) {
    nlopt_force_stop(q->opt);
    return;
  }
  int stop = report_iterate(ev, q->k, pg), idle = idle_iterates(ev, q->k, pg, 0);
  memcpy(q->bestX, ev->X, ev->n * sizeof *ev->X);
  ev->rep->iterations = q->k;
  ev->rep->pgnorm = pg;
  if (pg <= ev->o->tol) slsqp_stop(q, "converged");
  else if (stop) slsqp_stop(q, "interrupted");
  else if (q->k >= ev->o->max_iter) slsqp_stop(q, "max_iter");
  else if (idle >= OPT_FEW) slsqp_stop(q, "no_progress"), idle_detail(ev);
  q->k++;
}
#line 850 "paper/opt.nw"
static int metric_setup(Evaluator *ev, Metric *mt)
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
  double start = model_clock();
  if ((rc = model_contact_stiffness(ev->md, mt->R, ev->st))) return rc;
  
#line 870 "paper/opt.nw"
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
#line 864 "paper/opt.nw"
  ev->rep->metric_seconds += model_clock() - start;
  return rc;
}
#line 900 "paper/opt.nw"
static int slsqp(Evaluator *ev, double *X)
{
  int n = ev->n, m = 2 * n + 2 * (n - 1), rc;
  double *work = malloc(((size_t) n * n + 2 * n + m) * sizeof *work);
  Slsqp q = { ev, NULL, { n, NULL, NULL, 1 }, HUGE_VAL, 0, X, 0, 0, 0 };
  if (!work) return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  q.metric.R = work, q.metric.X0 = work + (size_t) n * n;
  double *y = q.metric.X0 + n, *tol = y + n, f;
  for (int more = 1; more; ) {
    memcpy(q.metric.X0, X, n * sizeof *X);
    if ((rc = evaluate(ev, X)) || (rc = metric_setup(ev, &q.metric))) break;
    if (!(q.opt = nlopt_create(NLOPT_LD_SLSQP, n))) {
      rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
      break;
    }
    
#line 923 "paper/opt.nw"
for (int i = 0; i < m; i++) tol[i] = 1e-14;
for (int i = 0; i < n; i++) y[i] = 0;
nlopt_result r = nlopt_add_inequality_mconstraint(q.opt, m, linear_constraints, &q, tol);
if (r > 0) r = nlopt_add_equality_constraint(q.opt, area_constraint, &q, 1e-14);
if (r > 0) r = nlopt_set_min_objective(q.opt, slsqp_objective, &q);
if (r > 0) r = nlopt_set_maxeval(q.opt, 50 * (ev->o->max_iter + 1) - ev->rep->evaluations + 1);
if (r > 0) r = nlopt_optimize(q.opt, y, &f);
nlopt_destroy(q.opt);
#line 940 "paper/opt.nw"
if (!(rc = ev->failed) && r == NLOPT_OUT_OF_MEMORY)
  rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
more = !rc && !ev->rep->stop_reason[0]
       && r != NLOPT_MAXEVAL_REACHED && q.fresh > 0;
if (!rc && !more && !ev->rep->stop_reason[0]) {
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s",
           r == NLOPT_MAXEVAL_REACHED ? "max_iter" : "no_progress");
  
#line 957 "paper/opt.nw"
if (r != NLOPT_MAXEVAL_REACHED)
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "SLSQP, %s, found no "
           "new iterate: %s%s", ev->rep->iterations ? "restarted from its last iterate"
           : "from the start", r == NLOPT_FORCED_STOP ? "its line search found no design "
           "in B with a lower energy" : "NLopt ended it as ",
           r == NLOPT_FORCED_STOP ? "" : nlopt_result_to_string(r));
#line 948 "paper/opt.nw"
}
if (!rc) rc = evaluate(ev, X);
q.fresh = q.stalled = 0;
(void) f;
#line 916 "paper/opt.nw"
  }
  free(work);
  return rc;
}
#line 1000 "paper/opt.nw"
typedef struct {
  Evaluator *ev;
  Newton_workspace *qp;   /* the model problem's solver */
  Newton_model mdl;       /* the model at the iterate */
  int n, m;               /* design nodes, contact unknowns */
  double rho;             /* the trust in the model, see above */
  double *S, *f, *g, *r, *v0;   /* m*m, m, n, n, m: the model's data */
  double *d, *v, *trial;  /* n, m, n: its solution and the trial design */
  double *Xk;             /* n: the iterate (the evaluator moves to trials) */
  double Ek, noisek;      /* E and its rounding delta E at the iterate */
  double rho_max;         /* from it on, the step is below the design's rounding */
  int measured;           /* the last step was judged by its ratio, or E fell
                             by more than its rounding */
  int failed;             /* models that failed since the last accepted step */
  int refused;            /* trials refused since then, failed models included */
  int sick;               /* iterations in a row whose model failed */
  char failure[400];      /* what the last model that failed measured */
} Newton_run;
#line 1026 "paper/opt.nw"
static int newton_model_at(Newton_run *nr)
{
  Evaluator *ev = nr->ev;
  const Model *md = ev->md;
  int n = nr->n, m = nr->m, rc;
  double mean = 0, Gmax = 0;
  if (m > 0 && (rc = qp_schur(md->solver, 0, nr->S, ev->st))) return rc;
  for (int c = 0; c < m; c++) {
    double sq = 0;
    for (int e = 0; e < m; e++) sq += nr->S[(size_t) c * m + e] * md->Q[md->dofs->contact[e]];
    nr->v0[c] = md->Q[md->dofs->contact[c]];
    nr->f[c] = sq - md->T[c];
    mean += nr->S[(size_t) c * m + c] / m;
  }
  for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev->G[i]));
  if (m == 0) mean = Gmax > 0 ? Gmax / ev->B->C0 : 1;
  for (int i = 0; i < n; i++) nr->g[i] = ev->G[i], nr->r[i] = mean;
  for (int c = 0; c < m; c++) {
    nr->g[md->dofs->contact_col[c]] += md->T[c];
    nr->r[md->dofs->contact_col[c]] = nr->S[(size_t) c * m + c];
  }
  memcpy(nr->Xk, ev->X, n * sizeof *nr->Xk);
  nr->Ek = ev->E, nr->noisek = ev->noise;
  
#line 1207 "paper/opt.nw"
double G2 = 0, rmin = HUGE_VAL;
for (int i = 0; i < n; i++) G2 += ev->G[i] * ev->G[i], rmin = fmin(rmin, nr->r[i]);
nr->rho_max = 2 * sqrt(G2) / (DBL_EPSILON * ev->B->C0 * rmin);
#line 1050 "paper/opt.nw"
  return STATUS_OK;
}
#line 1116 "paper/opt.nw"
/* eps times the sum of the magnitudes of the terms of m(0, v0) and m(d, v),
   with the curvature rho r the model was solved with */
static double model_rounding(const Newton_run *nr)
{
  double sum = 0;
  for (int i = 0; i < nr->n; i++)
    sum += fabs(nr->g[i] * nr->d[i]) + 0.5 * nr->rho * nr->r[i] * nr->d[i] * nr->d[i];
  for (int c = 0; c < nr->m; c++) {
    double s0 = 0, s1 = 0;
    for (int e = 0; e < nr->m; e++) {
      s0 += fabs(nr->S[(size_t) c * nr->m + e] * nr->v0[e]);
      s1 += fabs(nr->S[(size_t) c * nr->m + e] * nr->v[e]);
    }
    sum += (0.5 * s0 + fabs(nr->f[c])) * fabs(nr->v0[c])
         + (0.5 * s1 + fabs(nr->f[c])) * fabs(nr->v[c]);
  }
  return DBL_EPSILON * sum;
}
#line 1058 "paper/opt.nw"
static int newton_try(Newton_run *nr, int *accepted)
{
  Evaluator *ev = nr->ev;
  Newton_report nrep;
  int n = nr->n, rc;
  double start = model_clock(), E0 = nr->Ek, noise0 = nr->noisek;
  for (int i = 0; i < n; i++) nr->r[i] *= nr->rho;
  rc = newton_solve(nr->qp, &nr->mdl, nr->d, nr->v, &nrep, ev->st);
  for (int i = 0; i < n; i++) nr->r[i] /= nr->rho;
  if (rc == STATUS_NUMERIC) {          /* a model too ill-conditioned: trust less */
    ev->rep->model_seconds += model_clock() - start;
    nr->rho *= 4, *accepted = 0, nr->failed++, nr->refused++;
    snprintf(nr->failure, sizeof nr->failure, "%.*s", (int) sizeof nr->failure - 1, ev->st->msg);
    ev->st->code = STATUS_OK, ev->st->msg[0] = 0;
    return STATUS_OK;
  }
  for (int i = 0; !rc && i < n; i++) nr->trial[i] = nr->Xk[i] + nr->d[i];
  if (!rc) rc = design_project(ev->B, nr->trial, nr->trial, NULL, ev->st);
  ev->rep->model_seconds += model_clock() - start;
  if (rc || (rc = evaluate(ev, nr->trial))) return rc;
  double ared = E0 - ev->E, Enoise = noise0 + ev->noise, noise = Enoise + model_rounding(nr);
  double ratio = nrep.pred > 0 ? ared / nrep.pred : 0;
  *accepted = nrep.pred > noise ? ratio >= 0.1 : ared >= -noise;
  nr->measured = nrep.pred > noise || ared > Enoise;
  if (!*accepted) nr->rho *= 4, nr->refused++;
  else if (ratio > 0.75 && ared > Enoise) nr->rho = fmax(nr->rho / 8, 1e-15);
  return STATUS_OK;
}
#line 1238 "paper/opt.nw"
static void newton_why(const Newton_run *nr)
{
  char *s = nr->ev->rep->stop_detail;
  size_t z = sizeof nr->ev->rep->stop_detail;
  if (nr->rho >= nr->rho_max && nr->failed == nr->refused)
    snprintf(s, z, "the model problem failed at every trust, %d in a row; "
             "the last: %s", nr->failed, nr->failure);
  else if (nr->rho >= nr->rho_max)
    snprintf(s, z, "%d trials in a row refused (%d of them failed models): "
             "the trust region has shrunk the model's step below the rounding "
             "of the design", nr->refused, nr->failed);
  else if (nr->ev->idle >= OPT_FEW) idle_detail(nr->ev);
  else
    snprintf(s, z, "the model problem failed in %d iterations in a row; "
             "the last: %s", nr->sick, nr->failure);
}
#line 1216 "paper/opt.nw"
/* 1 when the run ends at this trial, its stop reason in the report */
static int newton_end(Newton_run *nr, int k, int accepted, double pg, int stop)
{
  const Opt_options *o = nr->ev->o;
  if (accepted) {
    idle_iterates(nr->ev, k, pg, k > 0 && nr->measured);
    nr->sick = k > 0 && nr->failed > 0 ? nr->sick + 1 : 0;
    nr->failed = nr->refused = 0;
  }
  const char *why = pg <= o->tol ? "converged"
                  : stop ? "interrupted"
                  : k >= o->max_iter ? "max_iter"
                  : nr->rho >= nr->rho_max || nr->ev->idle >= OPT_FEW
                    || nr->sick >= OPT_FEW ? "no_progress" : NULL;
  if (!why) return 0;
  snprintf(nr->ev->rep->stop_reason, sizeof nr->ev->rep->stop_reason, "%s", why);
  if (!strcmp(why, "no_progress")) newton_why(nr);
  return 1;
}
#line 1261 "paper/opt.nw"
static int newton(Evaluator *ev, double *X)
{
  int n = ev->n, m = ev->md->dofs->nc, rc = STATUS_OK, k = 0, accepted = 1;
  size_t mm = (size_t) (m > 0 ? m : 1);
  Newton_run nr = { .ev = ev, .qp = newton_alloc(n, m, ev->st), .n = n, .m = m,
                    .S = malloc((mm * mm + 3 * mm + 5 * (size_t) n) * sizeof(double)) };
  if (!nr.qp || !nr.S) {
    newton_free(nr.qp), free(nr.S);
    if (!nr.qp) return (int) ev->st->code;      /* newton_alloc said why */
    return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  }
  nr.f = nr.S + mm * mm, nr.v0 = nr.f + mm, nr.v = nr.v0 + mm;
  nr.g = nr.v + mm, nr.r = nr.g + n, nr.d = nr.r + n, nr.trial = nr.d + n, nr.Xk = nr.trial + n;
  nr.mdl = (Newton_model) { n, m, ev->md->dofs->contact_col, nr.Xk, ev->B, nr.g,
                            nr.r, nr.S, nr.f, nr.v0 };
  double pg = HUGE_VAL;
  
#line 1299 "paper/opt.nw"
if ((rc = newton_model_at(&nr))) {
  newton_free(nr.qp), free(nr.S);
  return rc;
}
double Gmax = 0, Dmean = 0;
for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev->G[i])), Dmean += nr.r[i] / n;
nr.rho = Gmax > 0 ? fmin(1e-2, Gmax / (ev->B->C0 * Dmean)) : 1e-2;
#line 1278 "paper/opt.nw"
  for (;;) {
    if (accepted && ((k > 0 && (rc = newton_model_at(&nr)))
                     || (rc = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))))
      break;
    int stop = accepted && report_iterate(ev, k, pg);
    if (accepted) ev->rep->pgnorm = pg, ev->rep->iterations = k;
    if (newton_end(&nr, k, accepted, pg, stop)) break;
    if ((rc = newton_try(&nr, &accepted))) break;
    if (accepted) k++;
  }
  memcpy(X, nr.Xk, n * sizeof *X);
  if (!rc) rc = evaluate(ev, X);
  newton_free(nr.qp), free(nr.S);
  return rc;
}
#line 1315 "paper/opt.nw"
int opt_minimize(Model *md, const Design_set *B, const Opt_options *o,
                 double *X, Opt_monitor monitor, void *data, Opt_report *rep,
                 Status *st)
{
  int n = B->N + 1, rc;
  Evaluator ev = { .md = md, .B = B, .o = o, .n = n, .X = malloc(2 * n * sizeof(double)),
                   .start = model_clock(), .monitor = monitor, .data = data, .rep = rep,
                   .st = st };
  memset(rep, 0, sizeof *rep);
  if (!ev.X) return status_set(st, STATUS_MEMORY, "optimiser: out of memory");
  ev.G = ev.X + n;
  if (!(rc = evaluate(&ev, X))) {
    
#line 1340 "paper/opt.nw"
double Gmax = 0;
for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev.G[i]));
ev.tau = B->C0 / (Gmax > 0 ? Gmax : 1.0);
#line 1328 "paper/opt.nw"
    rc = o->method == OPT_SLSQP ? slsqp(&ev, X)
       : o->method == OPT_NEWTON ? newton(&ev, X) : projgrad(&ev, X);
  }
  if (!rc) rep->energy = md->energy;
  rep->seconds = model_clock() - ev.start;
  free(ev.X);
  return rc;
}
#line 1356 "paper/opt.nw"
double opt_memory(const Opt_options *o, int N)
{
  double n = N + 1.0, k = o->method == OPT_NEWTON ? 4 : o->method == OPT_SLSQP ? 12 : 0;
  return 8 * k * n * n;
}
