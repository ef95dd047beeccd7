/* test_scene_write.c: the effective scene (scene_write, paper/scene.nw).
   Each scene below, with its overrides, is loaded, written to a file in
   another folder, and the written file loaded again: the two scenes must
   be the same bit for bit in every field (problem, both solvers' options,
   the initial shape's kind, formula and file, and alpha0), and their
   states, solved, the same energy bit for bit.  The cases cover the three
   shipped kinds of scene, a refined mesh with another model and another
   initial shape, every key of the fuzzing corpus, Coulomb friction, a
   constant shape under a loaded right side, and a shape file named
   relative to a scene that was itself named relative to the current
   folder, as it is and resampled onto a refined mesh; and parts of the
   user's own (a geometry file, named curves and surfaces, orthotropic
   materials, refined), whose states need the mesher and are not solved
   here.  Then the two
   refusals: a shape file whose path is too long for a line of a scene,
   and a file that cannot be written.  Run from the repository root. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "check.h"
#include "setup.h"
#include "same.h"
#include "model.h"
#include "part_geometry.h"

static char tmpdir[] = "/tmp/test_scene_write.XXXXXX";
static char root[4096];       /* the repository, where the test started */

#define NO_ARC "design.arc_x1=", "design.arc_x2=", "design.arc_radius="
static const struct {
  const char *what, *scene;
  const char *over[12];
} cases[] = {
  {"Example 5.1", "data/example-5.1.scene", {NULL}},
  {"Example 5.1 with Tresca friction", "data/example-5.1-tresca.scene", {NULL}},
  {"Example 5.2 (a line)", "data/example-5.2.scene", {NULL}},
  {"Example 5.1 refined twice, plane strain, a line",
   "data/example-5.1.scene", {"mesh.refine=2", "material.model=plane_strain",
   "design.initial=line", NO_ARC, "design.line_start=0.01",
   "design.line_end=0.04"}},
  {"every key (cgssor, projgrad, a body force)",
   "tests/fuzz/corpus/every-key.scene", {NULL}},
  {"Coulomb friction, SLSQP", "data/example-5.1-tresca.scene",
   {"contact.model=coulomb", "contact.g=", "contact.friction=0.3",
    "optimizer.method=slsqp", "solver.tol=3e-11"}},
  {"a constant shape, the right side loaded, psor",
   "data/example-5.1.scene", {"design.initial=constant", NO_ARC,
   "design.constant=0.03", "right.bc=traction", "right.from=0.5",
   "right.to=0.9", "right.P1=-1e7", "solver.state=psor", "solver.omega=1.3"}},
};

/* E of the state of s at alpha0; 0 and a FAIL line if it cannot be solved */
static double energy(const Scene *s, const char *what)
{
  cholmod_common cm;
  Status st = {STATUS_OK, ""};
  Model *md;
  double e = 0;
  test_start(&cm);
  if (!(md = model_new(&s->problem, &s->solver, &cm, &st))
      || model_solve(md, s->alpha0, &st))
    check(0, "%s: the state is solved: %s", what, st.msg);
  else e = model_energy(md);
  model_free(md);
  cholmod_l_finish(&cm);
  return e;
}

/* a is path with the overrides; write it, load it again as b, compare */
static void round_trip(const char *what, const char *path, int n,
                       char *const *ov, int k)
{
  char out[256];
  Scene a, b;
  Status st = {STATUS_OK, ""};
  FILE *f;
  const char *diff;
  double ea, eb;
  if (!check(scene_load(&a, path, n, ov, &st) == 0, "%s: loads: %s", what,
             st.msg))
    return;
  snprintf(out, sizeof out, "%s/effective-%d.scene", tmpdir, k);
  if (!(f = fopen(out, "w"))) {
    check(0, "%s: cannot open %s", what, out);
    scene_free(&a);
    return;
  }
  check(scene_write(&a, f, &st) == 0 && fclose(f) == 0,
        "%s: the effective scene is written: %s", what, st.msg);
  if (check(scene_load(&b, out, 0, NULL, &st) == 0,
            "%s: the effective scene loads: %s", what, st.msg)) {
    diff = scene_differs(&a, &b);
    check(!diff, "%s: it loads to the same scene, bit for bit%s%s", what,
          diff ? "; differs in " : "", diff ? diff : "");
    if (!a.problem.part.geometry[0]) {
      ea = energy(&a, what), eb = energy(&b, what);
      check(memcmp(&ea, &eb, sizeof ea) == 0 && ea != 0,
            "%s: the same energy, bit for bit (%.17g, %.17g)", what, ea, eb);
    }
    scene_free(&b);
  }
  unlink(out);
  scene_free(&a);
}

/* write text to the file path */
static void put(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f || fputs(text, f) < 0 || fclose(f)) {
    fprintf(stderr, "test_scene_write: cannot write %s\n", path);
    exit(1);
  }
}

/* design.file relative to a scene named relative to the current folder:
   the effective scene names the file by its absolute path, and loads
   from another current folder */
static void relative_file(void)
{
  char path[4200], text[4200], *ov[] = {"design.initial=file", NO_ARC,
                                        "design.file=shape.dat", NULL};
  int i, n = 0;
  snprintf(path, sizeof path, "%s/sub", tmpdir);
  mkdir(path, 0700);
  snprintf(path, sizeof path, "%s/sub/shape.dat", tmpdir);
  for (i = 0; i <= 16; i++)
    n += snprintf(text + n, sizeof text - n, "%g %.17g\n", 0.25 * i, 0.002 * i);
  put(path, text);
  snprintf(path, sizeof path, "%s/data/example-5.1.scene", root);
  snprintf(text, sizeof text, "%s/sub/x.scene", tmpdir);
  if (symlink(path, text)) {
    check(0, "a scene in a subfolder: cannot link %s", text);
    return;
  }
  if (chdir(tmpdir)) return;
  round_trip("a shape file beside a scene named sub/x.scene", "sub/x.scene",
             5, ov, 99);
  ov[5] = "mesh.refine=3";      /* the file's 17 rows resampled on 49 nodes */
  round_trip("the same file resampled on the mesh refined three times",
             "sub/x.scene", 6, ov, 98);
  if (chdir(root)) exit(1);
  snprintf(path, sizeof path, "%s/sub/shape.dat", tmpdir);
  unlink(path);
  unlink(text);
  snprintf(path, sizeof path, "%s/sub", tmpdir);
  rmdir(path);
}

/* parts: a geometry beside the scene, three named curves (a traction, a
   pressure, a clamped one) and two named surfaces, one orthotropic; the
   body orthotropic in plane strain, refined twice; then overrides that
   delete and add named sections and switch the plane model */
static void part_cases(void)
{
  static const char scene[] =
    "[geometry]\na = 0\nb = 4\n"
    "[design]\nN = 16\nC0 = 0.05\nC1 = 0.025\nC2 = 0.91\n"
    "initial = line\nline_start = 0\nline_end = 0.05\n"
    "[mesh]\nM = 1\nC0prime = 0.25\nrefine = 2\n"
    "[material]\nkind = orthotropic\nE1 = 2e11\nE2 = 1e11\nnu12 = 0.3\n"
    "G12 = 5e10\nangle = 30\nmodel = plane_strain\nE3 = 1.5e11\nnu13 = 0.25\n"
    "nu23 = 0.2\n"
    "[part]\ngeometry = block.geo\n"
    "[boundary.top]\nbc = traction\nP1 = 3e7\nP2 = -5.75e8\n"
    "[boundary.bore]\nbc = pressure\np = 1e7\n"
    "[material.rubber]\nE = 6e6\nnu = 0.45\n"
    "[material.ply]\nkind = orthotropic\nE1 = 1.4e11\nE2 = 1e10\nnu12 = 0.28\n"
    "G12 = 5e9\nangle = -45\nE3 = 1e10\nnu13 = 0.28\nnu23 = 0.4\n"
    "[boundary.seat]\nbc = clamped\n"
    "[left]\nbc = roller\n";
  char dir[512], path[600], *ov[] = {"boundary.top.bc=", "boundary.top.P1=",
    "boundary.top.P2=", "boundary.slot.bc=roller", "material.model=plane_stress",
    "mesh.refine=3", "material.rubber.kind=orthotropic", "material.rubber.E1=1e7",
    "material.rubber.E2=5e6", "material.rubber.nu12=0.4", "material.rubber.G12=2e6"};
  snprintf(dir, sizeof dir, "%s/part", tmpdir);
  mkdir(dir, 0700);
  snprintf(path, sizeof path, "%s/block.geo", dir);
  put(path, PART_GEO);
  snprintf(path, sizeof path, "%s/part.scene", dir);
  put(path, scene);
  round_trip("a part: orthotropic in plane strain, three curves, two surfaces, "
             "refined twice", path, 0, ov, 90);
  round_trip("the part with its top curve deleted, a roller curve added, plane "
             "stress, refined three times, the rubber orthotropic", path, 11, ov,
             91);
  unlink(path);
  snprintf(path, sizeof path, "%s/block.geo", dir);
  unlink(path);
  rmdir(dir);
}

/* the refusals: a path too long for a scene line or with " ;" in it, a
   file not writable */
static void refusals(void)
{
  char dir[512], path[768], text[4096], over[800], *ov[] = {
    "design.initial=file", NO_ARC, over};
  Scene s;
  Status st = {STATUS_OK, ""};
  FILE *f;
  int i, n = 0;
  snprintf(dir, sizeof dir, "%s/%0200d", tmpdir, 0);
  mkdir(dir, 0700);
  snprintf(path, sizeof path, "%s/shape.dat", dir);
  for (i = 0; i <= 16; i++)
    n += snprintf(text + n, sizeof text - n, "%g 0.02\n", 0.25 * i);
  put(path, text);
  snprintf(over, sizeof over, "design.file=%s", path);
  if (check(scene_load(&s, "data/example-5.1.scene", 5, ov, &st) == 0,
            "a shape file %d characters deep loads: %s", (int)strlen(path),
            st.msg)) {
    f = tmpfile();
    check(scene_write(&s, f, &st) == STATUS_INPUT && strstr(st.msg, "design.file")
          && strstr(st.msg, "more than a line"),
          "its effective scene is refused, the path too long: %s", st.msg);
    fclose(f);
    scene_free(&s);
  }
  unlink(path);
  rmdir(dir);
  snprintf(dir, sizeof dir, "%s/a ;b", tmpdir);       /* inih: "a" and a comment */
  mkdir(dir, 0700);
  snprintf(path, sizeof path, "%s/shape.dat", dir);
  put(path, text);
  snprintf(over, sizeof over, "design.file=%s", path);
  st.msg[0] = 0;
  if (check(scene_load(&s, "data/example-5.1.scene", 5, ov, &st) == 0,
            "a shape file in a folder \"a ;b\" loads from -s: %s", st.msg)) {
    f = tmpfile();
    check(scene_write(&s, f, &st) == STATUS_INPUT && strstr(st.msg, "would not read back"),
          "its effective scene is refused, the path would read as a comment: %s", st.msg);
    fclose(f);
    scene_free(&s);
  }
  unlink(path);
  rmdir(dir);
  if (scene_load(&s, "data/example-5.1.scene", 0, NULL, &st) == 0
      && (f = fopen("/dev/full", "w"))) {
    check(scene_write(&s, f, &st) == STATUS_SYSTEM
          && strstr(st.msg, "cannot write"),
          "a file that cannot be written: status 4: %s", st.msg);
    fclose(f);
    scene_free(&s);
  }
}

int main(void)
{
  size_t k;
  int n;
  if (!getcwd(root, sizeof root) || !mkdtemp(tmpdir)) {
    perror("test_scene_write");
    return 1;
  }
  for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    for (n = 0; n < 12 && cases[k].over[n]; n++) continue;
    round_trip(cases[k].what, cases[k].scene, n, (char *const *)cases[k].over,
               (int)k);
  }
  relative_file();
  part_cases();
  refusals();
  rmdir(tmpdir);
  return check_done();
}
