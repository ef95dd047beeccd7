/* test_scene_keys.c: the table of keys as `contactopt keys` prints it
   (scene_keys_print, paper/scene.nw) against what the loader does.  For
   every key printed with a default, the scene with the key deleted (-s
   key=) and the scene with the key set to the printed default load to the
   same Scene, bit for bit; a default printed for some words of its
   selector ("100 (pdas), 100000 (psor, cgssor)") is tried with each word.
   For every key printed as required, the scene without it is refused as
   missing that key.  The base is Example 5.1, with the overrides that make
   the key mean something (a loaded left side for left.P1, a part for the
   keys of a named section, an orthotropic material for E1, ...); the
   default of boundary.NAME.bc, whose section has no other key under it,
   shows in the refusal of a traction key without it.  The names
   themselves (every key printed is accepted, every key accepted is
   printed) are checked by tests/keys.sh.  Run from the repository root. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "same.h"
#include "scene.h"
#include "part_geometry.h"

static const char *base = "data/example-5.1.scene";
static char shape[64];          /* a shape file for design.file */
static char geo[2][64];         /* geometry files for part.geometry */
static const char *const geo_text[2] = {   /* a curve NAME; a surface NAME */
  PART_GEO_BODY "Physical Curve(\"NAME\") = {10};\n",
  PART_GEO_BODY "Physical Surface(\"NAME\") = {2};\n"};

/* the overrides that make a key mean something in the base, by the first
   prefix of section.key that matches */
#define NO_ARC "design.arc_x1=", "design.arc_x2=", "design.arc_radius="
/* a part: its geometry (which drops gamma, R and the top), and C2 as the
   strip's area, C0prime (b - a) - 0.09; the geometry names its top curve
   NAME (PART) or its middle layer NAME (PART_S), since one name may name
   one physical group */
#define PART geo[0], "design.C2=0.91"
#define PART_S geo[1], "design.C2=0.91"
#define ORTHO(sec) sec ".kind=orthotropic", sec ".E1=2e11", sec ".E2=1e11", \
  sec ".nu12=0.3", sec ".G12=5e10"
#define THIRD(sec) "material.model=plane_strain", sec ".E3=1e11", \
  sec ".nu13=0.25", sec ".nu23=0.2"
#define NAMED(k) "material.NAME." k
static struct { const char *prefix, *over[16]; } enable[] = {
  {"boundary.NAME.p", {PART, "boundary.NAME.bc=pressure", "boundary.NAME.p=1e6"}},
  {"boundary.NAME.", {PART, "boundary.NAME.bc=traction", "boundary.NAME.P1=1e6",
                      "boundary.NAME.P2=1e6"}},
  {NAMED("E3"), {PART_S, ORTHO("material.NAME"), THIRD("material.NAME")}},
  {NAMED("nu13"), {PART_S, ORTHO("material.NAME"), THIRD("material.NAME")}},
  {NAMED("nu23"), {PART_S, ORTHO("material.NAME"), THIRD("material.NAME")}},
  {NAMED("E1"), {PART_S, ORTHO("material.NAME")}},
  {NAMED("E2"), {PART_S, ORTHO("material.NAME")}},
  {NAMED("nu12"), {PART_S, ORTHO("material.NAME")}},
  {NAMED("G12"), {PART_S, ORTHO("material.NAME")}},
  {NAMED("angle"), {PART_S, ORTHO("material.NAME")}},
  {"material.NAME.", {PART_S, NAMED("E=1e9"), NAMED("nu=0.3")}},
  {"material.E3", {ORTHO("material"), THIRD("material")}},
  {"material.nu13", {ORTHO("material"), THIRD("material")}},
  {"material.nu23", {ORTHO("material"), THIRD("material")}},
  {"material.E1", {ORTHO("material")}},
  {"material.E2", {ORTHO("material")}},
  {"material.nu12", {ORTHO("material")}},
  {"material.G12", {ORTHO("material")}},
  {"material.angle", {ORTHO("material")}},
  {"left.bc", {NULL}},
  {"left.", {"left.bc=traction", "left.from=0.5", "left.to=1",
             "left.P1=1e6", "left.P2=1e6"}},
  {"right.bc", {NULL}},
  {"right.", {"right.bc=traction", "right.from=0.5", "right.to=1",
              "right.P1=1e6", "right.P2=1e6"}},
  {"top.bc", {"top.from=", "top.to=", "top.P1=", "top.P2="}},
  {"top.", {"top.P1=1e6"}},
  {"design.line", {"design.initial=line", NO_ARC, "design.line_start=0",
                   "design.line_end=0.05"}},
  {"design.constant", {"design.initial=constant", NO_ARC,
                       "design.constant=0.02"}},
  {"design.file", {"design.initial=file", NO_ARC, shape}},
  {"contact.g", {"contact.model=tresca", "contact.g=1e6"}},
  {"contact.friction", {"contact.model=coulomb", "contact.friction=0.2"}},
  {"contact.max_fixed_point", {"contact.model=coulomb", "contact.friction=0.2"}},
  {"objective.q", {"objective.kind=pressure_peak"}},
};

/* ov = the overrides enabling name, then more (NULL-ended); their number */
static int overrides(const char *name, char **ov, char *const *more)
{
  size_t i;
  int n = 0, j;
  for (i = 0; i < sizeof enable / sizeof enable[0]; i++)
    if (strncmp(name, enable[i].prefix, strlen(enable[i].prefix)) == 0) {
      for (j = 0; j < 16 && enable[i].over[j]; j++)
        ov[n++] = (char *)enable[i].over[j];
      break;
    }
  for (; *more; more++) ov[n++] = *more;
  return n;
}

/* the fields of a printed line, split at runs of two or more blanks */
static int split(char *line, char **field, int max)
{
  int n = 0;
  char *p = line;
  line[strcspn(line, "\n")] = '\0';
  while (*p && n < max) {
    field[n++] = p;
    p = strstr(p, "  ");
    if (!p) break;
    *p = '\0';
    for (p += 2; *p == ' '; p++) continue;
  }
  return n;
}

/* name with the selector's word sel (or none) loads to the same scene with
   name deleted as with name = value */
static void same_default(const char *name, const char *value, const char *sel)
{
  char del[64], set[96], *ov[32], *more[3] = {NULL, NULL, NULL};
  Scene a, b;
  Status sa = {STATUS_OK, ""}, sb = {STATUS_OK, ""};
  const char *diff = "";
  int n, ra, rb;
  snprintf(del, sizeof del, "%s=", name);
  snprintf(set, sizeof set, "%s=%s", name, value);
  more[0] = (char *)sel, more[sel ? 1 : 0] = del;
  ra = scene_load(&a, base, n = overrides(name, ov, more), ov, &sa);
  more[sel ? 1 : 0] = set;
  rb = scene_load(&b, base, overrides(name, ov, more), ov, &sb);
  if (!ra && !rb) diff = scene_differs(&a, &b);
  check(!ra && !rb && !diff, "%s: the printed default %s%s%s is the loader's "
        "(%d overrides)%s%s%s%s", name, value, sel ? " with " : "",
        sel ? sel : "", n, ra ? sa.msg : "", rb ? sb.msg : "",
        diff ? " differ in " : "", diff ? diff : "");
  scene_free(&a);
  scene_free(&b);
}

/* a default printed as "V (w, w), V (w)": each V with each of its words */
static void same_defaults(const char *name, const char *text)
{
  char buf[128], sel[96], *p = buf, *open, *close, *w, *save = NULL;
  const char *selector = strncmp(name, "solver.", 7) == 0 ? "solver.state"
                                                          : "optimizer.method";
  snprintf(buf, sizeof buf, "%s", text);
  while ((open = strstr(p, " (")) && (close = strchr(open, ')'))) {
    *open = *close = '\0';
    for (w = strtok_r(open + 2, ", ", &save); w; w = strtok_r(NULL, ", ", &save)) {
      snprintf(sel, sizeof sel, "%s=%s", selector, w);
      same_default(name, p, sel);
    }
    p = close + 1;
    if (*p == ',') p += 2;          /* ", " before the next value */
  }
}

/* name without a default is refused as missing when not given */
static void required(const char *name)
{
  char del[64], *ov[32], *more[2] = {del, NULL};
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc;
  snprintf(del, sizeof del, "%s=", name);
  rc = scene_load(&s, base, overrides(name, ov, more), ov, &st);
  check(rc == STATUS_INPUT && strstr(st.msg, name)
        && strstr(st.msg, "missing required key"),
        "%s: printed as required, and refused when not given: %s", name,
        st.msg);
  scene_free(&s);
}

/* boundary.NAME.bc: under its printed default a traction is refused, and
   bc = the default is that condition, in the part's first slot */
static void named_bc_default(const char *value)
{
  char want[64], set[64], *ov[8] = {PART, "boundary.NAME.P1=1e6"};
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc;
  snprintf(want, sizeof want, "has no effect with bc = %s", value);
  rc = scene_load(&s, base, 3, ov, &st);
  check(rc == STATUS_INPUT && strstr(st.msg, "boundary.NAME.P1") && strstr(st.msg, want),
        "boundary.NAME.bc: without it, a traction is refused with bc = %s: %s",
        value, st.msg);
  scene_free(&s);
  snprintf(set, sizeof set, "boundary.NAME.bc=%s", value);
  ov[2] = set;
  rc = scene_load(&s, base, 3, ov, &st);
  check(!rc && s.problem.part.ncurve == 1
        && strcmp(problem_bc_name(s.problem.part.curve[0].kind), value) == 0
        && strcmp(s.problem.part.curve[0].name, "NAME") == 0,
        "boundary.NAME.bc = %s fills the part's first curve %s", value,
        rc ? st.msg : "");
  scene_free(&s);
}

int main(void)
{
  char line[512], *f[5];
  FILE *fp = tmpfile();
  int n = 0, i;
  FILE *sh;
  snprintf(shape, sizeof shape, "design.file=/tmp/test_scene_keys.%d.dat", (int)getpid());
  for (i = 0; i < 2; i++) {
    snprintf(geo[i], sizeof geo[i], "part.geometry=/tmp/test_scene_keys.%d.%d.geo",
             (int)getpid(), i);
    if (!(sh = fopen(geo[i] + 14, "w")) || fputs(geo_text[i], sh) < 0 || fclose(sh)) {
      perror("test_scene_keys");
      return 1;
    }
  }
  if (!fp || !(sh = fopen(shape + 12, "w"))) {
    perror("test_scene_keys");
    return 1;
  }
  for (i = 0; i <= 16; i++) fprintf(sh, "%g %g\n", 0.25 * i, 0.001 * i);
  fclose(sh);
  scene_keys_print(fp, 0);
  rewind(fp);
  if (!fgets(line, sizeof line, fp)) return 1;        /* the header */
  while (fgets(line, sizeof line, fp)) {
    n++;
    if (split(line, f, 5) != 5) {
      check(0, "a printed line has five fields: %s", line);
      continue;
    }
    if (strcmp(f[0], "boundary.NAME.bc") == 0) named_bc_default(f[2]);
    else if (strcmp(f[2], "(empty)") == 0) same_default(f[0], "", NULL);
    else if (strcmp(f[2], "required") == 0) required(f[0]);
    else if (strchr(f[2], '(')) same_defaults(f[0], f[2]);
    else same_default(f[0], f[2], NULL);
  }
  check(n == 80, "contactopt keys prints %d keys", n);
  fclose(fp);
  unlink(shape + 12);
  unlink(geo[0] + 14);
  unlink(geo[1] + 14);
  return check_done();
}
