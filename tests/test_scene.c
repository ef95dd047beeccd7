/* test_scene.c: what a scene loads to (paper/scene.nw).  The shipped
   scenes load with the article's values (Examples 5.1 and 5.2, the initial
   shape alpha0 sampled at the design nodes); overrides apply, and an
   override of a selector drops the keys that its word makes meaningless;
   a shape file is read as it is at the design nodes and resampled
   elsewhere; a body that no side holds sideways loads when friction can
   hold it and is refused otherwise.  The refusals of the loader:
   test_scene_errors.c; the table of keys: test_scene_keys.c; the
   effective scene: test_scene_write.c.  Run from the repository root. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "scene.h"
#include "scene_files.h"
#include "mesh.h"
#include "resources.h"

/* Example 5.1's arc R1 - sqrt(R1^2 - (x1 - 4)^2) by the obvious formula,
   which loses four digits to cancellation (the module does not): good to
   1e-13.  Exact values, from 40-digit decimal arithmetic: 0.05 at x1 = 0
   (R1^2 - 16 = 159.975^2), 0.01249853527068868192... at x1 = 2. */
static double arc(double R1, double x1)
{
  return R1 - sqrt(R1 * R1 - (x1 - 4) * (x1 - 4));
}
static const double alpha_at_2 = 0.01249853527068868192;

/* Example 5.1 and its values */
static void test_example_5_1(void)
{
  const double R1 = 160.025;
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc = scene_load(&s, "data/example-5.1.scene", 0, NULL, &st), i, mono = 1;
  if (!check(rc == 0, "example 5.1 loads: %s", st.msg)) return;
  check(s.problem.a == 0 && s.problem.b == 4 && s.problem.gamma == 1, "5.1: a = 0, b = 4, gamma = 1");
  check(s.problem.N == 16 && s.problem.C0 == 0.05 && s.problem.C1 == 0.025 && s.problem.C2 == 3.91,
        "5.1: N = 16, C0 = 0.05, C1 = 0.025, C2 = 3.91");
  check(s.problem.M == 1 && s.problem.R == 3 && s.problem.C0prime == 0.25, "5.1: M = 1, R = 3, C0' = 0.25");
  check(s.problem.material.young == 2.15e11 && s.problem.material.nu == 0.29 && s.problem.model == MODEL_PLANE_STRESS,
        "5.1: E = 2.15e11, nu = 0.29, plane stress");
  check(s.problem.side[SIDE_LEFT].kind == BC_CLAMPED
        && s.problem.side[SIDE_RIGHT].kind == BC_ROLLER, "5.1: left clamped, right roller");
  check(s.problem.side[SIDE_TOP].kind == BC_TRACTION && s.problem.side[SIDE_TOP].from == 2
        && s.problem.side[SIDE_TOP].to == 4 && s.problem.side[SIDE_TOP].P[0] == 0
        && s.problem.side[SIDE_TOP].P[1] == -5.75e8, "5.1: top P = (0, -5.75e8) on (2, 4)");
  check(s.problem.body_force[0] == 0 && s.problem.body_force[1] == 0 && !s.problem.has_body_force, "5.1: F = 0");
  check(s.solver.method == QP_PDAS && s.solver.tol == 1e-10 && s.solver.max_iter == 100
        && s.solver.omega == 1.5, "5.1: pdas, tol 1e-10, defaults max_iter 100, omega 1.5");
  check(strcmp(s.initial, "arc") == 0, "5.1: initial = arc");
  check(fabs(s.alpha0[0] - arc(R1, 0)) < 1e-13,
        "5.1: alpha0(0) = R1 - sqrt(R1^2 - 16) = %.17g", s.alpha0[0]);
  check(fabs(s.alpha0[0] - 0.05) < 1e-16, "5.1: alpha0(0) = C0 = 0.05 to 1e-16");
  check(fabs(s.alpha0[8] - arc(R1, 2)) < 1e-13
        && fabs(s.alpha0[8] - alpha_at_2) < 1e-16,
        "5.1: alpha0(2) = R1 - sqrt(R1^2 - 4) = %.17g", s.alpha0[8]);
  check(s.alpha0[16] == 0, "5.1: alpha0(4) = 0 exactly");
  for (i = 0; i < 16; i++) mono &= s.alpha0[i + 1] < s.alpha0[i];
  check(mono, "5.1: alpha0 decreases from x1 = 0 to 4");
  scene_free(&s);
  scene_free(&s);
  check(s.alpha0 == NULL, "scene_free twice is harmless");
}

/* Example 5.2 (alpha0 = 0.0125 x1) and its flat variant */
static void test_example_5_2(void)
{
  Scene s;
  Status st = {STATUS_OK, ""};
  int i, ok = 1;
  if (check(scene_load(&s, "data/example-5.2.scene", 0, NULL, &st) == 0,
            "example 5.2 loads: %s", st.msg)) {
    for (i = 0; i <= 16; i++) ok &= fabs(s.alpha0[i] - 0.0125 * (i * 0.25)) < 1e-16;
    check(ok && s.alpha0[16] == 0.05, "5.2: alpha0 = 0.0125 x1 at the 17 nodes");
    check(s.problem.C2 == 3.91 && s.problem.side[SIDE_TOP].P[1] == -5.75e8, "5.2: the rest as 5.1");
    scene_free(&s);
  }
  if (check(scene_load(&s, "data/example-5.2-flat.scene", 0, NULL, &st) == 0,
            "example 5.2 flat loads: %s", st.msg)) {
    for (ok = 1, i = 0; i <= 16; i++) ok &= s.alpha0[i] == 0.05;
    check(ok && strcmp(s.initial, "constant") == 0, "5.2 flat: alpha0 = 0.05");
    scene_free(&s);
  }
}

/* -s overrides: M, N (re-sampling), a default that depends on a key */
static void test_overrides(void)
{
  const double R1 = 160.025;
  char *m4[] = {"mesh.M=4"}, *n64[] = {"design.N=64"};
  char *refine4[] = {"mesh.refine=4"};
  char *psor[] = {" solver.state = psor ", "body_force.F2=-7.8e4"};
  char *cgssor[] = {"contact.model=tresca", "contact.g=1e6", "solver.state=cgssor"};
  Scene s;
  Status st = {STATUS_OK, ""};
  if (check(scene_load(&s, "data/example-5.1.scene", 1, m4, &st) == 0
            && s.problem.M == 4 && s.problem.R == 3 && s.problem.N == 16, "-s mesh.M=4 sets M = 4"))
    scene_free(&s);
  if (check(scene_load(&s, "data/example-5.1.scene", 1, n64, &st) == 0
            && s.problem.N == 64, "-s design.N=64 sets N = 64")) {
    check(s.alpha0[64] == 0
          && fabs(s.alpha0[32] - alpha_at_2) < 1e-16
          && fabs(s.alpha0[0] - arc(R1, 0)) < 1e-13,
          "N = 64 re-samples the arc on 65 nodes");
    scene_free(&s);
  }
  if (check(scene_load(&s, "data/example-5.1.scene", 1, refine4, &st) == 0
            && s.problem.N == 64 && s.problem.M == 4 && s.problem.R == 12,
            "-s mesh.refine=4 makes N, M, R = 64, 4, 12 (from 16, 1, 3)")) {
    check(fabs(s.alpha0[32] - alpha_at_2) < 1e-16 && s.alpha0[64] == 0,
          "mesh.refine=4 samples the arc on the 65 refined nodes");
    scene_free(&s);
  }
  if (check(scene_load(&s, "data/example-5.1.scene", 2, psor, &st) == 0,
            "-s with blanks around the names: %s", st.msg)) {
    check(s.solver.method == QP_PSOR && s.solver.max_iter == 100000,
          "psor: the default max_iter is 100000");
    check(s.problem.has_body_force && s.problem.body_force[1] == -7.8e4, "a body force sets has_body_force");
    scene_free(&s);
  }
  if (check(scene_load(&s, "data/example-5.1.scene", 3, cgssor, &st) == 0
            && s.solver.method == QP_CGSSOR && s.problem.contact == CONTACT_TRESCA,
            "friction with cgssor loads (MPRGP on the dual): %s", st.msg))
    scene_free(&s);
}

/* an override of a selector drops the file's keys that its word makes
   meaningless; keys given by overrides are still refused */
static void test_switching(void)
{
  char *top_free[] = {"top.bc=free"}, *top_del[] = {"top.bc="};
  char *coulomb[] = {"contact.model=coulomb", "contact.friction=0.2"};
  char *line[] = {"design.initial=line", "design.line_start=0",
                  "design.line_end=0.05"};
  char *newton[] = {"optimizer.method=newton"};
  char *p2_after[] = {"top.bc=free", "top.P2=1e6"};
  char *p2_before[] = {"top.P2=1e6", "top.bc=free"};
  char text[4096], path[256];
  Scene s;
  Status st = {STATUS_OK, ""};
  if (check(scene_load(&s, "data/example-5.1.scene", 1, top_free, &st) == 0
            && s.problem.side[SIDE_TOP].kind == BC_FREE,
            "-s top.bc=free alone unloads the top of 5.1: %s", st.msg))
    scene_free(&s);
  if (check(scene_load(&s, "data/example-5.1.scene", 1, top_del, &st) == 0
            && s.problem.side[SIDE_TOP].kind == BC_FREE,
            "-s top.bc= (deleted) switches to the default, free: %s", st.msg))
    scene_free(&s);
  if (check(scene_load(&s, "data/example-5.1-tresca.scene", 2, coulomb, &st) == 0
            && s.problem.contact == CONTACT_COULOMB && s.problem.friction == 0.2,
            "-s contact.model=coulomb drops the file's g: %s", st.msg))
    scene_free(&s);
  if (check(scene_load(&s, "data/example-5.1.scene", 3, line, &st) == 0
            && strcmp(s.initial, "line") == 0 && s.alpha0[16] == 0.05,
            "-s design.initial=line drops the file's arc_*: %s", st.msg))
    scene_free(&s);
  edit(text, sizeof text, "\nP2 = -5.75e8\n",
       "\nP2 = -5.75e8\n[optimizer]\nmethod = slsqp\nmetric = euclidean\n");
  write_file("metric.scene", text, path, sizeof path);
  if (check(scene_load(&s, path, 1, newton, &st) == 0
            && s.optimizer.method == OPT_NEWTON,
            "-s optimizer.method=newton drops the file's metric: %s", st.msg))
    scene_free(&s);
  expect("a key given by an override after the switch is refused",
         "data/example-5.1.scene", 2, p2_after, "(-s top.P2=1e6): top.P2",
         "no effect with bc = free");
  expect("a key given by an override before the switch is refused",
         "data/example-5.1.scene", 2, p2_before, "(-s top.P2=1e6): top.P2",
         "no effect with bc = free");
}

/* text = rows x1 = x(i) alpha = 0.01 x1, i = 0..n */
static void linear_rows(char *text, size_t size, int n, double (*x)(int, int))
{
  int i, used = snprintf(text, size, "# x1[m] alpha[m]\n");
  for (i = 0; i <= n; i++)
    used += snprintf(text + used, size - used, "%.17g %.17g\n", x(i, n),
                     0.01 * x(i, n));
}
static double even(int i, int n) { return 4.0 * i / n; }
static double uneven(int i, int n) { return 4.0 * i * i / ((double)n * n); }
static double near(int i, int n) { return 4.0 * i / n + (i % n ? 1e-10 : 0); }
static double off(int i, int n) { return 4.0 * i / n + (i % n ? 1e-8 : 0); }

/* a shape file whose rows are not the 17 design nodes is resampled by
   linear interpolation onto them, and the scene's note says so; rows
   within the tolerance of the nodes are the nodes */
static void test_resampled_files(void)
{
  static const struct { const char *name, *what; int n; double (*x)(int, int); int note; } f[] = {
    {"fine.dat", "33 rows, every 1/8", 32, even, 1},
    {"uneven.dat", "17 rows at x1 = 4 (i/16)^2", 16, uneven, 1},
    {"off.dat", "17 rows 1e-8 off the nodes", 16, off, 1},
    {"near.dat", "17 rows 1e-10 off the nodes (within 4e-9)", 16, near, 0}};
  static const double peak[] = {0, 0.01, 0.04, 0.01, 0};  /* at x1 = 0..4 */
  char text[8192], scene[256];
  Scene s;
  Status st = {STATUS_OK, ""};
  size_t k;
  int i, ok;
  shape_scene("coarse.dat", "0 0\n1 0.01\n2 0.04\n3 0.01\n4 0\n", scene, sizeof scene);
  if (check(scene_load(&s, scene, 0, NULL, &st) == 0, "a coarse shape of 5 rows loads: %s", st.msg)) {
    for (ok = 1, i = 0; i <= 16; i++) {
      int j = i / 4 < 3 ? i / 4 : 3;
      double t = (i - 4.0 * j) / 4;
      ok &= fabs(s.alpha0[i] - ((1 - t) * peak[j] + t * peak[j + 1])) <= 1e-17;
    }
    check(ok && strstr(s.note, "coarse.dat: 5 rows on [0, 4] resampled by linear "
                       "interpolation onto the N + 1 = 17 design nodes"),
          "5 rows are resampled onto the 17 nodes, and the note says so: %s", s.note);
    scene_free(&s);
  }
  for (k = 0; k < sizeof f / sizeof f[0]; k++) {
    linear_rows(text, sizeof text, f[k].n, f[k].x);
    shape_scene(f[k].name, text, scene, sizeof scene);
    if (!check(scene_load(&s, scene, 0, NULL, &st) == 0, "%s: loads: %s", f[k].what, st.msg))
      continue;
    for (ok = 1, i = 0; i <= 16; i++)   /* as they are: bit for bit */
      ok &= f[k].note ? fabs(s.alpha0[i] - 0.01 * (0.25 * i)) <= 1e-17
                      : s.alpha0[i] == 0.01 * f[k].x(i, 16);
    check(ok && (f[k].note ? strstr(s.note, "resampled") != NULL : !s.note[0]),
          "%s: %s", f[k].what, f[k].note ? "resampled, alpha0 = 0.01 x1 at the "
          "nodes to 1e-17, with a note" : "the file's alpha as it is, no note");
    scene_free(&s);
  }
}

/* initial = file: comments, blank lines, two columns, relative path */
static void test_shape_file(void)
{
  char text[2048], path[256], scene[256];
  Scene s;
  Status st = {STATUS_OK, ""};
  int i, ok = 1, n = snprintf(text, sizeof text, "# x1 alpha\n\n");
  for (i = 0; i <= 16; i++)
    n += snprintf(text + n, sizeof text - (size_t)n, "%g %g # node %d\n",
                  i * 0.25, 0.001 * i, i);
  write_file("shape.dat", text, path, sizeof path);
  edit(text, sizeof text, "initial = line\nline_start = 0\nline_end = 0.05\n",
       "initial = file\nfile = shape.dat\n");
  write_file("file.scene", text, scene, sizeof scene);
  if (check(scene_load(&s, scene, 0, NULL, &st) == 0,
            "initial = file loads relative to the scene: %s", st.msg)) {
    for (i = 0; i <= 16; i++) {          /* the number of the file's text */
      char row[32];
      snprintf(row, sizeof row, "%g", 0.001 * i);
      ok &= s.alpha0[i] == strtod(row, NULL);
    }
    check(ok && !s.note[0], "initial = file: rows at the 17 nodes give alpha0 "
          "as they are, without a note");
    scene_free(&s);
  }
  test_resampled_files();
}

/* a body that no side holds sideways (Example 5.1 with free sides and a
   horizontal load of 1e7 Pa over [2, 4], L1 = 2e7 N/m, and the vertical
   load W = 5.75e8 * 2 = 1.15e9 N/m) loads when friction can hold it:
   capacity g (b - a) or F W above |L1|, at the least favourable area of
   the body for a body force (Section "Bodies that friction alone holds
   sideways"); refused otherwise, with the numbers */
static int held_load(int n, char **extra, Status *st)
{
  char *ov[12] = {"left.bc=free", "right.bc=free", "top.P1=1e7"};
  Scene s;
  memcpy(ov + 3, extra, n * sizeof *extra);
  *st = (Status) {STATUS_OK, ""};
  int rc = scene_load(&s, "data/example-5.1.scene", 3 + n, ov, st);
  scene_free(&s);
  return rc;
}

static void held_accepted(const char *what, int n, char **extra)
{
  Status st;
  int rc = held_load(n, extra, &st);
  check(rc == 0, "held by friction: %s: loads%s%s", what, rc ? ": " : "", st.msg);
}

static void held_refused(const char *what, int n, char **extra,
                         const char *word1, const char *word2)
{
  Status st;
  int rc = held_load(n, extra, &st);
  check(rc == STATUS_INPUT && strstr(st.msg, "data/example-5.1.scene")
        && strstr(st.msg, "no side holds u1") && strstr(st.msg, word1)
        && strstr(st.msg, word2) && !strchr(st.msg, '\n'),
        "held by friction: %s: refused: %s", what, st.msg);
}

static void test_held_by_friction(void)
{
  char *big[] = {"contact.model=tresca", "contact.g=2e8"};
  char *small[] = {"contact.model=tresca", "contact.g=4e6"};
  char *equal[] = {"contact.model=tresca", "contact.g=5e6"};
  char *above[] = {"contact.model=tresca", "contact.g=5.0000001e6"};
  char *co_in[] = {"contact.model=coulomb", "contact.friction=0.018"};
  char *co_out[] = {"contact.model=coulomb", "contact.friction=0.017"};
  char *co_roll[] = {"contact.model=coulomb", "contact.friction=0.2",
                     "top.bc=roller", "top.from=", "top.to=", "top.P1=", "top.P2="};
  char *tr_roll[] = {"contact.model=tresca", "contact.g=2e8", "top.bc=roller",
                     "top.from=", "top.to=", "top.P1=", "top.P2=",
                     "body_force.F1=1e6"};
  char *body_in[] = {"contact.model=tresca", "contact.g=1.01e8", "top.P1=",
                     "body_force.F1=1e8"};
  char *body_out[] = {"contact.model=tresca", "contact.g=0.9e8", "top.P1=",
                      "body_force.F1=1e8"};
  char *none[] = {"top.P1="};
  held_accepted("tresca, g (b - a) = 8e8 against 2e7 N/m", 2, big);
  held_refused("tresca, g (b - a) = 1.6e7 against 2e7 N/m", 2, small,
               "g (b - a) = 1.6e+07 N/m", "horizontal load of 2e+07 N/m");
  held_refused("tresca, g (b - a) = 2e7, equal to the load", 2, equal,
               "g (b - a) = 2e+07 N/m", "horizontal load of 2e+07 N/m");
  held_accepted("tresca, g (b - a) just above the load", 2, above);
  held_accepted("coulomb, F W = 0.018 * 1.15e9 = 2.07e7 against 2e7 N/m", 2, co_in);
  held_refused("coulomb, F W = 0.017 * 1.15e9 = 1.955e7 against 2e7 N/m", 2,
               co_out, "vertical load 1.15e+09 N/m holds at most 1.955e+07 N/m",
               "horizontal load of 2e+07 N/m");
  held_refused("coulomb with the top on rollers", 7, co_roll,
               "the top holds u2", "use contact.model = tresca");
  held_accepted("tresca with the top on rollers, a body force", 8, tr_roll);
  held_accepted("body force, 1.01e8 * 4 = 4.04e8 against 1e8 * 4 N/m", 4, body_in);
  held_refused("body force, 0.9e8 * 4 = 3.6e8 against 1e8 * 4 = 4e8 N/m at the "
               "largest area", 4, body_out, "g (b - a) = 3.6e+08 N/m",
               "horizontal load of 4e+08 N/m");
  held_refused("frictionless, no horizontal load", 1, none,
               "frictionless contact cannot stop the body sliding", "");
  expect_edit("cgssor with friction on rollers", "[left]\nbc = clamped\n",
              "[left]\nbc = roller\n[contact]\nmodel = tresca\ng = 1e8\n"
              "[solver]\nstate = cgssor\n", "solver.state",
              "do not hold in both directions (left.bc = roller, right.bc = "
              "roller, top.bc = traction): its dual needs the stiffness seen "
              "from the contact positive definite; use pdas");
  expect_edit("max_fixed_point 0", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = coulomb\nfriction = 0.2\n"
              "max_fixed_point = 0\n", "contact.max_fixed_point", "must be >= 1");
  expect_edit("max_fixed_point with tresca", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = tresca\ng = 1e6\n"
              "max_fixed_point = 5\n", "contact.max_fixed_point",
              "no effect with model = tresca");
}

/* a part: its geometry found beside the scene and kept absolute, no
   rows R, gamma = C0prime, its curves and surfaces in their slots in the
   order the file names them, refine kept for the mesher */
static void test_part(void)
{
  char path[256], geo[300], *ov[] = {"mesh.refine=2", "boundary.bore.bc=clamped",
    "material.rubber.E=7e6", "boundary.top.bc=", "boundary.top.P2=",
    "boundary.new.bc=roller"};
  const Problem_part *part;
  Scene s;
  Status st = {STATUS_OK, ""};
  part_scene("part.scene", NULL, NULL, NULL, path, sizeof path);
  snprintf(geo, sizeof geo, "%s/part.geo", tmpdir);
  if (!check(scene_load(&s, path, 1, ov, &st) == 0, "a part loads: %s", st.msg))
    return;
  part = &s.problem.part;
  check(strcmp(part->geometry, geo) == 0 && part->geometry[0] == '/',
        "part: the geometry is the file beside the scene, absolute: %s",
        part->geometry);
  check(s.problem.N == 32 && s.problem.M == 2 && s.problem.R == 0
        && part->refine == 2 && s.problem.gamma == s.problem.C0prime,
        "part, refined twice: N = 32, M = 2, R = 0, part.refine = 2, gamma = "
        "C0prime (%d %d %d %d %g)", s.problem.N, s.problem.M, s.problem.R,
        part->refine, s.problem.gamma);
  check(part->ncurve == 3 && strcmp(part->curve[0].name, "top") == 0
        && strcmp(part->curve[1].name, "bore") == 0
        && strcmp(part->curve[2].name, "seat") == 0
        && part->curve[0].kind == BC_TRACTION && part->curve[0].P[0] == 0
        && part->curve[0].P[1] == -5.75e8 && part->curve[1].kind == BC_PRESSURE
        && part->curve[1].pressure == 1e7 && part->curve[2].kind == BC_CLAMPED,
        "part: the curves top (traction), bore (pressure), seat (clamped), "
        "in the file's order");
  check(part->nregion == 1 && strcmp(part->region[0].name, "rubber") == 0
        && part->region[0].material.kind == MATERIAL_ISOTROPIC
        && part->region[0].material.young == 6e6
        && part->region[0].material.nu == 0.45
        && s.problem.material.young == 2.15e11,
        "part: the surface rubber, E = 6e6, nu = 0.45; the body's E = 2.15e11");
  check(s.problem.side[SIDE_TOP].kind == BC_FREE && s.problem.side[SIDE_LEFT].kind
        == BC_CLAMPED, "part: no top side, the strip's left side clamped");
  Mesh *m = mesh_new(&s.problem, &st);
  if (check(m != NULL, "part: its mesh (%s)", st.msg)) {
    Problem strip = s.problem;
    strip.part.nodes = 0;
    int own = m->nnodes - (m->N + 1) * (m->M + 1);
    check(own > 0 && part->nodes == own && resources_memory(&s.problem)
          >= resources_memory(&strip) + 800.0 * own,
          "part: the scene counts its %d nodes (the mesh has %d beside the strip's), "
          "and the estimate of memory counts their unknowns", part->nodes, own);
    mesh_free(m);
  }
  scene_free(&s);
  if (check(scene_load(&s, path, 6, ov, &st) == 0, "a part with overrides "
            "of named keys loads: %s", st.msg)) {
    check(part->ncurve == 3 && strcmp(part->curve[0].name, "bore") == 0
          && part->curve[0].kind == BC_CLAMPED && part->curve[0].pressure == 0
          && strcmp(part->curve[1].name, "seat") == 0
          && strcmp(part->curve[2].name, "new") == 0
          && part->curve[2].kind == BC_ROLLER
          && part->region[0].material.young == 7e6,
          "-s boundary.bore.bc=clamped drops the file's p; deleting top's keys "
          "removes its slot; -s boundary.new.bc=roller adds one; "
          "-s material.rubber.E=7e6");
    scene_free(&s);
  }
}

/* an orthotropic body: its keys, the third axis in plane strain only, and
   the switch of the plane model; -s part.geometry on a rectangle drops
   the rectangle's keys */
static void test_orthotropic(void)
{
  char path[256], *ov[] = {"material.model=plane_stress"},
    *ov2[] = {"part.geometry=part.geo", "design.C2=0.91"};
  const Problem_material *m;
  Scene s;
  Status st = {STATUS_OK, ""};
  part_scene("ortho.scene", "[material]\nE = 2.15e11\nnu = 0.29\n",
             "[material]\nkind = orthotropic\nE1 = 2e11\nE2 = 1e11\nnu12 = 0.3\n"
             "G12 = 5e10\nangle = 30\nmodel = plane_strain\nE3 = 1.5e11\n"
             "nu13 = 0.25\nnu23 = 0.2\n", NULL, path, sizeof path);
  if (!check(scene_load(&s, path, 0, NULL, &st) == 0, "an orthotropic part "
             "in plane strain loads: %s", st.msg))
    return;
  m = &s.problem.material;
  check(m->kind == MATERIAL_ORTHOTROPIC && m->E1 == 2e11 && m->E2 == 1e11
        && m->nu12 == 0.3 && m->G12 == 5e10 && m->angle == 30 && m->E3 == 1.5e11
        && m->nu13 == 0.25 && m->nu23 == 0.2 && m->young == 0
        && s.problem.model == MODEL_PLANE_STRAIN,
        "orthotropic: E1, E2, nu12, G12, angle, E3, nu13, nu23 in their fields");
  scene_free(&s);
  if (check(scene_load(&s, path, 1, ov, &st) == 0, "-s material.model="
            "plane_stress drops the file's third axis: %s", st.msg)) {
    check(m->E3 == 0 && m->nu13 == 0 && m->nu23 == 0 && m->E1 == 2e11,
          "plane stress: no third axis");
    scene_free(&s);
  }
  write_file("rect.scene", base, path, sizeof path);
  if (check(scene_load(&s, path, 2, ov2, &st) == 0, "-s part.geometry on the "
            "rectangle drops its gamma, R and top: %s", st.msg)) {
    check(s.problem.R == 0 && s.problem.gamma == 0.25
          && s.problem.part.geometry[0] == '/'
          && s.problem.side[SIDE_TOP].kind == BC_FREE,
          "the rectangle made a part by one override: R = 0, gamma = C0prime");
    scene_free(&s);
  }
}

int main(void)
{
  if (!scene_files_begin()) return 1;
  test_part();
  test_orthotropic();
  test_example_5_1();
  test_example_5_2();
  test_overrides();
  test_switching();
  test_shape_file();
  test_held_by_friction();
  scene_files_end();
  return check_done();
}
