#line 1870 "paper/scene.nw"
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fem.h"
#include "friction.h"
#include "scene_private.h"
#line 1921 "paper/scene.nw"
/* E, b - a and every non-zero load / E lie in [WINDOW_MIN, WINDOW_MAX] */
#define WINDOW_MIN 1e-30
#define WINDOW_MAX 1e30
/* the rounding of a ratio of decimals, relative: within it of a bound is on it */
#define WINDOW_ROUNDING (4 * DBL_EPSILON)

/* whether |x| / unit lies in the window, up to the rounding of the ratio
   (false if it overflows) */
static int in_window(double x, double unit)
{
  double r = fabs(x) / unit;
  return r >= WINDOW_MIN * (1 - WINDOW_ROUNDING)
         && r <= WINDOW_MAX * (1 + WINDOW_ROUNDING);
}

/* buf = r, outside the window, with three digits or the fewest more
   that still read outside it */
static const char *outside(double r, char *buf)
{
  int digits = 3;
  while (digits < 17 && in_window(strtod(status_digits(r, digits, buf), NULL), 1))
    digits++;
  return buf;
}

/* the modulus E of the material m that the window measures loads by:
   Young's modulus, or the larger of E1 and E2 */
static double modulus(const Problem_material *m)
{
  return m->kind == MATERIAL_ISOTROPIC ? m->young : fmax(m->E1, m->E2);
}

/* refuse the load x = the value converted last, times `times`, unless
   it is 0 or in the window times the body's modulus; what names it in the
   message */
static int check_load(Scene_loader *L, const Scene *s, double x, double times,
                      const char *what)
{
  double E = modulus(&s->problem.material);
  char r[STATUS_NUMBER];
  if (x == 0 || in_window(x * times, E)) return 0;
  return scene_blame(L, "%s / E = %s: a load must be 0 or lie within [1e-30, "
                     "1e30] times E, where every product the solvers form is "
                     "finite", what, outside(fabs(x) * times / E, r));
}
#line 1887 "paper/scene.nw"
static int read_contact(Scene_loader *L, Scene *s);
#line 1981 "paper/scene.nw"
/* [part] geometry: a readable file, kept by its absolute path; "": none */
static int read_part(Scene_loader *L, Scene *s)
{
  char path[sizeof s->problem.part.geometry];
  FILE *f;
  int e;
  if (!scene_entry(L, "part", "geometry")) return L->failed;
  if (!L->last.val[0]) return 0;
  if (scene_resolve(s->path, L->last.val, path, sizeof path))
    return scene_blame(L, "path longer than %d characters", (int)sizeof path - 1);
  errno = 0;
  if ((f = fopen(path, "r"))) {
    (void)getc(f);                  /* a folder opens, and fails to read */
    e = ferror(f) ? errno : 0;
    fclose(f);
  } else e = errno ? errno : EIO;
  if (e) {
    scene_blame(L, "cannot read the geometry file %s: %s", path, strerror(e));
    return scene_for_memory(L, e);
  }
  if (scene_absolute(path, s->problem.part.geometry,
                     sizeof s->problem.part.geometry))
    return scene_blame(L, "cannot make %s an absolute path", path);
  return 0;
}
#line 2014 "paper/scene.nw"
/* with a part: refuse any key of the rectangle in sec */
static int refuse_rectangle(Scene_loader *L, const Scene *s, const char *sec)
{
  int i;
  if (!s->problem.part.geometry[0]) return 0;
  for (i = 0; i < L->n; i++)
    if (strcmp(L->e[i].sec, sec) == 0
        && scene_key_find(L->e[i].sec, L->e[i].key)->rectangle)
      return scene_bad(L, &L->e[i], "has no effect with part.geometry: the "
                       "part above the strip is the geometry's, not the "
                       "rectangle's");
  return 0;
}
#line 2036 "paper/scene.nw"
/* [geometry]: a < b, b - a in the window, gamma (b - a) finite */
static int read_geometry(Scene_loader *L, Scene *s)
{
  char w[STATUS_NUMBER];
  int rc;
  if ((rc = refuse_rectangle(L, s, "geometry"))
      || (rc = scene_get(L, s, "geometry", "a"))
      || (rc = scene_get(L, s, "geometry", "b")))
    return rc;
  if (!(s->problem.b > s->problem.a))
    return scene_blame(L, "must exceed geometry.a = %s",
                       status_number(s->problem.a, w));
  if (!isfinite(s->problem.b - s->problem.a))
    return scene_blame(L, "the width b - a overflows a double");
  if (!in_window(s->problem.b - s->problem.a, 1))
    return scene_blame(L, "the width b - a = %s must lie in [1e-30, 1e30], where "
                       "every product the solvers form is finite",
                       outside(s->problem.b - s->problem.a, w));
  if (s->problem.part.geometry[0]) return 0;   /* gamma: with the mesh */
  if ((rc = scene_get(L, s, "geometry", "gamma"))) return rc;
  if (!isfinite(s->problem.gamma * (s->problem.b - s->problem.a)))
    return scene_blame(L, "the area gamma (b - a) overflows a double");
  return 0;
}
#line 2070 "paper/scene.nw"
/* [design]: N >= 1, C0 > 0, C1 >= 0, C2 > 0 */
static int read_design(Scene_loader *L, Scene *s)
{
  int rc;
  if ((rc = scene_get(L, s, "design", "N"))) return rc;
  if (s->problem.N < 1) return scene_blame(L, "must be >= 1 (design intervals)");
  if ((rc = scene_get(L, s, "design", "C0"))) return rc;
  if (!(s->problem.C0 > 0))
    return scene_blame(L, "must be > 0 (the bound of alpha)");
  if ((rc = scene_get(L, s, "design", "C1"))) return rc;
  if (!(s->problem.C1 >= 0))
    return scene_blame(L, "must be >= 0 (the bound of |alpha'|)");
  if ((rc = scene_get(L, s, "design", "C2"))) return rc;
  if (!(s->problem.C2 > 0))
    return scene_blame(L, "must be > 0 (the area of the body)");
  return 0;
}
#line 2106 "paper/scene.nw"
/* [mesh]: M, R >= 1, refine >= 1, 72 N (M + R) <= INT_MAX after the
   refinement, C0 < C0prime < gamma */
static int read_mesh(Scene_loader *L, Scene *s)
{
  char v[STATUS_NUMBER];
  int rc, k;
  int part = s->problem.part.geometry[0] != '\0';
  if ((rc = refuse_rectangle(L, s, "mesh"))
      || (rc = scene_get(L, s, "mesh", "M")))
    return rc;
  if (s->problem.M < 1)
    return scene_blame(L, "must be >= 1 (moving rows of cells)");
  if (!part && (rc = scene_get(L, s, "mesh", "R"))) return rc;
  if (!part && s->problem.R < 1)
    return scene_blame(L, "must be >= 1 (fixed rows of cells)");
  if ((rc = scene_integer(L, "mesh", "refine", &k))) return rc;
  if (k < 1) return scene_blame(L, "must be >= 1 (the factor of N, M and R)");
  
#line 2153 "paper/scene.nw"
if (!(72.0 * k * s->problem.N * k * ((double)s->problem.M + s->problem.R) <= INT_MAX))
  return scene_bad(L, scene_find(L, "mesh", k > 1 ? "refine" : part ? "M" : "R"),
                   "with design.N = %d, mesh.M = %d, mesh.R = %d and "
                   "mesh.refine = %d the mesh has 2 N (M + R) = %.0f triangles, "
                   "more than INT_MAX / 36 = %d: the stiffness matrix has 36 "
                   "entries a triangle, counted in C ints",
                   s->problem.N, s->problem.M, s->problem.R, k,
                   2.0 * k * s->problem.N * k * ((double)s->problem.M + s->problem.R),
                   INT_MAX / 36);
#line 2124 "paper/scene.nw"
  s->problem.N *= k, s->problem.M *= k, s->problem.R *= k;
  if (part) s->problem.part.refine = k;
  if ((rc = scene_get(L, s, "mesh", "C0prime"))) return rc;
  if (!(s->problem.C0prime > s->problem.C0))
    return scene_blame(L, "must exceed design.C0 = %s: the moving boundary must "
                       "stay below the fixed part of the mesh",
                       status_number(s->problem.C0, v));
  if (part) {
    s->problem.gamma = s->problem.C0prime;
    return 0;
  }
  if (!(s->problem.gamma > s->problem.C0prime))
    return scene_bad(L, scene_find(L, "geometry", "gamma"), "must exceed mesh.C0prime "
                     "= %s: the fixed part of the mesh needs a height",
                     status_number(s->problem.C0prime, v));
  return 0;
}
#line 2186 "paper/scene.nw"
/* B != {} iff 0 <= S <= C0 (b-a), S = gamma (b-a) - C2 */
static int check_admissible(Scene_loader *L, Scene *s)
{
  double w = s->problem.b - s->problem.a, S = s->problem.gamma * w - s->problem.C2;
  double slack = 1e-12 * s->problem.gamma * w;
  char v[2][STATUS_NUMBER];
  if (S >= -slack && S <= s->problem.C0 * w + slack) return 0;
  return scene_bad(L, scene_find(L, "design", "C2"), "C0, C1, C2 admit no shape: the "
                   "area under alpha would be S = %s (b-a) - C2 = %s, outside "
                   "[0, C0 (b-a)] = [0, %s]", s->problem.part.geometry[0]
                   ? "C0prime" : "gamma", status_number(S, v[0]),
                   status_number(s->problem.C0 * w, v[1]));
}
#line 2561 "paper/scene.nw"
/* the modulus E = the value converted last: > 0 and in the window; what
   names it in the message */
static int check_modulus(Scene_loader *L, double E, const char *what)
{
  if (!(E > 0)) return scene_blame(L, "%s must be > 0", what);
  if (!in_window(E, 1))
    return scene_blame(L, "%s must lie in [1e-30, 1e30], where every "
                       "product the solvers form is finite", what);
  return 0;
}

/* the isotropic material m of sec: E > 0 in the window, -1 < nu < 1/2 */
static int read_isotropic(Scene_loader *L, Scene *s, const char *sec,
                          const Problem_material *m)
{
  int rc;
  if ((rc = scene_get(L, s, sec, "E"))
      || (rc = check_modulus(L, m->young, "Young's modulus"))
      || (rc = scene_get(L, s, sec, "nu")))
    return rc;
  if (!(m->nu < 0.5))
    return scene_blame(L, "nu must be < 0.5: 0.5 is the incompressible limit, "
                       "where this displacement method locks");
  if (!(m->nu > -1)) return scene_blame(L, "nu must be > -1 (stability)");
  return 0;
}
#line 2596 "paper/scene.nw"
/* with plane stress: refuse the keys of the third axis in sec */
static int refuse_third_axis(Scene_loader *L, const char *sec)
{
  int i;
  for (i = 0; i < L->n; i++)
    if (strcmp(L->e[i].sec, sec) == 0
        && scene_key_find(L->e[i].sec, L->e[i].key)->strain)
      return scene_bad(L, &L->e[i], "has no effect with material.model = "
                       "plane_stress: the stress across the plane is zero");
  return 0;
}

/* the orthotropic material m of sec: its moduli > 0 in the window */
static int read_orthotropic(Scene_loader *L, Scene *s, const char *sec,
                            const Problem_material *m)
{
  int rc;
  if ((rc = scene_get(L, s, sec, "E1")) || (rc = check_modulus(L, m->E1, "E1"))
      || (rc = scene_get(L, s, sec, "E2")) || (rc = check_modulus(L, m->E2, "E2"))
      || (rc = scene_get(L, s, sec, "nu12"))
      || (rc = scene_get(L, s, sec, "G12"))
      || (rc = check_modulus(L, m->G12, "G12"))
      || (rc = scene_get(L, s, sec, "angle")))
    return rc;
  if (s->problem.model != MODEL_PLANE_STRAIN) return refuse_third_axis(L, sec);
  if ((rc = scene_get(L, s, sec, "E3")) || (rc = check_modulus(L, m->E3, "E3"))
      || (rc = scene_get(L, s, sec, "nu13")) || (rc = scene_get(L, s, sec, "nu23")))
    return rc;
  return 0;
}
#line 2633 "paper/scene.nw"
/* [material] or [material.NAME]: the kind, its keys, the material as a
   whole */
static int read_material_of(Scene_loader *L, Scene *s, const char *sec,
                            Problem_material *m)
{
  Scene_entry kind;
  char buf[256];
  const char *why;
  int rc;
  if ((rc = scene_get(L, s, sec, "kind"))) return rc;
  kind = L->last;
  if ((rc = scene_refuse_unused(L, sec, "kind",
                                scene_material_kind_names[m->kind]))
      || (rc = m->kind == MATERIAL_ISOTROPIC ? read_isotropic(L, s, sec, m)
                                             : read_orthotropic(L, s, sec, m)))
    return rc;
  if ((why = fem_material_refusal(m, s->problem.model, buf, sizeof buf)))
    return scene_bad(L, &kind, "%s", why);
  return 0;
}
#line 2657 "paper/scene.nw"
/* [material]: the plane model, then the material of the body */
static int read_material(Scene_loader *L, Scene *s)
{
  int rc;
  if ((rc = scene_get(L, s, "material", "model"))) return rc;
  return read_material_of(L, s, "material", &s->problem.material);
}
#line 2674 "paper/scene.nw"
/* the loaded interval [from, to] inside the side, and a non-zero P */
static int read_traction(Scene_loader *L, Scene *s, Problem_side_id id)
{
  const char *sec = scene_side_names[id];
  Problem_side *d = &s->problem.side[id];
  char v[2][STATUS_NUMBER];
  int rc;
  
#line 2696 "paper/scene.nw"
double lo = id == SIDE_TOP ? s->problem.a : s->problem.C0prime;
double hi = id == SIDE_TOP ? s->problem.b : s->problem.gamma;
const char *part = id == SIDE_TOP ? "the top side, [a, b]" :
  "the part of the side the design never moves, [C0prime, gamma]";
if ((rc = scene_get(L, s, sec, "from"))) return rc;
if (!(d->from >= lo))
  return scene_blame(L, "the loaded interval must lie in %s = [%s, %s]", part,
                     status_number(lo, v[0]), status_number(hi, v[1]));
if ((rc = scene_get(L, s, sec, "to"))) return rc;
if (!(d->to > d->from))
  return scene_blame(L, "must exceed %s.from = %s", sec,
                     status_number(d->from, v[0]));
if (!(d->to <= hi))
  return scene_blame(L, "the loaded interval must lie in %s = [%s, %s]", part,
                     status_number(lo, v[0]), status_number(hi, v[1]));
#line 2682 "paper/scene.nw"
  if ((rc = scene_get(L, s, sec, "P1"))
      || (rc = check_load(L, s, d->P[0], 1, "|P1|"))
      || (rc = scene_get(L, s, sec, "P2"))
      || (rc = check_load(L, s, d->P[1], 1, "|P2|")))
    return rc;
  if (d->P[0] == 0 && d->P[1] == 0)
    return scene_bad(L, scene_find(L, sec, "bc"), "the traction (%s.P1, %s.P2) is "
                     "zero: use bc = free", sec, sec);
  return 0;
}
#line 2718 "paper/scene.nw"
/* [left], [right] or [top]: the condition, free when not given */
static int read_side(Scene_loader *L, Scene *s, Problem_side_id id)
{
  const char *sec = scene_side_names[id];
  Problem_bc_kind *kind = &s->problem.side[id].kind;
  int rc;
  if ((rc = scene_get(L, s, sec, "bc"))
      || (rc = scene_refuse_unused(L, sec, "bc", problem_bc_names[*kind])))
    return rc;
  if (*kind == BC_TRACTION && s->problem.part.geometry[0])
    return scene_blame(L, "a side of the strip moves with the design over its "
                       "whole height under part.geometry: load a named curve, "
                       "[boundary.NAME]");
  return *kind == BC_TRACTION ? read_traction(L, s, id) : 0;
}
#line 2752 "paper/scene.nw"
/* some side holds u1, or friction can hold the body sideways */
static int check_held(Scene_loader *L, Scene *s)
{
  const Problem *p = &s->problem;
  Friction_hold h = friction_hold(p);
  char sides[256];
  if (friction_side_holds(p, 0)) return 0;
  problem_supports(p, sides, sizeof sides);
  if (p->contact == CONTACT_FRICTIONLESS)
    return scene_fail(L, "%s: %s: no side holds u1: frictionless contact cannot "
                      "stop the body sliding (singular problem)", L->path, sides);
  
#line 2773 "paper/scene.nw"
if (p->contact == CONTACT_COULOMB && friction_side_holds(p, 1))
  return scene_fail(L, "%s: %s: no side holds u1, and the top holds u2: Coulomb "
                    "friction's bound, its coefficient times the normal forces, "
                    "is not known before the solve (their sum is the vertical load "
                    "only when no side holds u2); use contact.model = tresca, or "
                    "hold u1 on a side", L->path, sides);
#line 2764 "paper/scene.nw"
  if (h.capacity > h.load) return 0;
  
#line 2782 "paper/scene.nw"
if (p->contact == CONTACT_COULOMB && h.vertical <= 0)
  return scene_fail(L, "%s: %s: the body is not held: the loads do not press it "
                    "onto the foundation (the load that presses it down is %g N/m), "
                    "and no side holds u2: nothing stops it lifting off", L->path,
                    sides, h.vertical);
if (p->contact == CONTACT_TRESCA)
  return scene_fail(L, "%s: %s: no side holds u1, and friction cannot hold the "
                    "body: contact.g = %g Pa holds at most g (b - a) = %g N/m "
                    "sideways, not more than the horizontal load of %g N/m", L->path, sides,
                    p->slip_bound, h.capacity, h.load);
return scene_fail(L, "%s: %s: no side holds u1, and friction cannot hold the "
                  "body: contact.friction = %g times the vertical load %g N/m "
                  "holds at most %g N/m sideways, not more than the horizontal load "
                  "of %g N/m",
                  L->path, sides, p->friction, h.vertical, h.capacity, h.load);
#line 2766 "paper/scene.nw"
}
#line 2801 "paper/scene.nw"
/* the three sides; with a part, the left and right ones, and no top */
static int read_sides(Scene_loader *L, Scene *s)
{
  int id, rc;
  if ((rc = refuse_rectangle(L, s, "top"))) return rc;
  for (id = 0; id < SIDE_COUNT; id++)
    if ((id != SIDE_TOP || !s->problem.part.geometry[0])
        && (rc = read_side(L, s, (Problem_side_id)id)))
      return rc;
  return 0;
}
#line 2828 "paper/scene.nw"
/* [boundary.NAME]: the condition of the curve c */
static int read_curve(Scene_loader *L, Scene *s, const char *sec,
                      Problem_curve *c)
{
  int rc;
  if ((rc = scene_get(L, s, sec, "bc"))
      || (rc = scene_refuse_unused(L, sec, "bc", problem_bc_names[c->kind])))
    return rc;
  if (c->kind == BC_TRACTION) {
    if ((rc = scene_get(L, s, sec, "P1"))
        || (rc = check_load(L, s, c->P[0], 1, "|P1|"))
        || (rc = scene_get(L, s, sec, "P2"))
        || (rc = check_load(L, s, c->P[1], 1, "|P2|")))
      return rc;
    if (c->P[0] == 0 && c->P[1] == 0)
      return scene_bad(L, scene_find(L, sec, "bc"), "the traction (%s.P1, %s.P2) "
                       "is zero: use bc = free", sec, sec);
  }
  if (c->kind == BC_PRESSURE) {
    if ((rc = scene_get(L, s, sec, "p"))
        || (rc = check_load(L, s, c->pressure, 1, "|p|")))
      return rc;
    if (c->pressure == 0) return scene_blame(L, "a pressure of 0: use bc = free");
  }
  return 0;
}

/* [boundary.NAME] and [material.NAME]: with a part only, each in its slot */
static int read_named(Scene_loader *L, Scene *s)
{
  Problem_part *part = &s->problem.part;
  const char *sec[PROBLEM_NAMED], *name;
  int j, n, rc;
  if (!part->geometry[0]) {
    for (j = 0; j < L->n; j++)
      if (scene_named_kind(L->e[j].sec, NULL) >= 0)
        return scene_bad(L, &L->e[j], "a named section needs part.geometry: "
                         "the rectangle has no named curves or surfaces");
    return 0;
  }
  n = scene_named_list(L, SCENE_BOUNDARY, sec, PROBLEM_NAMED);
  for (j = 0; j < n; j++) {
    scene_named_kind(sec[j], &name);
    snprintf(part->curve[j].name, sizeof part->curve[j].name, "%s", name);
    if ((rc = read_curve(L, s, sec[j], &part->curve[j]))) return rc;
  }
  part->ncurve = n;
  n = scene_named_list(L, SCENE_MATERIAL, sec, PROBLEM_NAMED);
  for (j = 0; j < n; j++) {
    scene_named_kind(sec[j], &name);
    snprintf(part->region[j].name, sizeof part->region[j].name, "%s", name);
    if ((rc = read_material_of(L, s, sec[j], &part->region[j].material)))
      return rc;
  }
  part->nregion = n;
  return 0;
}
#line 2897 "paper/scene.nw"
/* a part: mesh it once; its rollers' components, area and curves' load */
static int check_part(Scene_loader *L, Scene *s)
{
  Problem *p = &s->problem;
  Status st = {0};
  Mesh *m;
  if (!p->part.geometry[0]) return 0;
  if (!(m = mesh_new(p, &st))) {
    scene_fail(L, "%s: part.geometry: %s", L->path, st.msg);
    if (L->st) L->st->code = st.code;
    return L->failed = st.code;
  }
  for (int j = 0; j < p->part.ncurve; j++)
    if (p->part.curve[j].kind == BC_ROLLER)
      p->part.curve[j].normal = mesh_curve_normal(m, j);
  p->part.area = 0;
  for (int t = 2 * m->N * m->M; t < m->ntri; t++) p->part.area += mesh_area(m, t);
  fem_curve_resultant(m, p, p->part.load);
  p->part.nodes = m->nnodes - (m->N + 1) * (m->M + 1);
  mesh_free(m);
  return 0;
}
#line 2936 "paper/scene.nw"
/* [body_force] F, [contact] model; then what holds the body sideways */
static int read_loads(Scene_loader *L, Scene *s)
{
  int rc;
  double w = s->problem.b - s->problem.a;
  if ((rc = scene_get(L, s, "body_force", "F1"))
      || (rc = check_load(L, s, s->problem.body_force[0], w, "|F1| (b - a)"))
      || (rc = scene_get(L, s, "body_force", "F2"))
      || (rc = check_load(L, s, s->problem.body_force[1], w, "|F2| (b - a)")))
    return rc;
  s->problem.has_body_force = s->problem.body_force[0] != 0 || s->problem.body_force[1] != 0;
  if ((rc = read_contact(L, s))) return rc;
  return check_held(L, s);
}
#line 2954 "paper/scene.nw"
/* [contact] model, and g or friction as the law needs */
static int read_contact(Scene_loader *L, Scene *s)
{
  static const char *const law_key[] = {NULL, "g", "friction"};
  Problem *p = &s->problem;
  int k, rc;
  if ((rc = scene_get(L, s, "contact", "model"))
      || (rc = scene_refuse_unused(L, "contact", "model",
                                   problem_contact_names[p->contact])))
    return rc;
  if ((k = p->contact) == CONTACT_FRICTIONLESS) return 0;
  if ((rc = scene_get(L, s, "contact", law_key[k]))) return rc;
  if (!((k == CONTACT_TRESCA ? p->slip_bound : p->friction) >= 0))
    return scene_blame(L, "must be >= 0 (%s)", k == CONTACT_TRESCA ? "a slip bound "
                       "in Pa" : "a friction coefficient");
  if (k == CONTACT_TRESCA) return check_load(L, s, p->slip_bound, 1, "g");
  if (!(p->friction <= WINDOW_MAX))
    return scene_blame(L, "must be <= 1e30: it multiplies a contact force");
  if ((rc = scene_get(L, s, "contact", "max_fixed_point")))
    return rc;
  if (p->max_fixed_point < 1) return scene_blame(L, "must be >= 1");
  return 0;
}
#line 2986 "paper/scene.nw"
/* [solver]: the method, 0 < tol < 1, max_iter >= 1, 0 < omega < 2 */
static int read_solver(Scene_loader *L, Scene *s)
{
  Qp_options *o = &s->solver;
  int rc;
  if ((rc = scene_get(L, s, "solver", "state"))) return rc;
  if (o->method == QP_PSOR && s->problem.contact != CONTACT_FRICTIONLESS)
    return scene_blame(L, "cannot take friction (contact.model = %s): a slip bound "
                       "bounds a force, and psor bounds unknowns; use pdas or cgssor",
                       problem_contact_name(s->problem.contact));
  
#line 3014 "paper/scene.nw"
if (o->method == QP_CGSSOR && s->problem.contact != CONTACT_FRICTIONLESS
    && !(friction_side_holds(&s->problem, 0) && friction_side_holds(&s->problem, 1))) {
  char sides[256];
  problem_supports(&s->problem, sides, sizeof sides);
  return scene_blame(L, "cannot take friction (contact.model = %s) on a body that "
                     "the sides do not hold in both directions (%s): its dual "
                     "needs the stiffness seen from the contact positive "
                     "definite; use pdas", problem_contact_name(s->problem.contact),
                     sides);
}
#line 2997 "paper/scene.nw"
  if ((rc = scene_get(L, s, "solver", "tol"))) return rc;
  if (!(o->tol > 0 && o->tol < 1))
    return scene_blame(L, "must lie in (0, 1): it is a relative residual");
  if ((rc = scene_get(L, s, "solver", "max_iter"))) return rc;
  if (o->max_iter < 1) return scene_blame(L, "must be >= 1");
  if ((rc = scene_get(L, s, "solver", "omega"))) return rc;
  if (!(o->omega > 0 && o->omega < 2))
    return scene_blame(L, "must lie in (0, 2), where SOR converges");
  return 0;
}
#line 3056 "paper/scene.nw"
#define OTHER_OBJECTIVE_MAX_ITER 2000
/* the method of a scene that names none: newton where it applies
   (opt_refusal) */
static Opt_method default_method(const Scene *s)
{
  Status why;
  return opt_refusal(OPT_NEWTON, &s->optimizer.objective, s->problem.contact,
                     s->path, &why) ? OPT_SLSQP : OPT_NEWTON;
}

/* [optimizer]: the method, its metric, 0 < tol < 1, max_iter >= 1,
   levels >= 0, 1 <= starts <= 100 */
static int read_optimizer(Scene_loader *L, Scene *s)
{
  Opt_options *o = &s->optimizer;
  int rc;
  if ((rc = scene_get(L, s, "optimizer", "method"))) return rc;
  if ((s->method_chosen = !scene_find(L, "optimizer", "method")))
    o->method = default_method(s);
  if ((rc = scene_refuse_unused(L, "optimizer", "method",
                                opt_method_names[o->method])))
    return rc;
  o->metric = opt_options_default(o->method).metric;
  if (o->method != OPT_NEWTON && (rc = scene_get(L, s, "optimizer", "metric")))
    return rc;
  if (o->method == OPT_SLSQP && !scene_find(L, "optimizer", "metric")
      && !objective_fits_schur(&o->objective))
    o->metric = OPT_METRIC_EUCLIDEAN;
  if (o->method == OPT_PROJGRAD && o->metric == OPT_METRIC_SCHUR)
    return scene_blame(L, "schur needs optimizer.method = slsqp or mma: "
                       "Algorithm 4.1 projects in the euclidean metric");
  if ((rc = scene_get(L, s, "optimizer", "tol"))) return rc;
  if (!(o->tol > 0 && o->tol < 1))
    return scene_blame(L, "must lie in (0, 1): it is a relative measure");
  if ((rc = scene_get(L, s, "optimizer", "max_iter"))) return rc;
  if (o->max_iter < 1) return scene_blame(L, "must be >= 1");
  if (!scene_find(L, "optimizer", "max_iter")
      && !objective_is_energy(o->objective.kind))
    o->max_iter = OTHER_OBJECTIVE_MAX_ITER;
  if ((rc = scene_get(L, s, "optimizer", "levels"))) return rc;
  if (o->levels < 0) return scene_blame(L, "must be >= 0 (0: chosen by N)");
  if ((rc = scene_get(L, s, "optimizer", "starts"))) return rc;
  if (o->starts < 1 || o->starts > 100)
    return scene_blame(L, "must lie in [1, 100]: 1 runs from the scene's start only");
  return 0;
}
#line 3109 "paper/scene.nw"
/* [objective]: the kind; pressure_peak: 1 <= q <= 1000 */
static int read_objective(Scene_loader *L, Scene *s)
{
  Objective *o = &s->optimizer.objective;
  int rc;
  if ((rc = scene_get(L, s, "objective", "kind"))
      || (rc = scene_refuse_unused(L, "objective", "kind",
                                   objective_names[o->kind])))
    return rc;
  if (!objective_has_exponent(o->kind)) { o->q = objective_default().q; return 0; }
  if ((rc = scene_get(L, s, "objective", "q"))) return rc;
  if (!(o->q >= 1 && o->q <= 1000))
    return scene_blame(L, "must lie in [1, 1000]: a mean of order q of the "
                       "pressure, 1 the mean itself");
  return 0;
}
#line 3138 "paper/scene.nw"
/* the scene = the table, checked */
int scene_convert(Scene_loader *L, Scene *s)
{
  static int (*const step[])(Scene_loader *, Scene *) = {read_part,
    read_geometry, read_design, read_mesh, check_admissible, scene_read_initial,
    read_material, read_sides, read_named, check_part, read_loads, read_solver,
    read_objective, read_optimizer};
  size_t i;
  int rc = 0;
  for (i = 0; !rc && i < sizeof step / sizeof step[0]; i++)
    rc = step[i](L, s);
  return rc;
}
