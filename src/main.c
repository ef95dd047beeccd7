#line 18 "paper/main.nw"
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
#line 208 "paper/main.nw"
typedef struct {
  const Args *a;            /* the command line */
  Scene s;                  /* the scene, overrides applied */
  Model *md;                /* the discrete problem of s.problem */
  Output_run run;           /* the scene's facts for the summaries */
  char dir[1024];           /* the output folder */
} Run;
static int command_optimize(Run *r, Status *st);

static int run_command(const Args *a, const char *suffix,
                       int (*command)(Run *r, Status *st),
                       cholmod_common *cm, Status *st)
{
  Run r = { .a = a };
  int rc = scene_load(&r.s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  if (r.s.note[0]) printf("%s: %s\n", r.s.path, r.s.note);
  r.run = (Output_run) { r.s.path, qp_method_name(r.s.solver.method),
                         opt_method_name(r.s.optimizer.method),
                         opt_metric_name(r.s.optimizer.metric) };
  if (a->outdir) snprintf(r.dir, sizeof r.dir, "%s", a->outdir);
  else output_default_dir(a->scene, suffix, r.dir, sizeof r.dir);
  double extra = command == command_optimize ? opt_memory(&r.s.optimizer, r.s.problem.N) : 0;
  if (!(rc = output_check(r.dir, st))                  /* before any work */
      && !(rc = model_fits(&r.s.problem, extra, r.s.path, st))
      && !(rc = threads_start(r.s.path, model_memory(&r.s.problem) + extra, st))) {
    r.md = model_new(&r.s.problem, &r.s.solver, cm, st);
    rc = r.md ? command(&r, st) : (int) st->code;
  }
  model_free(r.md);
  scene_free(&r.s);
  return rc;
}
#line 265 "paper/main.nw"
#define LARGE 0.1    /* of the body's size: small strains no longer */
static void warn_large(const Run *r)
{
  const Problem *p = &r->s.problem;
  double size = fmax(p->b - p->a, p->gamma), u = model_displacement_max(r->md);
  if (u > LARGE * size)
    fprintf(stderr, "contactopt: warning: %s: the largest displacement, %.3g m, "
            "exceeds %g of the body's size %.3g m: linear (small-strain) "
            "elasticity does not hold there (E in Pa?)\n", r->s.path, u, LARGE, size);
}
#line 284 "paper/main.nw"
/* the staging folder of the command's files, signals caught while it is there */
static int begin(Run *r, Output *o, Status *st)
{
  interrupt_catch(1);
  int rc = output_begin(o, r->dir, st);
  if (rc) interrupt_catch(0);
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
  interrupt_catch(0);
  if (rc || !r->a->matrix_market) return rc;
  return output_matrix_market(r->a->matrix_market, r->md, st);
}
#line 313 "paper/main.nw"
static int command_solve(Run *r, Status *st)
{
  Output o;
  Model *md = r->md;
  int rc = model_solve(md, r->s.alpha0, st);
  if (rc || (rc = begin(r, &o, st))) return rc;
  if ((rc = finish(r, &o, output_solve(&o, &r->run, md, r->s.alpha0, st), st)))
    return rc;
  printf("%s: E = %.10g J/m, KKT residual %.2e after %d %s iterations, "
         "%d of %d contact nodes active, %.3f s -> %s/\n", r->s.path, md->energy,
         md->report.kkt, md->report.iterations, r->run.state_solver,
         md->report.active, md->dofs->nc, md->seconds, r->dir);
  return STATUS_OK;
}
#line 336 "paper/main.nw"
static void gradcheck_progress(int i, const Grad_check *gc, void *data)
{
  double *last = data, now = model_clock(), worst = 0;
  if (now - *last < 1 && i < gc->N) return;
  *last = now;
  for (int k = 0; k <= i; k++) worst = fmax(worst, gc->err[k]);
  printf("gradcheck: node %d of %d, largest relative error so far %.3e\n",
         i + 1, gc->N + 1, worst);
  fflush(stdout);
}
#line 356 "paper/main.nw"
static int command_gradcheck(Run *r, Status *st)
{
  Output o;
  if (grad_available(&r->s.problem, r->s.path, "gradcheck", st)) return st->code;
  Grad_check *gc = grad_check_new(r->s.problem.N, st);
  double last = model_clock();
  int rc = gc ? grad_check(r->md, r->s.alpha0, gc, gradcheck_progress, &last, st)
              : (int) st->code;
  if (!rc && !(rc = begin(r, &o, st)))
    rc = finish(r, &o, output_gradcheck(&o, &r->run, r->md, gc, st), st);
  if (!rc)
    printf("%s: largest relative error of the gradient %.3e (node %d) -> %s/\n",
           r->s.path, gc->err[gc->worst], gc->worst, r->dir);
  grad_check_free(gc);
  return rc;
}
#line 457 "paper/main.nw"
static int monitor(const Opt_progress *p, const double *X, void *data)
{
  printf("%4d  E = %.12g  pg = %.3e  active %d  state its %d  %.3f s\n",
         p->iteration, p->energy, p->pgnorm, p->active, p->state_iterations,
         p->seconds);
  fflush(stdout);
  output_history_add(data, p, X);
  return interrupt_signal() != 0;
}
#line 473 "paper/main.nw"
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
  return rc ? rc : model_solve(r->md, X, st);
}
#line 494 "paper/main.nw"
static int command_optimize(Run *r, Status *st)
{
  Design_set B = design_set(&r->s.problem);
  Output o;
  Output_start start;
  Opt_report rep;
  int n = r->s.problem.N + 1, rc;
  double *X = malloc(2 * n * sizeof *X), *G = X ? X + n : NULL, moved;
  Output_history *h = output_history_new(n, st);
  Design_multipliers *m = design_multipliers_new(&B, st);
  if (grad_available(&r->s.problem, r->s.path, "optimize", st)) rc = st->code;
  else if (!X) rc = status_set(st, STATUS_MEMORY, "optimize: out of memory");
  else if (!h || !m) rc = st->code;
  else if (!(rc = begin(r, &o, st))) {
    if (!(rc = output_history_vtu(h, &o, r->md, st))   /* iterates/, .pvd */
        && !(rc = optimize_start(r, &B, X, &moved, st))
        && !(rc = output_start(&o, r->md, X, moved, &start, st))
        && !(rc = opt_minimize(r->md, &B, &r->s.optimizer, X, monitor, h, &rep, st))
        && !(rc = output_state(&o, "final", r->md, X, st))
        && !(rc = output_history(&o, &r->s.problem, h, st))
        && !(rc = grad_energy(r->md, G, st))
        && !(rc = design_kkt(&B, X, G, -1, NULL, m, NULL, st))
        && !(rc = output_multipliers(&o, &r->s.problem, X, G, m, st)))
      rc = output_opt_summary(&o, &r->run, r->md, &start, &rep, m->mu, st);
    rc = finish(r, &o, rc, st);
  }
  if (!rc)
    printf("%s: E %.10g -> %.10g J/m in %d iterations, %d evaluations, "
           "projected gradient %.2e (%s) -> %s/\n", r->s.path, start.energy,
           rep.energy, rep.iterations, rep.evaluations, rep.pgnorm,
           rep.stop_reason, r->dir);
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
#line 552 "paper/main.nw"
static int command_plain(int argc, char **argv)
{
  int latex = argc == 3 && !strcmp(argv[2], "--latex");
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
#line 576 "paper/main.nw"
typedef struct {
  const char *name, *usage, *suffix;  /* the command, its help, its folder */
  int (*run)(Run *r, Status *st);     /* the command itself */
  int plot_files;                     /* honours --plot-files */
} Command;

static const Command commands[] = {
  { "solve", usage_solve, "", command_solve, 1 },
  { "gradcheck", usage_gradcheck, "-gradcheck", command_gradcheck, 0 },
  { "optimize", usage_optimize, "-optimize", command_optimize, 1 },
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
  cholmod_start(&cm);
  cm.print = 0;             /* the library reports through Status, not stderr */
  gsl_set_error_handler_off();  /* likewise GSL: its codes are checked */
  int rc = args_read(argc, argv, &a, &st);
  if (!rc && a.plot_files && !c->plot_files)
    rc = status_set(&st, STATUS_INPUT, "command line: --plot-files: %s "
                    "writes no mesh files", c->name);
  if (!rc) rc = run_command(&a, c->suffix, c->run, &cm, &st);
  if (rc) fprintf(stderr, "contactopt: %s\n", st.msg);
  cholmod_finish(&cm);
  return rc;
}
