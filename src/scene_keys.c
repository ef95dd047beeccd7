#line 408 "paper/scene.nw"
#include <stdio.h>
#include <string.h>
#include "scene_private.h"
#line 476 "paper/scene.nw"
const char *const scene_side_names[] = {"left", "right", "top", NULL};
/* the conditions of a side: those of problem_bc_names before pressure */
static const char *const scene_side_bc_names[] = {"free", "clamped",
  "roller", "traction", NULL};
static const char *const state_names[] = {"pdas", "psor", "cgssor", NULL};
const char *const scene_initial_names[] = {"arc", "line", "constant",
  "file", NULL};
/* the kinds of a material, in the order of Problem_material_kind */
const char *const scene_material_kind_names[] = {"isotropic", "orthotropic",
  NULL};
#line 506 "paper/scene.nw"
const Scene_named scene_named[SCENE_NAMED_KINDS] = {
  {"boundary", "boundary.NAME", sizeof(Problem_curve)},
  {"material", "material.NAME", sizeof(Problem_region)},
};

/* the kind of the named section sec, or -1; *name = its NAME */
int scene_named_kind(const char *sec, const char **name)
{
  int i;
  for (i = 0; i < SCENE_NAMED_KINDS; i++) {
    size_t n = strlen(scene_named[i].prefix);
    if (strncmp(sec, scene_named[i].prefix, n) == 0 && sec[n] == '.') {
      if (name) *name = sec + n + 1;
      return i;
    }
  }
  return -1;
}

/* whether name is a NAME: [A-Za-z0-9_]+, at most SCENE_NAME_MAX */
int scene_name_ok(const char *name)
{
  size_t n = strspn(name, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                          "0123456789_");
  return n > 0 && !name[n] && n <= SCENE_NAME_MAX;
}

/* the section of the table that holds the keys of sec: sec, or PREFIX.NAME */
const char *scene_table_section(const char *sec)
{
  int kind = scene_named_kind(sec, NULL);
  return kind < 0 ? sec : scene_named[kind].table;
}
#line 542 "paper/scene.nw"
/* the index of w in the NULL-terminated list names, or -1 */
int scene_name_index(const char *const *names, const char *w)
{
  int i;
  for (i = 0; names[i]; i++)
    if (strcmp(names[i], w) == 0) return i;
  return -1;
}
#line 555 "paper/scene.nw"
/* append s to the string buf of size bytes, cut to fit */
static void cat(char *buf, size_t size, const char *s)
{
  size_t n = strlen(buf), m = strlen(s);
  if (n + 1 >= size) return;
  if (m > size - n - 1) m = size - n - 1;
  memcpy(buf + n, s, m);
  buf[n + m] = '\0';
}

/* buf = the names, comma-separated (cut to size) */
const char *scene_name_list(const char *const *names, char *buf,
                            size_t size)
{
  int i;
  buf[0] = '\0';
  for (i = 0; names[i]; i++) {
    if (i) cat(buf, size, ", ");
    cat(buf, size, names[i]);
  }
  return buf;
}
#line 593 "paper/scene.nw"
/* the default of a key of [solver] under the state solver k */
static const char *solver_default(const char *key, int k, char *buf,
                                  size_t size)
{
  Qp_options d = qp_options_default((Qp_method)k);
  if (strcmp(key, "max_iter") == 0) snprintf(buf, size, "%d", d.max_iter);
  else status_number(strcmp(key, "tol") == 0 ? d.tol : d.omega, buf);
  return buf;
}

/* the default of a key of [optimizer] under the optimiser k */
static const char *optimizer_default(const char *key, int k, char *buf,
                                     size_t size)
{
  Opt_options d = opt_options_default((Opt_method)k);
  if (strcmp(key, "metric") == 0)
    snprintf(buf, size, "%s", opt_metric_name(d.metric));
  else if (strcmp(key, "max_iter") == 0) snprintf(buf, size, "%d", d.max_iter);
  else status_number(d.tol, buf);
  return buf;
}
#line 736 "paper/scene.nw"
#define MATERIAL_KEYS(sec, m)                                               \
  {sec, "kind", KEY_WORD, scene_material_kind_names, AT(m.kind), "-",       \
   "isotropic", .quiet = 1, .meaning = "the kind of the material"},         \
  {sec, "E", KEY_REAL, .at = AT(m.young), .unit = "Pa", .selector = "kind", \
   .when = "isotropic", .accepted = "1e-30 <= E <= 1e30",                   \
   .meaning = "Young's modulus"},                                          \
  {sec, "nu", KEY_REAL, .at = AT(m.nu), .unit = "1", .selector = "kind",    \
   .when = "isotropic", .accepted = "-1 < nu < 0.5",                        \
   .meaning = "Poisson's ratio"},                                          \
  ORTHOTROPIC_KEY(sec, "E1", m.E1, "Pa", "1e-30 <= E1 <= 1e30",             \
                  "Young's modulus along axis 1", 0),                       \
  ORTHOTROPIC_KEY(sec, "E2", m.E2, "Pa", "1e-30 <= E2 <= 1e30",             \
                  "Young's modulus along axis 2", 0),                       \
  ORTHOTROPIC_KEY(sec, "nu12", m.nu12, "1", "nu12^2 < E1 / E2",             \
                  "Poisson's ratio, strain 2 of stress 1", 0),              \
  ORTHOTROPIC_KEY(sec, "G12", m.G12, "Pa", "1e-30 <= G12 <= 1e30",          \
                  "the shear modulus in the plane", 0),                     \
  {sec, "angle", KEY_REAL, .at = AT(m.angle), .unit = "deg", .dflt = "0",   \
   .selector = "kind", .when = "orthotropic", .accepted = "finite",         \
   .meaning = "axis 1 from x1, counter-clockwise"},                         \
  ORTHOTROPIC_KEY(sec, "E3", m.E3, "Pa", "1e-30 <= E3 <= 1e30",             \
                  "Young's modulus across the plane", 1),                   \
  ORTHOTROPIC_KEY(sec, "nu13", m.nu13, "1", "nu13^2 < E1 / E3",             \
                  "Poisson's ratio, strain 3 of stress 1", 1),              \
  ORTHOTROPIC_KEY(sec, "nu23", m.nu23, "1", "nu23^2 < E2 / E3, det > 0",    \
                  "Poisson's ratio, strain 3 of stress 2", 1)
#define ORTHOTROPIC_KEY(sec, key, field, u, acc, what, third)               \
  {sec, key, KEY_REAL, .at = AT(field), .unit = u, .selector = "kind",      \
   .when = "orthotropic", .accepted = acc, .meaning = what,                 \
   .strain = third}
#line 891 "paper/scene.nw"
const Scene_key scene_keys[] = {
  
#line 670 "paper/scene.nw"
{"geometry", "a", KEY_REAL, .at = AT(problem.a), .unit = "m",
 .accepted = "finite", .meaning = "x1 of the left side"},
{"geometry", "b", KEY_REAL, .at = AT(problem.b), .unit = "m",
 .accepted = "a < b, b - a in [1e-30, 1e30]",
 .meaning = "x1 of the right side"},
{"geometry", "gamma", KEY_REAL, .at = AT(problem.gamma), .unit = "m",
 .accepted = "> mesh.C0prime", .rectangle = 1,
 .meaning = "x2 of the top side; not with part.geometry"},
{"design", "N", KEY_INT, .at = AT(problem.N), .unit = "-",
 .accepted = ">= 1", .meaning = "intervals of the design, N + 1 nodes"},
{"design", "C0", KEY_REAL, .at = AT(problem.C0), .unit = "m",
 .accepted = "> 0", .meaning = "bound of alpha in U_ad"},
{"design", "C1", KEY_REAL, .at = AT(problem.C1), .unit = "1",
 .accepted = ">= 0", .meaning = "bound of |alpha'| in U_ad"},
{"design", "C2", KEY_REAL, .at = AT(problem.C2), .unit = "m^2",
 .accepted = "gamma (b - a) - C2 in [0, C0 (b - a)]",
 .meaning = "area of the body in U_ad"},
{"design", "initial", KEY_TEXT, scene_initial_names, AT(initial), "-",
 .meaning = "the kind of the initial shape alpha0"},
{"design", "arc_x1", KEY_REAL, .at = AT(shape.centre[0]), .unit = "m",
 .selector = "initial", .when = "arc", .accepted = "finite",
 .meaning = "x1 of the centre of the arc"},
{"design", "arc_x2", KEY_REAL, .at = AT(shape.centre[1]), .unit = "m",
 .selector = "initial", .when = "arc", .accepted = "finite",
 .meaning = "x2 of the centre of the arc"},
{"design", "arc_radius", KEY_REAL, .at = AT(shape.radius), .unit = "m",
 .selector = "initial", .when = "arc", .accepted = "> 0, reaches every node",
 .meaning = "its radius: alpha0 is the lower half circle"},
{"design", "line_start", KEY_REAL, .at = AT(shape.start), .unit = "m",
 .selector = "initial", .when = "line", .accepted = "in [0, C0prime)",
 .meaning = "alpha0(a) of a straight line"},
{"design", "line_end", KEY_REAL, .at = AT(shape.end), .unit = "m",
 .selector = "initial", .when = "line", .accepted = "in [0, C0prime)",
 .meaning = "alpha0(b) of a straight line"},
{"design", "constant", KEY_REAL, .at = AT(shape.value), .unit = "m",
 .selector = "initial", .when = "constant", .accepted = "in [0, C0prime)",
 .meaning = "alpha0 everywhere"},
{"design", "file", KEY_TEXT, .at = AT(shape_file), .unit = "-",
 .selector = "initial", .when = "file",
 .accepted = "rows x1 alpha from x1 = a to b",
 .meaning = "a shape file, relative to the scene's folder (with -s too)"},
#line 893 "paper/scene.nw"
  
#line 714 "paper/scene.nw"
{"mesh", "M", KEY_INT, .at = AT(problem.M), .unit = "-",
 .accepted = ">= 1", .meaning = "moving rows of cells, alpha to C0prime"},
{"mesh", "R", KEY_INT, .at = AT(problem.R), .unit = "-", .accepted = ">= 1",
 .rectangle = 1,
 .meaning = "fixed rows of cells, C0prime to gamma; not with part.geometry"},
{"mesh", "C0prime", KEY_REAL, .at = AT(problem.C0prime), .unit = "m",
 .accepted = "C0 < C0prime < gamma",
 .meaning = "top of the moving rows of cells"},
{"mesh", "refine", KEY_INT, .at = AT(problem.part.refine), .unit = "-",
 .dflt = "1", .accepted = ">= 1",
 .meaning = "multiplies N, M and R, divides a part's mesh sizes: a finer mesh"},
MATERIAL_KEYS("material", problem.material),
{"material", "model", KEY_WORD, problem_model_names, AT(problem.model),
 "-", "plane_stress", .meaning = "the plane model of the whole body"},
#line 894 "paper/scene.nw"
  
#line 773 "paper/scene.nw"
{"part", "geometry", KEY_TEXT, .at = AT(problem.part.geometry), .unit = "-",
 .dflt = "", .quiet = 1, .accepted = "a gmsh .geo file; empty: none",
 .meaning = "the fixed part Omega' above the strip, from a geometry file "
 "relative to the scene's folder; none: the rectangle"},
{"boundary.NAME", "bc", KEY_WORD, problem_bc_names,
 AT(problem.part.curve[0].kind), "-", "free",
 .meaning = "the condition of the geometry's physical curve NAME"},
{"boundary.NAME", "P1", KEY_REAL, .at = AT(problem.part.curve[0].P[0]),
 .unit = "Pa", .dflt = "0", .selector = "bc", .when = "traction",
 .accepted = "0 or |P1| / E in [1e-30, 1e30]",
 .meaning = "the traction, x1 component; (P1, P2) != 0"},
{"boundary.NAME", "P2", KEY_REAL, .at = AT(problem.part.curve[0].P[1]),
 .unit = "Pa", .dflt = "0", .selector = "bc", .when = "traction",
 .accepted = "0 or |P2| / E in [1e-30, 1e30]",
 .meaning = "the traction, x2 component; (P1, P2) != 0"},
{"boundary.NAME", "p", KEY_REAL, .at = AT(problem.part.curve[0].pressure),
 .unit = "Pa", .selector = "bc", .when = "pressure",
 .accepted = "!= 0, |p| / E in [1e-30, 1e30]",
 .meaning = "the pressure, > 0 pushing into the body"},
MATERIAL_KEYS("material.NAME", problem.part.region[0].material),
#line 895 "paper/scene.nw"
  
#line 799 "paper/scene.nw"
#define SIDE_KEYS(sec, i, lo, hi, what, rect)                              \
  {sec, "bc", KEY_WORD, scene_side_bc_names, AT(problem.side[i].kind), "-",\
   "free", .rectangle = rect, .meaning = "the condition of the " what},    \
  {sec, "from", KEY_REAL, .at = AT(problem.side[i].from), .unit = "m",     \
   .selector = "bc", .when = "traction", .accepted = lo,                   \
   .rectangle = rect, .meaning = "start of the loaded interval"},          \
  {sec, "to", KEY_REAL, .at = AT(problem.side[i].to), .unit = "m",         \
   .selector = "bc", .when = "traction", .accepted = hi,                   \
   .rectangle = rect, .meaning = "end of the loaded interval"},            \
  {sec, "P1", KEY_REAL, .at = AT(problem.side[i].P[0]), .unit = "Pa",      \
   .dflt = "0", .selector = "bc", .when = "traction",                      \
   .accepted = "0 or |P1| / E in [1e-30, 1e30]", .rectangle = rect,        \
   .meaning = "the traction, x1 component; (P1, P2) != 0"},                \
  {sec, "P2", KEY_REAL, .at = AT(problem.side[i].P[1]), .unit = "Pa",      \
   .dflt = "0", .selector = "bc", .when = "traction",                      \
   .accepted = "0 or |P2| / E in [1e-30, 1e30]", .rectangle = rect,        \
   .meaning = "the traction, x2 component; (P1, P2) != 0"}
SIDE_KEYS("left", SIDE_LEFT, "C0prime <= from < to", "from < to <= gamma",
          "left side, x1 = a", 0),
SIDE_KEYS("right", SIDE_RIGHT, "C0prime <= from < to", "from < to <= gamma",
          "right side, x1 = b", 0),
SIDE_KEYS("top", SIDE_TOP, "a <= from < to", "from < to <= b",
          "top side, x2 = gamma; not with part.geometry", 1),
#line 896 "paper/scene.nw"
  
#line 826 "paper/scene.nw"
{"body_force", "F1", KEY_REAL, .at = AT(problem.body_force[0]), .unit = "N/m^3",
 .dflt = "0", .accepted = "0 or |F1| (b - a) / E in [1e-30, 1e30]",
 .meaning = "the body force, x1 component"},
{"body_force", "F2", KEY_REAL, .at = AT(problem.body_force[1]), .unit = "N/m^3",
 .dflt = "0", .accepted = "0 or |F2| (b - a) / E in [1e-30, 1e30]",
 .meaning = "the body force, x2 component"},
{"contact", "model", KEY_WORD, problem_contact_names, AT(problem.contact),
 "-", "frictionless", .meaning = "the contact law"},
{"contact", "g", KEY_REAL, .at = AT(problem.slip_bound), .unit = "Pa",
 .selector = "model", .when = "tresca",
 .accepted = "0 or g / E in [1e-30, 1e30]",
 .meaning = "slip bound of given friction"},
{"contact", "friction", KEY_REAL, .at = AT(problem.friction), .unit = "1",
 .selector = "model", .when = "coulomb", .accepted = "0 <= friction <= 1e30",
 .meaning = "Coulomb's coefficient of friction"},
{"contact", "max_fixed_point", KEY_INT, .at = AT(problem.max_fixed_point),
 .unit = "-", .dflt = "200", .selector = "model", .when = "coulomb",
 .accepted = ">= 1", .meaning = "round limit of Coulomb's fixed point"},
#line 897 "paper/scene.nw"
  
#line 847 "paper/scene.nw"
{"solver", "state", KEY_WORD, state_names, AT(solver.method), "-", "pdas",
 .meaning = "the method of the state problem (4.3)"},
{"solver", "tol", KEY_REAL, .at = AT(solver.tol), .unit = "1",
 .by = solver_default, .selector = "state", .accepted = "0 < tol < 1",
 .meaning = "the relative KKT residual to reach"},
{"solver", "max_iter", KEY_INT, .at = AT(solver.max_iter), .unit = "-",
 .by = solver_default, .selector = "state", .accepted = ">= 1",
 .meaning = "iteration limit of the state solver"},
{"solver", "omega", KEY_REAL, .at = AT(solver.omega), .unit = "1",
 .by = solver_default, .selector = "state", .accepted = "0 < omega < 2",
 .meaning = "relaxation of psor and cgssor"},
{"optimizer", "method", KEY_WORD, opt_method_names, AT(optimizer.method),
 "-", "newton", .meaning = "the optimiser; projgrad is Algorithm 4.1; not given: "
 "newton for the energy without Coulomb friction, slsqp otherwise"},
{"optimizer", "metric", KEY_WORD, opt_metric_names, AT(optimizer.metric),
 "-", .by = optimizer_default, .selector = "method",
 .when = "slsqp projgrad mma",
 .meaning = "the metric; projgrad takes euclidean, slsqp euclidean for the pressure objectives"},
{"optimizer", "tol", KEY_REAL, .at = AT(optimizer.tol), .unit = "1",
 .by = optimizer_default, .selector = "method", .accepted = "0 < tol < 1",
 .meaning = "the projected-gradient norm to reach"},
{"optimizer", "max_iter", KEY_INT, .at = AT(optimizer.max_iter),
 .unit = "-", .by = optimizer_default, .selector = "method",
 .accepted = ">= 1", .meaning = "iteration limit of the optimiser; 2000 unless "
 "given for the objectives other than the energy"},
{"optimizer", "levels", KEY_INT, .at = AT(optimizer.levels), .unit = "-",
 .dflt = "0", .accepted = ">= 0",
 .meaning = "meshes of the coarse-to-fine start: 1 none, 0 by N"},
{"optimizer", "starts", KEY_INT, .at = AT(optimizer.starts), .unit = "-",
 .dflt = "1", .accepted = "1 <= starts <= 100",
 .meaning = "starts: the scene's and starts - 1 waves in B; the best kept"},
#line 898 "paper/scene.nw"
  
#line 882 "paper/scene.nw"
{"objective", "kind", KEY_WORD, objective_names, AT(optimizer.objective.kind),
 "-", "energy", .meaning = "what the design minimises"},
{"objective", "q", KEY_REAL, .at = AT(optimizer.objective.q), .unit = "1",
 .dflt = "8", .selector = "kind", .when = "pressure_peak",
 .accepted = "1 <= q <= 1000", .meaning = "the exponent of pressure_peak"},
#line 899 "paper/scene.nw"
};
_Static_assert(sizeof scene_keys / sizeof scene_keys[0] == SCENE_NKEYS,
               "SCENE_NKEYS counts the records of the table");
#line 910 "paper/scene.nw"
/* the record of sec.key, or NULL */
const Scene_key *scene_key_find(const char *sec, const char *key)
{
  int i;
  sec = scene_table_section(sec);
  for (i = 0; i < SCENE_NKEYS; i++)
    if (strcmp(scene_keys[i].sec, sec) == 0 && strcmp(scene_keys[i].key, key) == 0)
      return &scene_keys[i];
  return NULL;
}

/* whether sec is a section of the table */
int scene_section_known(const char *sec)
{
  int i;
  sec = scene_table_section(sec);
  for (i = 0; i < SCENE_NKEYS; i++)
    if (strcmp(scene_keys[i].sec, sec) == 0) return 1;
  return 0;
}
#line 936 "paper/scene.nw"
/* buf = the sections (sec NULL) or the keys of sec, comma-separated */
const char *scene_key_names(const char *sec, char *buf, size_t size)
{
  int i;
  buf[0] = '\0';
  if (sec) sec = scene_table_section(sec);
  for (i = 0; i < SCENE_NKEYS; i++) {
    const char *name = sec ? scene_keys[i].key : scene_keys[i].sec;
    if (sec ? strcmp(scene_keys[i].sec, sec) != 0
            : i > 0 && strcmp(scene_keys[i].sec, scene_keys[i - 1].sec) == 0)
      continue;
    if (buf[0]) cat(buf, size, ", ");
    cat(buf, size, name);
  }
  return buf;
}
#line 956 "paper/scene.nw"
/* whether k means something when its selector has the word w */
int scene_key_means(const Scene_key *k, const char *w)
{
  size_t n = strlen(w);
  const char *p;
  if (!k->when) return 1;
  if (!n) return 0;
  for (p = k->when; (p = strstr(p, w)); p += n)
    if ((p == k->when || p[-1] == ' ') && (p[n] == ' ' || !p[n])) return 1;
  return 0;
}
#line 3205 "paper/scene.nw"
/* buf = the default of k as printed: its own, "required", or one for each
   word of its selector, "V (w, w), V (w)", or "V" if the same for all */
static const char *default_text(const Scene_key *k, char *buf, size_t size)
{
  const char *const *w;
  char v[8][32];
  int i, j, n, distinct = 0;
  if (!k->by) return !k->dflt ? "required" : *k->dflt ? k->dflt : "(empty)";
  w = scene_key_find(k->sec, k->selector)->words;
  for (n = 0; w[n] && n < 8; n++)
    if (scene_key_means(k, w[n])) k->by(k->key, n, v[n], sizeof v[n]);
    else v[n][0] = '\0';
  buf[0] = '\0';
  for (i = 0; i < n; i++) {
    for (j = 0; j < i && strcmp(v[j], v[i]) != 0; j++) continue;
    if (!v[i][0] || j < i) continue;          /* none, or told already */
    if (distinct++) cat(buf, size, ", ");
    cat(buf, size, v[i]);
    for (j = i; j < n; j++)
      if (strcmp(v[j], v[i]) == 0) {
        cat(buf, size, j == i ? " (" : ", ");
        cat(buf, size, w[j]);
      }
    cat(buf, size, ")");
  }
  if (distinct == 1) *strchr(buf, ' ') = '\0';  /* one value for all */
  return buf;
}
#line 3239 "paper/scene.nw"
/* buf = the values k accepts, as printed */
static const char *accepted_text(const Scene_key *k, char *buf, size_t size)
{
  if (k->accepted) return k->accepted;
  return scene_name_list(k->words, buf, size);
}

/* buf = the meaning of k, and the words of its selector it needs */
static const char *meaning_text(const Scene_key *k, char *buf, size_t size)
{
  const char *p;
  snprintf(buf, size, "%s", k->meaning);
  if (!k->when) return buf;
  cat(buf, size, " (with ");
  cat(buf, size, k->selector);
  cat(buf, size, " = ");
  for (p = k->when; *p; p++) {
    char c[2] = {*p, '\0'};
    cat(buf, size, *p == ' ' ? ", " : c);
  }
  if (k->strain) cat(buf, size, ", material.model = plane_strain");
  cat(buf, size, ")");
  return buf;
}
#line 3268 "paper/scene.nw"
/* write s to f as LaTeX text */
static void latex(FILE *f, const char *s)
{
  for (; *s; s++)
    if (s[0] == '<' && s[1] == '=') fputs("$\\le$", f), s++;
    else if (s[0] == '>' && s[1] == '=') fputs("$\\ge$", f), s++;
    else if (s[0] == '!' && s[1] == '=') fputs("$\\ne$", f), s++;
    else if (s[0] == '^' && s[1]) fprintf(f, "\\textsuperscript{%c}", *++s);
    else if (strchr("<>|", *s)) fprintf(f, "$%c$", *s);
    else if (strchr("_%&#${}", *s)) fprintf(f, "\\%c", *s);
    else fputc(*s, f);
}
#line 3286 "paper/scene.nw"
void scene_keys_print(FILE *f, int latex_table)
{
  char name[40], d[128], a[128], m[256];
  int i;
  if (latex_table)
    fputs("% the keys of a scene: written by contactopt keys --latex\n"
          "{\\footnotesize\\setlength{\\tabcolsep}{3pt}\n"
          "\\begin{longtable}{@{}llp{2.1cm}p{3.6cm}p{5.3cm}@{}}\n\\toprule\n"
          "key & unit & default & accepted & meaning\\tabularnewline\n"
          "\\midrule\\endhead\n\\bottomrule\\endfoot\n", f);
  else
    fprintf(f, "%-20s  %-5s  %-12s  %-31s  %s\n", "section.key", "unit",
            "default", "accepted", "meaning");
  for (i = 0; i < SCENE_NKEYS; i++) {
    snprintf(name, sizeof name, "%s.%s", scene_keys[i].sec, scene_keys[i].key);
    if (!latex_table) {
      fprintf(f, "%-20s  %-5s  %-12s  %-31s  %s\n", name, scene_keys[i].unit,
              default_text(&scene_keys[i], d, sizeof d),
              accepted_text(&scene_keys[i], a, sizeof a),
              meaning_text(&scene_keys[i], m, sizeof m));
      continue;
    }
    
#line 3315 "paper/scene.nw"
fputs("\\texttt{", f), latex(f, name), fputs("} & ", f);
latex(f, scene_keys[i].unit), fputs(" & \\raggedright ", f);
latex(f, default_text(&scene_keys[i], d, sizeof d));
fputs(" & \\raggedright ", f), latex(f, accepted_text(&scene_keys[i], a, sizeof a));
fputs(" & \\raggedright ", f), latex(f, meaning_text(&scene_keys[i], m, sizeof m));
fputs("\\tabularnewline\n", f);
#line 3309 "paper/scene.nw"
  }
  if (latex_table) fputs("\\end{longtable}}\n", f);
}
