/* test_scene.c: the scene module (paper/scene.nw).  The shipped scenes
   load with the article's values; overrides apply; every documented error
   is provoked once, in a small scene written to a temporary directory, and
   must give status 2, leave nothing allocated, and tell one line naming the
   file, the key and the reason.  Run from the repository root. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "scene.h"

static char tmpdir[] = "/tmp/test_scene.XXXXXX";
static char made[128][256];   /* files written in tmpdir, removed at the end */
static int nmade;

/* The base of every bad scene: Example 5.2, one key a line, line numbers
   as in the comment. */
static const char base[] =
  "[geometry]\na = 0\nb = 4\ngamma = 1\n"                         /* 1-4 */
  "[design]\nN = 16\nC0 = 0.05\nC1 = 0.025\nC2 = 3.91\n"          /* 5-9 */
  "initial = line\nline_start = 0\nline_end = 0.05\n"             /* 10-12 */
  "[mesh]\nM = 1\nR = 3\nC0prime = 0.25\n"                        /* 13-16 */
  "[material]\nE = 2.15e11\nnu = 0.29\n"                          /* 17-19 */
  "[left]\nbc = clamped\n[right]\nbc = roller\n"                  /* 20-23 */
  "[top]\nbc = traction\nfrom = 2\nto = 4\nP2 = -5.75e8\n";       /* 24-28 */

/* write text to tmpdir/name; path = its path */
static void write_file(const char *name, const char *text, char *path,
                       size_t size)
{
  FILE *fp;
  snprintf(path, size, "%s/%s", tmpdir, name);
  if (!(fp = fopen(path, "w")) || fputs(text, fp) < 0 || fclose(fp)) {
    fprintf(stderr, "test_scene: cannot write %s\n", path);
    exit(1);
  }
  if (nmade < 128) snprintf(made[nmade++], sizeof made[0], "%s", path);
}

/* write the n bytes of data (NUL bytes too) to tmpdir/name; path = it */
static void write_bytes(const char *name, const char *data, size_t n,
                        char *path, size_t size)
{
  FILE *fp;
  snprintf(path, size, "%s/%s", tmpdir, name);
  if (!(fp = fopen(path, "wb")) || fwrite(data, 1, n, fp) != n || fclose(fp)) {
    fprintf(stderr, "test_scene: cannot write %s\n", path);
    exit(1);
  }
  if (nmade < 128) snprintf(made[nmade++], sizeof made[0], "%s", path);
}

/* out = base with its first `old` replaced by `with`; 0 if old not found */
static int edit(char *out, size_t size, const char *old, const char *with)
{
  const char *at = strstr(base, old);
  if (!at) return 0;
  snprintf(out, size, "%.*s%s%s", (int)(at - base), base, with,
           at + strlen(old));
  return 1;
}

/* load path with the overrides; expect status 2 and a message holding
   the path, key and word */
static void expect(const char *what, const char *path, int nov,
                   char *const *ov, const char *key, const char *word)
{
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc = scene_load(&s, path, nov, ov, &st);
  check(rc == STATUS_INPUT && st.code == STATUS_INPUT && !s.alpha0
        && strstr(st.msg, path) && strstr(st.msg, key)
        && strstr(st.msg, word) && !strchr(st.msg, '\n'),
        "%s: %s", what, st.msg);
  scene_free(&s);
}

/* the base scene edited, then loaded: expect an error */
static void expect_edit(const char *what, const char *old, const char *with,
                        const char *key, const char *word)
{
  char text[4096], path[256], name[64];
  if (!edit(text, sizeof text, old, with)) {
    check(0, "%s: the edit does not apply to the base scene", what);
    return;
  }
  snprintf(name, sizeof name, "bad%02d.scene", nmade);
  write_file(name, text, path, sizeof path);
  expect(what, path, 0, NULL, key, word);
}

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
  check(s.problem.E == 2.15e11 && s.problem.nu == 0.29 && s.problem.model == MODEL_PLANE_STRESS,
        "5.1: E = 2.15e11, nu = 0.29, plane stress");
  check(s.problem.side[SIDE_LEFT].kind == BC_CLAMPED
        && s.problem.side[SIDE_RIGHT].kind == BC_ROLLER, "5.1: left clamped, right roller");
  check(s.problem.side[SIDE_TOP].kind == BC_TRACTION && s.problem.side[SIDE_TOP].from == 2
        && s.problem.side[SIDE_TOP].to == 4 && s.problem.side[SIDE_TOP].P[0] == 0
        && s.problem.side[SIDE_TOP].P[1] == -5.75e8, "5.1: top P = (0, -5.75e8) on (2, 4)");
  check(s.problem.F[0] == 0 && s.problem.F[1] == 0 && !s.problem.has_body_force, "5.1: F = 0");
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
    check(s.problem.has_body_force && s.problem.F[1] == -7.8e4, "a body force sets has_body_force");
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

/* write the shape file name holding text, and a scene (the base with
   initial = file) that names it; scene = its path */
static void shape_scene(const char *name, const char *text, char *scene,
                        size_t size)
{
  char path[256], with[128], body[4096];
  write_file(name, text, path, sizeof path);
  snprintf(with, sizeof with, "initial = file\nfile = %s\n", name);
  edit(body, sizeof body, "initial = line\nline_start = 0\nline_end = 0.05\n",
       with);
  snprintf(path, sizeof path, "%.60s.scene", name);
  write_file(path, body, scene, size);
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

/* shape files that are no shape on [a, b] = [0, 4] */
static void test_shape_file_errors(void)
{
  static const struct { const char *name, *text, *what, *word; } f[] = {
    {"short.dat", "0 0\n1 0.01\n", "a shape on [0, 1] for a body on [0, 4]",
     "short.dat line 2: x1 = 1: a shape ends at x1 = b = 4"},
    {"late.dat", "# x1 alpha\n0.5 0\n4 0\n", "a shape from 0.5",
     "late.dat line 2: x1 = 0.5: a shape begins at x1 = a = 0"},
    {"repeat.dat", "0 0\n2 0.01\n2 0.02\n4 0\n", "x1 repeated",
     "repeat.dat line 3: x1 = 2 does not increase (line 2 has 2)"},
    {"reverse.dat", "4 0\n3 0.01\n0 0\n", "x1 decreasing",
     "reverse.dat line 2: x1 = 3 does not increase (line 1 has 4)"},
    {"column.dat", "0.01\n0.02\n", "one column",
     "column.dat line 1: 1 number: a row of a shape file is x1 alpha"},
    {"three.dat", "0 0 0\n4 0 0\n", "three columns",
     "three.dat line 1: 3 numbers"},
    {"one.dat", "# x1 alpha\n0 0\n", "one row", "one.dat has 1 row x1 alpha"},
    {"none.dat", "# x1 alpha\n\n", "no row", "none.dat has 0 rows x1 alpha"},
    {"hex.dat", "0 0\n4 0x1p-7\n", "a hexadecimal alpha",
     "hex.dat line 2: '0x1p-7' is a hexadecimal number"},
  };
  char scene[256];
  size_t k;
  for (k = 0; k < sizeof f / sizeof f[0]; k++) {
    shape_scene(f[k].name, f[k].text, scene, sizeof scene);
    expect(f[k].what, scene, 0, NULL, "design.file", f[k].word);
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

/* NUL bytes: in a line (which would otherwise look overlong), in the
   last line without a newline (which inih would cut silently), a file in
   UTF-16, and a shape file with a NUL after a number */
static void test_nul_bytes(void)
{
  static const char u16[] = "\xff\xfe[\0g\0e\0o\0]\0\n\0";
  static const char dat[] = "0 0\n1 0.01\0 x\n";
  const char *line = "initial = line\nline_start = 0\nline_end = 0.05\n";
  char text[4096], path[256];
  size_t n;
  n = strlen(base);
  memcpy(text, base, n);
  memcpy(text + 4, "\0junk", 5);           /* [geo\0junk... on line 1 */
  write_bytes("nul.scene", text, n, path, sizeof path);
  expect("NUL byte in a line", path, 0, NULL, "line 1", "NUL byte");
  memcpy(text, base, n);
  memcpy(text + n, " \0 oops", 7);          /* P2 = -5.75e8 \0 oops, no \n */
  text[n - 1] = ' ';
  write_bytes("nul-last.scene", text, n + 7, path, sizeof path);
  expect("NUL byte in the last line, no newline", path, 0, NULL, "line 28",
         "NUL byte");
  write_bytes("utf16.scene", u16, sizeof u16 - 1, path, sizeof path);
  expect("a scene in UTF-16", path, 0, NULL, "line 1", "not UTF-16");
  write_bytes("nul.dat", dat, sizeof dat - 1, path, sizeof path);
  expect_edit("shape file with a NUL byte", line,
              "initial = file\nfile = nul.dat\n", "design.file",
              "nul.dat line 2: a NUL byte");
}

/* the errors of the file's syntax and names */
/* lines longer than inih's buffer: a comment of any length (a whole line
   after ';', '#' or blanks, or after a value), then a syntax error whose
   line number counts the long ones; a value line of 300 characters is
   refused, and a NUL byte in a long comment */
static void test_long_lines(void)
{
  char text[8192], path[256], c[1001], with[4096], v[301];
  Scene s;
  Status st = {STATUS_OK, ""};
  memset(c, 'c', sizeof c - 1);
  c[sizeof c - 1] = '\0';
  snprintf(with, sizeof with, "\n;%s\n#%s\n   ;%s\nR = 3 ;%s\n", c, c, c, c);
  edit(text, sizeof text, "\nR = 3\n", with);
  write_file("long-comments.scene", text, path, sizeof path);
  if (check(scene_load(&s, path, 0, NULL, &st) == 0 && s.problem.R == 3,
            "comments of 1000 characters (whole lines, indented, after a "
            "value) are read past: %s", st.msg))
    scene_free(&s);
  snprintf(with, sizeof with, "\n;%s\nR = 3\noops\n", c);
  edit(text, sizeof text, "\nR = 3\n", with);
  write_file("long-syntax.scene", text, path, sizeof path);
  expect("a syntax error after a long comment: its line", path, 0, NULL,
         "line 17", "syntax error");
  memset(v, '1', sizeof v - 1);
  v[sizeof v - 1] = '\0';
  snprintf(with, sizeof with, "\nR = %s\n", v);
  edit(text, sizeof text, "\nR = 3\n", with);
  write_file("long-value.scene", text, path, sizeof path);
  expect("a value line of 304 characters", path, 0, NULL, "line 15",
         "longer than 198 characters (only a comment may be longer)");
  snprintf(with, sizeof with, "\n;%s", c);
  edit(text, sizeof text, "\nR = 3\n", with);
  memcpy(strstr(text, "cccc") + 500, "\0", 1);
  write_bytes("long-nul.scene", text, strlen(text) + strlen(text + strlen(text) + 1) + 1,
              path, sizeof path);
  expect("a NUL byte in a long comment", path, 0, NULL, "line 15", "NUL byte");
}

static void test_syntax_errors(void)
{
  char text[4096], path[256];
  edit(text, sizeof text, "\nP2 = -5.75e8\n", "\nP2 = -5.75e8\noops\n");
  write_file("syntax.scene", text, path, sizeof path);
  expect("syntax error", path, 0, NULL, "line 29", "syntax error");
  test_long_lines();
  expect_edit("continuation line", "\nb = 4\n", "\nb = 4\n  gamma = 1\n",
              "geometry.b", "indented");
  expect_edit("key before any section", "[geometry]\n", "x = 1\n[geometry]\n",
              "x = 1", "before any [section]");
  expect_edit("unknown section", "\n[mesh]\n", "\n[foo]\nx = 1\n[mesh]\n",
              "[foo]", "unknown section");
  expect_edit("unknown key", "\n[mesh]\n", "\n[mesh]\nQ = 1\n", "mesh.Q",
              "unknown key");
  expect_edit("duplicate key", "\nM = 1\n", "\nM = 1\nM = 2\n", "mesh.M",
              "duplicate");
  expect_edit("missing required key", "\nR = 3\n", "\n", "mesh.R", "missing");
  test_nul_bytes();
}

/* malformed numbers and integers */
static void test_number_errors(void)
{
  expect_edit("malformed number 1e", "\nE = 2.15e11\n", "\nE = 1e\n",
              "material.E", "not a number");
  expect_edit("malformed number 0.3x", "\nnu = 0.29\n", "\nnu = 0.3x\n",
              "material.nu", "not a number");
  expect_edit("malformed number nan", "\nC0 = 0.05\n", "\nC0 = nan\n",
              "design.C0", "not a finite number");
  expect_edit("number out of range", "\ngamma = 1\n", "\ngamma = 1e999\n",
              "geometry.gamma", "out of the range");
  expect_edit("empty value", "\na = 0\n", "\na =\n", "geometry.a", "empty");
  expect_edit("# after a value", "\nb = 4\n", "\nb = 4 # four\n",
              "geometry.b", "not '#'");
  expect_edit("non-integer N", "\nN = 16\n", "\nN = 16.5\n", "design.N",
              "not an integer");
  expect_edit("non-integer M", "\nM = 1\n", "\nM = 1.0\n", "mesh.M",
              "not an integer");
  expect_edit("non-integer R", "\nR = 3\n", "\nR = 3e0\n", "mesh.R",
              "not an integer");
  expect_edit("non-integer max_iter", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[solver]\nmax_iter = 1e5\n", "solver.max_iter",
              "not an integer");
  expect_edit("integer out of range", "\nN = 16\n", "\nN = 99999999999\n",
              "design.N", "out of the range of an int");
  expect_edit("hexadecimal number 0x10", "\nE = 2.15e11\n", "\nE = 0x10\n",
              "material.E", "a hexadecimal number: write it in decimal");
  expect_edit("hexadecimal number -0x1p-3", "\nline_end = 0.05\n",
              "\nline_end = -0x1p-3\n", "design.line_end", "hexadecimal");
  expect_edit("hexadecimal integer 0x10", "\nN = 16\n", "\nN = 0x10\n",
              "design.N", "a hexadecimal number: write it in decimal");
  expect_edit("infinity", "\nC0 = 0.05\n", "\nC0 = -Infinity\n",
              "design.C0", "not a finite number");
  expect_edit("a number without digits", "\nC0 = 0.05\n", "\nC0 = .e5\n",
              "design.C0", "not a number");
  expect_edit("an exponent without digits", "\nC0 = 0.05\n", "\nC0 = 5e+\n",
              "design.C0", "not a number");
  expect_edit("a sign without digits", "\nN = 16\n", "\nN = -\n",
              "design.N", "not an integer");
}

/* magnitudes outside the window in which every product is finite */
static void test_magnitude_errors(void)
{
  const char *p2 = "\nP2 = -5.75e8\n";
  expect_edit("E above 1e30", "\nE = 2.15e11\n", "\nE = 1e308\n",
              "material.E", "[1e-30, 1e30]");
  expect_edit("E below 1e-30", "\nE = 2.15e11\n", "\nE = 1e-300\n",
              "material.E", "[1e-30, 1e30]");
  expect_edit("b - a above 1e30", "\nb = 4\n", "\nb = 2e30\n",
              "geometry.b", "b - a = 2e30 must lie in [1e-30, 1e30]");
  expect_edit("b - a below 1e-30", "\nb = 4\n", "\nb = 1e-31\n",
              "geometry.b", "b - a = 1e-31 must lie in [1e-30, 1e30]");
  expect_edit("a traction 4.7e288 E", p2, "\nP2 = -1e300\n", "top.P2",
              "|P2| / E = 4.65e288: a load must be 0 or lie within");
  expect_edit("a traction 4.7e-312 E", p2, "\nP2 = -5.75e8\nP1 = 1e-300\n",
              "top.P1", "|P1| / E = 4.65e-312");
  expect_edit("a body force 1.9e289 E / (b - a)", p2,
              "\nP2 = -5.75e8\n[body_force]\nF2 = -1e300\n", "body_force.F2",
              "|F2| (b - a) / E = 1.86e289");
  expect_edit("a slip bound 4.7e-302 E", p2,
              "\nP2 = -5.75e8\n[contact]\nmodel = tresca\ng = 1e-290\n",
              "contact.g", "g / E = 4.65e-302");
  expect_edit("a friction coefficient above 1e30", p2,
              "\nP2 = -5.75e8\n[contact]\nmodel = coulomb\nfriction = 1e31\n",
              "contact.friction", "must be <= 1e30");
}

/* values out of their range */
static void test_range_errors(void)
{
  expect_edit("E <= 0", "\nE = 2.15e11\n", "\nE = 0\n", "material.E", "> 0");
  expect_edit("nu >= 0.5", "\nnu = 0.29\n", "\nnu = 0.5\n", "material.nu",
              "incompressible");
  expect_edit("nu <= -1", "\nnu = 0.29\n", "\nnu = -1\n", "material.nu",
              "> -1");
  expect_edit("N < 1", "\nN = 16\n", "\nN = 0\n", "design.N", ">= 1");
  expect_edit("M < 1", "\nM = 1\n", "\nM = 0\n", "mesh.M", ">= 1");
  expect_edit("R < 1", "\nR = 3\n", "\nR = 0\n", "mesh.R", ">= 1");
  expect_edit("b <= a", "\nb = 4\n", "\nb = 0\n", "geometry.b", "exceed");
  expect_edit("b - a overflows", "\na = 0\nb = 4\n",
              "\na = -1e308\nb = 1e308\n", "geometry.b", "overflows");
  expect_edit("gamma (b - a) overflows", "\ngamma = 1\n",
              "\ngamma = 1e308\n", "geometry.gamma", "overflows");
  expect_edit("a mesh too large for int indices", "\nR = 3\n",
              "\nR = 2147483647\n", "mesh.R", "INT_MAX / 36");
  expect_edit("a mesh too large, N = 8 million", "\nN = 16\n",
              "\nN = 8000000\n", "mesh.R", "64000000 triangles");
  expect_edit("mesh.refine < 1", "\nR = 3\n", "\nR = 3\nrefine = 0\n",
              "mesh.refine", ">= 1");
  expect_edit("a mesh too large by its refinement", "\nR = 3\n",
              "\nR = 3\nrefine = 4000\n", "mesh.refine", "INT_MAX / 36");
  expect_edit("C0 <= 0", "\nC0 = 0.05\n", "\nC0 = 0\n", "design.C0", "> 0");
  expect_edit("C1 < 0", "\nC1 = 0.025\n", "\nC1 = -0.1\n", "design.C1", ">= 0");
  expect_edit("C2 <= 0", "\nC2 = 3.91\n", "\nC2 = 0\n", "design.C2", "> 0");
  expect_edit("C0prime <= C0", "\nC0prime = 0.25\n", "\nC0prime = 0.05\n",
              "mesh.C0prime", "exceed design.C0");
  expect_edit("gamma <= C0prime", "\ngamma = 1\n", "\ngamma = 0.25\n",
              "geometry.gamma", "exceed mesh.C0prime");
  expect_edit("empty admissible set", "\nC2 = 3.91\n", "\nC2 = 3.7\n",
              "design.C2", "admit no shape");
  expect_edit("solver.tol out of (0, 1)", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[solver]\ntol = 1\n", "solver.tol", "(0, 1)");
  expect_edit("solver.omega out of (0, 2)", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[solver]\nomega = 2\n", "solver.omega", "(0, 2)");
  expect_edit("solver.max_iter < 1", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[solver]\nmax_iter = 0\n", "solver.max_iter",
              ">= 1");
}

/* the initial shape */
static void test_initial_errors(void)
{
  const char *line = "initial = line\nline_start = 0\nline_end = 0.05\n";
  char path[256];
  expect_edit("initial shape outside [0, C0prime)", "\nline_end = 0.05\n",
              "\nline_end = 0.26\n", "design.initial", "node 16 (x1 = 4)");
  expect_edit("key of another initial", "\nline_end = 0.05\n",
              "\nline_end = 0.05\narc_radius = 1\n", "design.arc_radius",
              "no effect with initial = line");
  expect_edit("unknown initial", "\ninitial = line\n", "\ninitial = spline\n",
              "design.initial", "accepted: arc, line, constant, file");
  expect_edit("arc that does not reach a node", line,
              "initial = arc\narc_x1 = 4\narc_x2 = 1\narc_radius = 1\n",
              "design.arc_radius", "does not reach node 0");
  expect_edit("arc radius <= 0", line,
              "initial = arc\narc_x1 = 4\narc_x2 = 1\narc_radius = 0\n",
              "design.arc_radius", "> 0");
  expect_edit("shape file missing", line, "initial = file\nfile = none.dat\n",
              "design.file", "cannot read");
  test_shape_file_errors();
  write_file("nonnum.dat", "0 0\n1 abc\n", path, sizeof path);
  expect_edit("shape file with a non-number", line,
              "initial = file\nfile = nonnum.dat\n", "design.file",
              "nonnum.dat line 2: 'abc' is not a number");
}

/* the sides, the contact, the solver */
static void test_condition_errors(void)
{
  expect_edit("no side holds u1", "[left]\nbc = clamped\n[right]\nbc = roller\n",
              "[left]\nbc = free\n[right]\nbc = free\n", "top.bc = traction",
              "no side holds u1");
  expect_edit("traction outside the top", "\nfrom = 2\n", "\nfrom = -1\n",
              "top.from", "must lie in the top side");
  expect_edit("traction below C0prime on the left", "[left]\nbc = clamped\n",
              "[left]\nbc = traction\nfrom = 0.1\nto = 1\nP1 = 1\n",
              "left.from", "never moves");
  expect_edit("traction from >= to", "\nto = 4\n", "\nto = 2\n", "top.to",
              "must exceed top.from");
  expect_edit("traction zero", "\nP2 = -5.75e8\n", "\nP2 = 0\n", "top.bc",
              "zero: use bc = free");
  expect_edit("traction key on a roller", "\nbc = roller\n",
              "\nbc = roller\nP1 = 3\n", "right.P1", "no effect with bc = roller");
  expect_edit("unknown bc", "\nbc = roller\n", "\nbc = rolling\n", "right.bc",
              "accepted: free, clamped, roller, traction");
  expect_edit("unknown material model", "\nnu = 0.29\n",
              "\nnu = 0.29\nmodel = axisymmetric\n", "material.model",
              "accepted: plane_stress, plane_strain");
  expect_edit("unknown solver state", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[solver]\nstate = gauss\n", "solver.state",
              "accepted: pdas, psor, cgssor");
  expect_edit("unknown contact law", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = sticky\n", "contact.model",
              "accepted: frictionless, tresca, coulomb");
  expect_edit("tresca without g", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = tresca\n", "contact.g",
              "missing required key");
  expect_edit("coulomb without friction", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = coulomb\n", "contact.friction",
              "missing required key");
  expect_edit("g with coulomb", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = coulomb\nfriction = 0.2\ng = 1e6\n",
              "contact.g", "no effect with model = coulomb");
  expect_edit("friction with tresca", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = tresca\ng = 1e6\nfriction = 0.2\n",
              "contact.friction", "no effect with model = tresca");
  expect_edit("g without friction", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\ng = 1e6\n", "contact.g",
              "no effect with model = frictionless");
  expect_edit("negative g", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = tresca\ng = -1\n", "contact.g",
              "must be >= 0");
  expect_edit("negative friction coefficient", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = coulomb\nfriction = -0.1\n",
              "contact.friction", "must be >= 0");
  expect_edit("friction with psor", "\nP2 = -5.75e8\n",
              "\nP2 = -5.75e8\n[contact]\nmodel = coulomb\nfriction = 0.3\n"
              "[solver]\nstate = psor\n", "solver.state", "use pdas or cgssor");
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

/* a scene path longer than Scene.path: the message names its start */
static void test_long_path(void)
{
  char path[600];
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc;
  memset(path, 'd', sizeof path);
  memcpy(path + sizeof path - 7, ".scene", 7);
  rc = scene_load(&s, path, 0, NULL, &st);
  check(rc == STATUS_INPUT && !s.alpha0 && strstr(st.msg, "dddd...: ")
        && strstr(st.msg, "scene path longer than 511"),
        "scene path too long: %s", st.msg);
}

/* the file itself, and the overrides */
static void test_file_and_override_errors(void)
{
  const char *ex = "data/example-5.1.scene";
  char path[256], big[400];
  char *nu[] = {"material.nu=0.7"}, *nodot[] = {"meshM=4"};
  char *noeq[] = {"mesh.M"}, *unknown[] = {"mesh.Q=1"}, *longv[] = {big};
  Scene s;
  snprintf(path, sizeof path, "%s/none.scene", tmpdir);
  expect("missing scene file", path, 0, NULL, "cannot read", "No such file");
  expect("unreadable scene file (a directory)", tmpdir, 0, NULL,
         "cannot read", "directory");
  expect("value error from an override", ex, 1, nu,
         "(-s material.nu=0.7): material.nu = 0.7", "incompressible");
  expect("malformed override without '.'", ex, 1, nodot, "(-s meshM=4)",
         "malformed override");
  expect("malformed override without '='", ex, 1, noeq, "(-s mesh.M)",
         "malformed override");
  expect("unknown key in an override", ex, 1, unknown, "(-s mesh.Q=1)",
         "unknown key");
  memset(big, 'x', sizeof big);
  memcpy(big, "design.file=", 12);
  big[sizeof big - 1] = '\0';
  expect("override value too long", ex, 1, longv, "design.file",
         "longer than 255");
  check(scene_load(&s, path, 0, NULL, NULL) == STATUS_INPUT && !s.alpha0,
        "a NULL status still fails with 2");
  test_long_path();
}

static void test_names(void)
{
  check(strcmp(problem_bc_name(BC_ROLLER), "roller") == 0
        && strcmp(qp_method_name(QP_CGSSOR), "cgssor") == 0
        && strcmp(problem_model_name(MODEL_PLANE_STRAIN), "plane_strain") == 0
        && strcmp(problem_bc_name((Bc_kind)9), "?") == 0
        && strcmp(opt_method_name(OPT_PROJGRAD), "projgrad") == 0
        && strcmp(opt_metric_name((Opt_metric)-1), "?") == 0,
        "names of conditions, methods, models, and '?' out of range");
  Problem p = {0};
  p.a = -0.3; p.b = 0.7; p.N = 3;
  check(problem_node_x(&p, 0) == -0.3 && problem_node_x(&p, 3) == 0.7,
        "the end nodes are a and b exactly (a = -0.3, b = 0.7, N = 3)");
}

int main(void)
{
  int i;
  if (!mkdtemp(tmpdir)) {
    perror("test_scene: mkdtemp");
    return 1;
  }
  test_example_5_1();
  test_example_5_2();
  test_overrides();
  test_switching();
  test_shape_file();
  test_syntax_errors();
  test_number_errors();
  test_magnitude_errors();
  test_range_errors();
  test_initial_errors();
  test_condition_errors();
  test_held_by_friction();
  test_file_and_override_errors();
  test_names();
  for (i = 0; i < nmade; i++) unlink(made[i]);
  rmdir(tmpdir);
  return check_done();
}
