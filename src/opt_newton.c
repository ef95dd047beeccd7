#line 385 "paper/opt.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "opt_private.h"
#include "newton.h"
#line 1826 "paper/opt.nw"
typedef struct {
  Opt_evaluator *ev;
  Newton_workspace *solver; /* the model problem's solver */
  Newton_model mdl;       /* the model at the iterate */
  int n, m;               /* design nodes, contact unknowns */
  double rho;             /* the trust in the model, see above */
  double *S, *f, *grad, *r, *v0;   /* m*m, m, n, n, m: the model's data */
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
#line 1852 "paper/opt.nw"
static int newton_model_at(Newton_run *nr)
{
  Opt_evaluator *ev = nr->ev;
  int n = nr->n, m = nr->m, rc;
  double mean = 0, Gmax = 0;
  const int *col = model_contact_columns(ev->md);
  if ((rc = model_contact_state(ev->md, nr->S, nr->v0, nr->f, ev->st))) return rc;
  for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev->G[i])), nr->grad[i] = ev->G[i];
  for (int c = 0; c < m; c++) {                          /* nr->f holds T */
    double sq = 0;
    for (int e = 0; e < m; e++) sq += nr->S[(size_t) c * m + e] * nr->v0[e];
    nr->grad[col[c]] += nr->f[c];
    nr->f[c] = sq - nr->f[c];
    mean += nr->S[(size_t) c * m + c] / m;
  }
  if (m == 0) mean = Gmax > 0 ? Gmax / ev->B->C0 : 1;
  for (int i = 0; i < n; i++) nr->r[i] = mean;
  for (int c = 0; c < m; c++) nr->r[col[c]] = nr->S[(size_t) c * m + c];
  memcpy(nr->Xk, ev->X, n * sizeof *nr->Xk);
  nr->Ek = ev->J, nr->noisek = ev->noise;
  
#line 2009 "paper/opt.nw"
double G2 = 0, rmin = HUGE_VAL;
for (int i = 0; i < n; i++) G2 += ev->G[i] * ev->G[i], rmin = fmin(rmin, nr->r[i]);
nr->rho_max = 2 * sqrt(G2) / (DBL_EPSILON * ev->B->C0 * rmin);
#line 1873 "paper/opt.nw"
  return STATUS_OK;
}
#line 1880 "paper/opt.nw"
static int newton_try(Newton_run *nr, int *accepted)
{
  Opt_evaluator *ev = nr->ev;
  Newton_report nrep;
  int n = nr->n, rc;
  double start = resources_clock(), E0 = nr->Ek, noise0 = nr->noisek;
  for (int i = 0; i < n; i++) nr->r[i] *= nr->rho;
  rc = newton_solve(nr->solver, &nr->mdl, nr->d, nr->v, &nrep, ev->st);
  for (int i = 0; i < n; i++) nr->r[i] /= nr->rho;
  if (rc == STATUS_NUMERIC) {          /* a model too ill-conditioned: trust less */
    ev->rep->model_seconds += resources_clock() - start;
    nr->rho *= 4, *accepted = 0, nr->failed++, nr->refused++;
    snprintf(nr->failure, sizeof nr->failure, "%.*s", (int) sizeof nr->failure - 1, ev->st->msg);
    ev->st->code = STATUS_OK, ev->st->msg[0] = 0;
    return STATUS_OK;
  }
  for (int i = 0; !rc && i < n; i++) nr->trial[i] = nr->Xk[i] + nr->d[i];
  if (!rc) rc = design_project(ev->B, nr->trial, nr->trial, NULL, ev->st);
  ev->rep->model_seconds += resources_clock() - start;
  if (rc || (rc = opt_evaluate(ev, nr->trial))) return rc;
  double ared = E0 - ev->J, Enoise = noise0 + ev->noise, noise = Enoise + nrep.rounding;
  double ratio = nrep.pred > 0 ? ared / nrep.pred : 0;
  *accepted = nrep.pred > noise ? ratio >= 0.1 : ared >= -noise;
  nr->measured = nrep.pred > noise || ared > Enoise;
  if (!*accepted) nr->rho *= 4, nr->refused++;
  else if (ratio > 0.75 && ared > Enoise) nr->rho = fmax(nr->rho / 8, 1e-15);
  else if (nrep.pred > noise && ratio < 0.25) nr->rho *= 2;
  return STATUS_OK;
}
#line 2040 "paper/opt.nw"
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
  else if (nr->ev->idle >= OPT_FEW) opt_idle_detail(nr->ev);
  else
    snprintf(s, z, "the model problem failed in %d iterations in a row; "
             "the last: %s", nr->sick, nr->failure);
}
#line 2018 "paper/opt.nw"
/* 1 when the run ends at this trial, its stop reason in the report */
static int newton_end(Newton_run *nr, int k, int accepted, double pg, int stop)
{
  const Opt_options *o = nr->ev->o;
  if (accepted) {
    opt_idle_iterates(nr->ev, k, pg, k > 0 && nr->measured);
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
#line 2063 "paper/opt.nw"
int opt_newton(Opt_evaluator *ev, double *X)
{
  int n = ev->n, m = model_contact_count(ev->md), rc = STATUS_OK, k = 0, accepted = 1;
  size_t mm = (size_t) (m > 0 ? m : 1);
  Newton_run nr = { .ev = ev, .solver = newton_alloc(n, m, ev->st), .n = n, .m = m,
                    .S = malloc((mm * mm + 3 * mm + 5 * (size_t) n) * sizeof(double)) };
  if (!nr.solver || !nr.S) {
    newton_free(nr.solver), free(nr.S);
    if (!nr.solver) return (int) ev->st->code;      /* newton_alloc said why */
    return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  }
  nr.f = nr.S + mm * mm, nr.v0 = nr.f + mm, nr.v = nr.v0 + mm;
  nr.grad = nr.v + mm, nr.r = nr.grad + n, nr.d = nr.r + n;
  nr.trial = nr.d + n, nr.Xk = nr.trial + n;
  nr.mdl = (Newton_model) { n, m, model_dofs(ev->md)->contact_col, nr.Xk, ev->B, nr.grad,
                            nr.r, nr.S, nr.f, nr.v0 };
  double pg = HUGE_VAL;
  
#line 2102 "paper/opt.nw"
if ((rc = newton_model_at(&nr))) {
  newton_free(nr.solver), free(nr.S);
  return rc;
}
double Gmax = 0, Dmean = 0;
for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(ev->G[i])), Dmean += nr.r[i] / n;
nr.rho = Gmax > 0 ? fmin(1e-2, Gmax / (ev->B->C0 * Dmean)) : 1e-2;
#line 2081 "paper/opt.nw"
  for (;;) {
    if (accepted && ((k > 0 && (rc = newton_model_at(&nr)))
                     || (rc = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))))
      break;
    int stop = accepted && opt_report_iterate(ev, k, pg);
    if (accepted) ev->rep->pgnorm = pg, ev->rep->iterations = k;
    if (newton_end(&nr, k, accepted, pg, stop)) break;
    if ((rc = newton_try(&nr, &accepted))) break;
    if (accepted) k++;
  }
  memcpy(X, nr.Xk, n * sizeof *X);
  if (!rc) rc = opt_evaluate(ev, X);
  newton_free(nr.solver), free(nr.S);
  return rc;
}
