#line 153 "paper/opt.nw"
#ifndef CONTACTOPT_OPT_H
#define CONTACTOPT_OPT_H
#include "status.h"
#include "model.h"
#include "design.h"
#include "objective.h"

#line 172 "paper/opt.nw"
typedef enum { OPT_SLSQP, OPT_PROJGRAD, OPT_NEWTON, OPT_MMA } Opt_method;
typedef enum { OPT_METRIC_SCHUR, OPT_METRIC_EUCLIDEAN } Opt_metric;
extern const char *const opt_method_names[]; /* slsqp, projgrad, newton, mma */
extern const char *const opt_metric_names[]; /* schur, euclidean, NULL */

typedef struct {
  Opt_method method;      /* slsqp (NLopt), projgrad (Algorithm 4.1),
                             newton (Section sec:newton) or mma (NLopt) */
  Opt_metric metric;      /* the metric of the design space SLSQP starts in */
  double tol;             /* projected-gradient norm pi at which it stops */
  int max_iter;           /* iteration limit */
  Objective objective;    /* what it minimises ([objective]); newton: the
                             energy only */
  int levels;             /* meshes of the coarse-to-fine start
                             (sec:levels): 1 none, 0 chosen by N */
  int starts;             /* runs from K starts, the best kept
                             (sec:starts): 1 the scene's only */
} Opt_options;

#line 206 "paper/opt.nw"
typedef struct {
  int iteration;          /* 0 is the start */
  double value;           /* the objective at the iterate, E by default */
  double pgnorm;          /* the projected-gradient norm pi */
  int state_solves;       /* state solves so far */
  int active;             /* contact nodes at their bound */
  int state_iterations;   /* iterations of the last state solve */
  double seconds;         /* since the start of the optimisation */
} Opt_progress;

/* called at each accepted iterate; nonzero stops the run there */
typedef int (*Opt_monitor)(const Opt_progress *p, const double *X, void *data);

#line 222 "paper/opt.nw"
typedef struct {
  int iterations;         /* accepted iterates after the start */
  int evaluations;        /* evaluations of E and its gradient */
  double energy;          /* E at the final design */
  double pgnorm;          /* pi at the final design */
  char stop_reason[32];   /* "converged", "max_iter", "no_progress",
                             "interrupted", "lift_off" */
  char stop_detail[512];  /* with no_progress and lift_off: what was
                             measured, or "" */
  double seconds;         /* wall time of the whole optimisation */
  double metric_seconds;  /* of it, setting up SLSQP's metric */
  double model_seconds;   /* of it, building and solving Newton's models */
  double state_seconds;   /* of it, state solves and gradients */
  double monitor_seconds; /* of it, in the caller's monitor (its output) */
  double subproblem_seconds; /* of it, inside NLopt (SLSQP, MMA) between
                             its calls of the objective and constraints:
                             its subproblems and updates */
  int levels;             /* meshes of a coarse-to-fine start, 1 without */
  int coarse_evaluations; /* evaluations on the coarse meshes */
  double coarse_seconds;  /* their wall time, part of seconds */
  int starts;             /* starts of a multistart run, 1 without */
  int starts_best;        /* the start whose optimum the run went on from */
  double starts_min, starts_max; /* the lowest and highest J they ended at */
  int starts_evaluations; /* their evaluations, apart from evaluations */
  double starts_seconds;  /* their wall time, part of seconds */
} Opt_report;

#line 251 "paper/opt.nw"
/* the defaults: schur for slsqp, euclidean for projgrad, tol 1e-6,
   max_iter 200 (the scene raises it for objectives other than the energy) */
Opt_options opt_options_default(Opt_method method);
const char *opt_method_name(Opt_method m);   /* or "?" */
const char *opt_metric_name(Opt_metric m);   /* or "?" */
/* 0 if method m minimises the objective o under the contact law; else
   STATUS_INPUT, st saying why after "path: " (the Newton method's model
   is the Hessian of an energy without Coulomb friction) */
int opt_refusal(Opt_method m, const Objective *o, Problem_contact_law contact,
                const char *path, Status *st);
int opt_minimize(Model *md, const Design_set *B, const Opt_options *o,
                 double *X, Opt_monitor monitor, void *data, Opt_report *rep,
                 Status *st);
/* bytes the optimiser o needs beyond its model, for N + 1 design nodes */
double opt_memory(const Opt_options *o, int N);
/* X (2 Nc + 1 entries) = X (Nc + 1) interpolated linearly, in place */
void opt_interpolate(double *X, int Nc);
/* the meshes of o's coarse-to-fine start for p (sec:levels), >= 1 */
int opt_levels(const Problem *p, const Opt_options *o);
/* X (p->N + 1, in B) = the optimum of the levels - 1 coarser meshes,
   interpolated onto p's nodes, the first started from X; their work in
   coarse; fine (or NULL): p's model, given their contact as a guess;
   stop (or NULL): each level's monitor, whose stop ends the levels
   (coarse->stop_reason "interrupted", X left as it was) */
int opt_coarse_start(const Problem *p, const Qp_options *solver,
                     const Opt_options *o, int levels, double *X, Model *fine,
                     Opt_monitor stop, cholmod_common *cm, Opt_report *coarse,
                     Status *st);
/* X (N + 1) = the k-th of the spread starts in B (sec:starts), k >= 1 */
int opt_start_design(const Design_set *B, int k, double *X, Status *st);
/* pi(X) for the gradient G, with the step tau */
int opt_pgnorm(const Design_set *B, const double *X, const double *G,
               double tau, double *pg, Status *st);
#line 167 "paper/opt.nw"
#endif
