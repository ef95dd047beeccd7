#line 395 "paper/opt.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "opt_private.h"
#line 497 "paper/opt.nw"
int opt_evaluate(Opt_evaluator *ev, const double *X)
{
  if (ev->have && !memcmp(ev->X, X, ev->n * sizeof *X)) return STATUS_OK;
  ev->have = 0;
  double start = resources_clock();
  int rc = model_solve_to_rounding(ev->md, X, ev->st);
  ev->solves++;
  double J = 0, dJ = 0;
  ev->lifted = 0;
  if (!rc && (rc = objective_evaluate(ev->md, &ev->o->objective, &J, ev->G, &dJ,
                                      ev->st)))
    ev->lifted = rc == STATUS_NUMERIC && isnan(J);  /* no contact node presses */
  if (ev->rep)
    ev->rep->evaluations++, ev->rep->state_seconds += resources_clock() - start;
  if (rc) return rc;
  memcpy(ev->X, X, ev->n * sizeof *X);
  ev->J = J, ev->noise = dJ;
  ev->have = 1;
  return STATUS_OK;
}
#line 552 "paper/opt.nw"
int opt_pgnorm(const Design_set *B, const double *X, const double *G,
               double tau, double *pg, Status *st)
{
  double residual;                      /* ||X - P_B(X - tau G)|| / tau */
  int rc = design_kkt(B, X, G, tau, NULL, NULL, &residual, st);
  *pg = residual * tau / B->C0;
  return rc;
}
#line 563 "paper/opt.nw"
/* 1 if the monitor asks to stop here; its time is the caller's */
int opt_report_iterate(Opt_evaluator *ev, int iteration, double pg)
{
  double start = resources_clock();
  Opt_progress p = { iteration, ev->J, pg, ev->solves, model_report(ev->md)->active,
                     model_report(ev->md)->iterations, start - ev->start };
  int stop = ev->monitor && ev->monitor(&p, ev->X, ev->data);
  ev->rep->monitor_seconds += resources_clock() - start;
  memcpy(ev->Xacc, ev->X, ev->n * sizeof *ev->X);
  ev->accepted++;
  return stop;
}
#line 603 "paper/opt.nw"
/* after the accepted iterate k, at the evaluator's design, with pi = pg:
   the iterates in a row without measured progress; judged: the method
   measured the step by its own test */
int opt_idle_iterates(Opt_evaluator *ev, int k, double pg, int judged)
{
  int measured = k == 0 || judged || pg < 0.5 * ev->pg_best
              || ev->J < ev->last_J - (ev->noise + ev->last_noise);
  ev->idle = measured ? 0 : ev->idle + 1;
  if (measured) ev->idle_J = ev->J;
  ev->pg_last = pg;
  if (k == 0 || pg < ev->pg_best) ev->pg_best = pg;
  ev->last_J = ev->J, ev->last_noise = ev->noise;
  return ev->idle;
}

/* the stop_detail of a run stopped by OPT_FEW idle iterates */
void opt_idle_detail(Opt_evaluator *ev)
{
  Objective_kind k = ev->o->objective.kind;
  const char *J = objective_symbol(k), *u = objective_unit(k);
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "the last %d iterates "
           "lowered %s by %.1e%s in all, none by more than the rounding of %s at its "
           "two ends (%.1e%s at the last), and none halved pi (%.2e at the last, "
           "%.2e the smallest of the run)", ev->idle, J, ev->idle_J - ev->J, u, J,
           ev->noise, u, ev->pg_last, ev->pg_best);
}
#line 634 "paper/opt.nw"
const char *opt_nlopt_iterate(Opt_evaluator *ev, int k, double *bestX)
{
  double pg;
  if ((ev->failed = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))) return NULL;
  int stop = opt_report_iterate(ev, k, pg), idle = opt_idle_iterates(ev, k, pg, 0);
  memcpy(bestX, ev->X, ev->n * sizeof *ev->X);
  ev->rep->iterations = k;
  ev->rep->pgnorm = pg;
  if (pg <= ev->o->tol) return "converged";
  if (stop) return "interrupted";
  if (k >= ev->o->max_iter) return "max_iter";
  if (idle >= OPT_FEW) { opt_idle_detail(ev); return "no_progress"; }
  return NULL;
}
#line 897 "paper/opt.nw"
/* c (4n - 2): the box and the slopes of B at X (n), <= 0 when met */
void opt_constraints(const Design_set *B, const double *X, unsigned n, double *c)
{
  double d = B->delta / B->C0;
  for (unsigned i = 0; i < n; i++) {
    c[2 * i] = -X[i] / B->C0;                       /* X_i >= 0 */
    c[2 * i + 1] = X[i] / B->C0 - 1;                /* X_i <= C0 */
  }
  for (unsigned i = 0; i + 1 < n; i++) {
    double rise = (X[i + 1] - X[i]) / B->C0;
    c[2 * n + 2 * i] = rise - d;                    /* rising at most C1 h */
    c[2 * n + 2 * i + 1] = -rise - d;               /* falling at most C1 h */
  }
}
#line 916 "paper/opt.nw"
/* grad ((4n - 2) x ny, row-major) = d c / d y for X = X0 + C0 R y */
void opt_constraints_gradient(const double *R, unsigned n, unsigned ny, double *grad)
{
  for (unsigned j = 0; j < ny; j++) {
    for (unsigned i = 0; i < n; i++) {
      grad[2 * i * ny + j] = -R[i * ny + j];
      grad[(2 * i + 1) * ny + j] = R[i * ny + j];
    }
    for (unsigned i = 0; i + 1 < n; i++) {
      double rise = R[(i + 1) * ny + j] - R[i * ny + j];
      grad[(2 * n + 2 * i) * ny + j] = rise;
      grad[(2 * n + 2 * i + 1) * ny + j] = -rise;
    }
  }
}

