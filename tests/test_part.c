/* test_part: the fixed part Omega' meshed from a gmsh geometry
   (paper/part.nw).  Each geometry of tests/parts/ is meshed for Example
   5.1's strip (a = 0, b = 4, C0prime = 0.25, N = 16) and checked against
   what the geometry implies: the area of the body, the joining nodes on
   the strip's grid bit for bit, the regions by height, the boundary
   edges and their orientation; the same mesh on a second run; and every
   refusal of the interface, each from a geometry of its own. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "problem.h"
#include <dirent.h>
#include <unistd.h>
#include "part.h"

static const double PI = 3.14159265358979323846;

/* Example 5.1's strip at N = 16 refine; the geometry's absolute path */
static Problem part_problem(const char *geo, int refine)
{
  Problem p;
  char cwd[2048];
  memset(&p, 0, sizeof p);
  p.a = 0; p.b = 4; p.gamma = 1; p.N = 16 * refine; p.M = refine; p.R = 3 * refine;
  p.C0 = 0.05; p.C0prime = 0.25; p.material.young = 2.15e11; p.material.nu = 0.29;
  p.part.refine = refine;
  snprintf(p.part.geometry, sizeof p.part.geometry, "%s/%s",
           getcwd(cwd, sizeof cwd) ? cwd : ".", geo);
  return p;
}

static Part_mesh *mesh(const char *geo, int refine, Problem *p, Status *st)
{
  *p = part_problem(geo, refine);
  *st = (Status){ 0, "" };
  return part_mesh_new(p, st);
}

static double tri_area(const Part_mesh *pm, int t)
{
  const int *v = pm->tri + 3 * t;
  const double *p = pm->xy + 2 * v[0], *q = pm->xy + 2 * v[1], *r = pm->xy + 2 * v[2];
  return 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
}

static double mesh_area_sum(const Part_mesh *pm, int *positive)
{
  double area = 0;
  *positive = 1;
  for (int t = 0; t < pm->ntri; t++) { double s = tri_area(pm, t); *positive &= s > 0; area += s; }
  return area;
}

/* the shoelace sum of the boundary edges of curve c (all when c = -2) */
static double loop_area(const Part_mesh *pm, int c)
{
  double s = 0;
  for (int e = 0; e < pm->nedge; e++)
    if (c == -2 || pm->curve[e] == c) {
      const double *p = pm->xy + 2 * pm->edge[2 * e], *q = pm->xy + 2 * pm->edge[2 * e + 1];
      s += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
  return s;
}

/* the joining nodes: N+1, one per column, each at (x_i, C0prime) bit for bit */
static int joining_exact(const Part_mesh *pm, const Problem *p)
{
  int n = 0, ok = 1, *seen = calloc(p->N + 1, sizeof *seen);
  for (int k = 0; k < pm->nnodes; k++) {
    int i = pm->column[k];
    if (i < 0) continue;
    n++;
    ok &= i <= p->N && !seen[i] && pm->xy[2 * k] == problem_node_x(p, i)
          && pm->xy[2 * k + 1] == p->C0prime;
    if (i <= p->N) seen[i] = 1;
  }
  free(seen);
  return ok && n == p->N + 1;
}

/* the closing of the boundary by the joining segment, x_i -> x_{i+1}
   (the body above, on the left): its shoelace term */
static double joining_shoelace(const Problem *p)
{
  double s = 0;
  for (int i = 0; i < p->N; i++)
    s += 0.5 * (problem_node_x(p, i) * p->C0prime - problem_node_x(p, i + 1) * p->C0prime);
  return s;
}

static int named(const Part_mesh *pm, const char *name)
{
  for (int c = 0; c < pm->ncurve; c++) if (!strcmp(pm->curve_name[c], name)) return c;
  return -1;
}

/* (1) the rectangle as a geometry */
static void rectangle(void)
{
  Problem p;
  Status st;
  Part_mesh *pm = mesh("tests/parts/rectangle.geo", 1, &p, &st);
  if (!check(pm != NULL, "rectangle.geo meshes: %s", st.msg)) return;
  int positive;
  double area = mesh_area_sum(pm, &positive), want = (p.b - p.a) * (p.gamma - p.C0prime);
  check(positive, "rectangle: every triangle counter-clockwise (%d triangles, %d nodes)", pm->ntri, pm->nnodes);
  check(fabs(area - want) <= 1e-13 * want, "rectangle: the areas sum to (b-a)(gamma-C0prime) = 3 to 1e-13 (%.17g)", area);
  check(joining_exact(pm, &p), "rectangle: N+1 = 17 joining nodes, at (x_i, C0prime) bit for bit");
  check(fabs(loop_area(pm, -2) + joining_shoelace(&p) - area) <= 1e-13 * want,
        "rectangle: the boundary edges and the joining segment enclose the body, body on the left");
  int top = named(pm, "top"), tops = 0, ok = 1;
  for (int e = 0; e < pm->nedge; e++)
    if (pm->curve[e] == top) {
      tops++;
      ok &= pm->xy[2 * pm->edge[2 * e] + 1] == 1 && pm->xy[2 * pm->edge[2 * e + 1] + 1] == 1
            && pm->xy[2 * pm->edge[2 * e + 1]] < pm->xy[2 * pm->edge[2 * e]];
    }
  check(top >= 0 && tops > 0 && ok && pm->nsurface == 1 && !strcmp(pm->surface_name[0], "body"),
        "rectangle: the edges of \"top\" lie on x2 = 1 and run towards -x1 (body below, on their left)");
  part_mesh_free(pm);
}

/* the sizes: at most about h = (b-a)/N (gmsh's edges reach some 1.4
   times its size), and refine 2 has about four times the triangles of
   refine 1 (not sixteen: the factor 1/refine and N refined together) */
static void sizes(void)
{
  int ntri[2];
  for (int r = 0; r < 2; r++) {
    Problem p;
    Status st;
    Part_mesh *pm = mesh("tests/parts/rectangle.geo", 1 + r, &p, &st);
    if (!check(pm != NULL, "rectangle.geo at refine %d meshes: %s", 1 + r, st.msg)) return;
    double h = (p.b - p.a) / p.N, longest = 0;
    for (int t = 0; t < 3 * pm->ntri; t++) {
      const double *q = pm->xy + 2 * pm->tri[t], *u = pm->xy + 2 * pm->tri[t - t % 3 + (t + 1) % 3];
      longest = fmax(longest, hypot(u[0] - q[0], u[1] - q[1]));
    }
    ntri[r] = pm->ntri;
    check(longest <= 1.5 * h, "rectangle, refine %d: the longest edge is %.3g h", 1 + r, longest / h);
    part_mesh_free(pm);
  }
  check(ntri[1] > 3 * ntri[0] && ntri[1] < 5 * ntri[0],
        "rectangle: %d triangles at refine 1, %d at refine 2: about four times", ntri[0], ntri[1]);
}

/* (2) a bore of radius 0.2: the hole is the polygon of its edges, which
   runs clockwise; its area tends to pi r^2 */
static void bore(void)
{
  double miss[3], pr2 = PI * 0.04;
  int refine[3] = { 1, 2, 4 };
  for (int r = 0; r < 3; r++) {
    Problem p;
    Status st;
    Part_mesh *pm = mesh("tests/parts/bore.geo", refine[r], &p, &st);
    if (!check(pm != NULL, "bore.geo at refine %d meshes: %s", refine[r], st.msg)) return;
    int positive, c = named(pm, "bore");
    double area = mesh_area_sum(pm, &positive), hole = loop_area(pm, c);
    miss[r] = 3 - area;
    check(positive && c >= 0 && hole < 0 && fabs(3 + hole - area) <= 1e-13 * 3,
          "bore, refine %d: area = rectangle - polygon of the bore's edges, exactly; the loop clockwise (%.6g)",
          refine[r], hole);
    int closed = 1;   /* each node of the bore's loop starts one edge and ends one */
    for (int e = 0; e < pm->nedge; e++) {
      if (pm->curve[e] != c) continue;
      int starts = 0, ends = 0;
      for (int f = 0; f < pm->nedge; f++)
        if (pm->curve[f] == c) { starts += pm->edge[2 * f] == pm->edge[2 * e]; ends += pm->edge[2 * f + 1] == pm->edge[2 * e]; }
      closed &= starts == 1 && ends == 1;
    }
    check(closed && joining_exact(pm, &p), "bore, refine %d: the bore's edges form a closed loop; joining nodes exact", refine[r]);
    part_mesh_free(pm);
  }
  check(miss[0] < pr2 && miss[1] < pr2 && miss[2] < pr2 && pr2 - miss[2] < (pr2 - miss[1]) / 2.5
        && pr2 - miss[1] < (pr2 - miss[0]) / 2.5,
        "bore: pi r^2 - hole = %.3g, %.3g, %.3g at refine 1, 2, 4: from below, O(h^2)",
        pr2 - miss[0], pr2 - miss[1], pr2 - miss[2]);
}

/* (3) two layers: the region of each triangle is the layer of its centroid */
static void layers(void)
{
  Problem p;
  Status st;
  Part_mesh *pm = mesh("tests/parts/layers.geo", 1, &p, &st);
  if (!check(pm != NULL, "layers.geo meshes: %s", st.msg)) return;
  int soft = -1, stiff = -1, ok = 1, n[2] = { 0, 0 };
  for (int s = 0; s < pm->nsurface; s++) {
    if (!strcmp(pm->surface_name[s], "soft")) soft = s;
    if (!strcmp(pm->surface_name[s], "stiff")) stiff = s;
  }
  for (int t = 0; t < pm->ntri; t++) {
    const int *v = pm->tri + 3 * t;
    double y = (pm->xy[2 * v[0] + 1] + pm->xy[2 * v[1] + 1] + pm->xy[2 * v[2] + 1]) / 3;
    ok &= pm->region[t] == (y < 0.5 ? soft : stiff);
    n[y < 0.5]++;
  }
  check(soft >= 0 && stiff >= 0 && ok && n[0] > 0 && n[1] > 0,
        "layers: every triangle's region is its layer by the centroid (%d soft, %d stiff)", n[1], n[0]);
  int inner = 0;
  for (int e = 0; e < pm->nedge; e++)
    inner += fabs(pm->xy[2 * pm->edge[2 * e] + 1] - 0.5) < 1e-12 && fabs(pm->xy[2 * pm->edge[2 * e + 1] + 1] - 0.5) < 1e-12;
  check(inner == 0, "layers: the interface x2 = 0.5 between them has no boundary edge");
  part_mesh_free(pm);
}

/* (4) an overhang: its bottom beyond [a, b] is boundary, the joining segment is not */
static void overhang(void)
{
  Problem p;
  Status st;
  Part_mesh *pm = mesh("tests/parts/overhang.geo", 1, &p, &st);
  if (!check(pm != NULL, "overhang.geo meshes: %s", st.msg)) return;
  int ledge = named(pm, "ledge"), nledge = 0, on_join = 0, ledge_ok = 1, positive;
  for (int e = 0; e < pm->nedge; e++) {
    const double *q = pm->xy + 2 * pm->edge[2 * e], *r = pm->xy + 2 * pm->edge[2 * e + 1];
    int bottom = q[1] == 0.25 && r[1] == 0.25;
    if (bottom && q[0] >= 0 && r[0] >= 0 && q[0] <= 4 && r[0] <= 4) on_join++;
    if (pm->curve[e] == ledge) {
      nledge++;
      ledge_ok &= bottom && (fmax(q[0], r[0]) <= 0 || fmin(q[0], r[0]) >= 4) && r[0] > q[0];
    }
  }
  double area = mesh_area_sum(pm, &positive);
  check(nledge >= 8 && ledge_ok, "overhang: %d ledge edges, boundary edges on x2 = C0prime beyond [a, b], running towards +x1", nledge);
  check(on_join == 0 && joining_exact(&*pm, &p), "overhang: no boundary edge on the joining segment; joining nodes exact");
  check(positive && fabs(area - 4.5) <= 1e-13 * 4.5
        && fabs(loop_area(pm, -2) + joining_shoelace(&p) - area) <= 1e-13 * 4.5,
        "overhang: area 6 x 0.75, enclosed by the boundary edges and the joining segment");
  part_mesh_free(pm);
}

/* (6) the same mesh twice, bit for bit */
/* 1 if a and b are the same mesh bit for bit */
static int same_mesh(const Part_mesh *a, const Part_mesh *b)
{
  return a && b && a->nnodes == b->nnodes && a->ntri == b->ntri && a->nedge == b->nedge
         && !memcmp(a->xy, b->xy, 2 * sizeof *a->xy * a->nnodes)
         && !memcmp(a->tri, b->tri, 3 * sizeof *a->tri * a->ntri)
         && !memcmp(a->edge, b->edge, 2 * sizeof *a->edge * a->nedge)
         && !memcmp(a->column, b->column, sizeof *a->column * a->nnodes)
         && !memcmp(a->region, b->region, sizeof *a->region * a->ntri)
         && !memcmp(a->curve, b->curve, sizeof *a->curve * a->nedge);
}

/* gmsh makes the same mesh twice (another mesh between, so that the
   second is gmsh's and not the kept copy); asked again at once, the kept
   copy is the same, in arrays of its own */
static void twice(void)
{
  Problem p;
  Status st;
  Part_mesh *m1 = mesh("tests/parts/bore.geo", 2, &p, &st), *other = mesh("tests/parts/bore.geo", 1, &p, &st),
            *m2 = mesh("tests/parts/bore.geo", 2, &p, &st), *m3 = mesh("tests/parts/bore.geo", 2, &p, &st);
  check(other && same_mesh(m1, m2),
        "bore.geo meshed twice by gmsh: the same nodes, triangles and edges bit for bit");
  check(same_mesh(m2, m3) && m2->xy != m3->xy && m2->tri != m3->tri,
        "bore.geo asked for again: the kept mesh, the same, its own copy");
  part_mesh_free(m1);
  part_mesh_free(other);
  part_mesh_free(m2);
  part_mesh_free(m3);
}

/* (7) a curved outline: the half disc of radius 2 (OpenCASCADE) */
static void arch(void)
{
  double err[2];
  for (int r = 0; r < 2; r++) {
    Problem p;
    Status st;
    Part_mesh *pm = mesh("tests/parts/arch.geo", 1 + r, &p, &st);
    if (!check(pm != NULL, "arch.geo at refine %d meshes: %s", 1 + r, st.msg)) return;
    int positive;
    err[r] = 2 * PI - mesh_area_sum(pm, &positive);
    check(positive && joining_exact(pm, &p), "arch, refine %d: counter-clockwise triangles, joining nodes exact", 1 + r);
    part_mesh_free(pm);
  }
  check(err[0] > 0 && err[1] > 0 && err[1] < err[0] / 2.5,
        "arch: 2 pi - area = %.3g, %.3g at refine 1, 2: the inscribed polygon, O(h^2)", err[0], err[1]);
}

/* (5) every refusal, from a geometry of its own */
static void refused(const char *geo, Status_code code, const char *words)
{
  Problem p;
  Status st;
  char path[64];
  snprintf(path, sizeof path, "tests/parts/%s", geo);
  Part_mesh *pm = mesh(path, 1, &p, &st);
  check(!pm && st.code == code && strstr(st.msg, words) && !strncmp(st.msg, p.part.geometry, strlen(p.part.geometry))
        && !strchr(st.msg, '\n'),
        "%s refused with status %d: %s", geo, code, st.msg);
  part_mesh_free(pm);
}

static void refusals(void)
{
  refused("none.geo", STATUS_INPUT, "cannot open the geometry");
  refused("bad-syntax.geo", STATUS_INPUT, "syntax error");
  refused("bad-no-surface.geo", STATUS_INPUT, "no surface");
  refused("bad-below.geo", STATUS_INPUT, "point 1 at (0, 0.1) lies below x2 = C0prime = 0.25");
  refused("bad-dip.geo", STATUS_INPUT, "below x2 = C0prime = 0.25: a curve dips");
  refused("bad-apart.geo", STATUS_INPUT, "no curve of the geometry runs along [a, b] x {C0prime} = [0, 4] x {0.25}");
  refused("bad-half.geo", STATUS_INPUT, "runs along [x_8, x_16] x {C0prime} = [2, 4] x {0.25}");
  refused("bad-unsplit.geo", STATUS_INPUT, "past x1 = -1: split it by a point at x1 = 0");
  refused("bad-offgrid.geo", STATUS_INPUT, "ends at x1 = 1.1, off the strip's grid: the nearest node is x_4 = 1");
  refused("bad-joined-curve.geo", STATUS_INPUT, "physical curve \"bottom\" holds curve 1 of the joining segment");
  refused("bad-repeated.geo", STATUS_INPUT, "two physical groups are named \"top\"");
  refused("bad-long.geo", STATUS_INPUT, "is longer than 63 characters");
  refused("bad-character.geo", STATUS_INPUT, "\"top-side\" has a character other than");
  refused("bad-unnamed.geo", STATUS_INPUT, "physical curve 7 has no name");
  refused("bad-twice.geo", STATUS_INPUT, "curve 3 is in two physical curves, \"top\" and \"lid\"");
  refused("bad-many-curves.geo", STATUS_INPUT, "33 physical curves, more than the 32");
  refused("bad-many-surfaces.geo", STATUS_INPUT, "33 physical surfaces, more than the 32");
  refused("bad-quads.geo", STATUS_INPUT, "elements of gmsh's type 3, not 3-node triangles");
  refused("bad-order.geo", STATUS_INPUT, "elements of gmsh's type 9, not 3-node triangles");
  refused("bad-mesh.geo", STATUS_INPUT, "gmsh cannot mesh it: Unable to recover the edge");
  refused("bad-overlap.geo", STATUS_INPUT, "the node at (1.5, 0.4) lies on a triangle (physical surface \"body\") that it is no corner of: surfaces overlap");
  refused("bad-seam.geo", STATUS_INPUT, "that it is no corner of: surfaces overlap, or touch along a curve or at a point that they do not share");
  refused("bad-inner.geo", STATUS_INPUT, "physical curve \"inner\" runs inside the part (its line from (1, 0.6) to (1.25, 0.6) has a triangle on each side)");
  refused("bad-ghost.geo", STATUS_INPUT, "physical curve \"ghost\" holds curve 5, which bounds no surface");
  refused("bad-island.geo", STATUS_INPUT, "(physical surface \"island\") shares no node, through the others, with the joining segment");
}

/* make SAN=1: gmsh's parser leaks the lists it was building when a .geo
   has a syntax error (gmsh_yyparse, bad-syntax.geo), inside the library;
   LeakSanitizer is told to ignore that stack alone, so that a leak of an
   array gmsh hands to part.c still fails the run.  The stack is read by
   the slow unwinder, the fast one stopping in gmsh's code (built without
   frame pointers). */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "fast_unwind_on_malloc=0"; }
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:gmsh_yyparse\n"; }

/* the entries of a folder, . and .. left out */
static int entries(const char *dir)
{
  DIR *d = opendir(dir);
  struct dirent *e;
  int n = 0;
  while (d && (e = readdir(d))) n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
  if (d) closedir(d);
  return d ? n : -1;
}

int main(void)
{
  /* nothing written: HOME is an empty folder of its own for the whole
     run (FLTK would write its preferences there), and tests/parts/ keeps
     its files (no .msh beside a geometry) */
  char home[] = "/tmp/test_part.XXXXXX";
  int before = entries("tests/parts");
  if (!mkdtemp(home)) { printf("FAIL - mkdtemp\n"); return 1; }
  setenv("HOME", home, 1);
  rectangle();
  sizes();
  bore();
  layers();
  overhang();
  twice();
  arch();
  refusals();
  check(entries(home) == 0 && entries("tests/parts") == before,
        "nothing written: HOME and tests/parts/ as they were");
  rmdir(home);
  return check_done();
}
