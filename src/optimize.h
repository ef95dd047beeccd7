#line 54 "paper/optimize.nw"
#ifndef CONTACTOPT_OPTIMIZE_H
#define CONTACTOPT_OPTIMIZE_H
#include "status.h"
#include "scene.h"
#include "model.h"
#include "design.h"

typedef struct {
  int iteration;          /* 0 is the start */
  double energy;          /* E at the iterate */
  double pgnorm;          /* the projected-gradient norm pi */
  int state_solves;       /* state solves so far */
  int active;             /* contact nodes at their bound */
  int state_iterations;   /* iterations of the last state solve */
  double seconds;         /* since the start of the optimisation */
} Opt_progress;

typedef void (*Opt_monitor)(const Opt_progress *p, const double *X, void *data);

typedef struct {
  int iterations;         /* accepted iterates after the start */
  int evaluations;        /* evaluations of E and its gradient */
  double energy;          /* E at the final design */
  double pgnorm;          /* pi at the final design */
  char stop_reason[32];   /* "converged", "max_iter", "no_progress" */
  double seconds;         /* wall time of the whole optimisation */
  double metric_seconds;  /* of it, setting up SLSQP's metric */
  double state_seconds;   /* of it, state solves and gradients */
} Opt_report;

int opt_minimize(Model *md, const Design_set *B, const Scene *s, double *X,
                 Opt_monitor monitor, void *data, Opt_report *rep,
                 Status *st);
/* pi(X) for the gradient G, with the step tau */
int opt_pgnorm(const Design_set *B, const double *X, const double *G,
               double tau, double *pg, Status *st);
#endif
