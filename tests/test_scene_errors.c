/* test_scene_errors.c: every documented error of the scene loader
   (paper/scene.nw) provoked once, in a small scene written to a temporary
   directory (scene_files.h): the file's syntax, long lines and NUL bytes,
   malformed numbers, magnitudes outside the window in which every product
   is finite, values out of their range, the initial shape and its file,
   the sides, the contact and the solver, the file itself and the
   overrides.  Each must give status 2, leave nothing allocated, and tell
   one line naming the file, the key and the reason.  Run from the
   repository root. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "scene.h"
#include "scene_files.h"

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

/* the part's scene edited (its first old replaced by with, then more),
   then loaded with the overrides: expect an error */
static void expect_part(const char *what, const char *old, const char *with,
                        const char *more, int nov, char **ov, const char *key,
                        const char *word)
{
  char path[256], name[64];
  snprintf(name, sizeof name, "part%02d.scene", nmade);
  part_scene(name, old, with, more, path, sizeof path);
  expect(what, path, nov, ov, key, word);
}

/* a part and its named sections: the names, what means nothing with a
   part or without one, the loads of a curve, the materials */
static void test_part_errors(void)
{
  static const char *const pressure = "bc = pressure\np = 1e7\n";
  static const char *const rubber = "[material.rubber]\nE = 6e6\n";
  static const char *const ortho = "[material]\nkind = orthotropic\nE1 = 2e11\n"
    "E2 = 1e11\nnu12 = 0.3\nG12 = 5e10\n";
  char text[8192], many[4096], path[256], *ov[2];
  int i, n = 0;
  snprintf(text, sizeof text, "%s[boundary.bore]\nbc = clamped\n", base);
  write_file("named.scene", text, path, sizeof path);
  expect("a named section without part.geometry", path, 0, NULL,
         "boundary.bore.bc", "a named section needs part.geometry");
  ov[0] = "material.rubber.E=6e6";
  expect("a named material by -s without part.geometry", path, 1, ov,
         "boundary.bore.bc", "needs part.geometry");
  expect_part("a NAME with a '-'", "[boundary.bore]", "[boundary.bo-re]", NULL,
              0, NULL, "boundary.bo-re.bc", "a NAME is 1 to 40 letters, digits or _");
  snprintf(text, sizeof text, "[boundary.%041d]\nbc = clamped\n", 0);
  expect_part("a section name of 50 characters, which inih would cut", NULL, NULL,
              text, 0, NULL, "[boundary.0000", "a section name is at most 49 characters");
  snprintf(text, sizeof text, "boundary.%041d.bc=clamped", 0);
  ov[0] = text;
  expect_part("a NAME of 41 characters by -s", NULL, NULL, NULL, 1, ov,
              "boundary.0000", "a NAME is 1 to 40");
  snprintf(text, sizeof text, "[boundary.%040d]\nbc = clamped\n", 0);
  part_scene("name40.scene", NULL, NULL, text, path, sizeof path);
  {
    Scene s;
    Status st = {STATUS_OK, ""};
    check(scene_load(&s, path, 0, NULL, &st) == 0 && s.problem.part.ncurve == 4
          && strlen(s.problem.part.curve[3].name) == 40,
          "a NAME of 40 characters is kept whole: %s", st.msg);
    scene_free(&s);
  }
  expect_part("an empty NAME", "[boundary.seat]", "[boundary.]", NULL, 0, NULL,
              "boundary..bc", "a NAME is");
  ov[0] = "boundary.bo-re.bc=clamped";
  expect_part("a bad NAME by -s", NULL, NULL, NULL, 1, ov, "boundary.bo-re.bc",
              "a NAME is");
  expect_part("a duplicate key in a named section", "bc = clamped\n[left]",
              "bc = clamped\nbc = free\n[left]", NULL, 0, NULL, "boundary.seat.bc",
              "duplicate key");
  for (i = 0; i < 30; i++)       /* with top, bore, seat: 33 names */
    n += snprintf(many + n, sizeof many - n, "[boundary.c%d]\nbc = free\n", i);
  expect_part("33 named curves", NULL, NULL, many, 0, NULL, "boundary.c29.bc",
              "more than 32 [boundary.NAME] sections");
  expect_part("a traction of zero on a curve", "P2 = -5.75e8", "P2 = 0", NULL, 0,
              NULL, "boundary.top.bc", "is zero: use bc = free");
  expect_part("a pressure of zero", "p = 1e7", "p = 0", NULL, 0, NULL,
              "boundary.bore.p", "a pressure of 0");
  expect_part("a pressure too small for E", "p = 1e7", "p = 1e-25", NULL, 0,
              NULL, "boundary.bore.p", "a load must be 0 or lie within");
  expect_part("a pressure without p", pressure, "bc = pressure\n", NULL, 0,
              NULL, "boundary.bore.p", "missing required key");
  expect_part("a traction key on a pressure curve", pressure,
              "bc = pressure\np = 1e7\nP1 = 1e6\n", NULL, 0, NULL,
              "boundary.bore.P1", "has no effect with bc = pressure");
  expect_part("a curve's unknown condition", pressure, "bc = glued\n", NULL, 0,
              NULL, "boundary.bore.bc", "unknown value");
  expect_part("an orthotropic key in an isotropic material", rubber,
              "[material.rubber]\nE = 6e6\nE1 = 1e9\n", NULL, 0, NULL,
              "material.rubber.E1", "has no effect with kind = isotropic");
  expect_part("an isotropic key in an orthotropic material", "[material]\n",
              "[material]\nkind = orthotropic\nE1 = 2e11\nE2 = 1e11\nnu12 = 0.3\n"
              "G12 = 5e10\n", NULL, 0, NULL, "material.E",
              "has no effect with kind = orthotropic");
  expect_part("model in a named material", rubber,
              "[material.rubber]\nE = 6e6\nmodel = plane_strain\n", NULL, 0, NULL,
              "material.rubber.model", "the plane model is the whole body's");
  ov[0] = "material.rubber.model=plane_strain";
  expect_part("model in a named material by -s", NULL, NULL, NULL, 1, ov,
              "material.rubber.model", "whole body's");
  expect_part("a named material without nu", "E = 6e6\nnu = 0.45\n", "E = 6e6\n",
              NULL, 0, NULL, "material.rubber.nu", "missing required key");
  expect_part("the geometry file missing", "geometry = part.geo",
              "geometry = nosuch.geo", NULL, 0, NULL, "part.geometry",
              "cannot read the geometry file");
  expect_part("the geometry a folder", "geometry = part.geo", "geometry = .",
              NULL, 0, NULL, "part.geometry", "Is a directory");
  expect_part("gamma with a part", "b = 4\n", "b = 4\ngamma = 1\n", NULL, 0, NULL,
              "geometry.gamma", "has no effect with part.geometry");
  expect_part("R with a part", "M = 1\n", "M = 1\nR = 3\n", NULL, 0, NULL,
              "mesh.R", "has no effect with part.geometry");
  expect_part("the top with a part", NULL, NULL, "[top]\nbc = clamped\n", 0, NULL,
              "top.bc", "has no effect with part.geometry");
  expect_part("a loaded strip side with a part", "[right]\nbc = roller",
              "[right]\nbc = traction\nfrom = 0.1\nto = 0.2\nP1 = 1e6", NULL, 0,
              NULL, "right.bc", "moves with the design");
  expect_part("C2 as the rectangle's area with a part", "C2 = 0.91", "C2 = 3.91",
              NULL, 0, NULL, "design.C2", "S = C0prime (b-a) - C2");
  /* orthotropic materials */
  expect_part("E1 = 0", "[material]\nE = 2.15e11\nnu = 0.29\n",
              "[material]\nkind = orthotropic\nE1 = 0\nE2 = 1e11\nnu12 = 0.3\n"
              "G12 = 5e10\n", NULL, 0, NULL, "material.E1", "E1 must be > 0");
  expect_part("G12 beyond the window", "[material]\nE = 2.15e11\nnu = 0.29\n",
              "[material]\nkind = orthotropic\nE1 = 2e11\nE2 = 1e11\nnu12 = 0.3\n"
              "G12 = 5e31\n", NULL, 0, NULL, "material.G12", "must lie in [1e-30, 1e30]");
  expect_part("nu12^2 not below E1 / E2", "[material]\nE = 2.15e11\nnu = 0.29\n",
              "[material]\nkind = orthotropic\nE1 = 1e11\nE2 = 2e11\nnu12 = 0.71\n"
              "G12 = 5e10\n", NULL, 0, NULL, "material.kind = orthotropic",
              "|nu12| < sqrt(E1/E2) = 0.707107 (ellipticity)");
  expect_part("the third axis in plane stress", "[material]\nE = 2.15e11\nnu = 0.29\n",
              ortho, "[material.stiff]\nkind = orthotropic\nE1 = 2e11\nE2 = 1e11\n"
              "nu12 = 0.3\nG12 = 5e10\nE3 = 1e11\n", 0, NULL, "material.stiff.E3",
              "has no effect with material.model = plane_stress");
  expect_part("no E3 in plane strain", "[material]\nE = 2.15e11\nnu = 0.29\n",
              "[material]\nkind = orthotropic\nE1 = 2e11\nE2 = 1e11\nnu12 = 0.3\n"
              "G12 = 5e10\nmodel = plane_strain\nnu13 = 0.2\nnu23 = 0.2\n", NULL, 0,
              NULL, "material.E3", "missing required key");
  /* nu12 = nu13 = nu23 = 0.6, E equal: each ratio below 1, but the
     determinant 1 - 3 (0.36) - 2 (0.216) = -0.512 < 0 */
  expect_part("a plane-strain compliance not positive definite",
              "[material]\nE = 2.15e11\nnu = 0.29\n",
              "[material]\nkind = orthotropic\nE1 = 1e11\nE2 = 1e11\nnu12 = 0.6\n"
              "G12 = 5e10\nmodel = plane_strain\nE3 = 1e11\nnu13 = 0.6\n"
              "nu23 = 0.6\n", NULL, 0, NULL, "material.kind",
              "nu32 nu13 > 0 (ellipticity in plane strain), not -0.512");
  expect_part("nu13^2 not below E1 / E3", "[material]\nE = 2.15e11\nnu = 0.29\n",
              "[material]\nkind = orthotropic\nE1 = 1e11\nE2 = 1e11\nnu12 = 0.3\n"
              "G12 = 5e10\nmodel = plane_strain\nE3 = 4e11\nnu13 = 0.5\n"
              "nu23 = 0.2\n", NULL, 0, NULL, "material.kind", "|nu13| < sqrt(E1/E3) = 0.5 "
              "(ellipticity)");
  /* the window of loads measured by E = max(E1, E2) = 2e11: 1.5e41 Pa is
     7.5e29 E (over E2 = 1e11 it would be 1.5e30, outside), 2.5e41 Pa is
     1.25e30 E */
  snprintf(text, sizeof text, "%s", ortho);
  part_scene("ortho-load.scene", "[material]\nE = 2.15e11\nnu = 0.29\n", text,
             NULL, path, sizeof path);
  ov[0] = "boundary.top.P2=-1.5e41";
  {
    Scene s;
    Status st = {STATUS_OK, ""};
    check(scene_load(&s, path, 1, ov, &st) == 0, "an orthotropic body takes "
          "|P2| = 1.5e41 Pa = 7.5e29 max(E1, E2): %s", st.msg);
    scene_free(&s);
  }
  ov[0] = "boundary.top.P2=-2.5e41";
  expect("a traction beyond the window of the orthotropic body's max(E1, E2)",
         path, 1, ov, "boundary.top.P2", "|P2| / E = 1.25e30");
}

/* what the mesher refuses as the part's scene loads (check_part,
   paper/scene.nw; mesh_new, paper/mesh.nw; part_mesh_new, paper/part.nw):
   names the geometry lacks, rollers on curves that are not straight along
   an axis, a geometry that does not join [a, b] x {C0prime}, one gmsh
   cannot read */
static void test_mesher_errors(void)
{
  char path[256], name40[64], over[96], *ov[2];
  expect_part("a boundary name the geometry lacks", NULL, NULL,
              "[boundary.nosuch]\nbc = clamped\n", 0, NULL, "boundary.nosuch",
              "the geometry has no physical curve nosuch");
  ov[0] = "material.nosuch.E=1e9", ov[1] = "material.nosuch.nu=0.3";
  expect_part("a material name the geometry lacks, by -s", NULL, NULL, NULL, 2,
              ov, "material.nosuch", "the geometry has no physical surface nosuch");
  ov[0] = "boundary.bore.bc=roller", ov[1] = "boundary.bore.p=";
  expect_part("a roller on the bore, a circle", NULL, NULL, NULL, 2, ov,
              "boundary.bore.bc = roller", "the curve bore is not a straight line "
              "along x1 or x2");
  snprintf(name40, sizeof name40, "boundary.%s.bc", PART_GEO_NAME40);
  snprintf(over, sizeof over, "%s=roller", name40);
  ov[0] = over;
  expect_part("a roller on the chamfer, inclined", NULL, NULL, NULL, 1, ov,
              name40, "is not a straight line along x1 or x2");
  /* the geometry's bottom lies at x2 = 0.25; C2 keeps the area 0.09 under
     alpha: 0.2 (b - a) - 0.09 */
  ov[0] = "mesh.C0prime=0.2", ov[1] = "design.C2=0.71";
  expect_part("a geometry that does not join [a, b] x {C0prime}", NULL, NULL, NULL,
              2, ov, "part.geo", "no curve of the geometry runs along [a, b] x "
              "{C0prime} = [0, 4] x {0.2}");
  write_file("syntax.geo", PART_GEO "Line(99) = {1, 2, ;\n", path, sizeof path);
  expect_part("a geometry with a syntax error", "geometry = part.geo",
              "geometry = syntax.geo", NULL, 0, NULL, "syntax.geo", "syntax error");
}

/* make SAN=1: gmsh's parser leaks the lists it was building when a .geo
   has a syntax error (gmsh_yyparse), inside the library; LeakSanitizer
   ignores that stack alone, read by the slow unwinder (as in
   tests/test_part.c) */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "fast_unwind_on_malloc=0"; }
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:gmsh_yyparse\n"; }

int main(void)
{
  if (!scene_files_begin()) return 1;
  test_part_errors();
  test_mesher_errors();
  test_syntax_errors();
  test_number_errors();
  test_magnitude_errors();
  test_range_errors();
  test_initial_errors();
  test_condition_errors();
  test_file_and_override_errors();
  scene_files_end();
  return check_done();
}
