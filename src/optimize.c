#line 93 "paper/optimize.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <nlopt.h>
#include "optimize.h"
#include "sensitivity.h"

#line 112 "paper/optimize.nw"
typedef struct {
  Model *md;              /* the state at the last design evaluated */
  const Design_set *B;
  const Scene *s;
  int n;                  /* N+1 */
  double *X;              /* n: the last design evaluated */
  double *G;              /* n: grad E there */
  double E;               /* E there */
  int have;               /* X, G, E are valid */
  int solves;             /* state solves so far */
  double tau;             /* the step of pi, fixed at the start */
  double start;           /* clock at the start */
  Opt_monitor monitor;
  void *data;
  Opt_report *rep;
  Status *st;
  int failed;             /* a status to return after NLopt stops */
} Evaluator;
#line 133 "paper/optimize.nw"
static double opt_clock(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int evaluate(Evaluator *ev, const double *X)
{
  if (ev->have && !memcmp(ev->X, X, ev->n * sizeof *X)) return STATUS_OK;
  ev->have = 0;
  int rc = model_solve(ev->md, X, ev->st);
  ev->solves++;
  if (ev->rep) ev->rep->evaluations++;
  if (rc || (rc = grad_energy(ev->md, ev->G, ev->st))) return rc;
  memcpy(ev->X, X, ev->n * sizeof *X);
  ev->E = ev->md->energy;
  ev->have = 1;
  return STATUS_OK;
}
#line 156 "paper/optimize.nw"
int opt_pgnorm(const Design_set *B, const double *X, const double *G,
               double tau, double *pg, Status *st)
{
  double residual;                      /* ||X - P_B(X - tau G)|| / tau */
  int rc = design_kkt(B, X, G, tau, NULL, NULL, &residual, st);
  *pg = residual * tau / B->C0;
  return rc;
}
#line 167 "paper/optimize.nw"
static void report_iterate(Evaluator *ev, int iteration, double pg)
{
  Opt_progress p = { iteration, ev->E, pg, ev->solves, ev->md->report.active,
                     ev->md->report.iterations, opt_clock() - ev->start };
  if (ev->monitor) ev->monitor(&p, ev->X, ev->data);
}
#line 187 "paper/optimize.nw"
typedef struct {
  double *trial;          /* n: P_B(X - tG) */
  double *Y;              /* n: X - tG */
  double *X, *G;          /* n each: the iterate and its gradient */
} Projgrad_work;

static int projgrad_step(Evaluator *ev, double *t, Projgrad_work *w,
                         int *accepted)
{
  int n = ev->n, rc;
  double E0 = ev->E, *Xn = w->trial, *Y = w->Y, *X = w->X, *G = w->G;
  memcpy(X, ev->X, n * sizeof *X);
  memcpy(G, ev->G, n * sizeof *G);
  *accepted = 0;
  for (int halving = 0; halving < 50 && !*accepted; halving++, *t /= 2) {
    for (int i = 0; i < n; i++) Y[i] = X[i] - *t * G[i];
    if ((rc = design_project(ev->B, Y, Xn, NULL, ev->st))) return rc;
    double descent = 0;
    for (int i = 0; i < n; i++) descent += G[i] * (Xn[i] - X[i]);
    if (descent >= 0) continue;                /* the arc has collapsed */
    if ((rc = evaluate(ev, Xn))) return rc;
    *accepted = ev->E <= E0 + 1e-4 * descent;
  }
  if (*accepted) *t *= 4;                      /* undo the last halving, then double */
  else if ((rc = evaluate(ev, X))) return rc;  /* back to the last iterate */
  return STATUS_OK;
}
#line 217 "paper/optimize.nw"
static int projgrad(Evaluator *ev, double *X)
{
  int n = ev->n, rc, accepted = 1, k = 0;
  double t = ev->tau, pg;
  double *work = malloc(4 * n * sizeof *work);
  Projgrad_work w = { work, work + n, work + 2 * n, work + 3 * n };
  if (!work) return status_set(ev->st, STATUS_SYSTEM, "optimiser: out of memory");
  for (;; k++) {
    if ((rc = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))) break;
    report_iterate(ev, k, pg);
    ev->rep->pgnorm = pg;
    
#line 239 "paper/optimize.nw"
const char *why = pg <= ev->s->opt_tol ? "converged"
                : !accepted ? "no_progress"
                : k >= ev->s->opt_max_iter ? "max_iter" : NULL;
if (why) {
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s", why);
  break;
}
#line 229 "paper/optimize.nw"
    if ((rc = projgrad_step(ev, &t, &w, &accepted))) break;
  }
  ev->rep->iterations = k;
  memcpy(X, ev->X, n * sizeof *X);
  free(work);
  return rc;
}
#line 259 "paper/optimize.nw"
static void slope_constraints(unsigned m, double *c, unsigned n,
                              const double *z, double *grad, void *data)
{
  const Design_set *B = data;
  double d = B->delta / B->C0;           /* the slope bound in units of C0 */
  if (grad) memset(grad, 0, m * n * sizeof *grad);
  for (unsigned i = 0; i + 1 < n; i++) {
    c[2 * i] = z[i + 1] - z[i] - d;       /* rising at most C1 h */
    c[2 * i + 1] = z[i] - z[i + 1] - d;   /* falling at most C1 h */
    if (grad) {
      grad[2 * i * n + i + 1] = 1; grad[2 * i * n + i] = -1;
      grad[(2 * i + 1) * n + i] = 1; grad[(2 * i + 1) * n + i + 1] = -1;
    }
  }
}
#line 278 "paper/optimize.nw"
static double area_constraint(unsigned n, const double *z, double *grad,
                              void *data)
{
  const Design_set *B = data;
  double L = B->h * B->N, sum = 0;
  for (unsigned i = 0; i < n; i++) {
    double w = (i == 0 || i + 1 == n) ? 0.5 : 1.0;
    sum += w * z[i];
    if (grad) grad[i] = w * B->h / L;
  }
  return (B->h * sum - B->area / B->C0) / L;
}
#line 298 "paper/optimize.nw"
typedef struct {
  Evaluator *ev;
  nlopt_opt opt;
  double scale;           /* of the energy, see above */
  double best;            /* the lowest E evaluated */
  double *bestX;          /* n: where; the last accepted iterate */
  int k;                  /* accepted iterates so far */
} Slsqp;
static void slsqp_accept(Slsqp *q);

static double slsqp_objective(unsigned n, const double *z, double *grad,
                              void *data)
{
  Slsqp *q = data;
  Evaluator *ev = q->ev;
  double X[n];
  for (unsigned i = 0; i < n; i++) X[i] = ev->B->C0 * z[i];
  if ((ev->failed = evaluate(ev, X))) { nlopt_force_stop(q->opt); return HUGE_VAL; }
  if (grad) for (unsigned i = 0; i < n; i++) grad[i] = ev->B->C0 * ev->G[i] / q->scale;
  if (ev->E < q->best) slsqp_accept(q);
  return ev->E / q->scale;
}
#line 323 "paper/optimize.nw"
static void slsqp_accept(Slsqp *q)
{
  Evaluator *ev = q->ev;
  double pg;
  q->best = ev->E;
  if ((ev->failed = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))) {
    nlopt_force_stop(q->opt);
    return;
  }
  report_iterate(ev, q->k, pg);
  memcpy(q->bestX, ev->X, ev->n * sizeof *ev->X);
  ev->rep->iterations = q->k;
  ev->rep->pgnorm = pg;
  const char *why = pg <= ev->s->opt_tol ? "converged"
                  : q->k >= ev->s->opt_max_iter ? "max_iter" : NULL;
  if (why) {
    snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s", why);
    nlopt_force_stop(q->opt);
  }
  q->k++;
}
#line 355 "paper/optimize.nw"
static int slsqp(Evaluator *ev, double *X)
{
  int n = ev->n;
  double z[n], f, tol[2 * (n - 1) + 1];
  Slsqp q = { ev, nlopt_create(NLOPT_LD_SLSQP, n), 0, HUGE_VAL, X, 0 };
  if (!q.opt) return status_set(ev->st, STATUS_SYSTEM, "optimiser: NLopt failed");
  
#line 377 "paper/optimize.nw"
double Gmax = 0;
for (int i = 0; i < n; i++) {
  z[i] = X[i] / ev->B->C0;
  Gmax = fmax(Gmax, fabs(ev->G[i]));
}
q.scale = ev->B->C0 * (Gmax > 0 ? Gmax : 1.0);
#line 362 "paper/optimize.nw"
  for (int i = 0; i < 2 * (n - 1) + 1; i++) tol[i] = 1e-14;
  nlopt_set_lower_bounds1(q.opt, 0.0);
  nlopt_set_upper_bounds1(q.opt, 1.0);
  nlopt_add_inequality_mconstraint(q.opt, 2 * (n - 1), slope_constraints,
                                   (void *) ev->B, tol);
  nlopt_add_equality_constraint(q.opt, area_constraint, (void *) ev->B, 1e-14);
  nlopt_set_min_objective(q.opt, slsqp_objective, &q);
  nlopt_set_maxeval(q.opt, 50 * (ev->s->opt_max_iter + 1));
  nlopt_result r = nlopt_optimize(q.opt, z, &f);
  nlopt_destroy(q.opt);
  
#line 390 "paper/optimize.nw"
if (ev->failed) return ev->failed;
if (!ev->rep->stop_reason[0])
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s",
           r == NLOPT_MAXEVAL_REACHED ? "max_iter" : "no_progress");
(void) f;
return evaluate(ev, X);
#line 373 "paper/optimize.nw"
}
#line 405 "paper/optimize.nw"
int opt_minimize(Model *md, const Design_set *B, const Scene *s, double *X,
                 Opt_monitor monitor, void *data, Opt_report *rep, Status *st)
{
  int n = B->N + 1, rc;
  Evaluator ev = { md, B, s, n, malloc(2 * n * sizeof(double)), NULL, 0, 0,
                   0, 0, opt_clock(), monitor, data, rep, st, 0 };
  memset(rep, 0, sizeof *rep);
  if (!ev.X) return status_set(st, STATUS_SYSTEM, "optimiser: out of memory");
  ev.G = ev.X + n;
  if (!(rc = evaluate(&ev, X))) {
    double Gmax = 0;
    for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev.G[i]));
    ev.tau = B->C0 / (Gmax > 0 ? Gmax : 1.0);
    rc = s->opt == OPT_SLSQP ? slsqp(&ev, X) : projgrad(&ev, X);
  }
  if (!rc) rep->energy = md->energy;
  free(ev.X);
  return rc;
}
