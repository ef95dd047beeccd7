#line 395 "paper/opt.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "opt_private.h"
#line 408 "paper/opt.nw"
const char *const opt_method_names[] = {"slsqp", "projgrad", "newton", "mma", NULL};
const char *const opt_metric_names[] = {"schur", "euclidean", NULL};

Opt_options opt_options_default(Opt_method method)
{
  return (Opt_options) { method, method == OPT_PROJGRAD ? OPT_METRIC_EUCLIDEAN
                                                       : OPT_METRIC_SCHUR,
                         1e-6, 200, objective_default(), 0, 1 };
}

const char *opt_method_name(Opt_method m)
{
  return (unsigned)m <= OPT_MMA ? opt_method_names[m] : "?";
}

const char *opt_metric_name(Opt_metric m)
{
  return (unsigned)m <= OPT_METRIC_EUCLIDEAN ? opt_metric_names[m] : "?";
}
#line 436 "paper/opt.nw"
int opt_refusal(Opt_method m, const Objective *o, Problem_contact_law contact,
                const char *path, Status *st)
{
  if (m == OPT_NEWTON && contact == CONTACT_COULOMB)
    return status_set(st, STATUS_INPUT, "%s: contact.model = coulomb: "
                      "optimizer.method = newton models the Hessian of a Tresca "
                      "energy, not the cost J_F of a Coulomb state; use slsqp or "
                      "mma (or name no method: slsqp is chosen)", path);
  if (m == OPT_NEWTON && !objective_is_energy(o->kind))
    return status_set(st, STATUS_INPUT, "%s: optimizer.method = newton minimises "
                      "the energy only; objective.kind = %s needs slsqp, "
                      "mma or projgrad (or name no method: slsqp is chosen)",
                      path, objective_name(o->kind));
  return STATUS_OK;
}
#line 2128 "paper/opt.nw"
/* after a method failed at a design that lifts off: back to the last
   iterate, stop_reason lift_off */
static int opt_lift_off(Opt_evaluator *ev, double *X)
{
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "lift_off");
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "a trial design "
           "after iterate %d: %.400s", ev->rep->iterations, ev->st->msg);
  *ev->st = (Status) { STATUS_OK, "" };
  memcpy(X, ev->Xacc, ev->n * sizeof *X);
  return opt_evaluate(ev, X);
}

int opt_minimize(Model *md, const Design_set *B, const Opt_options *o,
                 double *X, Opt_monitor monitor, void *data, Opt_report *rep,
                 Status *st)
{
  int n = B->N + 1, rc;
  Opt_evaluator ev = { .md = md, .B = B, .o = o, .n = n, .X = malloc(3 * n * sizeof(double)),
                   .start = resources_clock(), .monitor = monitor, .data = data, .rep = rep,
                   .st = st };
  memset(rep, 0, sizeof *rep);
  if (!ev.X) return status_set(st, STATUS_MEMORY, "optimiser: out of memory");
  ev.G = ev.X + n, ev.Xacc = ev.G + n;
  if (!(rc = opt_evaluate(&ev, X))) {
    
#line 2167 "paper/opt.nw"
double Gmax = 0;
for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev.G[i]));
ev.tau = B->C0 / (Gmax > 0 ? Gmax : 1.0);
#line 2153 "paper/opt.nw"
    rc = o->method == OPT_SLSQP ? opt_slsqp(&ev, X)
       : o->method == OPT_MMA ? opt_mma(&ev, X)
       : o->method == OPT_NEWTON ? opt_newton(&ev, X) : opt_projgrad(&ev, X);
    if (rc && ev.lifted && ev.accepted) rc = opt_lift_off(&ev, X);
  }
  if (!rc) rep->energy = model_energy(md);
  rep->seconds = resources_clock() - ev.start;
  free(ev.X);
  return rc;
}
#line 2184 "paper/opt.nw"
double opt_memory(const Opt_options *o, int N)
{
  double n = N + 1.0, k = o->method == OPT_NEWTON ? 4
                        : o->method == OPT_SLSQP || o->method == OPT_MMA ? 12 : 0;
  return 8 * k * n * n;
}
#line 2235 "paper/opt.nw"
int opt_start_design(const Design_set *B, int k, double *X, Status *st)
{
  int N = B->N, j = (k + 1) / 2;
  double c = B->area / (N * B->h), a = fmin(c, B->C0 - c), s = k % 2 ? 1 : -1;
  double pi = acos(-1.0);
  for (int i = 0; i <= N; i++) X[i] = c + s * a * cos(j * pi * i / N);
  return design_project(B, X, X, NULL, st);
}
#line 2316 "paper/opt.nw"
/* X on 2 Nc intervals = the linear interpolation of X on Nc, in place:
   X_2i = X_i, X_2i+1 = (X_i + X_i+1) / 2 */
void opt_interpolate(double *X, int Nc)
{
  for (int i = Nc; i > 0; i--) X[2 * i] = X[i];
  for (int i = 0; i < Nc; i++) X[2 * i + 1] = 0.5 * (X[2 * i] + X[2 * i + 2]);
}

/* X on 2 Nc intervals = X on Nc prolonged, in place: X_2i = X_i, the new
   nodes by the four-point rule, by the mean in the end intervals */
static void opt_prolong(double *X, int Nc)
{
  opt_interpolate(X, Nc);
  for (int i = 1; i + 1 < Nc; i++)
    X[2 * i + 1] = (9 * (X[2 * i] + X[2 * i + 2]) - X[2 * i - 2] - X[2 * i + 4]) / 16;
}
#line 2339 "paper/opt.nw"
#define LEVELS_FROM 256       /* the least N that the default refines to */
#define LEVELS_COARSEST 64    /* the least N of a default coarse level */
#define LEVELS_TOL 100        /* a coarse level's tol, in the caller's */
int opt_levels(const Problem *p, const Opt_options *o)
{
  int want = o->levels, n = p->N, m = p->M, r = p->R, l = 1;
  if (want == 0 && n < LEVELS_FROM) return 1;
  while ((want ? l < want : n / 2 >= LEVELS_COARSEST)
         && n % 2 == 0 && m % 2 == 0 && r % 2 == 0)
    n /= 2, m /= 2, r /= 2, l++;
  return l;
}
#line 2367 "paper/opt.nw"
static int opt_level(const Problem *q, const Qp_options *solver,
                     const Opt_options *o, double *Y, double *gap, Opt_monitor stop,
                     cholmod_common *cm, Opt_report *coarse, Status *st);
int opt_coarse_start(const Problem *p, const Qp_options *solver,
                     const Opt_options *o, int levels, double *X, Model *fine,
                     Opt_monitor stop, cholmod_common *cm, Opt_report *coarse,
                     Status *st)
{
  int f = 1 << (levels - 1), rc = STATUS_OK, guess = solver->method == QP_PDAS;
  Problem q = *p;
  q.N /= f, q.M /= f, q.R /= f;
  double *Y = malloc(4 * ((size_t) p->N + 1) * sizeof *Y), *gap = Y + 2 * ((size_t) p->N + 1);
  memset(coarse, 0, sizeof *coarse);
  if (!Y) return status_set(st, STATUS_MEMORY, "optimiser: out of memory");
  for (int i = 0; i <= q.N; i++) Y[i] = X[i * f];
  for (int l = 1; !rc && !coarse->stop_reason[0] && l < levels; l++) {
    rc = opt_level(&q, solver, o, Y, guess ? gap : NULL, stop, cm, coarse, st);
    opt_prolong(Y, q.N);
    if (guess) opt_interpolate(gap, q.N);
    q.N *= 2, q.M *= 2, q.R *= 2;
  }
  Design_set B = design_set(p);
  double v, moved;
  int done = !rc && !coarse->stop_reason[0];
  if (done) rc = design_feasible_start(&B, Y, 1e-12, X, &v, &moved, st);
  if (done && !rc && guess && fine) model_guess_contact(fine, X, gap);
  free(Y);
  return rc;
}
#line 2407 "paper/opt.nw"
static int opt_level(const Problem *q, const Qp_options *solver,
                     const Opt_options *o, double *Y, double *gap, Opt_monitor stop,
                     cholmod_common *cm, Opt_report *coarse, Status *st)
{
  Design_set B = design_set(q);
  Opt_report rep;
  Opt_options oq = *o;
  oq.tol = fmax(o->tol, fmin(LEVELS_TOL * o->tol, 1e-2));
  double v, moved, *Z = malloc(((size_t) q->N + 1) * sizeof *Z);
  Model *md = Z ? model_new(q, solver, cm, st) : NULL;
  int rc = !Z ? status_set(st, STATUS_MEMORY, "optimiser: out of memory")
         : !md ? (int) st->code : design_feasible_start(&B, Y, 1e-12, Z, &v, &moved, st);
  if (!rc) memcpy(Y, Z, ((size_t) q->N + 1) * sizeof *Y);
  if (!rc && gap && coarse->levels) model_guess_contact(md, Y, gap);
  if (!rc && !(rc = opt_minimize(md, &B, &oq, Y, stop, NULL, &rep, st))) {
    if (!strcmp(rep.stop_reason, "interrupted"))
      memcpy(coarse->stop_reason, rep.stop_reason, sizeof rep.stop_reason);
    coarse->evaluations += rep.evaluations, coarse->iterations += rep.iterations;
    coarse->seconds += rep.seconds;
    if (gap) model_contact_gaps(md, gap);
    coarse->levels++;
  }
  model_free(md);
  free(Z);
  return rc;
}
