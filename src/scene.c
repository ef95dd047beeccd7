#line 253 "paper/scene.nw"
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ini.h>
#include "design.h"
#include "scene.h"
#line 274 "paper/scene.nw"
static const char *const geometry_keys[] = {"a", "b", "gamma", NULL};
static const char *const design_keys[] = {"N", "C0", "C1", "C2", "initial",
  "arc_x1", "arc_x2", "arc_radius", "line_start", "line_end", "constant",
  "file", NULL};
static const char *const mesh_keys[] = {"M", "R", "C0prime", "refine", NULL};
static const char *const material_keys[] = {"E", "nu", "model", NULL};
static const char *const side_keys[] = {"bc", "from", "to", "P1", "P2", NULL};
static const char *const body_force_keys[] = {"F1", "F2", NULL};
static const char *const contact_keys[] = {"model", "g", "friction", NULL};
static const char *const solver_keys[] = {"state", "tol", "max_iter",
  "omega", NULL};
static const char *const optimizer_keys[] = {"method", "metric", "tol",
  "max_iter", NULL};
static const char *const section_names[] = {"geometry", "design", "mesh",
  "material", "left", "right", "top", "body_force", "contact", "solver",
  "optimizer", NULL};
static const char *const *const section_keys[] = {geometry_keys,
  design_keys, mesh_keys, material_keys, side_keys, side_keys, side_keys,
  body_force_keys, contact_keys, solver_keys, optimizer_keys};
#line 300 "paper/scene.nw"
static const char *const side_names[] = {"left", "right", "top", NULL};
static const char *const state_names[] = {"pdas", "psor", "cgssor", NULL};
static const char *const initial_names[] = {"arc", "line", "constant",
  "file", NULL};
static const char *const arc_keys[] = {"arc_x1", "arc_x2", "arc_radius",
  NULL};
static const char *const line_keys[] = {"line_start", "line_end", NULL};
static const char *const constant_keys[] = {"constant", NULL};
static const char *const file_keys[] = {"file", NULL};
static const char *const *const initial_keys[] = {arc_keys, line_keys,
  constant_keys, file_keys};
static const char *const traction_keys[] = {"from", "to", "P1", "P2", NULL};
#line 315 "paper/scene.nw"
/* the index of w in the NULL-terminated list names, or -1 */
static int name_index(const char *const *names, const char *w)
{
  int i;
  for (i = 0; names[i]; i++)
    if (strcmp(names[i], w) == 0) return i;
  return -1;
}
#line 327 "paper/scene.nw"
/* buf = the names, comma-separated (truncated to size) */
static const char *name_list(const char *const *names, char *buf,
                             size_t size)
{
  size_t used = 0;
  int i;
  buf[0] = '\0';
  for (i = 0; names[i] && used < size; i++)
    used += (size_t)snprintf(buf + used, size - used, "%s%s",
                             i ? ", " : "", names[i]);
  return buf;
}
#line 350 "paper/scene.nw"
enum { ENTRY_VALUE = 256, TABLE_MAX = 64 };

typedef struct {
  char sec[16], key[16];  /* a section and a key of the schema */
  char val[ENTRY_VALUE];  /* the value, without blanks around or comment */
  int line;               /* its line in the scene file; 0: -s or default */
  const char *override;   /* the -s string that set it, or NULL */
} Entry;
#line 364 "paper/scene.nw"
typedef struct {
  const char *path;      /* the scene file: the first word of every message */
  Status *st;            /* where a failure is told (may be NULL) */
  int failed;            /* 0, or the code of the failure told */
  Entry e[TABLE_MAX];    /* the values given, in the order met */
  int n;                 /* entries used */
  FILE *fp;              /* the reader: the scene file, */
  int line;              /* the number of the line just read, 0 after it, */
  int indented;          /* whether that line starts with a blank, */
  const Entry *prev;     /* and the entry set by the previous key line */
  const char *override;  /* the override being applied, or NULL */
  Entry last;            /* the value converted last: a check blames it */
} Loader;
#line 395 "paper/scene.nw"
#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif
#line 405 "paper/scene.nw"
/* tell "fmt ..." as the failure of L, STATUS_INPUT */
static PRINTF_LIKE(2, 0)
int vfail(Loader *L, const char *fmt, va_list ap)
{
  char msg[sizeof ((Status *)0)->msg];
  vsnprintf(msg, sizeof msg, fmt, ap);
  return L->failed = status_set(L->st, STATUS_INPUT, "%s", msg);
}

static PRINTF_LIKE(2, 3)
int fail(Loader *L, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vfail(L, fmt, ap);
  va_end(ap);
  return L->failed;
}
#line 427 "paper/scene.nw"
/* buf = the scene path, and the override if one set the value */
static void origin(const Loader *L, const char *override, char *buf,
                   size_t size)
{
  if (override) snprintf(buf, size, "%s (-s %s)", L->path, override);
  else snprintf(buf, size, "%s", L->path);
}
#line 438 "paper/scene.nw"
/* tell "ORIGIN: section.key = value: reason" about e */
static PRINTF_LIKE(3, 0)
int vbad(Loader *L, const Entry *e, const char *fmt, va_list ap)
{
  char where[640], why[512];
  origin(L, e->override, where, sizeof where);
  vsnprintf(why, sizeof why, fmt, ap);
  return fail(L, "%s: %s.%s = %s: %s", where, e->sec, e->key, e->val, why);
}
#line 451 "paper/scene.nw"
static PRINTF_LIKE(3, 4)
int bad(Loader *L, const Entry *e, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vbad(L, e, fmt, ap);
  va_end(ap);
  return L->failed;
}

static PRINTF_LIKE(2, 3)
int blame(Loader *L, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vbad(L, &L->last, fmt, ap);
  va_end(ap);
  return L->failed;
}
#line 480 "paper/scene.nw"
/* e = sec.key = val at L's current origin, if the schema has the names */
static int admit(Loader *L, Entry *e, const char *sec, const char *key,
                 const char *val)
{
  char where[640], list[256];
  int s = name_index(section_names, sec);
  origin(L, L->override, where, sizeof where);
  
#line 502 "paper/scene.nw"
if (!*sec)
  return fail(L, "%s: line %d: %s = %s comes before any [section]", where,
              L->line, key, val);
if (s < 0)
  return fail(L, "%s: [%s]: unknown section (the sections are %s)", where,
              sec, name_list(section_names, list, sizeof list));
if (name_index(section_keys[s], key) < 0)
  return fail(L, "%s: %s.%s = %s: unknown key ([%s] has %s)", where, sec,
              key, val, sec, name_list(section_keys[s], list, sizeof list));
#line 488 "paper/scene.nw"
  if (strlen(val) >= sizeof e->val)
    return fail(L, "%s: %s.%s: value longer than %d characters", where, sec,
                key, (int)sizeof e->val - 1);
  snprintf(e->sec, sizeof e->sec, "%s", sec);
  snprintf(e->key, sizeof e->key, "%s", key);
  snprintf(e->val, sizeof e->val, "%s", val);
  e->line = L->line;
  e->override = L->override;
  return 0;
}
#line 515 "paper/scene.nw"
/* the entry sec.key of the table, or NULL */
static Entry *find(Loader *L, const char *sec, const char *key)
{
  int i;
  for (i = 0; i < L->n; i++)
    if (strcmp(L->e[i].sec, sec) == 0 && strcmp(L->e[i].key, key) == 0)
      return &L->e[i];
  return NULL;
}
#line 529 "paper/scene.nw"
/* append e; the schema and the refusal of duplicates bound the table */
static Entry *add(Loader *L, const Entry *e)
{
  if (L->n == TABLE_MAX) {
    fail(L, "%s: more than %d keys", L->path, TABLE_MAX);
    return NULL;
  }
  L->e[L->n] = *e;
  return &L->e[L->n++];
}
#line 559 "paper/scene.nw"
/* inih's reader: one line into buf, counted; NULL at the end or a failure */
static char *read_line(char *buf, int size, void *user)
{
  Loader *L = user;
  int c = EOF, n = 0;
  if (L->failed) return NULL;
  while (n < size - 1 && (c = getc(L->fp)) != EOF)
    if ((buf[n++] = (char)c) == '\n') break;
  if (n == 0) return NULL;
  buf[n] = '\0';
  L->line++;
  L->indented = buf[0] == ' ' || buf[0] == '\t';
  
#line 579 "paper/scene.nw"
if (n == size - 1 && buf[n - 1] != '\n' && !feof(L->fp)) {
  fail(L, "%s: line %d: longer than %d characters", L->path, L->line,
       size - 2);
  return NULL;
}
if (strlen(buf) < (size_t)n) {
  fail(L, "%s: line %d: a NUL byte: a scene file is text (ASCII or UTF-8, "
       "not UTF-16)", L->path, L->line);
  return NULL;
}
#line 572 "paper/scene.nw"
  return buf;
}
#line 596 "paper/scene.nw"
/* inih's handler: store section.key = val, read on line L->line */
static int on_key(void *user, const char *sec, const char *key,
                  const char *val)
{
  Loader *L = user;
  Entry e;
  const Entry *old;
  if (!key) return 1;
  if (admit(L, &e, sec, key, val)) return 0;
  
#line 613 "paper/scene.nw"
if (L->indented && L->prev && strcmp(L->prev->sec, sec) == 0
    && strcmp(L->prev->key, key) == 0) {
  fail(L, "%s: line %d: this indented line continues the value of %s.%s: "
       "a scene value is one line (remove the indentation)", L->path,
       L->line, sec, key);
  return 0;
}
#line 606 "paper/scene.nw"
  
#line 624 "paper/scene.nw"
if ((old = find(L, sec, key))) {
  bad(L, &e, "duplicate key on line %d (first given on line %d)", L->line,
      old->line);
  return 0;
}
#line 607 "paper/scene.nw"
  return (L->prev = add(L, &e)) != NULL;
}
#line 636 "paper/scene.nw"
/* the table = the entries of the scene file L->path */
static int read_scene(Loader *L)
{
  int rc;
  errno = 0;
  if (!(L->fp = fopen(L->path, "r")))
    return fail(L, "%s: cannot read: %s", L->path, strerror(errno));
  rc = ini_parse_stream(read_line, L, on_key, L);
  if (!L->failed && ferror(L->fp))
    fail(L, "%s: cannot read: %s", L->path,
         errno ? strerror(errno) : "read error");
  fclose(L->fp);
  L->fp = NULL;
  
#line 657 "paper/scene.nw"
if (rc > 0 && (!L->failed || rc < L->line))
  fail(L, "%s: line %d: syntax error: expected [section], key = value, "
       "a comment or a blank line", L->path, rc);
if (rc == -2 && !L->failed)
  L->failed = status_set(L->st, STATUS_SYSTEM, "%s: out of memory",
                         L->path);
#line 650 "paper/scene.nw"
  L->line = 0;
  return L->failed;
}
#line 677 "paper/scene.nw"
/* the text of s without leading and trailing blanks (s is modified) */
static char *trim(char *s)
{
  char *end;
  while (*s == ' ' || *s == '\t') s++;
  end = s + strlen(s);
  while (end > s && (end[-1] == ' ' || end[-1] == '\t')) end--;
  *end = '\0';
  return s;
}
#line 693 "paper/scene.nw"
/* apply the override o = "section.key=value" onto the table */
static int apply_override(Loader *L, const char *o)
{
  char *copy, *eq, *dot, *sec = NULL, *key = NULL, *val = NULL;
  Entry e, *old;
  L->override = o;
  if (!(copy = malloc(strlen(o) + 1)))
    return L->failed = status_set(L->st, STATUS_SYSTEM, "out of memory");
  strcpy(copy, o);
  eq = strchr(copy, '=');
  dot = strchr(copy, '.');
  
#line 717 "paper/scene.nw"
if (eq && dot && dot < eq) {
  *eq = *dot = '\0';
  sec = trim(copy);
  key = trim(dot + 1);
  val = trim(eq + 1);
}
if (!sec || !*sec || !*key)
  fail(L, "%s (-s %s): malformed override: expected section.key=value",
       L->path, o);
else
  admit(L, &e, sec, key, val);
#line 705 "paper/scene.nw"
  free(copy);
  if (L->failed) return L->failed;
  if ((old = find(L, e.sec, e.key))) {
    if (*e.val) *old = e;
    else *old = L->e[--L->n];          /* unset: the last entry fills the gap */
  } else if (*e.val) add(L, &e);
  return L->failed;
}
#line 738 "paper/scene.nw"
/* x = the number str: NULL, or why str is not a number */
static const char *to_real(const char *str, double *x)
{
  char *end;
  errno = 0;
  *x = strtod(str, &end);
  if (end == str || *end) return "not a number";
  if (errno == ERANGE) return "out of the range of a double";
  if (!isfinite(*x)) return "not a finite number";
  return NULL;
}
#line 753 "paper/scene.nw"
/* k = the integer str: NULL, or why str is not an int */
static const char *to_int(const char *str, int *k)
{
  char *end;
  long v;
  errno = 0;
  v = strtol(str, &end, 10);
  if (end == str || *end) return "not an integer";
  if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
    return "out of the range of an int";
  *k = (int)v;
  return NULL;
}
#line 770 "paper/scene.nw"
/* a hint on why val is malformed, or "" */
static const char *hint(const char *val)
{
  if (!*val) return " (the value is empty)";
  if (strchr(val, '#'))
    return " (a comment after a value starts with ' ;', not '#')";
  if (strchr(val, ';'))
    return " (a comment after a value needs a blank before ';')";
  return "";
}
#line 786 "paper/scene.nw"
#define REQUIRED NULL   /* no default: the key must be given */

/* L->last = the entry of sec.key, or its default dflt; NULL if missing */
static const Entry *entry(Loader *L, const char *sec, const char *key,
                          const char *dflt)
{
  const Entry *e = find(L, sec, key);
  if (e) L->last = *e;
  else if (!dflt) {
    fail(L, "%s: %s.%s: missing required key", L->path, sec, key);
    return NULL;
  } else {
    memset(&L->last, 0, sizeof L->last);
    snprintf(L->last.sec, sizeof L->last.sec, "%s", sec);
    snprintf(L->last.key, sizeof L->last.key, "%s", key);
    snprintf(L->last.val, sizeof L->last.val, "%s", dflt);
  }
  return &L->last;
}
#line 809 "paper/scene.nw"
/* x = the number sec.key (default dflt) */
static int real(Loader *L, const char *sec, const char *key,
                const char *dflt, double *x)
{
  const char *why;
  if (!entry(L, sec, key, dflt)) return L->failed;
  if ((why = to_real(L->last.val, x)))
    return blame(L, "%s%s", why, hint(L->last.val));
  return 0;
}
#line 822 "paper/scene.nw"
/* k = the integer sec.key (default dflt) */
static int integer(Loader *L, const char *sec, const char *key,
                   const char *dflt, int *k)
{
  const char *why;
  if (!entry(L, sec, key, dflt)) return L->failed;
  if ((why = to_int(L->last.val, k)))
    return blame(L, "%s%s", why, hint(L->last.val));
  return 0;
}
#line 835 "paper/scene.nw"
/* k = the index of the word sec.key (default dflt) in names */
static int word(Loader *L, const char *sec, const char *key,
                const char *dflt, const char *const *names, int *k)
{
  char list[256];
  if (!entry(L, sec, key, dflt)) return L->failed;
  if ((*k = name_index(names, L->last.val)) >= 0) return 0;
  return blame(L, "unknown value (accepted: %s)",
               name_list(names, list, sizeof list));
}
#line 850 "paper/scene.nw"
/* refuse any of sec's keys: they mean nothing with what = value */
static int refuse_keys(Loader *L, const char *sec, const char *const *keys,
                       const char *what, const char *value)
{
  const Entry *e;
  for (; *keys; keys++)
    if ((e = find(L, sec, *keys)))
      return bad(L, e, "has no effect with %s = %s", what, value);
  return 0;
}
#line 869 "paper/scene.nw"
/* [geometry]: a < b, and gamma, with b - a and gamma (b - a) finite */
static int read_geometry(Loader *L, Scene *s)
{
  int rc;
  if ((rc = real(L, "geometry", "a", REQUIRED, &s->problem.a))
      || (rc = real(L, "geometry", "b", REQUIRED, &s->problem.b)))
    return rc;
  if (!(s->problem.b > s->problem.a)) return blame(L, "must exceed geometry.a = %g", s->problem.a);
  if (!isfinite(s->problem.b - s->problem.a))
    return blame(L, "the width b - a overflows a double");
  if ((rc = real(L, "geometry", "gamma", REQUIRED, &s->problem.gamma))) return rc;
  if (!isfinite(s->problem.gamma * (s->problem.b - s->problem.a)))
    return blame(L, "the area gamma (b - a) overflows a double");
  return 0;
}
#line 894 "paper/scene.nw"
/* [design]: N >= 1, C0 > 0, C1 >= 0, C2 > 0 */
static int read_design(Loader *L, Scene *s)
{
  int rc;
  if ((rc = integer(L, "design", "N", REQUIRED, &s->problem.N))) return rc;
  if (s->problem.N < 1) return blame(L, "must be >= 1 (design intervals)");
  if ((rc = real(L, "design", "C0", REQUIRED, &s->problem.C0))) return rc;
  if (!(s->problem.C0 > 0)) return blame(L, "must be > 0 (the bound of alpha)");
  if ((rc = real(L, "design", "C1", REQUIRED, &s->problem.C1))) return rc;
  if (!(s->problem.C1 >= 0)) return blame(L, "must be >= 0 (the bound of |alpha'|)");
  if ((rc = real(L, "design", "C2", REQUIRED, &s->problem.C2))) return rc;
  if (!(s->problem.C2 > 0)) return blame(L, "must be > 0 (the area of the body)");
  return 0;
}
#line 920 "paper/scene.nw"
/* [mesh]: M, R >= 1, refine >= 1, 72 N (M + R) <= INT_MAX after the
   refinement, C0 < C0prime < gamma */
static int read_mesh(Loader *L, Scene *s)
{
  int rc, k;
  if ((rc = integer(L, "mesh", "M", REQUIRED, &s->problem.M))) return rc;
  if (s->problem.M < 1) return blame(L, "must be >= 1 (moving rows of cells)");
  if ((rc = integer(L, "mesh", "R", REQUIRED, &s->problem.R))) return rc;
  if (s->problem.R < 1) return blame(L, "must be >= 1 (fixed rows of cells)");
  if ((rc = integer(L, "mesh", "refine", "1", &k))) return rc;
  if (k < 1) return blame(L, "must be >= 1 (the factor of N, M and R)");
  
#line 954 "paper/scene.nw"
if (!(72.0 * k * s->problem.N * k * ((double)s->problem.M + s->problem.R) <= INT_MAX))
  return bad(L, find(L, "mesh", k > 1 ? "refine" : "R"),
             "with design.N = %d, mesh.M = %d, mesh.R = %d and "
             "mesh.refine = %d the mesh has 2 N (M + R) = %.0f triangles, "
             "more than INT_MAX / 36 = %d: the stiffness matrix has 36 "
             "entries a triangle, counted in C ints", s->problem.N, s->problem.M, s->problem.R, k,
             2.0 * k * s->problem.N * k * ((double)s->problem.M + s->problem.R), INT_MAX / 36);
#line 932 "paper/scene.nw"
  s->problem.N *= k, s->problem.M *= k, s->problem.R *= k;
  if ((rc = real(L, "mesh", "C0prime", REQUIRED, &s->problem.C0prime))) return rc;
  if (!(s->problem.C0prime > s->problem.C0))
    return blame(L, "must exceed design.C0 = %g: the moving boundary must "
                 "stay below the fixed part of the mesh", s->problem.C0);
  if (!(s->problem.gamma > s->problem.C0prime))
    return bad(L, find(L, "geometry", "gamma"), "must exceed mesh.C0prime "
               "= %g: the fixed part of the mesh needs a height", s->problem.C0prime);
  return 0;
}
#line 985 "paper/scene.nw"
/* B != {} iff 0 <= S <= C0 (b-a), S = gamma (b-a) - C2 */
static int check_admissible(Loader *L, Scene *s)
{
  double w = s->problem.b - s->problem.a, S = s->problem.gamma * w - s->problem.C2;
  double slack = 1e-12 * s->problem.gamma * w;
  if (S >= -slack && S <= s->problem.C0 * w + slack) return 0;
  return bad(L, find(L, "design", "C2"), "C0, C1, C2 admit no shape: the "
             "area under alpha would be S = gamma (b-a) - C2 = %g, outside "
             "[0, C0 (b-a)] = [0, %g]", S, s->problem.C0 * w);
}
#line 1005 "paper/scene.nw"
/* the keys of an arc: centre (arc_x1, arc_x2), arc_radius > 0 */
static int read_arc_shape(Loader *L, Shape *sh)
{
  int rc;
  sh->kind = SHAPE_ARC;
  if ((rc = real(L, "design", "arc_x1", REQUIRED, &sh->centre[0]))
      || (rc = real(L, "design", "arc_x2", REQUIRED, &sh->centre[1]))
      || (rc = real(L, "design", "arc_radius", REQUIRED, &sh->radius)))
    return rc;
  if (!(sh->radius > 0)) return blame(L, "the radius must be > 0");
  return 0;
}
#line 1021 "paper/scene.nw"
/* the keys of a line: line_start at x1 = a, line_end at x1 = b */
static int read_line_shape(Loader *L, Shape *sh)
{
  int rc;
  sh->kind = SHAPE_LINE;
  if ((rc = real(L, "design", "line_start", REQUIRED, &sh->start)))
    return rc;
  return real(L, "design", "line_end", REQUIRED, &sh->end);
}
#line 1033 "paper/scene.nw"
/* the key of a constant */
static int read_constant_shape(Loader *L, Shape *sh)
{
  sh->kind = SHAPE_CONSTANT;
  return real(L, "design", "constant", REQUIRED, &sh->value);
}
#line 1045 "paper/scene.nw"
/* alpha0 = the shape of the keys read by read_keys, sampled */
static int fill_formula(Loader *L, Scene *s,
                        int (*read_keys)(Loader *, Shape *))
{
  Shape sh = {0};
  Status why = {STATUS_OK, ""};
  int rc = read_keys(L, &sh);
  if (!rc && design_shape(&s->problem, &sh, s->alpha0, &why))
    rc = blame(L, "%s", why.msg);
  return rc;
}
#line 1061 "paper/scene.nw"
/* buf = file, relative to the directory of the scene file; 0 if it fits */
static int resolve(const char *scene, const char *file, char *buf,
                   size_t size)
{
  const char *slash = strrchr(scene, '/');
  int n;
  if (file[0] == '/' || !slash) n = snprintf(buf, size, "%s", file);
  else n = snprintf(buf, size, "%.*s/%s", (int)(slash - scene), scene, file);
  return n < 0 || (size_t)n >= size;
}
#line 1077 "paper/scene.nw"
/* one line of a shape file: store its last number as alpha0[*row] */
static int read_row(Loader *L, Scene *s, const char *path, int lineno,
                    char *line, int *row)
{
  char *tok, *save = NULL, *hash = strchr(line, '#');
  double x = 0;
  if (hash) *hash = '\0';
  if (!(tok = strtok_r(line, " \t\r\n", &save))) return 0;
  for (; tok; tok = strtok_r(NULL, " \t\r\n", &save))
    if (to_real(tok, &x))
      return blame(L, "%s line %d: '%s' is not a number", path, lineno, tok);
  if (*row <= s->problem.N) s->alpha0[*row] = x;
  (*row)++;
  return 0;
}
#line 1099 "paper/scene.nw"
/* alpha0 = the last column of the N+1 rows of the file at path */
static int read_shape(Loader *L, Scene *s, const char *path)
{
  FILE *fp;
  char *line = NULL;
  size_t cap = 0;
  ssize_t len;
  int rc = 0, row = 0, lineno = 0;
  if (!(fp = fopen(path, "r")))
    return blame(L, "cannot read %s: %s", path, strerror(errno));
  while (!rc && (len = getline(&line, &cap, fp)) != -1)
    rc = strlen(line) < (size_t)len
      ? blame(L, "%s line %d: a NUL byte: a shape file is text", path,
              ++lineno)
      : read_row(L, s, path, ++lineno, line, &row);
  if (!rc && ferror(fp))
    rc = blame(L, "cannot read %s: %s", path, strerror(errno));
  free(line);
  fclose(fp);
  if (!rc && row != s->problem.N + 1)
    rc = blame(L, "%s has %d rows of values, expected N + 1 = %d", path,
               row, s->problem.N + 1);
  return rc;
}
#line 1127 "paper/scene.nw"
/* alpha0 = the shape in the file design.file */
static int fill_file(Loader *L, Scene *s)
{
  char path[4096];
  if (!entry(L, "design", "file", REQUIRED)) return L->failed;
  if (resolve(s->path, L->last.val, path, sizeof path))
    return blame(L, "path longer than %d characters", (int)sizeof path - 1);
  return read_shape(L, s, path);
}
#line 1140 "paper/scene.nw"
/* 0 <= alpha0_i < C0prime at every node */
static int check_alpha0(Loader *L, const Scene *s)
{
  int i;
  for (i = 0; i <= s->problem.N; i++)
    if (!(s->alpha0[i] >= 0 && s->alpha0[i] < s->problem.C0prime))
      return bad(L, find(L, "design", "initial"), "alpha0 = %g at node %d "
                 "(x1 = %g) is outside [0, C0prime) = [0, %g)",
                 s->alpha0[i], i, problem_node_x(&s->problem, i),
                 s->problem.C0prime);
  return 0;
}
#line 1158 "paper/scene.nw"
/* [design] initial: alpha0 at the N+1 nodes */
static int read_initial(Loader *L, Scene *s)
{
  static int (*const read_keys[])(Loader *, Shape *) = {read_arc_shape,
    read_line_shape, read_constant_shape};
  int j, k, rc;
  if ((rc = word(L, "design", "initial", REQUIRED, initial_names, &k)))
    return rc;
  snprintf(s->initial, sizeof s->initial, "%s", initial_names[k]);
  
#line 1178 "paper/scene.nw"
for (j = 0; j < 4; j++)
  if (j != k && refuse_keys(L, "design", initial_keys[j], "initial",
                            initial_names[k]))
    return L->failed;
#line 1168 "paper/scene.nw"
  if (!(s->alpha0 = malloc(((size_t)s->problem.N + 1) * sizeof *s->alpha0)))
    return L->failed = status_set(L->st, STATUS_SYSTEM, "%s: out of memory "
                                  "for %d nodes", L->path, s->problem.N + 1);
  rc = k == 3 ? fill_file(L, s) : fill_formula(L, s, read_keys[k]);
  return rc ? rc : check_alpha0(L, s);
}
#line 1193 "paper/scene.nw"
/* [material]: E > 0, -1 < nu < 1/2, the plane model */
static int read_material(Loader *L, Scene *s)
{
  int rc, k;
  if ((rc = real(L, "material", "E", REQUIRED, &s->problem.E))) return rc;
  if (!(s->problem.E > 0)) return blame(L, "Young's modulus must be > 0");
  if ((rc = real(L, "material", "nu", REQUIRED, &s->problem.nu))) return rc;
  if (!(s->problem.nu < 0.5))
    return blame(L, "nu must be < 0.5: 0.5 is the incompressible limit, "
                 "where this displacement method locks");
  if (!(s->problem.nu > -1)) return blame(L, "nu must be > -1 (stability)");
  if ((rc = word(L, "material", "model", "plane_stress", problem_model_names, &k)))
    return rc;
  s->problem.model = (Plane_model)k;
  return 0;
}
#line 1219 "paper/scene.nw"
/* the loaded interval [from, to] inside the side, and a non-zero P */
static int read_traction(Loader *L, Scene *s, Side_id id)
{
  const char *sec = side_names[id];
  Side *d = &s->problem.side[id];
  int rc;
  
#line 1238 "paper/scene.nw"
double lo = id == SIDE_TOP ? s->problem.a : s->problem.C0prime;
double hi = id == SIDE_TOP ? s->problem.b : s->problem.gamma;
const char *part = id == SIDE_TOP ? "the top side, [a, b]" :
  "the part of the side the design never moves, [C0prime, gamma]";
if ((rc = real(L, sec, "from", REQUIRED, &d->from))) return rc;
if (!(d->from >= lo))
  return blame(L, "the loaded interval must lie in %s = [%g, %g]", part,
               lo, hi);
if ((rc = real(L, sec, "to", REQUIRED, &d->to))) return rc;
if (!(d->to > d->from))
  return blame(L, "must exceed %s.from = %g", sec, d->from);
if (!(d->to <= hi))
  return blame(L, "the loaded interval must lie in %s = [%g, %g]", part,
               lo, hi);
#line 1226 "paper/scene.nw"
  if ((rc = real(L, sec, "P1", "0", &d->P[0]))
      || (rc = real(L, sec, "P2", "0", &d->P[1])))
    return rc;
  if (d->P[0] == 0 && d->P[1] == 0)
    return bad(L, find(L, sec, "bc"), "the traction (%s.P1, %s.P2) is "
               "zero: use bc = free", sec, sec);
  return 0;
}
#line 1256 "paper/scene.nw"
/* [left], [right] or [top]: the condition, free when not given */
static int read_side(Loader *L, Scene *s, Side_id id)
{
  const char *sec = side_names[id];
  int k, rc;
  if ((rc = word(L, sec, "bc", "free", problem_bc_names, &k))) return rc;
  s->problem.side[id].kind = (Bc_kind)k;
  if (k != BC_TRACTION)
    return refuse_keys(L, sec, traction_keys, "bc", problem_bc_names[k]);
  return read_traction(L, s, id);
}
#line 1277 "paper/scene.nw"
/* some side holds u1: clamped anywhere, or a roller on left or right */
static int check_held(Loader *L, const Scene *s)
{
  int id, held = 0;
  for (id = 0; id < SIDE_COUNT; id++)
    held |= s->problem.side[id].kind == BC_CLAMPED
      || (s->problem.side[id].kind == BC_ROLLER && id != SIDE_TOP);
  if (held) return 0;
  return fail(L, "%s: left.bc = %s, right.bc = %s, top.bc = %s: no side "
              "holds u1: frictionless contact cannot stop the body sliding "
              "(singular problem)", L->path, problem_bc_name(s->problem.side[0].kind),
              problem_bc_name(s->problem.side[1].kind), problem_bc_name(s->problem.side[2].kind));
}
#line 1293 "paper/scene.nw"
/* the three sides */
static int read_sides(Loader *L, Scene *s)
{
  int id, rc;
  for (id = 0; id < SIDE_COUNT; id++)
    if ((rc = read_side(L, s, (Side_id)id))) return rc;
  return check_held(L, s);
}
#line 1329 "paper/scene.nw"
/* [contact] model, and g or friction as the law needs */
static int read_contact(Loader *L, Scene *s)
{
  static const char *const g_key[] = {"g", NULL}, *const F_key[] = {"friction", NULL};
  static const char *const *const law_keys[] = {NULL, g_key, F_key};
  Problem *p = &s->problem;
  double *value[] = {NULL, &p->slip_bound, &p->friction};
  int k, rc;
  if ((rc = word(L, "contact", "model", "frictionless", problem_contact_names, &k)))
    return rc;
  p->contact = (Contact_law)k;
  for (int j = 1; j < 3; j++)
    if (j != k && refuse_keys(L, "contact", law_keys[j], "model",
                              problem_contact_names[k]))
      return L->failed;
  if (k == CONTACT_FRICTIONLESS) return 0;
  if ((rc = real(L, "contact", law_keys[k][0], REQUIRED, value[k]))) return rc;
  if (!(*value[k] >= 0))
    return blame(L, "must be >= 0 (%s)", k == CONTACT_TRESCA ? "a slip bound "
                 "in Pa" : "a friction coefficient");
  return 0;
}
#line 1315 "paper/scene.nw"
/* [body_force] F, [contact] model */
static int read_loads(Loader *L, Scene *s)
{
  int rc;
  if ((rc = real(L, "body_force", "F1", "0", &s->problem.F[0]))
      || (rc = real(L, "body_force", "F2", "0", &s->problem.F[1])))
    return rc;
  s->problem.has_body_force = s->problem.F[0] != 0 || s->problem.F[1] != 0;
  return read_contact(L, s);
}
#line 1363 "paper/scene.nw"
/* [solver]: the method, 0 < tol < 1, max_iter >= 1, 0 < omega < 2 */
static int read_solver(Loader *L, Scene *s)
{
  Qp_options *o = &s->solver, d;
  char tol[32], max_iter[32], omega[32];
  int rc, k;
  if ((rc = word(L, "solver", "state", "pdas", state_names, &k))) return rc;
  d = qp_options_default((Qp_method)k);
  snprintf(tol, sizeof tol, "%.17g", d.tol);
  snprintf(max_iter, sizeof max_iter, "%d", d.max_iter);
  snprintf(omega, sizeof omega, "%.17g", d.omega);
  o->method = (Qp_method)k;
  if (k == QP_PSOR && s->problem.contact != CONTACT_FRICTIONLESS)
    return blame(L, "cannot take friction (contact.model = %s): a slip bound "
                 "bounds a force, and psor bounds unknowns; use pdas or cgssor",
                 problem_contact_name(s->problem.contact));
  if ((rc = real(L, "solver", "tol", tol, &o->tol))) return rc;
  if (!(o->tol > 0 && o->tol < 1))
    return blame(L, "must lie in (0, 1): it is a relative residual");
  if ((rc = integer(L, "solver", "max_iter", max_iter, &o->max_iter)))
    return rc;
  if (o->max_iter < 1) return blame(L, "must be >= 1");
  if ((rc = real(L, "solver", "omega", omega, &o->omega))) return rc;
  if (!(o->omega > 0 && o->omega < 2))
    return blame(L, "must lie in (0, 2), where SOR converges");
  return 0;
}
#line 1400 "paper/scene.nw"
/* [optimizer]: the method, its metric, 0 < tol < 1, max_iter >= 1 */
static int read_optimizer(Loader *L, Scene *s)
{
  static const char *const metric_key[] = {"metric", NULL};
  Opt_options *o = &s->optimizer, d;
  char tol[32], max_iter[32];
  int rc, k;
  if ((rc = word(L, "optimizer", "method", "newton", opt_method_names, &k)))
    return rc;
  d = opt_options_default((Opt_method)k);
  snprintf(tol, sizeof tol, "%.17g", d.tol);
  snprintf(max_iter, sizeof max_iter, "%d", d.max_iter);
  o->method = (Opt_method)k;
  if (o->method == OPT_NEWTON && refuse_keys(L, "optimizer", metric_key,
                                             "method", "newton"))
    return L->failed;
  if ((rc = word(L, "optimizer", "metric", opt_metric_names[d.metric],
                 opt_metric_names, &k)))
    return rc;
  o->metric = (Opt_metric)k;
  if (o->method == OPT_PROJGRAD && o->metric == OPT_METRIC_SCHUR)
    return blame(L, "schur needs optimizer.method = slsqp: Algorithm 4.1 "
                 "projects in the euclidean metric");
  if ((rc = real(L, "optimizer", "tol", tol, &o->tol))) return rc;
  if (!(o->tol > 0 && o->tol < 1))
    return blame(L, "must lie in (0, 1): it is a relative measure");
  if ((rc = integer(L, "optimizer", "max_iter", max_iter, &o->max_iter)))
    return rc;
  if (o->max_iter < 1) return blame(L, "must be >= 1");
  return 0;
}
#line 1441 "paper/scene.nw"
/* the scene = the table, checked */
static int convert(Loader *L, Scene *s)
{
  static int (*const step[])(Loader *, Scene *) = {read_geometry,
    read_design, read_mesh, check_admissible, read_initial, read_material,
    read_sides, read_loads, read_solver, read_optimizer};
  size_t i;
  int rc = 0;
  for (i = 0; !rc && i < sizeof step / sizeof step[0]; i++)
    rc = step[i](L, s);
  return rc;
}
#line 1458 "paper/scene.nw"
int scene_load(Scene *s, const char *path, int noverride,
               char *const *override, Status *st)
{
  Loader L;
  int i, rc;
  memset(s, 0, sizeof *s);
  if (strlen(path) >= sizeof s->path)
    return status_set(st, STATUS_INPUT, "%.64s...: scene path longer than "
                      "%d characters", path, (int)sizeof s->path - 1);
  strcpy(s->path, path);
  memset(&L, 0, sizeof L);
  L.path = path;
  L.st = st;
  rc = read_scene(&L);
  for (i = 0; !rc && i < noverride; i++) rc = apply_override(&L, override[i]);
  if (!rc) rc = convert(&L, s);
  if (rc) scene_free(s);
  return rc;
}
#line 1481 "paper/scene.nw"
void scene_free(Scene *s)
{
  if (!s) return;
  free(s->alpha0);
  s->alpha0 = NULL;
}
