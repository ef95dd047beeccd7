#line 16 "paper/main.nw"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "status.h"
#include "scene.h"
#include "output.h"
#include "usage.h"
#line 111 "paper/main.nw"
#define MAX_OVERRIDES 64
typedef struct {
  const char *scene;                   /* the scene file */
  const char *outdir;                  /* -o, or NULL for out/NAME */
  const char *matrix_market;           /* --matrix-market FILE, or NULL */
  int plot_files;                      /* --plot-files */
  int noverride;
  char *override[MAX_OVERRIDES];       /* -s section.key=value */
} Args;

static int args_read(int argc, char **argv, Args *a, Status *st)
{
  memset(a, 0, sizeof *a);
  for (int k = 2; k < argc; k++) {
    const char *s = argv[k];
    int more = k + 1 < argc;
    if (!strcmp(s, "-o") && more) a->outdir = argv[++k];
    else if (!strcmp(s, "--matrix-market") && more) a->matrix_market = argv[++k];
    else if (!strcmp(s, "--plot-files")) a->plot_files = 1;
    else if (!strcmp(s, "-s") && more && a->noverride == MAX_OVERRIDES)
      return status_set(st, STATUS_INPUT, "command line: more than %d -s",
                        MAX_OVERRIDES);
    else if (!strcmp(s, "-s") && more) a->override[a->noverride++] = argv[++k];
    else if (s[0] != '-' && !a->scene) a->scene = s;
    else return status_set(st, STATUS_INPUT, "command line: %s: %s", s,
                           s[0] == '-' ? "unknown option or missing value"
                                       : "more than one scene");
  }
  if (!a->scene) return status_set(st, STATUS_INPUT, "command line: no SCENE given");
  return STATUS_OK;
}
#line 154 "paper/main.nw"
typedef struct {
  const Args *a;            /* the command line */
  Scene s;                  /* the scene, overrides applied */
  Model *md;                /* the discrete problem of s.problem */
  Output_run run;           /* the scene's facts for the summaries */
  char dir[1024];           /* the output folder */
} Run;

static int run_command(const Args *a, const char *suffix,
                       int (*command)(Run *r, Status *st),
                       cholmod_common *cm, Status *st)
{
  Run r = { .a = a };
  int rc = scene_load(&r.s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  r.run = (Output_run) { r.s.path, qp_method_name(r.s.solver.method),
                         opt_method_name(r.s.optimizer.method),
                         opt_metric_name(r.s.optimizer.metric) };
  if (a->outdir) snprintf(r.dir, sizeof r.dir, "%s", a->outdir);
  else output_default_dir(a->scene, suffix, r.dir, sizeof r.dir);
  r.md = model_new(&r.s.problem, &r.s.solver, cm, st);
  rc = r.md ? command(&r, st) : (int) st->code;
  model_free(r.md);
  scene_free(&r.s);
  return rc;
}
#line 189 "paper/main.nw"
static int command_solve(Run *r, Status *st)
{
  Output o;
  Model *md = r->md;
  int rc = model_solve(md, r->s.alpha0, st);
  if (rc || (rc = output_begin(&o, r->dir, st))) return rc;
  o.plot_files = r->a->plot_files;
  rc = output_solve(&o, &r->run, md, r->s.alpha0, st);
  if (!rc && r->a->matrix_market)
    rc = output_matrix_market(r->a->matrix_market, md, st);
  if ((rc = output_end(&o, rc, st))) return rc;
  printf("%s: E = %.10g J/m, KKT residual %.2e after %d %s iterations, "
         "%d of %d contact nodes active, %.3f s -> %s/\n", r->s.path, md->energy,
         md->report.kkt, md->report.iterations, r->run.state_solver,
         md->report.active, md->dofs->nc, md->seconds, r->dir);
  return STATUS_OK;
}
#line 211 "paper/main.nw"
static int refuse_coulomb(const Run *r, const char *command, Status *st)
{
  if (r->s.problem.contact != CONTACT_COULOMB) return STATUS_OK;
  return status_set(st, STATUS_INPUT, "%s: contact.model = coulomb: %s needs "
                    "the gradient of an energy, and a Coulomb state minimises "
                    "none (contact.model = tresca has one)", r->s.path, command);
}
#line 228 "paper/main.nw"
static int command_gradcheck(Run *r, Status *st)
{
  Output o;
  if (refuse_coulomb(r, "gradcheck", st)) return st->code;
  Grad_check *gc = grad_check_new(r->s.problem.N, st);
  int rc = gc ? grad_check(r->md, r->s.alpha0, gc, NULL, NULL, st) : (int) st->code;
  if (!rc && !(rc = output_begin(&o, r->dir, st))
      && !(rc = output_end(&o, output_gradcheck(&o, &r->run, r->md, gc, st), st)))
    printf("%s: largest relative error of the gradient %.3e (node %d) -> %s/\n",
           r->s.path, gc->err[gc->worst], gc->worst, r->dir);
  grad_check_free(gc);
  return rc;
}
#line 254 "paper/main.nw"
static void monitor(const Opt_progress *p, const double *X, void *data)
{
  printf("%4d  E = %.12g  pg = %.3e  active %d  state its %d  %.3f s\n",
         p->iteration, p->energy, p->pgnorm, p->active, p->state_iterations,
         p->seconds);
  fflush(stdout);
  output_history_add(data, p, X);
}
#line 269 "paper/main.nw"
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
#line 288 "paper/main.nw"
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
  if (refuse_coulomb(r, "optimize", st)) rc = st->code;
  else if (!X) rc = status_set(st, STATUS_SYSTEM, "optimize: out of memory");
  else if (!h || !m) rc = st->code;
  else if (!(rc = output_begin(&o, r->dir, st))) {
    o.plot_files = r->a->plot_files;
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
    rc = output_end(&o, rc, st);
  }
  if (!rc)
    printf("%s: E %.10g -> %.10g J/m in %d iterations, %d evaluations, "
           "projected gradient %.2e (%s) -> %s/\n", r->s.path, start.energy,
           rep.energy, rep.iterations, rep.evaluations, rep.pgnorm,
           rep.stop_reason, r->dir);
  if (!rc && strcmp(rep.stop_reason, "converged"))
    rc = status_set(st, STATUS_NUMERIC, "%s: not converged (%s): projected gradient "
                    "%.2e > optimizer.tol = %.0e after %d iterations; the files of the last "
                    "design accepted are in %s/", r->s.path, rep.stop_reason, rep.pgnorm,
                    r->s.optimizer.tol, rep.iterations, r->dir);
  free(X);
  output_history_free(h);
  design_multipliers_free(m);
  return rc;
}
#line 338 "paper/main.nw"
typedef struct {
  const char *name, *usage, *suffix;  /* the command, its help, its folder */
  int (*run)(Run *r, Status *st);     /* the command itself */
} Command;

static const Command commands[] = {
  { "solve", usage_solve, "", command_solve },
  { "gradcheck", usage_gradcheck, "-gradcheck", command_gradcheck },
  { "optimize", usage_optimize, "-optimize", command_optimize },
};

int main(int argc, char **argv)
{
  Status st = { STATUS_OK, "" };
  Args a;
  const Command *c = NULL;
  int help = 0;
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
  if (!rc) rc = run_command(&a, c->suffix, c->run, &cm, &st);
  if (rc) fprintf(stderr, "contactopt: %s\n", st.msg);
  cholmod_finish(&cm);
  return rc;
}
