#line 2208 "paper/scene.nw"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "design.h"
#include "scene_private.h"
#line 2330 "paper/scene.nw"
typedef struct {
  double *x, *alpha;  /* the rows: x1 and alpha */
  int *line;          /* the line of each row in the file */
  int n, cap;         /* rows read, and room for */
} Rows;

/* append the row (x, alpha) of line `line`; 0, or -1 without memory */
static int rows_add(Rows *r, double x, double alpha, int line)
{
  if (r->n == r->cap) {
    int cap = r->cap ? 2 * r->cap : 64;
    double *nx = realloc(r->x, cap * sizeof *nx);
    double *na = nx ? realloc(r->alpha, cap * sizeof *na) : NULL;
    int *nl = na ? realloc(r->line, cap * sizeof *nl) : NULL;
    if (nx) r->x = nx;
    if (na) r->alpha = na;
    if (!nl) return -1;
    r->line = nl, r->cap = cap;
  }
  r->x[r->n] = x, r->alpha[r->n] = alpha, r->line[r->n++] = line;
  return 0;
}

static void rows_free(Rows *r)
{
  free(r->x), free(r->alpha), free(r->line);
}
#line 2223 "paper/scene.nw"
static void resample(const Problem *p, const Rows *r, double *alpha0);
static int shape_from_rows(Scene_loader *L, Scene *s, const char *path, const Rows *r);
#line 2241 "paper/scene.nw"
/* the keys of an arc: centre (arc_x1, arc_x2), arc_radius > 0 */
static int read_arc_shape(Scene_loader *L, Scene *s)
{
  int rc;
  s->shape.kind = SHAPE_ARC;
  if ((rc = scene_get(L, s, "design", "arc_x1"))
      || (rc = scene_get(L, s, "design", "arc_x2"))
      || (rc = scene_get(L, s, "design", "arc_radius")))
    return rc;
  if (!(s->shape.radius > 0)) return scene_blame(L, "the radius must be > 0");
  return 0;
}
#line 2257 "paper/scene.nw"
/* the keys of a line: line_start at x1 = a, line_end at x1 = b */
static int read_line_shape(Scene_loader *L, Scene *s)
{
  int rc;
  s->shape.kind = SHAPE_LINE;
  if ((rc = scene_get(L, s, "design", "line_start")))
    return rc;
  return scene_get(L, s, "design", "line_end");
}
#line 2269 "paper/scene.nw"
/* the key of a constant */
static int read_constant_shape(Scene_loader *L, Scene *s)
{
  s->shape.kind = SHAPE_CONSTANT;
  return scene_get(L, s, "design", "constant");
}
#line 2281 "paper/scene.nw"
/* alpha0 = the shape of the keys read by read_keys, sampled */
static int fill_formula(Scene_loader *L, Scene *s,
                        int (*read_keys)(Scene_loader *, Scene *))
{
  Status why = {STATUS_OK, ""};
  int rc = read_keys(L, s);
  if (!rc && design_shape(&s->problem, &s->shape, s->alpha0, &why))
    rc = scene_blame(L, "%s", why.msg);
  return rc;
}
#line 2301 "paper/scene.nw"
/* buf = file, relative to the directory of the scene file; 0 if it fits */
int scene_resolve(const char *scene, const char *file, char *buf, size_t size)
{
  const char *slash = strrchr(scene, '/');
  int n;
  if (file[0] == '/' || !slash) n = snprintf(buf, size, "%s", file);
  else n = snprintf(buf, size, "%.*s/%s", (int)(slash - scene), scene, file);
  return n < 0 || (size_t)n >= size;
}
#line 2313 "paper/scene.nw"
/* buf = path, absolute; 0 if it fits */
int scene_absolute(const char *path, char *buf, size_t size)
{
  char cwd[4096];
  int n;
  if (path[0] == '/') n = snprintf(buf, size, "%s", path);
  else if (!getcwd(cwd, sizeof cwd)) return 1;
  else n = snprintf(buf, size, "%s/%s", cwd, path);
  return n < 0 || (size_t)n >= size;
}
#line 2360 "paper/scene.nw"
/* one line of a shape file: add its row x1 alpha to r, if it has one */
static int read_row(Scene_loader *L, const char *path, int lineno, char *line,
                    Rows *r)
{
  char *tok, *save = NULL, *hash = strchr(line, '#');
  const char *why;
  double v[2];
  int k = 0;
  if (hash) *hash = '\0';
  for (tok = strtok_r(line, " \t\r\n", &save); tok;
       tok = strtok_r(NULL, " \t\r\n", &save), k++)
    if ((why = scene_to_real(tok, &v[k < 2 ? k : 1])))
      return scene_blame(L, "%s line %d: '%s' is %s", path, lineno, tok, why);
  if (k == 0) return 0;
  if (k != 2)
    return scene_blame(L, "%s line %d: %d number%s: a row of a shape file is x1 "
                       "alpha", path, lineno, k, k == 1 ? "" : "s");
  if (rows_add(r, v[0], v[1], lineno))
    return L->failed = status_set(L->st, STATUS_MEMORY, "%s: out of memory "
                                  "for the rows of %s", L->path, path);
  return 0;
}
#line 2389 "paper/scene.nw"
/* alpha0 = the shape in the file at path, on the design nodes */
static int read_shape(Scene_loader *L, Scene *s, const char *path)
{
  FILE *fp;
  char *line = NULL;
  size_t cap = 0;
  ssize_t len;
  Rows r = {0};
  int rc = 0, lineno = 0;
  if (!(fp = fopen(path, "r"))) {
    int e = errno;
    scene_blame(L, "cannot read %s%s: %s", path, L->last.val[0] == '/' ? ""
                : " (design.file is relative to the scene's folder)", strerror(e));
    return scene_for_memory(L, e);
  }
  while (!rc && (len = getline(&line, &cap, fp)) != -1)
    rc = strlen(line) < (size_t)len
      ? scene_blame(L, "%s line %d: a NUL byte: a shape file is text", path,
                    ++lineno)
      : read_row(L, path, ++lineno, line, &r);
  if (!rc && ferror(fp)) {
    int e = errno;
    scene_blame(L, "cannot read %s: %s", path, strerror(e));
    rc = scene_for_memory(L, e);
  }
  free(line);
  fclose(fp);
  if (!rc) rc = shape_from_rows(L, s, path, &r);
  rows_free(&r);
  return rc;
}
#line 2434 "paper/scene.nw"
/* alpha0 = the rows r of the file at path on the design nodes, as they
   are or resampled; refuse rows that are no shape on [a, b] */
static int shape_from_rows(Scene_loader *L, Scene *s, const char *path,
                           const Rows *r)
{
  const Problem *p = &s->problem;
  double tol = 1e-9 * fmax(fabs(p->a), fabs(p->b));
  int i, j, same = r->n == p->N + 1;
  if (r->n < 2)
    return scene_blame(L, "%s has %d row%s x1 alpha: a shape needs rows at x1 = a "
                       "and at x1 = b", path, r->n, r->n == 1 ? "" : "s");
  for (j = 1; j < r->n; j++)
    if (!(r->x[j] > r->x[j - 1]))
      return scene_blame(L, "%s line %d: x1 = %.10g does not increase (line %d "
                         "has %.10g)", path, r->line[j], r->x[j], r->line[j - 1],
                         r->x[j - 1]);
  
#line 2466 "paper/scene.nw"
if (!(fabs(r->x[0] - p->a) <= tol))
  return scene_blame(L, "%s line %d: x1 = %.10g: a shape begins at x1 = a = %.10g",
                     path, r->line[0], r->x[0], p->a);
if (!(fabs(r->x[r->n - 1] - p->b) <= tol))
  return scene_blame(L, "%s line %d: x1 = %.10g: a shape ends at x1 = b = %.10g",
                     path, r->line[r->n - 1], r->x[r->n - 1], p->b);
#line 2451 "paper/scene.nw"
  for (i = 0; same && i <= p->N; i++)
    same = fabs(r->x[i] - problem_node_x(p, i)) <= tol;
  if (same) {
    memcpy(s->alpha0, r->alpha, ((size_t)p->N + 1) * sizeof *s->alpha0);
    return 0;
  }
  resample(p, r, s->alpha0);
  snprintf(s->note, sizeof s->note, "design.file = %s: %d rows on [%.10g, "
           "%.10g] resampled by linear interpolation onto the N + 1 = %d "
           "design nodes", L->last.val, r->n, r->x[0], r->x[r->n - 1], p->N + 1);
  return 0;
}
#line 2477 "paper/scene.nw"
/* alpha0_i = the piecewise linear interpolant of the rows r at x_i */
static void resample(const Problem *p, const Rows *r, double *alpha0)
{
  int i, j = 0;
  for (i = 0; i <= p->N; i++) {
    double x = problem_node_x(p, i), t;
    while (j + 2 < r->n && r->x[j + 1] < x) j++;
    t = (x - r->x[j]) / (r->x[j + 1] - r->x[j]);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    alpha0[i] = (1 - t) * r->alpha[j] + t * r->alpha[j + 1];
  }
}
#line 2495 "paper/scene.nw"
/* alpha0 = the shape in the file design.file */
static int fill_file(Scene_loader *L, Scene *s)
{
  char path[sizeof s->shape_file];
  int rc;
  if (!scene_entry(L, "design", "file")) return L->failed;
  if (scene_resolve(s->path, L->last.val, path, sizeof path))
    return scene_blame(L, "path longer than %d characters", (int)sizeof path - 1);
  if ((rc = read_shape(L, s, path))) return rc;
  if (scene_absolute(path, s->shape_file, sizeof s->shape_file))
    return scene_blame(L, "cannot make %s an absolute path", path);
  return 0;
}
#line 2512 "paper/scene.nw"
/* 0 <= alpha0_i < C0prime at every node */
static int check_alpha0(Scene_loader *L, const Scene *s)
{
  char v[3][STATUS_NUMBER];
  int i;
  for (i = 0; i <= s->problem.N; i++)
    if (!(s->alpha0[i] >= 0 && s->alpha0[i] < s->problem.C0prime))
      return scene_bad(L, scene_find(L, "design", "initial"), "alpha0 = %s at node %d "
                       "(x1 = %s) is outside [0, C0prime) = [0, %s)",
                 status_number(s->alpha0[i], v[0]), i,
                 status_number(problem_node_x(&s->problem, i), v[1]),
                 status_number(s->problem.C0prime, v[2]));
  return 0;
}
#line 2532 "paper/scene.nw"
/* [design] initial: alpha0 at the N+1 nodes */
int scene_read_initial(Scene_loader *L, Scene *s)
{
  static int (*const read_keys[])(Scene_loader *, Scene *) = {read_arc_shape,
    read_line_shape, read_constant_shape};
  int k, rc;
  if ((rc = scene_word(L, "design", "initial", &k)))
    return rc;
  snprintf(s->initial, sizeof s->initial, "%s", scene_initial_names[k]);
  if ((rc = scene_refuse_unused(L, "design", "initial", scene_initial_names[k])))
    return rc;
  if (!(s->alpha0 = malloc(((size_t)s->problem.N + 1) * sizeof *s->alpha0)))
    return L->failed = status_set(L->st, STATUS_MEMORY, "%s: out of memory "
                                  "for %d nodes", L->path, s->problem.N + 1);
  rc = k == 3 ? fill_file(L, s) : fill_formula(L, s, read_keys[k]);
  return rc ? rc : check_alpha0(L, s);
}
