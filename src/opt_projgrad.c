#line 349 "paper/opt.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "opt_private.h"
#line 679 "paper/opt.nw"
typedef struct {
  double *trial;          /* n: P_B(X - tG) */
  double *Y;              /* n: X - tG */
  double *X, *G;          /* n each: the iterate and its gradient */
} Projgrad_scratch;

#line 689 "paper/opt.nw"
static int projgrad_step(Opt_evaluator *ev, double *t, Projgrad_scratch *w,
                         int *accepted)
{
  int n = ev->n, rc;
  double J0 = ev->J, *Xn = w->trial, *Y = w->Y, *X = w->X, *G = w->G;
  memcpy(X, ev->X, n * sizeof *X);
  memcpy(G, ev->G, n * sizeof *G);
  *accepted = 0;
  for (int halving = 0; halving < 50 && !*accepted; halving++, *t /= 2) {
    
#line 708 "paper/opt.nw"
for (int i = 0; i < n; i++) Y[i] = X[i] - *t * G[i];
if ((rc = design_project(ev->B, Y, Xn, NULL, ev->st))) return rc;
double descent = 0;
for (int i = 0; i < n; i++) descent += G[i] * (Xn[i] - X[i]);
if (descent >= 0) continue;                /* the arc has collapsed */
if ((rc = opt_evaluate(ev, Xn))) return rc;
*accepted = ev->J <= J0 + 1e-4 * descent;
#line 699 "paper/opt.nw"
  }
  if (*accepted) *t *= 4;                      /* undo the last halving, then double */
  else if ((rc = opt_evaluate(ev, X))) return rc;  /* back to the last iterate */
  return STATUS_OK;
}
#line 720 "paper/opt.nw"
int opt_projgrad(Opt_evaluator *ev, double *X)
{
  int n = ev->n, rc, accepted = 1, k = 0;
  double t = ev->tau, pg;
  double *scratch = malloc(4 * n * sizeof *scratch);
  Projgrad_scratch w = { scratch, scratch + n, scratch + 2 * n, scratch + 3 * n };
  if (!scratch) return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  for (;; k++) {
    if ((rc = opt_pgnorm(ev->B, ev->X, ev->G, ev->tau, &pg, ev->st))) break;
    int stop = opt_report_iterate(ev, k, pg);
    ev->rep->pgnorm = pg;
    
#line 742 "paper/opt.nw"
int idle = opt_idle_iterates(ev, k, pg, 0);
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
  else if (!strcmp(why, "no_progress")) opt_idle_detail(ev);
  break;
}
#line 732 "paper/opt.nw"
    if ((rc = projgrad_step(ev, &t, &w, &accepted))) break;
  }
  ev->rep->iterations = k;
  memcpy(X, ev->X, n * sizeof *X);
  free(scratch);
  return rc;
}
