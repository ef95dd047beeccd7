#line 319 "paper/opt.nw"
#ifndef CONTACTOPT_OPT_PRIVATE_H
#define CONTACTOPT_OPT_PRIVATE_H
#include "resources.h"
#include "opt.h"
#line 460 "paper/opt.nw"
typedef struct {
  Model *md;              /* the state at the last design evaluated */
  const Design_set *B;
  const Opt_options *o;
  int n;                  /* N+1 */
  double *X;              /* n: the last design evaluated */
  double *G;              /* n: its gradient there */
  double J;               /* the objective there, E by default */
  double noise;           /* the rounding of J there (below) */
  int have;               /* X, G, J are valid */
  int solves;             /* state solves so far */
  double tau;             /* the step of pi, fixed at the start */
  double start;           /* clock at the start */
  Opt_monitor monitor;
  void *data;
  Opt_report *rep;
  Status *st;
  int failed;             /* a status to return after NLopt stops */
  double last_J, last_noise; /* J and its rounding at the last accepted iterate */
  double pg_best;         /* the smallest pi of the accepted iterates */
  int idle;               /* accepted iterates in a row without measured progress */
  double idle_J;          /* J before those iterates */
  double pg_last;         /* pi at the last accepted iterate */
  double *Xacc;           /* n: the last accepted iterate */
  int accepted;           /* iterates reported so far */
  int lifted;             /* the last evaluation failed: the body lifts off */
} Opt_evaluator;
enum { OPT_FEW = 3 };     /* so many such iterates in a row: no progress */
#line 324 "paper/opt.nw"
/* solve the state at X, then E and grad E, unless X was the last design */
int opt_evaluate(Opt_evaluator *ev, const double *X);
/* report the accepted iterate at the evaluator's design; 1 if the
   monitor asks to stop */
int opt_report_iterate(Opt_evaluator *ev, int iteration, double pg);
/* the accepted iterates in a row without measured progress, after k */
int opt_idle_iterates(Opt_evaluator *ev, int k, double pg, int judged);
/* the stop_detail of a run stopped by OPT_FEW idle iterates */
void opt_idle_detail(Opt_evaluator *ev);
/* c (4n - 2): the box and the slopes of B at X (n), <= 0 when met */
void opt_constraints(const Design_set *B, const double *X, unsigned n, double *c);
/* grad ((4n - 2) x ny) = d c / d y for X = X0 + C0 R y, R n x ny */
void opt_constraints_gradient(const double *R, unsigned n, unsigned ny, double *grad);
/* the k-th iterate of an NLopt method, at the evaluator's design, kept
   in bestX: its stop reason, or NULL to go on (ev->failed if pi failed) */
const char *opt_nlopt_iterate(Opt_evaluator *ev, int k, double *bestX);
/* the four methods: from X to the terminal check, X the final design */
int opt_projgrad(Opt_evaluator *ev, double *X);
int opt_slsqp(Opt_evaluator *ev, double *X);
int opt_newton(Opt_evaluator *ev, double *X);
int opt_mma(Opt_evaluator *ev, double *X);
#endif
