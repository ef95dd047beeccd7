#line 10 "paper/main.nw"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cholmod.h>
#include "status.h"
#include "scene.h"
#include "model.h"
#include "output.h"

#line 25 "paper/main.nw"
static const char *usage_main =
  "usage: contactopt COMMAND SCENE [options]\n"
  "Shape optimisation of an elastic body on a rigid frictionless foundation\n"
  "(Haslinger & Neittaanmaki, M2AN 21, 1987).\n\n"
  "commands:\n"
  "  solve     solve the contact state at the scene's initial shape\n\n"
  "'contactopt COMMAND --help' explains the options of a command.\n";

static const char *usage_solve =
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
#line 52 "paper/main.nw"
#define MAX_OVERRIDES 64
typedef struct {
  const char *command;                 /* "solve" */
  const char *scene;                   /* the scene file */
  const char *outdir;                  /* -o, or NULL for out/NAME */
  const char *matrix_market;           /* --matrix-market FILE, or NULL */
  int noverride;
  char *override[MAX_OVERRIDES];       /* -s section.key=value */
} Args;
#line 64 "paper/main.nw"
static int args_read(int argc, char **argv, Args *a, Status *st)
{
  memset(a, 0, sizeof *a);
  a->command = argv[1];
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
#line 90 "paper/main.nw"
static void default_outdir(const char *scene, char *dir, size_t size)
{
  const char *base = strrchr(scene, '/');
  base = base ? base + 1 : scene;
  size_t len = strlen(base);
  if (len > 6 && !strcmp(base + len - 6, ".scene")) len -= 6;
  snprintf(dir, size, "out/%.*s", (int) len, base);
}
#line 107 "paper/main.nw"
static int write_summary(Output *o, const Scene *s, const Model *md, Status *st)
{
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\n");
  fprintf(f, "scene %s\nstate_solver %s\nmodel %s\n", s->path,
          scene_state_name(s->state), scene_model_name(s->model));
  fprintf(f, "N %d\nM %d\nR %d\ntriangles %d\ndofs %d\ncontact_nodes %d\n",
          s->N, s->M, s->R, md->mesh->ntri, md->dofs->n, md->dofs->nc);
  fprintf(f, "energy %.15g\nkkt_residual %.3e\niterations %d\n", md->energy,
          md->report.kkt, md->report.iterations);
  fprintf(f, "active_contact_nodes %d\nseconds %.6f\n", md->report.active,
          md->seconds);
  return output_close(o, f, st);
}
#line 126 "paper/main.nw"
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
#line 144 "paper/main.nw"
static int solve_write(const Args *a, const Scene *s, Model *md,
                       cholmod_common *cm, Status *st)
{
  char dir[1024];
  Output o;
  if (a->outdir) snprintf(dir, sizeof dir, "%s", a->outdir);
  else default_outdir(a->scene, dir, sizeof dir);
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
         md->report.kkt, md->report.iterations, scene_state_name(s->state),
         md->report.active, md->dofs->nc, md->seconds, dir);
  return STATUS_OK;
}

static int command_solve(const Args *a, cholmod_common *cm, Status *st)
{
  Scene s;
  int rc = scene_load(&s, a->scene, a->noverride, a->override, st);
  if (rc) return rc;
  Model *md = model_new(&s, cm, st);
  if (!md) rc = st->code;
  else if (!(rc = model_solve(md, s.alpha0, st)))
    rc = solve_write(a, &s, md, cm, st);
  model_free(md);
  scene_free(&s);
  return rc;
}
#line 188 "paper/main.nw"
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
  if (argc < 2 || (wants_help(argc, argv) && (argc == 2 || strcmp(argv[1], "solve")))) {
    fputs(usage_main, argc < 2 ? stderr : stdout);
    return argc < 2 ? STATUS_INPUT : STATUS_OK;
  }
  if (strcmp(argv[1], "solve")) {
    fprintf(stderr, "contactopt: unknown command '%s' (try --help)\n", argv[1]);
    return STATUS_INPUT;
  }
  if (wants_help(argc, argv)) { fputs(usage_solve, stdout); return STATUS_OK; }
  cholmod_common cm;
  cholmod_start(&cm);
  cm.print = 0;             /* the library reports through Status, not stderr */
  int rc = args_read(argc, argv, &a, &st);
  if (!rc) rc = command_solve(&a, &cm, &st);
  if (rc) fprintf(stderr, "contactopt: %s\n", st.msg);
  cholmod_finish(&cm);
  return rc;
}
