#line 21 "paper/main.nw"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "status.h"
#include "scene.h"
#include "output.h"
#include "usage.h"
#include "interrupt.h"
#include "args.h"
#include "threads.h"
#include "resources.h"
#include "plot.h"
#line 280 "paper/main.nw"
/* st's message = "path: message", unless it begins with the path already */
static void name_the_scene(Status *st, const char *path)
{
  char msg[sizeof st->msg];
  size_t n = strlen(path);
  if (!strncmp(st->msg, path, n) && (st->msg[n] == ':' || st->msg[n] == ' ')) return;
  memcpy(msg, st->msg, sizeof msg);
  if (snprintf(st->msg, sizeof st->msg, "%s: %s", path, msg) >= (int) sizeof st->msg)
    strcpy(st->msg + sizeof st->msg - 4, "...");
}
#line 298 "paper/main.nw"
/* *v = the number at *p, digits only; *p moves past it */
static int component_number(const char **p, long *v)
{
  char *end;
  if (!isdigit((unsigned char) **p)) return -1;
  *v = strtol(*p, &end, 10);
  *p = end;
  return 0;
}

/* chosen[I..J by S] = 1 for the item at *p: I, I-J or I-J/S */
static int component_item(const char **p, int N, unsigned char *chosen)
{
  long i, j, step = 1;
  if (component_number(p, &i)) return -1;
  j = i;
  if (**p == '-' && (++*p, component_number(p, &j))) return -1;
  if (**p == '/' && (++*p, component_number(p, &step) || step < 1)) return -1;
  if (i > j || j > N) return -1;
  if (step > N) step = N + 1;          /* one node; k + step cannot overflow */
  for (long k = i; k <= j; k += step) chosen[k] = 1;
  return 0;
}

/* the nodes of spec, ascending, into gc's list (gc NULL: only checked) */
static int components_read(const char *spec, int N, Grad_check *gc, Status *st)
{
  const char *p = spec;
  unsigned char *chosen = spec ? calloc((size_t) N + 1, 1) : NULL;
  int rc = STATUS_OK, bad;
  if (!spec) return STATUS_OK;
  if (!chosen) return status_set(st, STATUS_MEMORY, "--components: out of memory");
  while (!(bad = component_item(&p, N, chosen)) && *p == ',') p++;
  if (bad || *p)
    rc = status_set(st, STATUS_INPUT, "command line: --components %s: not a list of "
                    "nodes I, ranges I-J and I-J/S (step S >= 1), comma-separated, "
                    "in 0..N = 0..%d", spec, N);
  else if (gc) {
    gc->ncheck = 0;
    for (int i = 0; i <= N; i++) if (chosen[i]) gc->check[gc->ncheck++] = i;
  }
  free(chosen);
  return rc;
}
#line 345 "paper/main.nw"
typedef struct {
  const Args *a;            /* the command line */
  Scene s;                  /* the scene, overrides applied */
  Model *md;                /* the discrete problem of s.problem */
  Output_run run;           /* the scene's facts for the summaries */
  char dir[OUTPUT_PATH];    /* the output folder */
  int optimizing;           /* the command runs the optimiser */
  const char *command;      /* its name: solve, optimize, gradcheck */
} Run;

/* a scene with no traction and no body force: say that its state is 0 */
static void warn_unloaded(const Scene *s)
{
  for (int id = 0; id < SIDE_COUNT; id++)
    if (s->problem.side[id].kind == BC_TRACTION) return;
  for (int j = 0; j < s->problem.part.ncurve; j++)
    if (s->problem.part.curve[j].kind >= BC_TRACTION) return;
  if (!s->problem.has_body_force)
    fprintf(stderr, "contactopt: warning: %s: the scene has no load (no side "
            "or curve with bc = traction or pressure, no body force): its "
            "state is u = 0\n", s->path);
}
#line 390 "paper/main.nw"
#define LOCK_RATIO 20.0  /* lambda/mu in plane strain: P1 triangles lock */
static void warn_material(const char *path, const char *key, const Problem_material *m)
{
  if (m->kind != MATERIAL_ISOTROPIC) return;
  double ratio = 2 * m->nu / (1 - 2 * m->nu);
  if (ratio >= LOCK_RATIO)
    fprintf(stderr, "contactopt: warning: %s: %s.nu = %.6g in plane strain "
            "(lambda/mu = %.3g): linear triangles lock as nu nears 1/2, and "
            "the body comes out too stiff; compare the results under a "
            "larger mesh.refine\n", path, key, m->nu, ratio);
}

/* plane strain: each isotropic material near incompressibility */
static void warn_locking(const Scene *s)
{
  const Problem *p = &s->problem;
  char key[PROBLEM_NAME + 16];
  if (p->model != MODEL_PLANE_STRAIN) return;
  warn_material(s->path, "material", &p->material);
  for (int j = 0; j < p->part.nregion; j++) {
    snprintf(key, sizeof key, "material.%s", p->part.region[j].name);
    warn_material(s->path, key, &p->part.region[j].material);
  }
}
#line 417 "paper/main.nw"
typedef struct {
  const char *name, *usage, *suffix;  /* the command, its help, its folder */
  int (*run)(Run *r, Status *st);     /* the command itself */
  int plot_files;                     /* honours --plot-files */
  int components;                     /* honours --components */
  int optimizes;                      /* runs the optimiser (its memory too) */
} Command;

static int run_command(const Args *a, const Command *c, cholmod_common *cm,
                       Status *st)
{
  Run r = { .a = a, .optimizing = c->optimizes, .command = c->name };
  int rc = scene_load(&r.s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  if (r.s.note[0]) printf("%s: %s\n", r.s.path, r.s.note);
  r.run = (Output_run) { r.s.path, qp_method_name(r.s.solver.method),
                         opt_method_name(r.s.optimizer.method),
                         opt_metric_name(r.s.optimizer.metric),
                         &r.s.optimizer.objective };
  if (!a->outdir) output_default_dir(a->scene, c->suffix, r.dir, sizeof r.dir);
  double extra = c->optimizes ? opt_memory(&r.s.optimizer, r.s.problem.N) : 0;
  if (!(rc = a->outdir ? output_dir_name(a->outdir, r.dir, sizeof r.dir, st) : 0)
      && !(rc = output_check(r.dir, c->name, a->replace, st)) /* before any work */
      && !(rc = a->matrix_market ? output_check_file(a->matrix_market, r.dir, st) : 0)
      && !(rc = components_read(a->components, r.s.problem.N, NULL, st))
      && !(rc = resources_fits(&r.s.problem, extra, r.s.path, st))
      && !(rc = threads_start(r.s.path, resources_memory(&r.s.problem) + extra, st))) {
    r.md = model_new(&r.s.problem, &r.s.solver, cm, st);
    rc = r.md ? c->run(&r, st) : (int) st->code;
  }
  if (!rc) warn_unloaded(&r.s), warn_locking(&r.s);
  if (rc) name_the_scene(st, r.s.path);
  model_free(r.md);
  scene_free(&r.s);
  return rc;
}
#line 477 "paper/main.nw"
#define LARGE 0.1    /* of the body's size: small strains no longer */
static void warn_large(const Run *r)
{
  const Problem *p = &r->s.problem;
  double size = fmax(p->b - p->a, model_mesh(r->md)->gamma);
  double u = model_displacement_max(r->md);
  if (u > LARGE * size)
    fprintf(stderr, "contactopt: warning: %s: the largest displacement, %.3g m, "
            "exceeds %g of the body's size %.3g m: linear (small-strain) "
            "elasticity does not hold there (E in Pa?)\n", r->s.path, u, LARGE, size);
}
#line 497 "paper/main.nw"
/* the staging folder of the command's files, signals caught while it is
   there: the first says what the run does about it, a second removes it */
static int begin(Run *r, Output *o, Status *st)
{
  char line[1024];
  snprintf(line, sizeof line, "contactopt: %s: interrupted: %s; interrupt "
           "again to stop at once without them\n", r->s.path,
           r->optimizing ? "the run stops at the next iterate "
           "and writes the files of that design" : "the run's work is done, "
           "its files are being finished");
  memset(o, 0, sizeof *o);   /* nothing staged, as the handler will see it */
  interrupt_catch(1, line, output_abort_now, o);
  int rc = output_begin(o, r->dir, r->command, r->a->replace, st);
  if (rc) interrupt_catch(0, NULL, NULL, NULL);
  else o->plot_files = r->a->plot_files;
  return rc;
}

/* after rc: effective.scene, the commit, then the stiffness matrix if
   asked (after: its file may lie in the folder the commit replaces) */
static int finish(Run *r, Output *o, int rc, Status *st)
{
  FILE *f = rc ? NULL : output_open(o, "effective.scene", st);
  if (!rc && !f) rc = st->code;
  if (f) {
    int wrc = scene_write(&r->s, f, st), crc = output_close(o, f, st);
    rc = wrc ? wrc : crc;
  }
  if (!rc) warn_large(r);
  rc = output_end(o, rc, st);
  interrupt_catch(0, NULL, NULL, NULL);
  if (rc || !r->a->matrix_market) return rc;
  return output_matrix_market(r->a->matrix_market, r->md, st);
}
#line 534 "paper/main.nw"
static int command_solve(Run *r, Status *st)
{
  Output o;
  Model *md = r->md;
  int rc = model_solve(md, r->s.alpha0, st);
  if (rc || (rc = begin(r, &o, st))) return rc;
  if ((rc = finish(r, &o, output_solve(&o, &r->run, md, r->s.alpha0, st), st)))
    return rc;
  printf("%s: E = %.10g J/m, KKT residual %.2e after %d %s iterations, "
         "%d of %d contact nodes active, %.3f s -> %s/\n", r->s.path, model_energy(md),
         model_report(md)->kkt, model_report(md)->iterations, r->run.state_solver,
         model_report(md)->active, model_dofs(md)->nc, model_seconds(md), r->dir);
  return STATUS_OK;
}
#line 572 "paper/main.nw"
#define GRADCHECK_LONG 60.0   /* seconds: a check to warn of */
static int gradcheck_estimate(Run *r, const Grad_check *gc, Status *st)
{
  const Problem *p = &r->s.problem;
  int rc = model_solve_to_rounding(r->md, r->s.alpha0, st);
  if (rc || (rc = model_solve_to_rounding(r->md, r->s.alpha0, st))) return rc;
  long solves = grad_check_solves(gc, p, r->s.alpha0);
  double t = model_seconds(r->md), total = solves * t;
  printf("gradcheck: %d of %d nodes, %ld state solves of about %.2g s: about %.0f s\n",
         gc->ncheck, p->N + 1, solves, t, ceil(total));
  fflush(stdout);
  if (total > GRADCHECK_LONG) {
    int fit = (int) fmax(2, GRADCHECK_LONG / 2 / (total / gc->ncheck));
    int step = (p->N + fit - 2) / (fit - 1);
    fprintf(stderr, "contactopt: warning: %s: gradcheck of %d nodes will take "
            "about %.0f s (%ld state solves of %.2g s); --components 0-%d/%d checks "
            "%d of them in about %.0f s\n", r->s.path, gc->ncheck, ceil(total),
            solves, t, p->N, step, p->N / step + 1,
            ceil(total / gc->ncheck * (p->N / step + 1)));
  }
  return STATUS_OK;
}
#line 598 "paper/main.nw"
typedef struct {
  double start, last;       /* the check's start, the last line's time */
  int done;                 /* nodes checked so far */
} Gradcheck_progress;

static void gradcheck_progress(int i, const Grad_check *gc, void *data)
{
  Gradcheck_progress *g = data;
  double now = resources_clock(), worst = 0;
  (void) i;
  if (++g->done < gc->ncheck && now - g->last < 1) return;
  g->last = now;
  for (int k = 0; k < g->done; k++) worst = fmax(worst, gc->err[gc->check[k]]);
  printf("gradcheck: node %d of %d, largest relative error so far %.3e, "
         "about %.0f s left\n", g->done, gc->ncheck, worst,
         ceil((now - g->start) / g->done * (gc->ncheck - g->done)));
  fflush(stdout);
}
#line 626 "paper/main.nw"
/* the method the scene did not name, and why it is the one */
static void say_method(const Run *r)
{
  const Scene *s = &r->s;
  if (!s->method_chosen) return;
  printf("%s: optimizer.method = %s, chosen for %s%s\n", s->path,
         opt_method_name(s->optimizer.method),
         s->optimizer.method == OPT_NEWTON ? "the energy without Coulomb friction"
         : s->problem.contact == CONTACT_COULOMB ? "contact.model = coulomb"
         : "objective.kind = ",
         s->optimizer.method == OPT_NEWTON || s->problem.contact == CONTACT_COULOMB
         ? "" : objective_name(s->optimizer.objective.kind));
}

/* the nodes whose differences met other held sets than the design's:
   there the gradient is one-sided, that of the design's sets */
static void gradcheck_crossed(const Grad_check *gc)
{
  int n = 0;
  for (int k = 0; k < gc->ncheck; k++) n += gc->crossed[gc->check[k]];
  if (!n) return;
  printf("gradcheck: at %d node%s (", n, n == 1 ? "" : "s");
  for (int k = 0, m = 0; k < gc->ncheck; k++)
    if (gc->crossed[gc->check[k]]) printf("%s%d", m++ ? " " : "", gc->check[k]);
  printf(") the differences crossed a change of the contact set: the %s is "
         "one-sided there, its gradient that of the design's set\n",
         objective_name(gc->objective->kind));
}

static int command_gradcheck(Run *r, Status *st)
{
  Output o;
  Grad_check *gc = grad_check_new(r->s.problem.N, st);
  Gradcheck_progress g = { 0, 0, 0 };
  int rc = gc ? components_read(r->a->components, r->s.problem.N, gc, st)
              : (int) st->code;
  if (gc) gc->objective = &r->s.optimizer.objective;
  if (!rc && !(rc = gradcheck_estimate(r, gc, st))) {
    g.start = g.last = resources_clock();
    rc = grad_check(r->md, r->s.alpha0, gc, gradcheck_progress, &g, st);
  }
  if (!rc && !(rc = begin(r, &o, st)))
    rc = finish(r, &o, output_gradcheck(&o, &r->run, r->md, gc, st), st);
  if (!rc) gradcheck_crossed(gc);
  if (!rc)
    printf("%s: largest relative error of the gradient %.3e (node %d; %d "
           "nodes checked) -> %s/\n", r->s.path, gc->err[gc->worst], gc->worst,
           gc->ncheck, r->dir);
  grad_check_free(gc);
  return rc;
}
#line 825 "paper/main.nw"
static int monitor(const Opt_progress *p, const double *X, void *data)
{
  const Output_history *h = data;
  printf("%4d  %s = %.12g  pg = %.3e  active %d  state its %d  %.3f s\n",
         p->iteration, objective_symbol(h->objective), p->value, p->pgnorm,
         p->active, p->state_iterations, p->seconds);
  fflush(stdout);
  output_history_add(data, p, X);
  return interrupt_signal() != 0;
}
#line 842 "paper/main.nw"
#define START_TOL 1e-12     /* the violation of B that moves the start */
static int optimize_start(Run *r, const Design_set *B, double *X,
                          double *moved, Status *st)
{
  double v;
  int rc = design_feasible_start(B, r->s.alpha0, START_TOL, X, &v, moved, st);
  if (!rc && v > START_TOL)
    printf("%s: the initial design is not in B (largest relative violation "
           "%.3g): moved to the nearest point of B, at distance %.6g m\n",
           r->s.path, v, *moved);
  return rc ? rc : model_solve_to_rounding(r->md, X, st);
}
#line 867 "paper/main.nw"
/* the coarse levels' monitor: only Ctrl-C, which ends them */
static int coarse_monitor(const Opt_progress *p, const double *X, void *data)
{
  (void) p, (void) X, (void) data;
  return interrupt_signal() != 0;
}

/* X = the coarse-to-fine start when the levels of the run are > 1; c its
   report (levels 1 and no cost without) */
static int optimize_coarse(Run *r, double *X, Opt_report *c, Status *st)
{
  int levels = opt_levels(&r->s.problem, &r->s.optimizer), N = r->s.problem.N;
  memset(c, 0, sizeof *c);
  c->levels = 1;
  if (levels < 2) return STATUS_OK;
  model_release(r->md);        /* the coarse models do not add to its factor */
  int rc = opt_coarse_start(&r->s.problem, &r->s.solver, &r->s.optimizer,
                            levels, X, r->md, coarse_monitor, model_cholmod(r->md), c, st);
  c->levels = levels;
  if (!rc && c->stop_reason[0])
    printf("%s: coarse to fine: interrupted after %d evaluation%s, %.2f s; "
           "N = %d starts from the scene's design\n", r->s.path, c->evaluations,
           c->evaluations == 1 ? "" : "s", c->seconds, N);
  else if (!rc)
    printf("%s: coarse to fine: N = %d .. %d in %d evaluation%s, %.2f s; "
           "N = %d starts from their optimum\n", r->s.path, N >> (levels - 1),
           N / 2, c->evaluations, c->evaluations == 1 ? "" : "s", c->seconds, N);
  return rc;
}
#line 900 "paper/main.nw"
/* rep, the fine level's report, with the coarse levels' c added */
static int optimize_report_coarse(Opt_report *rep, const Opt_report *c)
{
  rep->levels = c->levels;
  rep->coarse_evaluations = c->evaluations;
  rep->coarse_seconds = c->seconds;
  rep->seconds += c->seconds;
  return STATUS_OK;
}
#line 920 "paper/main.nw"
/* the value of the run's objective at the model's state */
static double optimize_value(Run *r, Status *st)
{
  double v;
  if (objective_value(r->md, &r->s.optimizer.objective, &v, st)) v = NAN;
  return v;
}

/* one start k of the K: X its design on entry, its optimum on return;
   *v its value (NaN where it failed, with a line saying why) */
static int optimize_one_start(Run *r, const Design_set *B, int k, double *X,
                              Opt_report *rk, double *v, Status *st)
{
  const Opt_options *o = &r->s.optimizer;
  int rc = k > 0 ? opt_start_design(B, k, X, st) : STATUS_OK;
  if (!rc) rc = opt_minimize(r->md, B, o, X, coarse_monitor, NULL, rk, st);
  *v = rc ? NAN : optimize_value(r, st);
  if (rc == STATUS_NUMERIC || (!rc && isnan(*v))) {
    printf("%s: start %d of %d failed: %s\n", r->s.path, k + 1, o->starts, st->msg);
    *st = (Status) { STATUS_OK, "" };
    return STATUS_OK;
  }
  if (!rc)
    printf("%s: start %d of %d: %s = %.12g%s (%s after %d iterations)\n", r->s.path,
           k + 1, o->starts, objective_symbol(o->objective.kind), *v,
           objective_unit(o->objective.kind), rk->stop_reason, rk->iterations);
  return rc;
}
#line 951 "paper/main.nw"
/* X = the lowest optimum of the K starts (X the first on entry); sr
   their report (starts 1 and no cost when K = 1) */
static int optimize_starts(Run *r, const Design_set *B, double *X,
                           Opt_report *sr, Status *st)
{
  int K = r->s.optimizer.starts, n = B->N + 1, rc = STATUS_OK;
  memset(sr, 0, sizeof *sr);
  sr->starts = 1, sr->starts_min = sr->starts_max = NAN;
  if (K < 2) return STATUS_OK;
  double *Y = malloc(2 * n * sizeof *Y), *X0 = Y + n, t0 = resources_clock();
  if (!Y) return status_set(st, STATUS_MEMORY, "optimize: out of memory");
  memcpy(X0, X, n * sizeof *X);
  for (int k = 0; k < K && !rc; k++) {
    Opt_report rk;
    double v;
    memcpy(Y, X0, n * sizeof *Y);
    if ((rc = optimize_one_start(r, B, k, Y, &rk, &v, st))) break;
    sr->starts_evaluations += rk.evaluations;
    
#line 981 "paper/main.nw"
if (!isnan(v) && (isnan(sr->starts_min) || v < sr->starts_min))
  sr->starts_min = v, sr->starts_best = k + 1, memcpy(X, Y, n * sizeof *X);
if (!isnan(v) && (isnan(sr->starts_max) || v > sr->starts_max)) sr->starts_max = v;
#line 970 "paper/main.nw"
    if (!strcmp(rk.stop_reason, "interrupted")) break;
  }
  sr->starts = K;
  sr->starts_seconds = resources_clock() - t0;
  
#line 987 "paper/main.nw"
if (!rc && sr->starts_best)
  printf("%s: %d starts: %s from %.12g to %.12g%s (spread %.2e relative); the "
         "run goes on from start %d\n", r->s.path, K,
         objective_symbol(r->s.optimizer.objective.kind), sr->starts_min,
         sr->starts_max, objective_unit(r->s.optimizer.objective.kind),
         sr->starts_min ? (sr->starts_max - sr->starts_min) / fabs(sr->starts_min) : 0,
         sr->starts_best);
else if (!rc)
  printf("%s: %d starts: none ended; the run goes on from the first\n", r->s.path, K);
#line 975 "paper/main.nw"
  free(Y);
  return rc;
}
#line 1000 "paper/main.nw"
static int optimize_report_starts(Opt_report *rep, const Opt_report *sr)
{
  rep->starts = sr->starts, rep->starts_best = sr->starts_best;
  rep->starts_min = sr->starts_min, rep->starts_max = sr->starts_max;
  rep->starts_evaluations = sr->starts_evaluations;
  rep->starts_seconds = sr->starts_seconds;
  rep->seconds += sr->starts_seconds;
  return STATUS_OK;
}
#line 1020 "paper/main.nw"
static int command_optimize(Run *r, Status *st)
{
  Design_set B = design_set(&r->s.problem);
  Output o;
  Output_start start;
  Opt_report rep, coarse, starts;
  int n = r->s.problem.N + 1, rc;
  double *X = malloc(2 * n * sizeof *X), *G = X ? X + n : NULL, moved;
  Output_history *h = output_history_new(n, st);
  Design_multipliers *m = design_multipliers_new(&B, st);
  const Objective *J = &r->s.optimizer.objective;
  if (h) h->objective = J->kind;
  rc = opt_refusal(r->s.optimizer.method, J, r->s.problem.contact, r->s.path, st);
  if (!rc && !X) rc = status_set(st, STATUS_MEMORY, "optimize: out of memory");
  else if (!rc && (!h || !m)) rc = st->code;
  else if (!rc && (say_method(r), !(rc = begin(r, &o, st)))) {
    if (!(rc = output_history_vtu(h, &o, r->md, st))   /* iterates/, .pvd */
        && !(rc = optimize_start(r, &B, X, &moved, st))
        && !(rc = output_start(&o, r->md, X, moved,
                                              r->s.optimizer.objective.q, &start, st))
        && !(rc = optimize_coarse(r, X, &coarse, st))
        && !(rc = optimize_starts(r, &B, X, &starts, st))
        && !(rc = opt_minimize(r->md, &B, &r->s.optimizer, X, monitor, h, &rep, st))
        && !(rc = optimize_report_coarse(&rep, &coarse))
        && !(rc = optimize_report_starts(&rep, &starts))
        && !(rc = output_state(&o, "final", r->md, X, st))
        && !(rc = output_history(&o, &r->s.problem, h, st))
        && !(rc = objective_evaluate(r->md, J, NULL, G, NULL, st))
        && !(rc = design_kkt(&B, X, G, -1, NULL, m, NULL, st))
        && !(rc = output_multipliers(&o, &r->s.problem, X, G, m, st)))
      rc = output_opt_summary(&o, &r->run, r->md, &start, &rep, m->mu, st);
    rc = finish(r, &o, rc, st);
  }
  double J0 = start.J.value[J->kind], J1;   /* the objective, E by default */
  if (!rc) rc = objective_value(r->md, J, &J1, st);
  if (!rc)
    printf("%s: %s %.10g -> %.10g%s in %d iteration%s, %d evaluation%s, "
           "projected gradient %.2e (%s) -> %s/\n", r->s.path,
           objective_symbol(J->kind), J0, J1, objective_unit(J->kind),
           rep.iterations, rep.iterations == 1 ? "" : "s", rep.evaluations,
           rep.evaluations == 1 ? "" : "s", rep.pgnorm, rep.stop_reason, r->dir);
  if (!rc && !strcmp(rep.stop_reason, "interrupted"))
    rc = status_set(st, STATUS_INTERRUPTED, "%s: interrupted by signal %d at "
                    "iteration %d: the files of the best design so far are in %s/",
                    r->s.path, interrupt_signal(), rep.iterations, r->dir);
  else if (!rc && strcmp(rep.stop_reason, "converged"))
    rc = status_set(st, STATUS_NUMERIC, "%s: not converged (%s): projected gradient "
                    "%.2e > optimizer.tol = %.0e after %d iterations%s%s%s; the files of "
                    "the last design accepted are in %s/", r->s.path, rep.stop_reason,
                    rep.pgnorm, r->s.optimizer.tol, rep.iterations,
                    rep.stop_detail[0] ? " (" : "", rep.stop_detail,
                    rep.stop_detail[0] ? ")" : "", r->dir);
  free(X);
  output_history_free(h);
  design_multipliers_free(m);
  return rc;
}
#line 1087 "paper/main.nw"
static int command_plot(int argc, char **argv)
{
  Status st = { STATUS_OK, "" };
  Plot_args a;
  Plot_drawn d;
  int rc;
  for (int k = 2; k < argc; k++)
    if (!strcmp(argv[k], "-h") || !strcmp(argv[k], "--help"))
      return fputs(usage_plot, stdout) == EOF ? STATUS_SYSTEM : STATUS_OK;
  if (!(rc = plot_args_read(argc, argv, &a, &st))) rc = plot_run(&a, stdout, &d, &st);
  if (rc) {
    fprintf(stderr, "contactopt: %s\n", st.msg);
    return rc;
  }
  for (int k = 0; k < d.n; k++)
    printf("%s: %s.pdf, %s.png\n", a.dir, d.name[d.drawn[k]], d.name[d.drawn[k]]);
  return fflush(stdout) ? STATUS_SYSTEM : STATUS_OK;
}
#line 1117 "paper/main.nw"
static int command_plain(int argc, char **argv)
{
  int latex = argc == 3 && !strcmp(argv[2], "--latex");
  if (!strcmp(argv[1], "plot")) return command_plot(argc, argv);
  if (!strcmp(argv[1], "--version"))
    printf("contactopt %s\n", CONTACTOPT_VERSION), threads_version(stdout);
  else if (strcmp(argv[1], "keys")) return -1;
  else if (argc > 2 && (!strcmp(argv[2], "-h") || !strcmp(argv[2], "--help")))
    fputs(usage_keys, stdout);
  else if (argc > 3 || (argc == 3 && !latex)) {
    fprintf(stderr, "contactopt: keys: %s: unknown option (try --help)\n", argv[2]);
    return STATUS_INPUT;
  } else scene_keys_print(stdout, latex);
  return fflush(stdout) ? STATUS_SYSTEM : STATUS_OK;
}
#line 1145 "paper/main.nw"
static const Command commands[] = {
  { "solve", usage_solve, "", command_solve, 1, 0, 0 },
  { "gradcheck", usage_gradcheck, "-gradcheck", command_gradcheck, 0, 1, 0 },
  { "optimize", usage_optimize, "-optimize", command_optimize, 1, 0, 1 },
};

int main(int argc, char **argv)
{
  Status st = { STATUS_OK, "" };
  Args a;
  const Command *c = NULL;
  int help = 0, plain = argc > 1 ? command_plain(argc, argv) : -1;
  if (plain >= 0) return plain;
  for (size_t k = 0; argc > 1 && k < sizeof commands / sizeof *commands; k++)
    if (!strcmp(commands[k].name, argv[1])) c = &commands[k];
  for (int k = 1; k < argc; k++)
    help |= !strcmp(argv[k], "-h") || !strcmp(argv[k], "--help");
  if (argc < 2 || (!c && help)) {
    fputs(usage_main, argc < 2 ? stderr : stdout);
    return argc < 2 ? STATUS_INPUT : STATUS_OK;
  }
  if (!c) {
    fprintf(stderr, "contactopt: unknown command '%s' (try --help)\n", argv[1]);
    return STATUS_INPUT;
  }
  if (help) { fputs(c->usage, stdout); return STATUS_OK; }
  cholmod_common cm;
  cholmod_l_start(&cm);
  cm.print = 0;             /* the library reports through Status, not stderr */
  gsl_set_error_handler_off();  /* likewise GSL: its codes are checked */
  int rc = args_read(argc, argv, &a, &st);
  if (!rc && a.plot_files && !c->plot_files)
    rc = status_set(&st, STATUS_INPUT, "command line: --plot-files: %s "
                    "writes no mesh files", c->name);
  if (!rc && a.components && !c->components)
    rc = status_set(&st, STATUS_INPUT, "command line: --components: %s "
                    "checks no gradient", c->name);
  if (!rc) rc = run_command(&a, c, &cm, &st);
  if (rc) fprintf(stderr, "contactopt: %s\n", st.msg);
  cholmod_l_finish(&cm);
  return rc;
}
