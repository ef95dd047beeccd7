#line 152 "paper/part.nw"
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "part.h"
#line 166 "paper/part.nw"
typedef void Gmsh_free(void *p);
typedef void Gmsh_initialize(int argc, char **argv, const int readConfigFiles, int *ierr);
typedef void Gmsh_finalize(int *ierr);
typedef void Gmsh_open(const char *fileName, int *ierr);
typedef void Gmsh_option_set_number(const char *name, const double value, int *ierr);
typedef void Gmsh_logger_start(int *ierr);
typedef void Gmsh_logger_get_last_error(char **error, int *ierr);
typedef void Gmsh_logger_get(char ***log, size_t *log_n, int *ierr);
typedef void Gmsh_logger_stop(int *ierr);
typedef void Gmsh_get_entities(int **dimTags, size_t *dimTags_n, const int dim, int *ierr);
typedef void Gmsh_get_value(const int dim, const int tag, double *parametricCoord,
  size_t parametricCoord_n, double **coord, size_t *coord_n, int *ierr);
typedef void Gmsh_get_parametrization_bounds(const int dim, const int tag,
  double **min, size_t *min_n, double **max, size_t *max_n, int *ierr);
typedef void Gmsh_get_adjacencies(const int dim, const int tag, int **upward,
  size_t *upward_n, int **downward, size_t *downward_n, int *ierr);
typedef void Gmsh_get_physical_groups(int **dimTags, size_t *dimTags_n, const int dim, int *ierr);
typedef void Gmsh_get_entities_for_physical_group(const int dim, const int tag,
  int **tags, size_t *tags_n, int *ierr);
typedef void Gmsh_get_physical_name(const int dim, const int tag, char **name, int *ierr);
typedef void Gmsh_set_transfinite_curve(const int tag, const int numNodes,
  const char *meshType, const double coef, int *ierr);
typedef void Gmsh_generate(const int dim, int *ierr);
typedef void Gmsh_get_nodes(size_t **nodeTags, size_t *nodeTags_n, double **coord,
  size_t *coord_n, double **parametricCoord, size_t *parametricCoord_n,
  const int dim, const int tag, const int includeBoundary,
  const int returnParametricCoord, int *ierr);
typedef void Gmsh_get_elements(int **elementTypes, size_t *elementTypes_n,
  size_t ***elementTags, size_t **elementTags_n, size_t *elementTags_nn,
  size_t ***nodeTags, size_t **nodeTags_n, size_t *nodeTags_nn,
  const int dim, const int tag, int *ierr);

typedef struct {
  Gmsh_free *free;
  Gmsh_initialize *initialize;
  Gmsh_finalize *finalize;
  Gmsh_open *open;
  Gmsh_option_set_number *option_set_number;
  Gmsh_logger_start *logger_start;
  Gmsh_logger_get_last_error *logger_get_last_error;
  Gmsh_logger_get *logger_get;
  Gmsh_logger_stop *logger_stop;
  Gmsh_get_entities *get_entities;
  Gmsh_get_value *get_value;
  Gmsh_get_parametrization_bounds *get_parametrization_bounds;
  Gmsh_get_adjacencies *get_adjacencies;
  Gmsh_get_physical_groups *get_physical_groups;
  Gmsh_get_entities_for_physical_group *get_entities_for_physical_group;
  Gmsh_get_physical_name *get_physical_name;
  Gmsh_set_transfinite_curve *set_transfinite_curve;
  Gmsh_generate *generate;
  Gmsh_get_nodes *get_nodes;
  Gmsh_get_elements *get_elements;
} Part_gmsh;

static const struct { const char *name; size_t at; } part_gmsh_symbols[] = {
  {"gmshFree", offsetof(Part_gmsh, free)},
  {"gmshInitialize", offsetof(Part_gmsh, initialize)},
  {"gmshFinalize", offsetof(Part_gmsh, finalize)},
  {"gmshOpen", offsetof(Part_gmsh, open)},
  {"gmshOptionSetNumber", offsetof(Part_gmsh, option_set_number)},
  {"gmshLoggerStart", offsetof(Part_gmsh, logger_start)},
  {"gmshLoggerGetLastError", offsetof(Part_gmsh, logger_get_last_error)},
  {"gmshLoggerGet", offsetof(Part_gmsh, logger_get)},
  {"gmshLoggerStop", offsetof(Part_gmsh, logger_stop)},
  {"gmshModelGetEntities", offsetof(Part_gmsh, get_entities)},
  {"gmshModelGetValue", offsetof(Part_gmsh, get_value)},
  {"gmshModelGetParametrizationBounds", offsetof(Part_gmsh, get_parametrization_bounds)},
  {"gmshModelGetAdjacencies", offsetof(Part_gmsh, get_adjacencies)},
  {"gmshModelGetPhysicalGroups", offsetof(Part_gmsh, get_physical_groups)},
  {"gmshModelGetEntitiesForPhysicalGroup", offsetof(Part_gmsh, get_entities_for_physical_group)},
  {"gmshModelGetPhysicalName", offsetof(Part_gmsh, get_physical_name)},
  {"gmshModelMeshSetTransfiniteCurve", offsetof(Part_gmsh, set_transfinite_curve)},
  {"gmshModelMeshGenerate", offsetof(Part_gmsh, generate)},
  {"gmshModelMeshGetNodes", offsetof(Part_gmsh, get_nodes)},
  {"gmshModelMeshGetElements", offsetof(Part_gmsh, get_elements)},
};
#line 290 "paper/part.nw"
typedef struct { int tag, group; } Part_member;  /* entity tag -> group index */
typedef struct { int tag, lo, hi; } Part_join;   /* a joining curve, x_lo..x_hi */
#line 911 "paper/part.nw"
typedef struct {
  size_t maxtag;
  long *index;      /* maxtag+1: a tag's node, -1 while unused */
  long *where;      /* maxtag+1: the tag's place in gmsh's list, -1 if none */
  double *coord;    /* gmsh's coordinates, 3 a node */
} Part_nodes;
#line 293 "paper/part.nw"
typedef struct {
  const Part_gmsh *g;
  const Problem *p;
  const char *path;
  Status *st;
  double h, tol_y, tol_x;      /* (b-a)/N, 1e-9 (b-a), 1e-9 h */
  Part_member *curve_of, *surface_of;  /* entities of the physical groups */
  int ncurve_of, nsurface_of;
  char names[2 * PROBLEM_NAMED][PROBLEM_NAME]; /* curves', then surfaces' */
  int ncurve, nsurface;
  Part_join *join;
  int njoin;
  Part_nodes nodes;
  Part_mesh *pm;
} Part_build;
#line 1201 "paper/part.nw"
typedef struct {
  double x0, y0, c;
  int nx, ny;
  int *first, *list;     /* nx*ny + 1; the triangles, cell by cell */
} Part_grid;
#line 1357 "paper/part.nw"
typedef struct { int lo, hi, from, to, t; } Part_edge;
#line 254 "paper/part.nw"
#define PART_GMSH_LIBRARY "libgmsh.so.4.8"

static const Part_gmsh *part_gmsh_load(const char *path, Status *st)
{
  static Part_gmsh api;
  static int loaded;
  if (loaded) return &api;
  void *lib = dlopen(PART_GMSH_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  const char *why = lib ? NULL : dlerror(), *gone = "";
  for (size_t k = 0; lib && k < sizeof part_gmsh_symbols / sizeof *part_gmsh_symbols; k++) {
    void *f = dlsym(lib, part_gmsh_symbols[k].name);
    if (!f) { why = part_gmsh_symbols[k].name; gone = " missing"; dlclose(lib); lib = NULL; break; }
    memcpy((char *) &api + part_gmsh_symbols[k].at, &f, sizeof f);
  }
  int memory = why && (strstr(why, "failed to map segment") || strstr(why, "allocate memory"));
  if (!lib && memory)
    status_set(st, STATUS_MEMORY, "%s: cannot load gmsh's library %s (%s): the memory "
               "this process may use is too small for it", path, PART_GMSH_LIBRARY, why);
  else if (!lib)
    status_set(st, STATUS_SYSTEM, "%s: cannot load gmsh's library %s (%s%s): "
      "install Debian's libgmsh-dev", path, PART_GMSH_LIBRARY,
      why ? why : "not found", gone);
  if (!lib) return NULL;
  loaded = 1;
  return &api;
}
#line 315 "paper/part.nw"
static int part_gmsh_error(Part_build *b, Status_code code, const char *what)
{
  char *err = NULL;
  int ierr = 0;
  b->g->logger_get_last_error(&err, &ierr);
  if (err)
    for (char *c = err; *c; c++) if (*c == '\n' || *c == '\r') *c = ' ';
  status_set(b->st, code, "%s: %s%s%s", b->path, what,
             err && *err ? ": " : "", err && *err ? err : "");
  if (err) b->g->free(err);
  return code;
}

static int part_memory(Part_build *b)
{
  return status_set(b->st, STATUS_MEMORY, "%s: out of memory for its mesh", b->path);
}
#line 343 "paper/part.nw"
static void part_nodes_free(const Part_gmsh *g, Part_nodes *nd)
{
  free(nd->index); free(nd->where);
  if (nd->coord) g->free(nd->coord);
  *nd = (Part_nodes){ 0, NULL, NULL, NULL };
}

#line 533 "paper/part.nw"
static int part_count_errors(Part_build *b, char *last, size_t size)
{
  char **log = NULL;
  size_t n = 0;
  int ierr = 0, count = 0;
  b->g->logger_get(&log, &n, &ierr);
  for (size_t k = 0; k < n; k++) {
    if (!ierr && !strncmp(log[k], "Error", 5)) {
      const char *m = log[k] + 5;
      while (*m == ' ' || *m == ':') m++;    /* "Error: what", or "Error   : what" */
      count++;
      snprintf(last, size, "%s", m);
    }
    b->g->free(log[k]);
  }
  if (log) b->g->free(log);
  return count;
}

static int part_generate(Part_build *b)
{
  char last[512] = "";
  int ierr = 0, before = part_count_errors(b, last, sizeof last);
  b->g->option_set_number("General.AbortOnError", 0, &ierr);
  if (!ierr) b->g->generate(2, &ierr);
  if (ierr || part_count_errors(b, last, sizeof last) > before) {
    for (char *c = last; *c; c++) if (*c == '\n' || *c == '\r') *c = ' ';
    return status_set(b->st, STATUS_INPUT, "%s: gmsh cannot mesh it: %s",
                      b->path, *last ? last : "no message");
  }
  return STATUS_OK;
}
#line 575 "paper/part.nw"
static int part_check_points(Part_build *b)
{
  const Part_gmsh *g = b->g;
  int *dt = NULL, ierr = 0, code = STATUS_OK;
  size_t n = 0;
  g->get_entities(&dt, &n, 2, &ierr);
  if (dt) g->free(dt);
  if (ierr) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh lists no surfaces");
  if (n == 0)
    return status_set(b->st, STATUS_INPUT, "%s: the geometry has no surface "
      "(Plane Surface, Surface, Rectangle, ...) to mesh", b->path);
  dt = NULL;
  g->get_entities(&dt, &n, 0, &ierr);
  n /= 2;
  for (size_t k = 0; !code && !ierr && k < n; k++) {
    double *xyz = NULL;
    size_t nxyz = 0;
    g->get_value(0, dt[2 * k + 1], NULL, 0, &xyz, &nxyz, &ierr);
    if (!ierr && nxyz >= 3 && xyz[1] < b->p->C0prime - b->tol_y) {
      char x[STATUS_NUMBER], y[STATUS_NUMBER], c[STATUS_NUMBER];
      code = status_set(b->st, STATUS_INPUT, "%s: point %d at (%s, %s) lies "
        "below x2 = C0prime = %s, in the strip", b->path, dt[2 * k + 1],
        status_number(xyz[0], x), status_number(xyz[1], y),
        status_number(b->p->C0prime, c));
    }
    if (xyz) g->free(xyz);
  }
  if (dt) g->free(dt);
  if (ierr && !code) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot read its points");
  return code;
}
#line 619 "paper/part.nw"
static int part_check_name(Part_build *b, const char *kind, int tag, const char *name)
{
  size_t len = strlen(name);
  if (len == 0)
    return status_set(b->st, STATUS_INPUT, "%s: physical %s %d has no name: "
      "name it (Physical %s(\"name\") = {...})", b->path, kind, tag,
      kind[0] == 'c' ? "Curve" : "Surface");
  if (len >= PROBLEM_NAME)
    return status_set(b->st, STATUS_INPUT, "%s: the name of physical %s %d, "
      "\"%.*s...\", is longer than %d characters", b->path, kind, tag, 16, name,
      PROBLEM_NAME - 1);
  if (strspn(name, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                   "0123456789_") != len)
    return status_set(b->st, STATUS_INPUT, "%s: physical %s \"%s\" has a "
      "character other than A-Z, a-z, 0-9 and _ in its name", b->path, kind, name);
  return STATUS_OK;
}
#line 640 "paper/part.nw"
static int part_add_members(Part_build *b, int dim, int tag, int group,
                            char (*names)[PROBLEM_NAME], Part_member **list, int *n)
{
  const Part_gmsh *g = b->g;
  int *tags = NULL, ierr = 0, code = STATUS_OK;
  size_t nt = 0;
  g->get_entities_for_physical_group(dim, tag, &tags, &nt, &ierr);
  Part_member *grown = ierr ? NULL : realloc(*list, (*n + nt + 1) * sizeof **list);
  if (grown) *list = grown;
  for (size_t k = 0; grown && !code && k < nt; k++) {
    for (int m = 0; m < *n; m++)
      if ((*list)[m].tag == tags[k])
        code = status_set(b->st, STATUS_INPUT, "%s: %s %d is in two physical "
          "%ss, \"%s\" and \"%s\"", b->path, dim == 1 ? "curve" : "surface",
          tags[k], dim == 1 ? "curve" : "surface", names[(*list)[m].group], names[group]);
    (*list)[(*n)++] = (Part_member){ tags[k], group };
  }
  if (tags) g->free(tags);
  if (ierr) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot list a physical group");
  return grown ? code : part_memory(b);
}
#line 667 "paper/part.nw"
static int part_read_dim(Part_build *b, int dim, char (*names)[PROBLEM_NAME], int *count)
{
  const Part_gmsh *g = b->g;
  const char *kind = dim == 1 ? "curve" : "surface";
  int *dt = NULL, ierr = 0, code = STATUS_OK;
  size_t n = 0;
  g->get_physical_groups(&dt, &n, dim, &ierr);
  n /= 2;
  if (!ierr && n > PROBLEM_NAMED)
    code = status_set(b->st, STATUS_INPUT, "%s: %zu physical %ss, more than "
      "the %d a scene can name", b->path, n, kind, PROBLEM_NAMED);
  for (size_t k = 0; !ierr && !code && k < n; k++) {
    char *name = NULL;
    int tag = dt[2 * k + 1];
    g->get_physical_name(dim, tag, &name, &ierr);
    if (!ierr && !(code = part_check_name(b, kind, tag, name ? name : ""))) {
      snprintf(names[*count], PROBLEM_NAME, "%s", name);
      (*count)++;
      code = part_add_members(b, dim, tag, (int) k, names,
                              dim == 1 ? &b->curve_of : &b->surface_of,
                              dim == 1 ? &b->ncurve_of : &b->nsurface_of);
    }
    if (name) g->free(name);
  }
  if (dt) g->free(dt);
  if (ierr && !code)
    return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot list its physical groups");
  return code;
}
#line 700 "paper/part.nw"
static int part_read_groups(Part_build *b)
{
  int code, n;
  if ((code = part_read_dim(b, 1, b->names, &b->ncurve))
      || (code = part_read_dim(b, 2, b->names + b->ncurve, &b->nsurface)))
    return code;
  n = b->ncurve + b->nsurface;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < i; j++)
      if (!strcmp(b->names[i], b->names[j]))
        return status_set(b->st, STATUS_INPUT, "%s: two physical groups are "
          "named \"%s\": a name may name one", b->path, b->names[i]);
  return STATUS_OK;
}

static int part_copy_names(Part_build *b)
{
  Part_mesh *pm = b->pm;
  pm->ncurve = b->ncurve;
  pm->nsurface = b->nsurface;
  pm->curve_name = calloc(b->ncurve + 1, sizeof *pm->curve_name);
  pm->surface_name = calloc(b->nsurface + 1, sizeof *pm->surface_name);
  if (!pm->curve_name || !pm->surface_name) return part_memory(b);
  memcpy(pm->curve_name, b->names, b->ncurve * sizeof *pm->curve_name);
  memcpy(pm->surface_name, b->names + b->ncurve, b->nsurface * sizeof *pm->surface_name);
  return STATUS_OK;
}
#line 730 "paper/part.nw"
static int part_group_of(const Part_member *list, int n, int tag)
{
  for (int m = 0; m < n; m++)
    if (list[m].tag == tag) return list[m].group;
  return -1;
}
#line 746 "paper/part.nw"
static int part_on_joining_line(Part_build *b, int tag, double x[2], int *on)
{
  const Part_gmsh *g = b->g;
  double *lo = NULL, *hi = NULL, *xyz = NULL, u[9];
  size_t nlo = 0, nhi = 0, nxyz = 0;
  int ierr = 0;
  *on = 0;
  g->get_parametrization_bounds(1, tag, &lo, &nlo, &hi, &nhi, &ierr);
  if (!ierr && nlo == 1 && nhi == 1) {
    for (int k = 0; k < 9; k++) u[k] = lo[0] + (hi[0] - lo[0]) * k / 8;
    g->get_value(1, tag, u, 9, &xyz, &nxyz, &ierr);
  }
  if (!ierr && nxyz == 27) {
    *on = 1;
    for (int k = 0; k < 9; k++)
      *on &= fabs(xyz[3 * k + 1] - b->p->C0prime) <= b->tol_y;
    x[0] = xyz[0];
    x[1] = xyz[24];
  }
  if (lo) g->free(lo);
  if (hi) g->free(hi);
  if (xyz) g->free(xyz);
  return ierr ? part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot evaluate a curve") : STATUS_OK;
}
#line 774 "paper/part.nw"
static int part_grid_index(Part_build *b, int tag, double x, int *i)
{
  const Problem *p = b->p;
  char s[4][STATUS_NUMBER];
  if (x < p->a - b->tol_x || x > p->b + b->tol_x)
    return status_set(b->st, STATUS_INPUT, "%s: curve %d runs along x2 = "
      "C0prime = %s past x1 = %s: split it by a point at x1 = %s", b->path,
      tag, status_number(p->C0prime, s[0]), status_number(x, s[1]),
      status_number(x < p->a ? p->a : p->b, s[2]));
  *i = (int) lround((x - p->a) / b->h);
  if (*i < 0) *i = 0;
  if (*i > p->N) *i = p->N;
  if (fabs(x - problem_node_x(p, *i)) > b->tol_x)
    return status_set(b->st, STATUS_INPUT, "%s: curve %d along the joining "
      "segment ends at x1 = %s, off the strip's grid: the nearest node is "
      "x_%d = %s (N = %d)", b->path, tag, status_number(x, s[0]), *i,
      status_number(problem_node_x(p, *i), s[1]), p->N);
  return STATUS_OK;
}
#line 798 "paper/part.nw"
static int part_check_joining_curve(Part_build *b, int tag)
{
  const Part_gmsh *g = b->g;
  int *up = NULL, *down = NULL, ierr = 0, group;
  size_t nup = 0, ndown = 0;
  g->get_adjacencies(1, tag, &up, &nup, &down, &ndown, &ierr);
  if (up) g->free(up);
  if (down) g->free(down);
  if (ierr) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot find a curve's surfaces");
  if (nup != 1)
    return status_set(b->st, STATUS_INPUT, "%s: curve %d along the joining "
      "segment bounds %zu surfaces, not one", b->path, tag, nup);
  if ((group = part_group_of(b->curve_of, b->ncurve_of, tag)) >= 0)
    return status_set(b->st, STATUS_INPUT, "%s: physical curve \"%s\" holds "
      "curve %d of the joining segment, which lies inside the body once the "
      "strip is attached", b->path, b->names[group], tag);
  return STATUS_OK;
}
#line 820 "paper/part.nw"
static int part_collect_joining(Part_build *b, const int *dt, size_t n)
{
  const Problem *p = b->p;
  int code = STATUS_OK;
  if (!(b->join = malloc((n + 1) * sizeof *b->join))) return part_memory(b);
  for (size_t k = 0; !code && k < n; k++) {
    int tag = dt[2 * k + 1], on, i0, i1;
    double x[2];
    if ((code = part_on_joining_line(b, tag, x, &on)) || !on) continue;
    double lo = fmin(x[0], x[1]), hi = fmax(x[0], x[1]);
    if (hi <= p->a + b->tol_x || lo >= p->b - b->tol_x) continue;
    if ((code = part_grid_index(b, tag, lo, &i0))
        || (code = part_grid_index(b, tag, hi, &i1))
        || (code = part_check_joining_curve(b, tag)))
      break;
    b->join[b->njoin++] = (Part_join){ tag, i0, i1 };
  }
  return code;
}
#line 844 "paper/part.nw"
static int part_join_cmp(const void *x, const void *y)
{
  const Part_join *s = x, *t = y;
  return s->lo != t->lo ? (s->lo > t->lo) - (s->lo < t->lo) : (s->tag > t->tag) - (s->tag < t->tag);
}

static int part_missing(Part_build *b, int from, int to)
{
  const Problem *p = b->p;
  char s[3][STATUS_NUMBER], piece[64];
  if (from == 0 && to == p->N) snprintf(piece, sizeof piece, "[a, b]");
  else snprintf(piece, sizeof piece, "[x_%d, x_%d]", from, to);
  return status_set(b->st, STATUS_INPUT, "%s: no curve of the geometry runs "
    "along %s x {C0prime} = [%s, %s] x {%s}", b->path, piece,
    status_number(problem_node_x(p, from), s[0]),
    status_number(problem_node_x(p, to), s[1]), status_number(p->C0prime, s[2]));
}

static int part_check_cover(Part_build *b)
{
  const Problem *p = b->p;
  char s[3][STATUS_NUMBER];
  int reach = 0;
  qsort(b->join, b->njoin, sizeof *b->join, part_join_cmp);
  for (int k = 0; k < b->njoin; k++) {
    if (b->join[k].lo > reach) return part_missing(b, reach, b->join[k].lo);
    if (b->join[k].lo < reach)
      return status_set(b->st, STATUS_INPUT, "%s: curve %d covers [%s, %s] x "
        "{%s} of the joining segment again", b->path, b->join[k].tag,
        status_number(problem_node_x(p, b->join[k].lo), s[0]),
        status_number(problem_node_x(p, reach), s[1]),
        status_number(p->C0prime, s[2]));
    reach = b->join[k].hi;
  }
  return reach < p->N ? part_missing(b, reach, p->N) : STATUS_OK;
}
#line 883 "paper/part.nw"
static int part_find_joining(Part_build *b)
{
  const Part_gmsh *g = b->g;
  int *dt = NULL, ierr = 0, code;
  size_t n = 0;
  g->get_entities(&dt, &n, 1, &ierr);
  if (ierr) {
    if (dt) g->free(dt);
    return part_gmsh_error(b, STATUS_SYSTEM, "gmsh lists no curves");
  }
  code = part_collect_joining(b, dt, n / 2);
  if (dt) g->free(dt);
  if (code || (code = part_check_cover(b))) return code;
  for (int k = 0; k < b->njoin; k++)
    g->set_transfinite_curve(b->join[k].tag, b->join[k].hi - b->join[k].lo + 1,
                             "Progression", 1.0, &ierr);
  return ierr ? part_gmsh_error(b, STATUS_SYSTEM, "gmsh refuses a transfinite curve") : STATUS_OK;
}
#line 922 "paper/part.nw"
static int part_surface_triangles(Part_build *b, int tag, size_t **nodes, size_t *n)
{
  const Part_gmsh *g = b->g;
  int *types = NULL, ierr = 0, code = STATUS_OK;
  size_t ntypes = 0, **etags = NULL, *netags = NULL, netagsn = 0,
         **ntags = NULL, *nntags = NULL, nntagsn = 0;
  g->get_elements(&types, &ntypes, &etags, &netags, &netagsn, &ntags, &nntags,
                  &nntagsn, 2, tag, &ierr);
  *nodes = NULL; *n = 0;
  for (size_t k = 0; !ierr && k < ntypes; k++) {
    if (types[k] != 2 && !code)
      code = status_set(b->st, STATUS_INPUT, "%s: surface %d is meshed with "
        "elements of gmsh's type %d, not 3-node triangles (type 2): no "
        "Recombine, no second order", b->path, tag, types[k]);
    else if (!code) { *nodes = ntags[k]; *n = nntags[k] / 3; ntags[k] = NULL; }
    if (etags[k]) g->free(etags[k]);
    if (ntags[k]) g->free(ntags[k]);
  }
  if (types) g->free(types);
  if (etags) g->free(etags);
  if (netags) g->free(netags);
  if (ntags) g->free(ntags);
  if (nntags) g->free(nntags);
  if (ierr) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot list a surface's triangles");
  if (!code && *n == 0)
    code = status_set(b->st, STATUS_INPUT, "%s: gmsh made no triangle on "
      "surface %d", b->path, tag);
  if (code && *nodes) { g->free(*nodes); *nodes = NULL; }
  return code;
}
#line 956 "paper/part.nw"
static int part_append_triangles(Part_build *b, int tag, Part_nodes *nd)
{
  Part_mesh *pm = b->pm;
  size_t *nodes, n;
  int code = part_surface_triangles(b, tag, &nodes, &n);
  if (code) return code;
  int *tri = realloc(pm->tri, 3 * (pm->ntri + n) * sizeof *tri);
  if (tri) pm->tri = tri;
  int *region = tri ? realloc(pm->region, (pm->ntri + n) * sizeof *region) : NULL;
  if (region) pm->region = region;
  int group = part_group_of(b->surface_of, b->nsurface_of, tag);
  for (size_t t = 0; region && !code && t < n; t++) {
    for (int v = 0; v < 3; v++) {
      size_t nt = nodes[3 * t + v];
      if (nt > nd->maxtag || nd->where[nt] < 0)
        code = status_set(b->st, STATUS_SYSTEM, "%s: gmsh's triangle uses "
          "node %zu, which it does not list", b->path, nt);
      else { nd->index[nt] = 0; pm->tri[3 * (pm->ntri + t) + v] = (int) nt; }
    }
    pm->region[pm->ntri + t] = group;
  }
  b->g->free(nodes);
  if (!region) return part_memory(b);
  pm->ntri += (int) n;
  return code;
}
#line 988 "paper/part.nw"
static int part_read_nodes(Part_build *b, Part_nodes *nd)
{
  const Part_gmsh *g = b->g;
  size_t *tags = NULL, ntags = 0, ncoord = 0, npar = 0;
  double *par = NULL;
  int ierr = 0;
  g->get_nodes(&tags, &ntags, &nd->coord, &ncoord, &par, &npar, -1, -1, 0, 0, &ierr);
  if (par) g->free(par);
  if (ierr) {
    if (tags) g->free(tags);
    return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot list its nodes");
  }
  for (size_t k = 0; k < ntags; k++) if (tags[k] > nd->maxtag) nd->maxtag = tags[k];
  nd->index = malloc((nd->maxtag + 1) * sizeof *nd->index);
  nd->where = malloc((nd->maxtag + 1) * sizeof *nd->where);
  for (size_t t = 0; nd->index && nd->where && t <= nd->maxtag; t++)
    nd->index[t] = nd->where[t] = -1;
  for (size_t k = 0; nd->where && k < ntags; k++) nd->where[tags[k]] = (long) k;
  if (tags) g->free(tags);
  return nd->index && nd->where ? STATUS_OK : part_memory(b);
}

static int part_number_nodes(Part_build *b, Part_nodes *nd)
{
  Part_mesh *pm = b->pm;
  long n = 0;
  for (size_t t = 0; t <= nd->maxtag; t++) if (nd->index[t] == 0) nd->index[t] = n++;
  pm->nnodes = (int) n;
  pm->xy = malloc(2 * (size_t) n * sizeof *pm->xy);
  pm->column = malloc((size_t) n * sizeof *pm->column);
  if (!pm->xy || !pm->column) return part_memory(b);
  for (size_t t = 0; t <= nd->maxtag; t++)
    if (nd->index[t] >= 0) {
      const double *c = nd->coord + 3 * nd->where[t];
      long k = nd->index[t];
      pm->xy[2 * k] = c[0]; pm->xy[2 * k + 1] = c[1]; pm->column[k] = -1;
      if (c[1] < b->p->C0prime - b->tol_y) {
        char x[STATUS_NUMBER], y[STATUS_NUMBER], z[STATUS_NUMBER];
        return status_set(b->st, STATUS_INPUT, "%s: the mesh has a node at "
          "(%s, %s), below x2 = C0prime = %s: a curve dips into the strip",
          b->path, status_digits(c[0], 6, x), status_digits(c[1], 6, y),
          status_number(b->p->C0prime, z));
      }
    }
  for (int v = 0; v < 3 * pm->ntri; v++) pm->tri[v] = (int) nd->index[pm->tri[v]];
  return STATUS_OK;
}
#line 1040 "paper/part.nw"
static int part_read_mesh(Part_build *b)
{
  const Part_gmsh *g = b->g;
  Part_nodes *nd = &b->nodes;
  int *dt = NULL, ierr = 0, code;
  size_t n = 0;
  if ((code = part_read_nodes(b, nd))) return code;
  g->get_entities(&dt, &n, 2, &ierr);
  n /= 2;
  if (ierr) code = part_gmsh_error(b, STATUS_SYSTEM, "gmsh lists no surfaces");
  for (size_t k = 0; !code && k < n; k++)
    code = part_append_triangles(b, dt[2 * k + 1], nd);
  if (dt) g->free(dt);
  return code ? code : part_number_nodes(b, nd);
}

#line 1068 "paper/part.nw"
static int part_snap_curve(Part_build *b, const Part_join *j, int *seen)
{
  const Part_gmsh *g = b->g;
  Part_mesh *pm = b->pm;
  size_t *tags = NULL, nt = 0, nc = 0, np = 0;
  double *c = NULL, *par = NULL;
  int ierr = 0, code = STATUS_OK;
  g->get_nodes(&tags, &nt, &c, &nc, &par, &np, 1, j->tag, 1, 0, &ierr);
  for (size_t k = 0; !ierr && !code && k < nt; k++) {
    long node = tags[k] <= b->nodes.maxtag ? b->nodes.index[tags[k]] : -1;
    int i = (int) lround((c[3 * k] - b->p->a) / b->h);
    if (node < 0 || i < j->lo || i > j->hi
        || fabs(c[3 * k] - problem_node_x(b->p, i)) > 1e-6 * b->h
        || (seen[i] >= 0 && seen[i] != node))
      code = status_set(b->st, STATUS_NUMERIC, "%s: gmsh did not put the "
        "nodes of curve %d on the strip's grid", b->path, j->tag);
    else {
      seen[i] = (int) node;
      pm->column[node] = i;
      pm->xy[2 * node] = problem_node_x(b->p, i);
      pm->xy[2 * node + 1] = b->p->C0prime;
    }
  }
  if (tags) g->free(tags);
  if (c) g->free(c);
  if (par) g->free(par);
  return ierr ? part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot list a curve's nodes") : code;
}

static int part_snap_joining(Part_build *b)
{
  int N = b->p->N, code = STATUS_OK;
  int *seen = malloc((N + 1) * sizeof *seen);
  if (!seen) return part_memory(b);
  for (int i = 0; i <= N; i++) seen[i] = -1;
  for (int k = 0; !code && k < b->njoin; k++) code = part_snap_curve(b, &b->join[k], seen);
  for (int i = 0; !code && i <= N; i++)
    if (seen[i] < 0)
      code = status_set(b->st, STATUS_NUMERIC, "%s: gmsh put no node at "
        "x_%d of the joining segment", b->path, i);
  free(seen);
  return code;
}
#line 1121 "paper/part.nw"
static double part_area(const Part_mesh *pm, const int *v)
{
  const double *p = pm->xy + 2 * v[0], *q = pm->xy + 2 * v[1], *r = pm->xy + 2 * v[2];
  return 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
}

static int part_orient(Part_build *b)
{
  Part_mesh *pm = b->pm;
  for (int t = 0; t < pm->ntri; t++) {
    int *v = pm->tri + 3 * t;
    if (part_area(pm, v) < 0) { int s = v[1]; v[1] = v[2]; v[2] = s; }
    if (!(part_area(pm, v) > 0)) {
      char x[STATUS_NUMBER], y[STATUS_NUMBER];
      return status_set(b->st, STATUS_INPUT, "%s: gmsh's triangle at (%s, %s) "
        "has no area", b->path, status_digits(pm->xy[2 * v[0]], 6, x),
        status_digits(pm->xy[2 * v[0] + 1], 6, y));
    }
  }
  return STATUS_OK;
}
#line 1173 "paper/part.nw"
/* the physical surface of triangle t, for a message: " (surface NAME)" */
static const char *part_region_words(const Part_mesh *pm, int t, char *buf, size_t size)
{
  if (pm->region[t] < 0) snprintf(buf, size, " (in no physical surface)");
  else snprintf(buf, size, " (physical surface \"%s\")", pm->surface_name[pm->region[t]]);
  return buf;
}

/* 1 when node k lies inside or on triangle t, of which it is no corner */
static int part_covers(const Part_mesh *pm, int t, int k)
{
  const int *v = pm->tri + 3 * t;
  if (v[0] == k || v[1] == k || v[2] == k) return 0;
  const double *x = pm->xy + 2 * k;
  double area = 2 * part_area(pm, v);
  for (int i = 0; i < 3; i++) {
    const double *p = pm->xy + 2 * v[(i + 1) % 3], *q = pm->xy + 2 * v[(i + 2) % 3];
    double lambda = ((q[0] - p[0]) * (x[1] - p[1]) - (x[0] - p[0]) * (q[1] - p[1])) / area;
    if (lambda < -1e-9) return 0;
  }
  return 1;
}
#line 1209 "paper/part.nw"
static void part_cells(const Part_grid *gr, const double lo[2], const double hi[2],
                       int from[2], int to[2])
{
  double o[2] = { gr->x0, gr->y0 }, pad = 1e-6 * gr->c;
  int n[2] = { gr->nx, gr->ny };
  for (int d = 0; d < 2; d++) {
    from[d] = (int) floor((lo[d] - pad - o[d]) / gr->c);
    to[d] = (int) floor((hi[d] + pad - o[d]) / gr->c);
    from[d] = from[d] < 0 ? 0 : from[d] >= n[d] ? n[d] - 1 : from[d];
    to[d] = to[d] < 0 ? 0 : to[d] >= n[d] ? n[d] - 1 : to[d];
  }
}

static void part_triangle_box(const Part_mesh *pm, int t, double lo[2], double hi[2])
{
  for (int d = 0; d < 2; d++) {
    lo[d] = hi[d] = pm->xy[2 * pm->tri[3 * t] + d];
    for (int i = 1; i < 3; i++) {
      double z = pm->xy[2 * pm->tri[3 * t + i] + d];
      lo[d] = fmin(lo[d], z), hi[d] = fmax(hi[d], z);
    }
  }
}

static int part_grid_fill(const Part_mesh *pm, Part_grid *gr, int count)
{
  for (int t = 0; t < pm->ntri; t++) {
    double lo[2], hi[2];
    int from[2], to[2];
    part_triangle_box(pm, t, lo, hi);
    part_cells(gr, lo, hi, from, to);
    for (int j = from[1]; j <= to[1]; j++)
      for (int i = from[0]; i <= to[0]; i++) {
        size_t cell = (size_t) j * gr->nx + i;
        if (count) gr->first[cell + 1]++;
        else gr->list[gr->first[cell]++] = t;
      }
  }
  if (count) {
    size_t ncell = (size_t) gr->nx * gr->ny;
    for (size_t k = 0; k < ncell; k++) gr->first[k + 1] += gr->first[k];
    return gr->first[ncell];
  }
  for (size_t k = (size_t) gr->nx * gr->ny; k > 0; k--) gr->first[k] = gr->first[k - 1];
  gr->first[0] = 0;
  return 0;
}

static int part_grid_new(const Part_mesh *pm, Part_grid *gr)
{
  double lo[2] = { pm->xy[0], pm->xy[1] }, hi[2] = { lo[0], lo[1] }, area = 0;
  for (int k = 0; k < pm->nnodes; k++)
    for (int d = 0; d < 2; d++)
      lo[d] = fmin(lo[d], pm->xy[2 * k + d]), hi[d] = fmax(hi[d], pm->xy[2 * k + d]);
  for (int t = 0; t < pm->ntri; t++) area += part_area(pm, pm->tri + 3 * t);
  gr->c = fmax(sqrt(area / pm->ntri), 1e-3 * fmax(hi[0] - lo[0], hi[1] - lo[1]));
  gr->x0 = lo[0], gr->y0 = lo[1];
  gr->nx = (int) ((hi[0] - lo[0]) / gr->c) + 1, gr->ny = (int) ((hi[1] - lo[1]) / gr->c) + 1;
  gr->first = calloc((size_t) gr->nx * gr->ny + 1, sizeof *gr->first);
  gr->list = NULL;
  if (!gr->first) return 0;
  int n = part_grid_fill(pm, gr, 1);
  if (!(gr->list = malloc((size_t) n * sizeof *gr->list + 1))) return 0;
  part_grid_fill(pm, gr, 0);
  return 1;
}
#line 1279 "paper/part.nw"
static int part_no_overlap(Part_build *b)
{
  const Part_mesh *pm = b->pm;
  Part_grid gr;
  int code = part_grid_new(pm, &gr) ? STATUS_OK : part_memory(b);
  for (int k = 0; !code && k < pm->nnodes; k++) {
    int from[2], to[2];
    part_cells(&gr, pm->xy + 2 * k, pm->xy + 2 * k, from, to);
    size_t cell = (size_t) from[1] * gr.nx + from[0];
    for (int l = gr.first[cell]; !code && l < gr.first[cell + 1]; l++) {
      int t = gr.list[l];
      if (!part_covers(pm, t, k)) continue;
      char x[STATUS_NUMBER], y[STATUS_NUMBER], words[PROBLEM_NAME + 32];
      code = status_set(b->st, STATUS_INPUT, "%s: the node at (%s, %s) lies on a "
        "triangle%s that it is no corner of: surfaces overlap, or touch along "
        "a curve or at a point that they do not share (gmsh: Coherence, or "
        "BooleanFragments with OpenCASCADE)", b->path, status_digits(pm->xy[2 * k], 6, x),
        status_digits(pm->xy[2 * k + 1], 6, y), part_region_words(pm, t, words, sizeof words));
    }
  }
  free(gr.first); free(gr.list);
  return code;
}
#line 1307 "paper/part.nw"
static int part_root(int *parent, int k)
{
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

static int part_joined(Part_build *b)
{
  const Part_mesh *pm = b->pm;
  int *parent = malloc(2 * (size_t) pm->nnodes * sizeof *parent + 1), code = STATUS_OK;
  if (!parent) return part_memory(b);
  int *rests = parent + pm->nnodes;
  for (int k = 0; k < pm->nnodes; k++) parent[k] = k, rests[k] = 0;
  for (int t = 0; t < pm->ntri; t++)
    for (int i = 1; i < 3; i++) {
      int r = part_root(parent, pm->tri[3 * t]), s = part_root(parent, pm->tri[3 * t + i]);
      if (r != s) parent[r < s ? s : r] = r < s ? r : s;
    }
  for (int k = 0; k < pm->nnodes; k++) if (pm->column[k] >= 0) rests[part_root(parent, k)] = 1;
  for (int t = 0; !code && t < pm->ntri; t++) {
    if (rests[part_root(parent, pm->tri[3 * t])]) continue;
    const double *x = pm->xy + 2 * pm->tri[3 * t];
    char x1[STATUS_NUMBER], x2[STATUS_NUMBER], words[PROBLEM_NAME + 32];
    code = status_set(b->st, STATUS_INPUT, "%s: the triangle at (%s, %s)%s shares "
      "no node, through the others, with the joining segment: a surface apart, "
      "which nothing joins to the strip", b->path, status_digits(x[0], 6, x1),
      status_digits(x[1], 6, x2), part_region_words(pm, t, words, sizeof words));
  }
  free(parent);
  return code;
}

static int part_one_body(Part_build *b)
{
  int code = part_no_overlap(b);
  return code ? code : part_joined(b);
}
#line 1361 "paper/part.nw"
static int part_edge_cmp(const void *x, const void *y)
{
  const Part_edge *s = x, *u = y;
  if (s->lo != u->lo) return (s->lo > u->lo) - (s->lo < u->lo);
  if (s->hi != u->hi) return (s->hi > u->hi) - (s->hi < u->hi);
  return (s->t > u->t) - (s->t < u->t);
}

static Part_edge *part_all_edges(const Part_mesh *pm)
{
  Part_edge *e = malloc(3 * (size_t) pm->ntri * sizeof *e);
  for (int t = 0; e && t < pm->ntri; t++)
    for (int k = 0; k < 3; k++) {
      int from = pm->tri[3 * t + k], to = pm->tri[3 * t + (k + 1) % 3];
      e[3 * t + k] = (Part_edge){ from < to ? from : to, from < to ? to : from, from, to, t };
    }
  if (e) qsort(e, 3 * (size_t) pm->ntri, sizeof *e, part_edge_cmp);
  return e;
}
#line 1385 "paper/part.nw"
static int part_curve_lines(Part_build *b, Part_edge **lines, size_t *nlines)
{
  const Part_gmsh *g = b->g;
  int *dt = NULL, ierr = 0, code = STATUS_OK;
  size_t n = 0;
  g->get_entities(&dt, &n, 1, &ierr);
  n /= 2;
  for (size_t k = 0; !ierr && !code && k < n; k++) {
    int tag = dt[2 * k + 1], *types = NULL;
    size_t ntypes = 0, **etags = NULL, *netags = NULL, ne = 0, **ntags = NULL,
           *nntags = NULL, nn = 0;
    g->get_elements(&types, &ntypes, &etags, &netags, &ne, &ntags, &nntags, &nn, 1, tag, &ierr);
    for (size_t y = 0; !ierr && y < ntypes; y++) {
      if (types[y] != 1 && !code)
        code = status_set(b->st, STATUS_INPUT, "%s: curve %d is meshed with "
          "elements of gmsh's type %d, not 2-node lines", b->path, tag, types[y]);
      size_t want = (*nlines + nntags[y] / 2 + 1) * sizeof **lines;
      Part_edge *grown = code ? NULL : realloc(*lines, want);
      if (!code && !grown) code = part_memory(b);
      if (grown) *lines = grown;
      for (size_t l = 0; grown && l < nntags[y] / 2; l++)
        
#line 1425 "paper/part.nw"
{
  size_t u = ntags[y][2 * l], w = ntags[y][2 * l + 1];
  long iu = u <= b->nodes.maxtag ? b->nodes.index[u] : -1;
  long iw = w <= b->nodes.maxtag ? b->nodes.index[w] : -1;
  int group = part_group_of(b->curve_of, b->ncurve_of, tag);
  if (iu >= 0 && iw >= 0)
    (*lines)[(*nlines)++] = (Part_edge){ (int) (iu < iw ? iu : iw), (int) (iu < iw ? iw : iu),
      0, 0, group };
  else if (group >= 0 && !code)
    code = status_set(b->st, STATUS_INPUT, "%s: physical curve \"%s\" holds curve %d, "
      "which bounds no surface: a condition there would act on nothing", b->path,
      b->names[group], tag);
}
#line 1407 "paper/part.nw"
      g->free(etags[y]); g->free(ntags[y]);
    }
    if (types) g->free(types);
    if (etags) g->free(etags);
    if (netags) g->free(netags);
    if (ntags) g->free(ntags);
    if (nntags) g->free(nntags);
  }
  if (dt) g->free(dt);
  if (ierr && !code) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh cannot list its lines");
  if (!code) qsort(*lines, *nlines, sizeof **lines, part_edge_cmp);
  return code;
}
#line 1449 "paper/part.nw"
static Part_edge *part_line_of(Part_edge *lines, size_t nlines, int lo, int hi)
{
  for (size_t a = 0, z = nlines; a < z;) {   /* binary search on (lo, hi) */
    size_t mid = (a + z) / 2;
    int c = lo != lines[mid].lo ? (lo > lines[mid].lo) - (lo < lines[mid].lo)
                                : (hi > lines[mid].hi) - (hi < lines[mid].hi);
    if (c == 0) return lines + mid;
    if (c < 0) z = mid; else a = mid + 1;
  }
  return NULL;
}

/* the refusal of the physical curve of line l, whose edge e is not on the
   boundary; what: its words, with the edge's two ends */
static int part_inner_curve(Part_build *b, const Part_edge *e, const Part_edge *l,
                            const char *what)
{
  const double *p = b->pm->xy + 2 * e->lo, *q = b->pm->xy + 2 * e->hi;
  char x[4][STATUS_NUMBER], words[256];
  snprintf(words, sizeof words, what, status_digits(p[0], 6, x[0]),
           status_digits(p[1], 6, x[1]), status_digits(q[0], 6, x[2]),
           status_digits(q[1], 6, x[3]));
  return status_set(b->st, STATUS_INPUT, "%s: physical curve \"%s\" %s: a condition "
    "acts on the boundary only", b->path, b->pm->curve_name[l->t], words);
}

static int part_boundary_edges(Part_build *b, const Part_edge *e, Part_edge *lines,
                               size_t nlines)
{
  Part_mesh *pm = b->pm;
  size_t n3 = 3 * (size_t) pm->ntri;
  pm->nedge = 0;
  for (size_t k = 0; k < n3; k++) {
    int next = k + 1 < n3 && e[k + 1].lo == e[k].lo && e[k + 1].hi == e[k].hi;
    int twice = next || (k > 0 && e[k - 1].lo == e[k].lo && e[k - 1].hi == e[k].hi);
    Part_edge *l = part_line_of(lines, nlines, e[k].lo, e[k].hi);
    if (next && l && l->t >= 0) return part_inner_curve(b, e + k, l, "runs inside the "
      "part (its line from (%s, %s) to (%s, %s) has a triangle on each side)");
    if (twice || (pm->column[e[k].lo] >= 0 && pm->column[e[k].hi] >= 0)) continue;
    pm->edge[2 * pm->nedge] = e[k].from;
    pm->edge[2 * pm->nedge + 1] = e[k].to;
    pm->curve[pm->nedge++] = l ? l->t : -1;
    if (l) l->from = 1;
  }
  for (size_t k = 0; k < nlines; k++)
    if (lines[k].t >= 0 && !lines[k].from) return part_inner_curve(b, lines + k, lines + k,
      "has a line from (%s, %s) to (%s, %s) that is no edge of the mesh");
  return STATUS_OK;
}

static int part_boundary(Part_build *b)
{
  Part_mesh *pm = b->pm;
  Part_edge *lines = NULL;
  size_t nlines = 0;
  int code = part_curve_lines(b, &lines, &nlines);
  Part_edge *e = code ? NULL : part_all_edges(pm);
  if (!code) {
    pm->edge = malloc(6 * (size_t) pm->ntri * sizeof *pm->edge + 1);
    pm->curve = malloc(3 * (size_t) pm->ntri * sizeof *pm->curve + 1);
    code = e && pm->edge && pm->curve ? part_boundary_edges(b, e, lines, nlines)
                                      : part_memory(b);
  }
  free(e);
  free(lines);
  return code;
}

#line 395 "paper/part.nw"
static int part_steps(Part_build *b)
{
  const Part_gmsh *g = b->g;
  int ierr = 0, code;
  g->option_set_number("General.Terminal", 0, &ierr);
  g->logger_start(&ierr);
  g->option_set_number("General.NumThreads", 1, &ierr);
  if (ierr) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh refuses its options");
  g->open(b->path, &ierr);
  if (ierr) return part_gmsh_error(b, STATUS_INPUT, "gmsh cannot read it");
  if ((code = part_check_points(b)) || (code = part_read_groups(b))
      || (code = part_find_joining(b)))
    return code;
  g->option_set_number("Mesh.MeshSizeMax", b->h * b->p->part.refine, &ierr);
  g->option_set_number("Mesh.MeshSizeFactor", 1.0 / b->p->part.refine, &ierr);
  if (ierr) return part_gmsh_error(b, STATUS_SYSTEM, "gmsh refuses its sizes");
  if ((code = part_generate(b))) return code;
  if (!(b->pm = calloc(1, sizeof *b->pm))) return part_memory(b);
  if ((code = part_copy_names(b)) || (code = part_read_mesh(b))
      || (code = part_snap_joining(b)) || (code = part_orient(b))
      || (code = part_one_body(b)) || (code = part_boundary(b)))
    return code;
  return STATUS_OK;
}
#line 509 "paper/part.nw"
static void part_gmsh_initialize(const Part_gmsh *g, int *ierr)
{
  const char *home = getenv("HOME");
  char *saved = home ? strdup(home) : NULL;
  if (home && !saved) { *ierr = 1; return; }
  setenv("HOME", "/dev/null", 1);
  g->initialize(0, NULL, 0, ierr);
  if (saved) setenv("HOME", saved, 1); else unsetenv("HOME");
  free(saved);
}

#line 434 "paper/part.nw"
static struct {
  Problem key;             /* the problem that made it: the fields read */
  Part_mesh *pm;           /* NULL: none yet */
} part_memo;

static int part_memo_same(const Problem *p, const Problem *q)
{
  return !strcmp(p->part.geometry, q->part.geometry) && p->a == q->a && p->b == q->b
         && p->N == q->N && p->C0prime == q->C0prime && p->part.refine == q->part.refine;
}

static void *part_dup(const void *x, size_t bytes, int *ok)
{
  void *y = malloc(bytes + 1);
  if (y) memcpy(y, x, bytes);
  else *ok = 0;
  return y;
}

/* a copy of pm; NULL when memory runs out */
static Part_mesh *part_mesh_copy(const Part_mesh *pm)
{
  Part_mesh *c = malloc(sizeof *c);
  int ok = c != NULL;
  if (!c) return NULL;
  *c = *pm;
  size_t n = pm->nnodes, t = pm->ntri, e = pm->nedge;
  c->xy = part_dup(pm->xy, 2 * n * sizeof *pm->xy, &ok);
  c->column = part_dup(pm->column, n * sizeof *pm->column, &ok);
  c->tri = part_dup(pm->tri, 3 * t * sizeof *pm->tri, &ok);
  c->region = part_dup(pm->region, t * sizeof *pm->region, &ok);
  c->edge = part_dup(pm->edge, 2 * e * sizeof *pm->edge, &ok);
  c->curve = part_dup(pm->curve, e * sizeof *pm->curve, &ok);
  c->curve_name = part_dup(pm->curve_name, (pm->ncurve + 1) * sizeof *pm->curve_name, &ok);
  c->surface_name = part_dup(pm->surface_name, (pm->nsurface + 1) * sizeof *pm->surface_name,
                             &ok);
  if (!ok) { part_mesh_free(c); return NULL; }
  return c;
}

/* a copy of the last mesh if p made it; NULL if not, and NULL with st
   set and *failed = 1 when the copy fails */
static Part_mesh *part_memo_get(const Problem *p, Status *st, int *failed)
{
  if (!part_memo.pm || !part_memo_same(p, &part_memo.key)) return NULL;
  Part_mesh *c = part_mesh_copy(part_memo.pm);
  if (!c) *failed = 1, status_set(st, STATUS_MEMORY, "%s: out of memory for its mesh",
                                  p->part.geometry);
  return c;
}

/* keep a copy of pm, made by p (none if memory runs out: the next call
   meshes again) */
static void part_memo_put(const Problem *p, const Part_mesh *pm)
{
  part_mesh_free(part_memo.pm);
  part_memo.pm = part_mesh_copy(pm);
  part_memo.key = *p;
}

#line 355 "paper/part.nw"
Part_mesh *part_mesh_new(const Problem *p, Status *st)
{
  const char *path = p->part.geometry;
  int failed = 0;
  Part_mesh *copy = part_memo_get(p, st, &failed);
  if (copy || failed) return copy;
  const Part_gmsh *g = part_gmsh_load(path, st);
  if (!g) return NULL;
  Part_build *b = calloc(1, sizeof *b);
  if (!b) { status_set(st, STATUS_MEMORY, "%s: out of memory for its mesh", path); return NULL; }
  FILE *f = fopen(path, "r");
  if (!f) {
    status_set(st, STATUS_INPUT, "%s: cannot open the geometry: %s", path, strerror(errno));
    free(b);
    return NULL;
  }
  fclose(f);
  *b = (Part_build){ .g = g, .p = p, .path = path, .st = st, .h = (p->b - p->a) / p->N,
                     .tol_y = 1e-9 * (p->b - p->a), .tol_x = 1e-9 * (p->b - p->a) / p->N };
  int ierr = 0;
  part_gmsh_initialize(g, &ierr);
  int code = ierr ? part_gmsh_error(b, STATUS_SYSTEM, "gmsh does not start")
                  : part_steps(b);
  part_nodes_free(g, &b->nodes);
  g->logger_stop(&ierr);
  g->finalize(&ierr);
  Part_mesh *pm = b->pm;
  free(b->curve_of); free(b->surface_of); free(b->join); free(b);
  if (code) { part_mesh_free(pm); return NULL; }
  part_memo_put(p, pm);
  return pm;
}
#line 1519 "paper/part.nw"
void part_mesh_free(Part_mesh *pm)
{
  if (!pm) return;
  free(pm->xy); free(pm->column); free(pm->tri); free(pm->region);
  free(pm->edge); free(pm->curve); free(pm->curve_name); free(pm->surface_name);
  free(pm);
}
