/* test_output: the staging of the output folder with a folder staged whole
   (iterates/), and the recorder's VTU of each iterate.  (1) A second run
   with fewer iterates replaces the folder whole: no iterate of the first
   is left, nothing is left aside, and a file put among the first run's
   goes with it.  (2) The checked error of
   the recorder: an iterate whose design is not the model's is refused
   (STATUS_INPUT, naming the iterate), and the output folder stays as it
   was.  The files' contents are read back by tests/paraview.sh. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "case.h"
#include "output.h"

/* the entries of folder path, . and .. aside; -1 if it is not there */
static int entries(const char *path)
{
  DIR *d = opendir(path);
  int n = 0;
  if (!d) return -1;
  for (struct dirent *e; (e = readdir(d)); )
    n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
  closedir(d);
  return n;
}

/* one optimisation's files as the command line writes them: the recorder
   with VTUs, `iterations` iterates at the model's design (the last one at
   `bad` if given), history.dat, iterates.dat, iterates.pvd */
static int run(const char *dir, Model *md, const Problem *p, const double *X,
               int iterations, const double *bad, Status *st)
{
  Output o;
  Output_history *h = output_history_new(p->N + 1, st);
  int rc = h ? output_begin(&o, dir, "solve", 0, st) : (int) st->code;
  if (rc) { output_history_free(h); return rc; }
  rc = output_history_vtu(h, &o, md, st);
  for (int k = 0; !rc && k < iterations; k++) {
    Opt_progress pr = { k, model_energy(md), 1, k + 1, 0, 1, 0 };
    output_history_add(h, &pr, bad && k == iterations - 1 ? bad : X);
  }
  if (!rc) rc = output_history(&o, p, h, st);
  FILE *f = rc ? NULL : output_open(&o, "summary.dat", st);   /* a run's folder */
  if (f) fputs("# name value\n", f), rc = output_close(&o, f, st);
  output_history_free(h);
  return output_end(&o, rc, st);
}

int main(void)
{
  Case cs;
  Status st = { STATUS_OK, "" };
  char dir[] = "/tmp/test_output-XXXXXX", out[64], path[128];
  if (!check(!case_load(&cs, EX51, 0, NULL) && mkdtemp(dir),
             "the scene loads, a scratch folder: %s", cs.st.msg))
    return check_done();
  if (!check(!case_model(&cs) && !case_solve(&cs), "the model solves at alpha0: %s", cs.st.msg))
    return check_done();
  Model *md = cs.md;
  Scene *s = &cs.s;
  snprintf(out, sizeof out, "%s/out", dir);

  /* (1) iterates/ replaced whole */
  int rc1 = run(out, md, &s->problem, s->alpha0, 5, NULL, &st);
  snprintf(path, sizeof path, "%s/iterates", out);
  check(!rc1 && entries(path) == 5, "a run of 5 iterates: iterates/ holds %d files", entries(path));
  snprintf(path, sizeof path, "%s/other.txt", out);
  FILE *f = fopen(path, "w");
  if (f) fclose(f);
  int rc2 = run(out, md, &s->problem, s->alpha0, 2, NULL, &st);
  char iter[128];
  snprintf(iter, sizeof iter, "%s/iterates", out);
  check(!rc2 && entries(iter) == 2, "a second run of 2 iterates into the same folder: "
        "iterates/ holds %d files (its own only)", entries(iter));
  check(entries(out) == 5 && access(path, F_OK) != 0, "the output folder: iterates/, "
        "history.dat, iterates.dat, iterates.pvd, summary.dat, nothing set aside, and "
        "other.txt gone with the first run (%d entries)", entries(out));
  check(entries(dir) == 1, "no staging folder is left beside it (%d entries)", entries(dir));

  /* (2) an iterate at a design that is not the model's */
  double bad[s->problem.N + 1];
  memcpy(bad, s->alpha0, sizeof bad);
  bad[3] *= 0.5;
  int rc3 = run(out, md, &s->problem, s->alpha0, 4, bad, &st);
  check(rc3 == STATUS_INPUT && strstr(st.msg, "not at iterate 3") && strstr(st.msg, "alpha_3"),
        "a model not at the iterate: status %d, \"%s\"", rc3, st.msg);
  snprintf(path, sizeof path, "%s/iterates", out);
  check(entries(path) == 2 && entries(out) == 5 && entries(dir) == 1,
        "after the refusal the output folder is as it was (iterates/ %d files), no stage left",
        entries(path));

  close_case(&cs);
  snprintf(path, sizeof path, "rm -rf %s", dir);
  if (system(path)) check(0, "removing %s", dir);
  return check_done();
}
