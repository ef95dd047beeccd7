#line 137 "paper/figures.nw"
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <time.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "plot_private.h"
#include "interrupt.h"
#line 311 "paper/figures.nw"
int plot_args_read(int argc, char **argv, Plot_args *a, Status *st)
{
  memset(a, 0, sizeof *a);
  for (int k = 2; k < argc; k++) {
    const char *s = argv[k];
    int more = k + 1 < argc;
    if (!strcmp(s, "-o") && more) a->name = argv[++k];
    else if (!strcmp(s, "--start") && more) a->start = argv[++k];
    else if (!strcmp(s, "--title") && more) a->title = argv[++k];
    else if (!strcmp(s, "--body")) a->figures |= PLOT_BODY;
    else if (!strcmp(s, "--results")) a->figures |= PLOT_RESULTS;
    else if (!strcmp(s, "--gnuplot")) a->print = 1;
    else if (s[0] != '-' && !a->dir) a->dir = s;
    else return status_set(st, STATUS_INPUT, "command line: %s: %s", s,
                           s[0] == '-' ? "unknown option or missing value"
                                       : "more than one folder");
  }
  if (!a->figures) a->figures = PLOT_BODY | PLOT_RESULTS;
  if (!a->dir || !a->dir[0])
    return status_set(st, STATUS_INPUT, "command line: plot: no DIR given");
  if (a->name && !a->name[0])
    return status_set(st, STATUS_INPUT, "command line: -o: an empty name");
  if (a->start && !(a->figures & PLOT_RESULTS))
    return status_set(st, STATUS_INPUT, "command line: --start: only the "
                      "results figure draws it");
  return STATUS_OK;
}
#line 351 "paper/figures.nw"
/* dir/name is there, a plain file */
static int has(const char *dir, const char *name)
{
  char path[2200];
  struct stat sb;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return !stat(path, &sb) && S_ISREG(sb.st_mode);
}

/* dir's last component contains ".partial-": a staging folder */
static int staging(const char *dir)
{
  char last[1024];
  size_t n = strlen(dir), k;
  while (n > 1 && dir[n - 1] == '/') n--;
  for (k = n; k > 0 && dir[k - 1] != '/'; k--) ;
  snprintf(last, sizeof last, "%.*s", (int) (n - k), dir + k);
  return strstr(last, ".partial-") != NULL;
}
#line 375 "paper/figures.nw"
static const char *const state_files[] = { "shape.dat", "contact.dat", "solution.vtu" };

/* dir: a finished run of solve or optimize (*optimize says which) whose
   states have their mesh files */
static int plot_folder(const char *dir, int *optimize, Status *st)
{
  struct stat sb;
  if (staging(dir))
    return status_set(st, STATUS_INPUT, "plot: %s: the staging folder of a run "
                      "that did not finish, not an output folder", dir);
  if (stat(dir, &sb))
    return status_set(st, STATUS_INPUT, "plot: %s: %s", dir,
                      errno == ENOENT ? "no such folder" : strerror(errno));
  if (!S_ISDIR(sb.st_mode))
    return status_set(st, STATUS_INPUT, "plot: %s: not a folder", dir);
  if (has(dir, "gradient.dat"))
    return status_set(st, STATUS_INPUT, "plot: %s: an output folder of gradcheck; "
                      "plot draws those of solve and optimize", dir);
  if (!has(dir, "summary.dat") || !has(dir, "effective.scene"))
    return status_set(st, STATUS_INPUT, "plot: %s: not an output folder of solve "
                      "or optimize (no summary.dat and effective.scene)", dir);
  *optimize = has(dir, "history.dat");
  for (int k = 0; k < (*optimize ? 2 : 1); k++)
    for (int j = 0; j < 3; j++) {
      char name[64];
      snprintf(name, sizeof name, "%s%s", *optimize ? (k ? "final/" : "initial/")
               : "", state_files[j]);
      if (!has(dir, name))
        return status_set(st, STATUS_INPUT, "plot: %s: not an output folder of "
                          "solve or optimize (no %s)", dir, name);
    }
  return STATUS_OK;
}
#line 413 "paper/figures.nw"
/* the value of the line "name value" of dir/summary.dat, or fallback */
static double summary_value(const char *dir, const char *name, double fallback)
{
  char path[2200], line[1024], key[128];
  double v, found = fallback;
  FILE *f;
  snprintf(path, sizeof path, "%s/summary.dat", dir);
  if (!(f = fopen(path, "r"))) return fallback;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "%127s %lf", key, &v) == 2 && !strcmp(key, name)) found = v;
  fclose(f);
  return found;
}
#line 430 "paper/figures.nw"
/* the least and greatest objective (column 2) of dir/history.dat; NaN
   where it has none */
static void history_range(const char *dir, double *lo, double *hi)
{
  char path[2200], line[1024];
  double k, v;
  FILE *f;
  *lo = *hi = NAN;
  snprintf(path, sizeof path, "%s/history.dat", dir);
  if (!(f = fopen(path, "r"))) return;
  while (fgets(line, sizeof line, f))
    if (line[0] != '#' && sscanf(line, "%lf %lf", &k, &v) == 2 && isfinite(v))
      *lo = isnan(*lo) ? v : fmin(*lo, v), *hi = isnan(*hi) ? v : fmax(*hi, v);
  fclose(f);
}
#line 2832 "paper/figures.nw"
extern char **environ;

/* gnuplot started, reading its script from *f, its errors going to err */
static int gnuplot_start(pid_t *pid, FILE **f, int err, Status *st)
{
  int fd[2], rc;
  char *argv[] = { (char *) "gnuplot", NULL };
  posix_spawn_file_actions_t fa;
  if (pipe(fd))
    return status_set(st, STATUS_SYSTEM, "plot: cannot run gnuplot: %s", strerror(errno));
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fd[0], 0);
  posix_spawn_file_actions_adddup2(&fa, err, 2);
  posix_spawn_file_actions_addclose(&fa, fd[0]);
  posix_spawn_file_actions_addclose(&fa, fd[1]);
  rc = posix_spawnp(pid, "gnuplot", &fa, NULL, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  close(fd[0]);
  if (rc) {
    close(fd[1]);
    return status_set(st, STATUS_SYSTEM, "plot: cannot run gnuplot (%s); it draws "
                      "the figures: install it (Debian: apt-get install gnuplot-nox)",
                      strerror(rc));
  }
  if (!(*f = fdopen(fd[1], "w"))) {
    close(fd[1]);
    waitpid(*pid, NULL, 0);
    return status_set(st, STATUS_SYSTEM, "plot: cannot write to gnuplot: %s", strerror(errno));
  }
  return STATUS_OK;
}
#line 2867 "paper/figures.nw"
static void last_line(FILE *f, char *buf, size_t size)
{
  char line[1024];
  buf[0] = 0;
  rewind(f);
  while (fgets(line, sizeof line, f)) {
    char *s = line, *e = line + strlen(line);
    while (*s == ' ' || *s == '\t') s++;
    while (e > s && (e[-1] == '\n' || e[-1] == ' ' || e[-1] == '\t')) *--e = 0;
    if (*s) snprintf(buf, size, "%s", s);
  }
}
#line 2888 "paper/figures.nw"
enum { GNUPLOT_GRACE = 2000 };   /* ms that gnuplot has to end after an interrupt */
static int gnuplot_end(pid_t pid, FILE *err, const char *name, Status *st)
{
  int ws = 0, done, waited = 0;
  char why[1024];
  while ((done = waitpid(pid, &ws, WNOHANG)) == 0 || (done < 0 && errno == EINTR)) {
    if (done == 0 && interrupt_signal() && (waited += 10) > GNUPLOT_GRACE) kill(pid, SIGKILL);
    nanosleep(&(struct timespec) { 0, 10000000L }, NULL);
  }
  if (done >= 0 && WIFEXITED(ws) && WEXITSTATUS(ws) == 0) return STATUS_OK;
  if (interrupt_signal())
    return status_set(st, STATUS_INTERRUPTED, "plot: interrupted by signal %d: "
                      "%s not drawn", interrupt_signal(), name);
  if (done >= 0 && WIFSIGNALED(ws))
    return status_set(st, STATUS_SYSTEM, "plot: gnuplot was killed by signal %d "
                      "drawing %s", WTERMSIG(ws), name);
  last_line(err, why, sizeof why);
  return status_set(st, STATUS_SYSTEM, "plot: gnuplot failed (exit status %d) "
                    "drawing %s%s%s", done < 0 ? -1 : WEXITSTATUS(ws), name,
                    why[0] ? ": " : "", why);
}
#line 2916 "paper/figures.nw"
static void write_script(FILE *f, const Plot *pl, int fig, const char *out)
{
  if (fig == PLOT_BODY) plot_body_figure(f, pl, out);
  else plot_results_figure(f, pl, out);
}

/* remove the staged files of a figure */
static void unstage(const char *stage)
{
  char path[1300];
  snprintf(path, sizeof path, "%s.pdf", stage);
  remove(path);
  snprintf(path, sizeof path, "%s.png", stage);
  remove(path);
}

/* the staged files of a figure moved into place */
static int commit(const char *stage, const char *name, Status *st)
{
  static const char *const ext[] = { "pdf", "png" };
  char from[1300], to[1300];
  for (int k = 0; k < 2; k++) {
    snprintf(from, sizeof from, "%s.%s", stage, ext[k]);
    snprintf(to, sizeof to, "%s.%s", name, ext[k]);
    if (rename(from, to)) {
      int e = errno;
      unstage(stage);
      return status_set(st, STATUS_SYSTEM, "plot: cannot move %s into place: %s", to,
                        strerror(e));
    }
  }
  return STATUS_OK;
}
#line 2958 "paper/figures.nw"
static int draw(const Plot *pl, int fig, const char *name, Status *st)
{
  char stage[1200];
  struct sigaction ignore, before;
  FILE *f, *err = tmpfile();
  pid_t pid;
  int rc;
  if (!err)
    return status_set(st, STATUS_SYSTEM, "plot: cannot make a temporary file: %s",
                      strerror(errno));
  snprintf(stage, sizeof stage, "%s.partial-%ld", name, (long) getpid());
  if ((rc = gnuplot_start(&pid, &f, fileno(err), st))) {
    fclose(err);
    return rc;
  }
  memset(&ignore, 0, sizeof ignore);
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &before);
  write_script(f, pl, fig, stage);
  fclose(f);               /* an error here is gnuplot's, and its status says it */
  rc = gnuplot_end(pid, err, name, st);
  sigaction(SIGPIPE, &before, NULL);
  fclose(err);
  if (rc) unstage(stage);
  return rc ? rc : commit(stage, name, st);
}
#line 2995 "paper/figures.nw"
static void figure_name(const Plot_args *a, int fig, char *buf, size_t size)
{
  const char *suffix = fig == PLOT_BODY ? "body" : "results";
  if (a->name && a->figures != (PLOT_BODY | PLOT_RESULTS)) snprintf(buf, size, "%s", a->name);
  else if (a->name) snprintf(buf, size, "%s-%s", a->name, suffix);
  else snprintf(buf, size, "%s/plot-%s", a->dir, suffix);
}

static int writable(const char *name, Status *st)
{
  char dir[1200];
  const char *slash = strrchr(name, '/');
  if (!slash) snprintf(dir, sizeof dir, ".");
  else if (slash == name) snprintf(dir, sizeof dir, "/");
  else snprintf(dir, sizeof dir, "%.*s", (int) (slash - name), name);
  if (access(dir, W_OK))
    return status_set(st, STATUS_SYSTEM, "plot: cannot write %s.pdf: %s: %s", name,
                      dir, strerror(errno));
  return STATUS_OK;
}
#line 3025 "paper/figures.nw"
static int plot_open(Plot *pl, const Plot_args *a, Status *st)
{
  char scene[1100], file[64];
  char *override[2] = { (char *) "design.initial=file", file };
  int start_optimize = 0, rc;
  memset(pl, 0, sizeof *pl);
  pl->args = a;
  if ((rc = plot_folder(a->dir, &pl->optimize, st))) return rc;
  if (a->start && !pl->optimize)
    return status_set(st, STATUS_INPUT, "plot: --start: %s is a run of solve; --start "
                      "gives a run of optimize its initial state", a->dir);
  if (a->start && (rc = plot_folder(a->start, &start_optimize, st))) return rc;
  if (start_optimize)
    return status_set(st, STATUS_INPUT, "plot: --start %s: a run of optimize, not of "
                      "solve", a->start);
  snprintf(pl->state[0], sizeof pl->state[0], "%s%s", a->start ? a->start : a->dir,
           pl->optimize && !a->start ? "/initial" : "");
  snprintf(pl->state[1], sizeof pl->state[1], "%s/final", a->dir);
  snprintf(file, sizeof file, "design.file=%sshape.dat", pl->optimize ? "initial/" : "");
  snprintf(scene, sizeof scene, "%s/effective.scene", a->dir);
  if ((rc = scene_load(&pl->s, scene, 2, override, st))) return rc;
  pl->projected = summary_value(a->dir, "initial_projected", 0) != 0;
  pl->iterations = (int) summary_value(a->dir, "iterations", 0);
  pl->start_value = a->start ? summary_value(a->start,
                   objective_name(pl->s.optimizer.objective.kind), NAN) : NAN;
  history_range(a->dir, &pl->jlo, &pl->jhi);
  pl->top = pl->s.problem.gamma;
  pl->left = pl->s.problem.a, pl->right = pl->s.problem.b;
  if (pl->s.problem.part.geometry[0]) {
    if (!(pl->part = mesh_new(&pl->s.problem, st))) return st->code;
    pl->top = pl->part->gamma;
    for (int k = 0; k < pl->part->nnodes; k++)     /* a part may overhang [a, b] */
      pl->left = fmin(pl->left, pl->part->xy[2 * k]),
      pl->right = fmax(pl->right, pl->part->xy[2 * k]);
    if (plot_chains(pl->part, &pl->chains))
      return status_set(st, STATUS_MEMORY, "plot: out of memory");
  }
  for (int k = 0; k < 1 + pl->optimize && (a->figures & PLOT_RESULTS); k++)
    if ((rc = plot_state_read(pl->state[k], &pl->s.problem, pl->part, &pl->mesh[k], st)))
      return rc;
  return STATUS_OK;
}
#line 3072 "paper/figures.nw"
int plot_run(const Plot_args *a, FILE *out, Plot_drawn *d, Status *st)
{
  static const int fig[2] = { PLOT_BODY, PLOT_RESULTS };
  Plot pl;
  int rc = plot_open(&pl, a, st);
  d->n = 0;
  for (int k = 0; k < 2 && !rc; k++) {
    figure_name(a, fig[k], d->name[k], sizeof d->name[k]);
    if ((a->figures & fig[k]) && !a->print) rc = writable(d->name[k], st);
  }
  if (!rc && !a->print)
    interrupt_catch(1, "contactopt: plot: interrupted: the figures finished are "
                    "kept, the one being drawn is not\n", NULL, NULL);
  for (int k = 0; k < 2 && !rc; k++) {
    if (!(a->figures & fig[k])) continue;
    if (a->print) write_script(out, &pl, fig[k], d->name[k]);
    else if (!(rc = draw(&pl, fig[k], d->name[k], st))) d->drawn[d->n++] = k;
    if (!rc && !a->print && interrupt_signal())
      rc = status_set(st, STATUS_INTERRUPTED, "plot: interrupted by signal %d after "
                      "%s", interrupt_signal(), d->name[k]);
  }
  if (!a->print) interrupt_catch(0, NULL, NULL, NULL);
  if (!rc && a->print && fflush(out))
    rc = status_set(st, STATUS_SYSTEM, "plot: cannot print the script: %s", strerror(errno));
  plot_state_free(&pl.mesh[0]), plot_state_free(&pl.mesh[1]);
  plot_chains_free(&pl.chains);
  mesh_free(pl.part);
  scene_free(&pl.s);
  return rc;
}
