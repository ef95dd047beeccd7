#line 10 "paper/main.nw"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "status.h"
#include "scene.h"
#include "model.h"
#include "output.h"
#include "grad.h"
#include "design.h"
#include "opt.h"

#line 30 "paper/main.nw"
static const char usage_main[] =
  "usage: contactopt COMMAND SCENE [options]\n"
  "Shape optimisation of an elastic body on a rigid frictionless foundation\n"
  "(Haslinger & Neittaanmaki, M2AN 21, 1987).\n\n"
  "commands:\n"
  "  solve     solve the contact state at the scene's initial shape\n"
  "  gradcheck compare the gradient (4.8) with finite differences of E\n"
  "  optimize  find the contact shape of least energy (Section 4.4)\n\n"
  "'contactopt COMMAND --help' explains the options of a command.\n";

static const char usage_solve[] =
  "usage: contactopt solve SCENE [-o DIR] [-s section.key=value ...]\n"
  "                  [--matrix-market FILE]\n"
  "Solve the contact state problem (4.3) at the scene's initial design and\n"
  "write the results into DIR.\n\n"
  "  -o DIR                output folder (default: out/NAME for SCENE\n"
  "                        NAME.scene); other files in it are left alone\n"
  "  -s section.key=value  override a key of the scene, e.g. -s mesh.M=4;\n"
  "                        repeat for several keys\n"
  "  --matrix-market FILE  also write the stiffness matrix A(X), Dirichlet\n"
  "                        DOFs removed, in Matrix Market format\n"
  "  -h, --help            this text\n\n"
  "DIR receives summary.dat (energy, kkt_residual, iterations,\n"
  "active_contact_nodes, dofs, seconds, ...), shape.dat, contact.dat,\n"
  "nodes.dat, triangles.dat and solution.vtu (ParaView).\n"
  "Exit status: 0 success, 2 bad input, 3 no convergence, 4 cannot write.\n";

static const char usage_gradcheck[] =
  "usage: contactopt gradcheck SCENE [-o DIR] [-s section.key=value ...]\n"
  "Compare the gradient of E by formula (4.8) at the scene's initial design\n"
  "with finite differences of E at the steps C0 * 1e-2 .. 1e-6: central\n"
  "differences, or second-order one-sided ones at a node on the foundation\n"
  "(alpha_i = 0).  Prints the largest relative error |G - G_fd| / max|G|.\n\n"
  "  -o DIR                output folder (default: out/NAME-gradcheck)\n"
  "  -s section.key=value  override a key of the scene (repeatable)\n"
  "  -h, --help            this text\n\n"
  "DIR receives gradient.dat (i, x1, analytic dE/dX_i, best finite\n"
  "difference, relative error) and summary.dat (max_relative_error, ...).\n";

static const char usage_optimize[] =
  "usage: contactopt optimize SCENE [-o DIR] [-s section.key=value ...]\n"
  "Minimise the total potential energy E over the design set B (4.4) from\n"
  "the scene's initial design (moved to the nearest point of B first if it\n"
  "is not in B), by optimizer.method = slsqp (NLopt's SQP, default) or\n"
  "projgrad (Algorithm 4.1).  Prints one line per iteration: iteration, E,\n"
  "projected-gradient norm, active contact nodes, state iterations, seconds.\n\n"
  "  -o DIR                output folder (default: out/NAME-optimize)\n"
  "  -s section.key=value  override a key of the scene (repeatable),\n"
  "                        e.g. -s optimizer.method=projgrad\n"
  "  -h, --help            this text\n\n"
  "DIR receives history.dat, iterates.dat (every iterate), summary.dat\n"
  "(initial_energy, energy, iterations, evaluations, projected_gradient,\n"
  "stop_reason, contact_pressure_cv_initial, contact_pressure_cv_final, ...),\n"
  "multipliers.dat, and initial/ and final/ with the files of solve.\n";
#line 87 "paper/main.nw"
#define MAX_OVERRIDES 64
typedef struct {
  const char *scene;                   /* the scene file */
  const char *outdir;                  /* -o, or NULL for out/NAME */
  const char *matrix_market;           /* --matrix-market FILE, or NULL */
  int noverride;
  char *override[MAX_OVERRIDES];       /* -s section.key=value */
} Args;
#line 98 "paper/main.nw"
static int args_read(int argc, char **argv, Args *a, Status *st)
{
  memset(a, 0, sizeof *a);
  for (int k = 2; k < argc; k++) {
    const char *s = argv[k];
    int more = k + 1 < argc;
    if (!strcmp(s, "-o") && more) a->outdir = argv[++k];
    else if (!strcmp(s, "--matrix-market") && more) a->matrix_market = argv[++k];
    else if (!strcmp(s, "-s") && more) {
      if (a->noverride == MAX_OVERRIDES)
        return status_set(st, STATUS_INPUT, "command line: more than %d -s",
                          MAX_OVERRIDES);
      a->override[a->noverride++] = argv[++k];
    } else if (s[0] != '-' && !a->scene) a->scene = s;
    else return status_set(st, STATUS_INPUT, "command line: %s: %s", s,
                           s[0] == '-' ? "unknown option or missing value"
                                       : "more than one scene");
  }
  if (!a->scene) return status_set(st, STATUS_INPUT, "command line: no SCENE given");
  return STATUS_OK;
}
#line 124 "paper/main.nw"
static void output_dir(const Args *a, const char *suffix, char *dir,
                       size_t size)
{
  if (a->outdir) { snprintf(dir, size, "%s", a->outdir); return; }
  const char *base = strrchr(a->scene, '/');
  base = base ? base + 1 : a->scene;
  size_t len = strlen(base);
  if (len > 6 && !strcmp(base + len - 6, ".scene")) len -= 6;
  snprintf(dir, size, "out/%.*s%s", (int) len, base, suffix);
}
#line 143 "paper/main.nw"
static int write_summary(Output *o, const Scene *s, const Model *md, Status *st)
{
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\n");
  fprintf(f, "scene %s\nstate_solver %s\nmodel %s\n", s->path,
          qp_method_name(s->solver.method), problem_model_name(s->problem.model));
  fprintf(f, "N %d\nM %d\nR %d\ntriangles %d\ndofs %d\ncontact_nodes %d\n",
          s->problem.N, s->problem.M, s->problem.R, md->mesh->ntri, md->dofs->n, md->dofs->nc);
  fprintf(f, "energy %.15g\nkkt_residual %.3e\niterations %d\n", md->energy,
          md->report.kkt, md->report.iterations);
  fprintf(f, "active_contact_nodes %d\nseconds %.6f\n", md->report.active,
          md->seconds);
  return output_close(o, f, st);
}
#line 162 "paper/main.nw"
static int write_matrix_market(const char *path, cholmod_sparse *A,
                               cholmod_common *cm, Status *st)
{
  char tmp[1100];
  snprintf(tmp, sizeof tmp, "%s.partial", path);
  FILE *f = fopen(tmp, "w");
  if (!f) return status_set(st, STATUS_SYSTEM, "%s: cannot write", path);
  int ok = cholmod_write_sparse(f, A, NULL, NULL, cm) >= 0;
  ok = !fclose(f) && ok;
  if (!ok || rename(tmp, path)) {
    remove(tmp);
    return status_set(st, STATUS_SYSTEM, "%s: cannot write", path);
  }
  return STATUS_OK;
}
#line 180 "paper/main.nw"
static int solve_write(const Args *a, const Scene *s, Model *md,
                       cholmod_common *cm, Status *st)
{
  char dir[1024];
  Output o;
  output_dir(a, "", dir, sizeof dir);
  int rc = output_begin(&o, dir, st);
  if (rc) return rc;
  if ((rc = output_state(&o, "", md, s->alpha0, st))
      || (rc = write_summary(&o, s, md, st))) {
    output_abort(&o);
    return rc;
  }
  if (a->matrix_market && (rc = write_matrix_market(a->matrix_market, md->A, cm, st))) {
    output_abort(&o);
    return rc;
  }
  if ((rc = output_commit(&o, st))) return rc;
  printf("%s: E = %.10g J/m, KKT residual %.2e after %d %s iterations, "
         "%d of %d contact nodes active, %.3f s -> %s/\n", s->path, md->energy,
         md->report.kkt, md->report.iterations, qp_method_name(s->solver.method),
         md->report.active, md->dofs->nc, md->seconds, dir);
  return STATUS_OK;
}

static int command_solve(const Args *a, cholmod_common *cm, Status *st)
{
  Scene s;
  int rc = scene_load(&s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  Model *md = model_new(&s.problem, &s.solver, cm, st);
  if (!md) rc = st->code;
  else if (!(rc = model_solve(md, s.alpha0, st)))
    rc = solve_write(a, &s, md, cm, st);
  model_free(md);
  scene_free(&s);
  return rc;
}
#line 234 "paper/main.nw"
static int energy_at(Model *md, const double *X, double *E, Status *st)
{
  int rc = model_solve(md, X, st);
  *E = md->energy;
  return rc;
}

static int finite_difference(Model *md, double *X, int i, double s,
                             double *fd, Status *st)
{
  double x0 = X[i], E1, E2, E0;
  int rc, central = x0 - s >= 0;
  X[i] = central ? x0 - s : x0;
  if (!(rc = energy_at(md, X, &E0, st))) {
    X[i] = x0 + s;
    if (!(rc = energy_at(md, X, &E1, st)) && !central) {
      X[i] = x0 + 2 * s;
      rc = energy_at(md, X, &E2, st);
    }
  }
  X[i] = x0;
  if (!rc) *fd = central ? (E1 - E0) / (2 * s) : (-3 * E0 + 4 * E1 - E2) / (2 * s);
  return rc;
}
#line 261 "paper/main.nw"
static int best_differences(Model *md, const Scene *s, const double *G,
                            double *best, double *err, Status *st)
{
  int n = s->problem.N + 1, rc = STATUS_OK;
  double Gmax = 0, *X = malloc(n * sizeof *X);
  if (!X) return status_set(st, STATUS_SYSTEM, "gradcheck: out of memory");
  memcpy(X, s->alpha0, n * sizeof *X);
  for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(G[i]));
  for (int i = 0; i < n && !rc; i++) {
    err[i] = INFINITY;
    for (double step = 1e-2; step >= 1e-6 * 0.999 && !rc; step /= 10) {
      double fd;
      if ((rc = finite_difference(md, X, i, step * s->problem.C0, &fd, st))) break;
      double e = fabs(fd - G[i]) / (Gmax > 0 ? Gmax : 1);
      if (e < err[i]) { err[i] = e; best[i] = fd; }
    }
  }
  free(X);
  return rc;
}
#line 284 "paper/main.nw"
static int write_gradient(Output *o, const Model *md, const double *G,
                          const double *best, const double *err, Status *st)
{
  FILE *f = output_open(o, "gradient.dat", st);
  if (!f) return st->code;
  fprintf(f, "# i x1[m] dE/dX_i[J/m^2] finite_difference[J/m^2] relative_error\n");
  for (int i = 0; i < md->mesh->ncol; i++)
    fprintf(f, "%d %.10g %.15g %.15g %.3e\n", i, md->mesh->xy[2 * i], G[i],
            best[i], err[i]);
  return output_close(o, f, st);
}

static int gradcheck_write(const Args *a, const Scene *s, const Model *md,
                           const double *G, const double *best,
                           const double *err, Status *st)
{
  char dir[1024];
  Output o;
  int worst = 0, rc;
  for (int i = 1; i <= s->problem.N; i++) if (err[i] > err[worst]) worst = i;
  output_dir(a, "-gradcheck", dir, sizeof dir);
  if ((rc = output_begin(&o, dir, st))) return rc;
  FILE *f = output_open(&o, "summary.dat", st);
  if (!f) { output_abort(&o); return st->code; }
  fprintf(f, "# name value\nscene %s\nmodel %s\nN %d\nenergy %.15g\n"
             "max_relative_error %.3e\nworst_node %d\n", s->path,
          problem_model_name(s->problem.model), s->problem.N, md->energy, err[worst], worst);
  if ((rc = output_close(&o, f, st)) || (rc = write_gradient(&o, md, G, best, err, st))
      || (rc = output_commit(&o, st))) {
    output_abort(&o);
    return rc;
  }
  printf("%s: largest relative error of the gradient %.3e (node %d) -> %s/\n",
         s->path, err[worst], worst, dir);
  return STATUS_OK;
}
#line 324 "paper/main.nw"
static int command_gradcheck(const Args *a, cholmod_common *cm, Status *st)
{
  Scene s;
  int rc = scene_load(&s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  Model *md = model_new(&s.problem, &s.solver, cm, st);
  double *G = malloc(3 * (s.problem.N + 1) * sizeof *G);
  if (!md) rc = st->code;
  else if (!G) rc = status_set(st, STATUS_SYSTEM, "gradcheck: out of memory");
  else if (!(rc = model_solve(md, s.alpha0, st)) && !(rc = grad_energy(md, G, st))) {
    double *best = G + s.problem.N + 1, *err = best + s.problem.N + 1;
    if (!(rc = best_differences(md, &s, G, best, err, st))
        && !(rc = model_solve(md, s.alpha0, st)))
      rc = gradcheck_write(a, &s, md, G, best, err, st);
  }
  free(G);
  model_free(md);
  scene_free(&s);
  return rc;
}
#line 354 "paper/main.nw"
typedef struct {
  int n, size;              /* iterations recorded, room */
  int ndesign;              /* N+1 */
  Opt_progress *p;          /* the history */
  double *X;                /* ndesign per iteration: the iterates */
  int failed;               /* out of memory while recording */
} History;

static int history_grow(History *h)
{
  int size = 2 * h->size + 16;
  Opt_progress *p = realloc(h->p, size * sizeof *p);
  if (p) h->p = p;
  double *X = realloc(h->X, (size_t) size * h->ndesign * sizeof *X);
  if (X) h->X = X;
  if (!p || !X) return h->failed = 1;
  h->size = size;
  return 0;
}

static void monitor(const Opt_progress *p, const double *X, void *data)
{
  History *h = data;
  printf("%4d  E = %.12g  pg = %.3e  active %d  state its %d  %.3f s\n",
         p->iteration, p->energy, p->pgnorm, p->active, p->state_iterations,
         p->seconds);
  fflush(stdout);
  if (h->failed || (h->n == h->size && history_grow(h))) return;
  memcpy(h->X + (size_t) h->n * h->ndesign, X, h->ndesign * sizeof *X);
  h->p[h->n++] = *p;
}
#line 390 "paper/main.nw"
static int feasible_start(const Scene *s, const Design_set *B, double *X,
                          double *moved, Status *st)
{
  int n = s->problem.N + 1, rc = STATUS_OK;
  *moved = 0;
  memcpy(X, s->alpha0, n * sizeof *X);
  double v = design_violation(B, X);
  if (v <= 1e-12) return STATUS_OK;
  if ((rc = design_project(B, s->alpha0, X, NULL, st))) return rc;
  for (int i = 0; i < n; i++) *moved += (X[i] - s->alpha0[i]) * (X[i] - s->alpha0[i]);
  *moved = sqrt(*moved);
  printf("%s: the initial design is not in B (largest relative violation "
         "%.3g): moved to the nearest point of B, at distance %.6g m\n",
         s->path, v, *moved);
  return STATUS_OK;
}
#line 409 "paper/main.nw"
static int write_history(Output *o, const Scene *s, const History *h,
                         Status *st)
{
  int rc;
  FILE *f = output_open(o, "history.dat", st);
  if (!f) return st->code;
  fprintf(f, "# iteration E[J/m] projected_gradient state_solves seconds\n");
  for (int k = 0; k < h->n; k++)
    fprintf(f, "%d %.15g %.6e %d %.6f\n", h->p[k].iteration, h->p[k].energy,
            h->p[k].pgnorm, h->p[k].state_solves, h->p[k].seconds);
  if ((rc = output_close(o, f, st))) return rc;
  if (!(f = output_open(o, "iterates.dat", st))) return st->code;
  fprintf(f, "# iteration i x1[m] alpha[m]: one block per iteration\n");
  for (int k = 0; k < h->n; k++, fprintf(f, "\n"))
    for (int i = 0; i < h->ndesign; i++)
      fprintf(f, "%d %d %.10g %.17g\n", h->p[k].iteration, i,
              s->problem.a + i * (s->problem.b - s->problem.a) / s->problem.N, h->X[(size_t) k * h->ndesign + i]);
  return output_close(o, f, st);
}

#line 438 "paper/main.nw"
static int write_multipliers(Output *o, const Scene *s, const Model *md,
                             const double *X, double *mu, Status *st)
{
  Design_set B = design_set(&s->problem);
  int n = s->problem.N + 1, rc;
  double *G = malloc(n * sizeof *G), residual;
  Design_multipliers *m = design_multipliers_new(&B, st);
  FILE *f = NULL;
  if (!m) rc = st->code;
  else if (!G) rc = status_set(st, STATUS_SYSTEM, "optimize: out of memory");
  else if (!(rc = grad_energy(md, G, st))
           && !(rc = design_kkt(&B, X, G, -1, NULL, m, &residual, st))
           && !(rc = (f = output_open(o, "multipliers.dat", st)) ? 0 : st->code)) {
    fprintf(f, "# i x1[m] alpha[m] dE/dX_i lower(-X_i<=0) upper(X_i-C0<=0) "
               "rise(X_i+1-X_i-d<=0) fall(X_i-X_i+1-d<=0); mu = %.15g\n", m->mu);
    for (int i = 0; i < n; i++)
      fprintf(f, "%d %.10g %.17g %.15g %.15g %.15g %.15g %.15g\n", i,
              s->problem.a + i * B.h, X[i], G[i], m->lower[i], m->upper[i],
              i < s->problem.N ? m->up[i] : 0.0, i < s->problem.N ? m->down[i] : 0.0);
    *mu = m->mu;
    rc = output_close(o, f, st);
  }
  free(G);
  design_multipliers_free(m);
  return rc;
}

static int write_opt_summary(Output *o, const Scene *s, const Model *md,
                             const Opt_report *r, double E0, double cv0,
                             double moved, double mu, Status *st)
{
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\nscene %s\noptimizer %s\nmetric %s\nstate_solver %s\n"
          "model %s\n", s->path, opt_method_name(s->optimizer.method), opt_metric_name(s->optimizer.metric),
          qp_method_name(s->solver.method), problem_model_name(s->problem.model));
  fprintf(f, "N %d\nM %d\nR %d\ninitial_projected %d\ninitial_moved %.6e\n",
          s->problem.N, s->problem.M, s->problem.R, moved > 0, moved);
  fprintf(f, "initial_energy %.15g\nenergy %.15g\niterations %d\nevaluations %d\n",
          E0, r->energy, r->iterations, r->evaluations);
  fprintf(f, "projected_gradient %.6e\nstop_reason %s\n", r->pgnorm, r->stop_reason);
  fprintf(f, "seconds %.6f\nmetric_seconds %.6f\nstate_seconds %.6f\n",
          r->seconds, r->metric_seconds, r->state_seconds);
  fprintf(f, "contact_pressure_cv_initial %.6f\ncontact_pressure_cv_final %.6f\n",
          cv0, model_pressure_cv(md));
  fprintf(f, "active_contact_nodes %d\nkkt_residual %.3e\narea_multiplier %.15g\n",
          md->report.active, md->report.kkt, mu);
  return output_close(o, f, st);
}
#line 491 "paper/main.nw"
static int optimize_run(const Scene *s, Model *md, double *X,
                        Output *o, Status *st)
{
  Design_set B = design_set(&s->problem);
  History h = { 0, 0, s->problem.N + 1, NULL, NULL, 0 };
  Opt_report r;
  double moved, E0, cv0, mu = 0;
  int rc;
  if ((rc = feasible_start(s, &B, X, &moved, st)) || (rc = model_solve(md, X, st))
      || (rc = output_state(o, "initial", md, X, st)))
    return rc;
  E0 = md->energy;
  cv0 = model_pressure_cv(md);
  if (!(rc = opt_minimize(md, &B, &s->optimizer, X, monitor, &h, &r, st))) {
    if (h.failed) rc = status_set(st, STATUS_SYSTEM, "optimize: out of memory");
    else if (!(rc = output_state(o, "final", md, X, st))
             && !(rc = write_history(o, s, &h, st))
             && !(rc = write_multipliers(o, s, md, X, &mu, st)))
      rc = write_opt_summary(o, s, md, &r, E0, cv0, moved, mu, st);
  }
  if (!rc)
    printf("%s: E %.10g -> %.10g J/m in %d iterations, %d evaluations, "
           "projected gradient %.2e (%s) -> %s/\n", s->path, E0, r.energy,
           r.iterations, r.evaluations, r.pgnorm, r.stop_reason, o->dir);
  free(h.p);
  free(h.X);
  return rc;
}

static int command_optimize(const Args *a, cholmod_common *cm, Status *st)
{
  Scene s;
  char dir[1024];
  Output o;
  int rc = scene_load(&s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  Model *md = model_new(&s.problem, &s.solver, cm, st);
  double *X = malloc((s.problem.N + 1) * sizeof *X);
  output_dir(a, "-optimize", dir, sizeof dir);
  if (!md) rc = st->code;
  else if (!X) rc = status_set(st, STATUS_SYSTEM, "optimize: out of memory");
  else if (!(rc = output_begin(&o, dir, st))) {
    if ((rc = optimize_run(&s, md, X, &o, st)) || (rc = output_commit(&o, st)))
      output_abort(&o);
  }
  free(X);
  model_free(md);
  scene_free(&s);
  return rc;
}
#line 548 "paper/main.nw"
typedef struct {
  const char *name;
  const char *usage;
  int (*run)(const Args *a, cholmod_common *cm, Status *st);
} Command;

static const Command commands[] = {
  { "solve", usage_solve, command_solve },
  { "gradcheck", usage_gradcheck, command_gradcheck },
  { "optimize", usage_optimize, command_optimize },
};

static const Command *command_find(const char *name)
{
  for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++)
    if (!strcmp(commands[k].name, name)) return &commands[k];
  return NULL;
}

static int wants_help(int argc, char **argv)
{
  for (int k = 1; k < argc; k++)
    if (!strcmp(argv[k], "-h") || !strcmp(argv[k], "--help")) return 1;
  return 0;
}

int main(int argc, char **argv)
{
  Status st = { STATUS_OK, "" };
  Args a;
  const Command *c = argc > 1 ? command_find(argv[1]) : NULL;
  if (argc < 2 || (!c && wants_help(argc, argv))) {
    fputs(usage_main, argc < 2 ? stderr : stdout);
    return argc < 2 ? STATUS_INPUT : STATUS_OK;
  }
  if (!c) {
    fprintf(stderr, "contactopt: unknown command '%s' (try --help)\n", argv[1]);
    return STATUS_INPUT;
  }
  if (wants_help(argc, argv)) { fputs(c->usage, stdout); return STATUS_OK; }
  cholmod_common cm;
  cholmod_start(&cm);
  cm.print = 0;             /* the library reports through Status, not stderr */
  gsl_set_error_handler_off();  /* likewise GSL: its codes are checked */
  int rc = args_read(argc, argv, &a, &st);
  if (!rc) rc = c->run(&a, &cm, &st);
  if (rc) fprintf(stderr, "contactopt: %s\n", st.msg);
  cholmod_finish(&cm);
  return rc;
}
