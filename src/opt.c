#line 322 "paper/opt.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "opt_private.h"
#include "grad.h"
#line 335 "paper/opt.nw"
const char *const opt_method_names[] = {"slsqp", "projgrad", "newton", NULL};
const char *const opt_metric_names[] = {"schur", "euclidean", NULL};

Opt_options opt_options_default(Opt_method method)
{
  return (Opt_options) { method, method == OPT_PROJGRAD ? OPT_METRIC_EUCLIDEAN
                                                       : OPT_METRIC_SCHUR,
                         1e-6, 200, objective_default() };
}

const char *opt_method_name(Opt_method m)
{
  return (unsigned)m <= OPT_NEWTON ? opt_method_names[m] : "?";
}

const char *opt_metric_name(Opt_metric m)
{
  return (unsigned)m <= OPT_METRIC_EUCLIDEAN ? opt_metric_names[m] : "?";
}
#line 390 "paper/opt.nw"
/* the rounding of another objective than E: relative to |J| + 1 (the
   pressure spread is a difference from 1) */
#define OPT_J_ROUNDING (64 * DBL_EPSILON)

int opt_evaluate(Evaluator *ev, const double *X)
{
  if (ev->have && !memcmp(ev->X, X, ev->n * sizeof *X)) return STATUS_OK;
  ev->have = 0;
  double start = resources_clock();
  int rc = model_solve(ev->md, X, ev->st);
  ev->solves++;
  const Objective *o = &ev->o->objective;
  double J = 0;
  if (!rc) rc = o->kind == OBJECTIVE_ENERGY ? grad_energy(ev->md, ev->G, ev->st)
    : objective_value(ev->md, o, &J, ev->st) || objective_gradient(ev->md, o, ev->G, ev->st)
    ? (int) ev->st->code : STATUS_OK;
  if (ev->rep)
    ev->rep->evaluations++, ev->rep->state_seconds += resources_clock() - start;
  if (rc) return rc;
  memcpy(ev->X, X, ev->n * sizeof *X);
  ev->E = o->kind == OBJECTIVE_ENERGY ? ev->md->energy : J;
  ev->noise = o->kind == OBJECTIVE_ENERGY ? model_energy_rounding(ev->md)
                                          : OPT_J_ROUNDING * (fabs(J) + 1);
  ev->have = 1;
  return STATUS_OK;
}
#line 451 "paper/opt.nw"
int opt_pgnorm(const Design_set *B, const double *X, const double *G,
               double tau, double *pg, Status *st)
{
  double residual;                      /* ||X - P_B(X - tau G)|| / tau */
  int rc = design_kkt(B, X, G, tau, NULL, NULL, &residual, st);
  *pg = residual * tau / B->C0;
  return rc;
}
#line 462 "paper/opt.nw"
/* 1 if the monitor asks to stop here; its time is the caller's */
int opt_report_iterate(Evaluator *ev, int iteration, double pg)
{
  double start = resources_clock();
  Opt_progress p = { iteration, ev->E, pg, ev->solves, ev->md->report.active,
                     ev->md->report.iterations, start - ev->start };
  int stop = ev->monitor && ev->monitor(&p, ev->X, ev->data);
  ev->rep->monitor_seconds += resources_clock() - start;
  return stop;
}
#line 493 "paper/opt.nw"
/* after the accepted iterate k, at the evaluator's design, with pi = pg:
   the iterates in a row without measured progress; judged: the method
   measured the step by its own test */
int opt_idle_iterates(Evaluator *ev, int k, double pg, int judged)
{
  int measured = k == 0 || judged || pg < 0.5 * ev->pg_best
              || ev->E < ev->last_E - (ev->noise + ev->last_noise);
  ev->idle = measured ? 0 : ev->idle + 1;
  if (k == 0 || pg < ev->pg_best) ev->pg_best = pg;
  ev->last_E = ev->E, ev->last_noise = ev->noise;
  return ev->idle;
}

/* the stop_detail of a run stopped by OPT_FEW idle iterates */
void opt_idle_detail(Evaluator *ev)
{
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "%d iterates in a row "
           "lowered E by no more than its rounding (%.1e J/m) and did not halve pi: "
           "the rounding of E allows no smaller pi", ev->idle, ev->noise);
}
#line 1359 "paper/opt.nw"
int opt_minimize(Model *md, const Design_set *B, const Opt_options *o,
                 double *X, Opt_monitor monitor, void *data, Opt_report *rep,
                 Status *st)
{
  int n = B->N + 1, rc;
  Evaluator ev = { .md = md, .B = B, .o = o, .n = n, .X = malloc(2 * n * sizeof(double)),
                   .start = resources_clock(), .monitor = monitor, .data = data, .rep = rep,
                   .st = st };
  memset(rep, 0, sizeof *rep);
  if (md->problem->contact == CONTACT_COULOMB && o->method == OPT_NEWTON)
    return free(ev.X), status_set(st, STATUS_INPUT, "optimiser: the Newton "
                                  "method has no model of a Coulomb state's cost");
  if (!ev.X) return status_set(st, STATUS_MEMORY, "optimiser: out of memory");
  ev.G = ev.X + n;
  md->fixed_point_rounding = 1;             /* Coulomb: forces to rounding */
  if (!(rc = opt_evaluate(&ev, X))) {
    
#line 1388 "paper/opt.nw"
double Gmax = 0;
for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev.G[i]));
ev.tau = B->C0 / (Gmax > 0 ? Gmax : 1.0);
#line 1376 "paper/opt.nw"
    rc = o->method == OPT_SLSQP ? opt_slsqp(&ev, X)
       : o->method == OPT_NEWTON ? opt_newton(&ev, X) : opt_projgrad(&ev, X);
  }
  if (!rc) rep->energy = md->energy;
  rep->seconds = resources_clock() - ev.start;
  free(ev.X);
  return rc;
}
#line 1404 "paper/opt.nw"
double opt_memory(const Opt_options *o, int N)
{
  double n = N + 1.0, k = o->method == OPT_NEWTON ? 4 : o->method == OPT_SLSQP ? 12 : 0;
  return 8 * k * n * n;
}
