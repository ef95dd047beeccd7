#line 343 "paper/scene.nw"
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include <ini.h>
#include "design.h"
#include "friction.h"
#include "scene.h"
#line 385 "paper/scene.nw"
static const char *const side_names[] = {"left", "right", "top", NULL};
static const char *const state_names[] = {"pdas", "psor", "cgssor", NULL};
static const char *const initial_names[] = {"arc", "line", "constant",
  "file", NULL};
#line 392 "paper/scene.nw"
/* the index of w in the NULL-terminated list names, or -1 */
static int name_index(const char *const *names, const char *w)
{
  int i;
  for (i = 0; names[i]; i++)
    if (strcmp(names[i], w) == 0) return i;
  return -1;
}
#line 405 "paper/scene.nw"
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
static const char *name_list(const char *const *names, char *buf,
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
#line 443 "paper/scene.nw"
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
#line 472 "paper/scene.nw"
typedef enum { KEY_REAL, KEY_INT, KEY_WORD, KEY_TEXT } Key_type;
typedef const char *Default_of(const char *key, int k, char *buf,
                               size_t size);
#define AT(field) ((long)offsetof(Scene, field))
#define AT_DEFAULT (-1L)  /* no field: written as its default */

typedef struct {
  const char *sec, *key;     /* the section and the key */
  Key_type type;             /* a real, an integer, a word, a text */
  const char *const *words;  /* the words a word (or design.initial) takes */
  long at;                   /* the offset of its value in a Scene */
  const char *unit;          /* m, Pa, ...; 1: a pure number; -: none */
  const char *dflt;          /* the default as a scene writes it, or */
  Default_of *by;            /* the default under the selector's word k */
  const char *selector;      /* a word of the section that decides: */
  const char *when;          /* its words with which the key means something,
                                blank-separated (NULL: all of them) */
  const char *accepted;      /* the values accepted (NULL: the words) */
  const char *meaning;       /* one line */
} Key;

_Static_assert(sizeof(Plane_model) == sizeof(int)
               && sizeof(Bc_kind) == sizeof(int)
               && sizeof(Contact_law) == sizeof(int)
               && sizeof(Qp_method) == sizeof(int)
               && sizeof(Opt_method) == sizeof(int)
               && sizeof(Opt_metric) == sizeof(int),
               "a word of a scene is an enum stored as an int");
#line 642 "paper/scene.nw"
static const Key keys[] = {
  
#line 506 "paper/scene.nw"
{"geometry", "a", KEY_REAL, .at = AT(problem.a), .unit = "m",
 .accepted = "finite", .meaning = "x1 of the left side"},
{"geometry", "b", KEY_REAL, .at = AT(problem.b), .unit = "m",
 .accepted = "a < b, b - a in [1e-30, 1e30]",
 .meaning = "x1 of the right side"},
{"geometry", "gamma", KEY_REAL, .at = AT(problem.gamma), .unit = "m",
 .accepted = "> mesh.C0prime", .meaning = "x2 of the top side"},
{"design", "N", KEY_INT, .at = AT(problem.N), .unit = "-",
 .accepted = ">= 1", .meaning = "intervals of the design, N + 1 nodes"},
{"design", "C0", KEY_REAL, .at = AT(problem.C0), .unit = "m",
 .accepted = "> 0", .meaning = "bound of alpha in U_ad"},
{"design", "C1", KEY_REAL, .at = AT(problem.C1), .unit = "1",
 .accepted = ">= 0", .meaning = "bound of |alpha'| in U_ad"},
{"design", "C2", KEY_REAL, .at = AT(problem.C2), .unit = "m^2",
 .accepted = "gamma (b - a) - C2 in [0, C0 (b - a)]",
 .meaning = "area of the body in U_ad"},
{"design", "initial", KEY_TEXT, initial_names, AT(initial), "-",
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
 .meaning = "a shape file, relative to the scene's folder"},
#line 644 "paper/scene.nw"
  
#line 549 "paper/scene.nw"
{"mesh", "M", KEY_INT, .at = AT(problem.M), .unit = "-",
 .accepted = ">= 1", .meaning = "moving rows of cells, alpha to C0prime"},
{"mesh", "R", KEY_INT, .at = AT(problem.R), .unit = "-",
 .accepted = ">= 1", .meaning = "fixed rows of cells, C0prime to gamma"},
{"mesh", "C0prime", KEY_REAL, .at = AT(problem.C0prime), .unit = "m",
 .accepted = "C0 < C0prime < gamma",
 .meaning = "top of the moving rows of cells"},
{"mesh", "refine", KEY_INT, .at = AT_DEFAULT, .unit = "-", .dflt = "1",
 .accepted = ">= 1", .meaning = "multiplies N, M and R: a finer mesh"},
{"material", "E", KEY_REAL, .at = AT(problem.E), .unit = "Pa",
 .accepted = "1e-30 <= E <= 1e30", .meaning = "Young's modulus"},
{"material", "nu", KEY_REAL, .at = AT(problem.nu), .unit = "1",
 .accepted = "-1 < nu < 0.5", .meaning = "Poisson's ratio"},
{"material", "model", KEY_WORD, problem_model_names, AT(problem.model),
 "-", "plane_stress", .meaning = "the plane model"},
#line 645 "paper/scene.nw"
  
#line 569 "paper/scene.nw"
#define SIDE_KEYS(sec, i, lo, hi, what)                                    \
  {sec, "bc", KEY_WORD, problem_bc_names, AT(problem.side[i].kind), "-",   \
   "free", .meaning = "the condition of the " what},                       \
  {sec, "from", KEY_REAL, .at = AT(problem.side[i].from), .unit = "m",     \
   .selector = "bc", .when = "traction", .accepted = lo,                   \
   .meaning = "start of the loaded interval"},                             \
  {sec, "to", KEY_REAL, .at = AT(problem.side[i].to), .unit = "m",         \
   .selector = "bc", .when = "traction", .accepted = hi,                   \
   .meaning = "end of the loaded interval"},                               \
  {sec, "P1", KEY_REAL, .at = AT(problem.side[i].P[0]), .unit = "Pa",      \
   .dflt = "0", .selector = "bc", .when = "traction",                      \
   .accepted = "0 or |P1| / E in [1e-30, 1e30]",                            \
   .meaning = "the traction, x1 component; (P1, P2) != 0"},  \
  {sec, "P2", KEY_REAL, .at = AT(problem.side[i].P[1]), .unit = "Pa",      \
   .dflt = "0", .selector = "bc", .when = "traction",                      \
   .accepted = "0 or |P2| / E in [1e-30, 1e30]",                            \
   .meaning = "the traction, x2 component; (P1, P2) != 0"}
SIDE_KEYS("left", SIDE_LEFT, "C0prime <= from < to", "from < to <= gamma",
          "left side, x1 = a"),
SIDE_KEYS("right", SIDE_RIGHT, "C0prime <= from < to", "from < to <= gamma",
          "right side, x1 = b"),
SIDE_KEYS("top", SIDE_TOP, "a <= from < to", "from < to <= b",
          "top side, x2 = gamma"),
#line 646 "paper/scene.nw"
  
#line 596 "paper/scene.nw"
{"body_force", "F1", KEY_REAL, .at = AT(problem.F[0]), .unit = "N/m^3",
 .dflt = "0", .accepted = "0 or |F1| (b - a) / E in [1e-30, 1e30]",
 .meaning = "the body force, x1 component"},
{"body_force", "F2", KEY_REAL, .at = AT(problem.F[1]), .unit = "N/m^3",
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
#line 647 "paper/scene.nw"
  
#line 617 "paper/scene.nw"
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
 "-", "newton", .meaning = "the optimiser; projgrad is Algorithm 4.1"},
{"optimizer", "metric", KEY_WORD, opt_metric_names, AT(optimizer.metric),
 "-", .by = optimizer_default, .selector = "method",
 .when = "slsqp projgrad", .meaning = "the metric; projgrad takes euclidean"},
{"optimizer", "tol", KEY_REAL, .at = AT(optimizer.tol), .unit = "1",
 .by = optimizer_default, .selector = "method", .accepted = "0 < tol < 1",
 .meaning = "the projected-gradient norm to reach"},
{"optimizer", "max_iter", KEY_INT, .at = AT(optimizer.max_iter),
 .unit = "-", .by = optimizer_default, .selector = "method",
 .accepted = ">= 1", .meaning = "iteration limit of the optimiser"},
#line 648 "paper/scene.nw"
};
enum { NKEYS = sizeof keys / sizeof keys[0] };
#line 654 "paper/scene.nw"
/* the record of sec.key, or NULL */
static const Key *key_find(const char *sec, const char *key)
{
  int i;
  for (i = 0; i < NKEYS; i++)
    if (strcmp(keys[i].sec, sec) == 0 && strcmp(keys[i].key, key) == 0)
      return &keys[i];
  return NULL;
}

/* whether sec is a section of the table */
static int section_known(const char *sec)
{
  int i;
  for (i = 0; i < NKEYS; i++)
    if (strcmp(keys[i].sec, sec) == 0) return 1;
  return 0;
}
#line 677 "paper/scene.nw"
/* buf = the sections (sec NULL) or the keys of sec, comma-separated */
static const char *key_names(const char *sec, char *buf, size_t size)
{
  int i;
  buf[0] = '\0';
  for (i = 0; i < NKEYS; i++) {
    const char *name = sec ? keys[i].key : keys[i].sec;
    if (sec ? strcmp(keys[i].sec, sec) != 0
            : i > 0 && strcmp(keys[i].sec, keys[i - 1].sec) == 0)
      continue;
    if (buf[0]) cat(buf, size, ", ");
    cat(buf, size, name);
  }
  return buf;
}
#line 696 "paper/scene.nw"
/* whether k means something when its selector has the word w */
static int key_means(const Key *k, const char *w)
{
  size_t n = strlen(w);
  const char *p;
  if (!k->when) return 1;
  if (!n) return 0;
  for (p = k->when; (p = strstr(p, w)); p += n)
    if ((p == k->when || p[-1] == ' ') && (p[n] == ' ' || !p[n])) return 1;
  return 0;
}
#line 719 "paper/scene.nw"
enum { ENTRY_VALUE = 256, TABLE_MAX = 64 };
_Static_assert((int)NKEYS <= (int)TABLE_MAX, "a scene's values fit the loader");

typedef struct {
  char sec[16], key[16];  /* a section and a key of the table of keys */
  char val[ENTRY_VALUE];  /* the value, without blanks around or comment */
  int line;               /* its line in the scene file; 0: -s or default */
  const char *override;   /* the -s string that set it, or NULL */
} Entry;
#line 734 "paper/scene.nw"
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
#line 765 "paper/scene.nw"
#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif
#line 775 "paper/scene.nw"
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
#line 797 "paper/scene.nw"
/* buf = the scene path, and the override if one set the value */
static void origin(const Loader *L, const char *override, char *buf,
                   size_t size)
{
  if (override) snprintf(buf, size, "%s (-s %s)", L->path, override);
  else snprintf(buf, size, "%s", L->path);
}
#line 808 "paper/scene.nw"
/* tell "ORIGIN: section.key = value: reason" about e */
static PRINTF_LIKE(3, 0)
int vbad(Loader *L, const Entry *e, const char *fmt, va_list ap)
{
  char where[640], why[512];
  origin(L, e->override, where, sizeof where);
  vsnprintf(why, sizeof why, fmt, ap);
  return fail(L, "%s: %s.%s = %s: %s", where, e->sec, e->key, e->val, why);
}
#line 821 "paper/scene.nw"
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
#line 850 "paper/scene.nw"
/* e = sec.key = val at L's current origin, if the table of keys has them */
static int admit(Loader *L, Entry *e, const char *sec, const char *key,
                 const char *val)
{
  char where[640], list[256];
  origin(L, L->override, where, sizeof where);
  
#line 871 "paper/scene.nw"
if (!*sec)
  return fail(L, "%s: line %d: %s = %s comes before any [section]", where,
              L->line, key, val);
if (!section_known(sec))
  return fail(L, "%s: [%s]: unknown section (the sections are %s)", where,
              sec, key_names(NULL, list, sizeof list));
if (!key_find(sec, key))
  return fail(L, "%s: %s.%s = %s: unknown key ([%s] has %s)", where, sec,
              key, val, sec, key_names(sec, list, sizeof list));
#line 857 "paper/scene.nw"
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
#line 884 "paper/scene.nw"
/* the entry sec.key of the table, or NULL */
static Entry *find(Loader *L, const char *sec, const char *key)
{
  int i;
  for (i = 0; i < L->n; i++)
    if (strcmp(L->e[i].sec, sec) == 0 && strcmp(L->e[i].key, key) == 0)
      return &L->e[i];
  return NULL;
}
#line 898 "paper/scene.nw"
/* append e; the keys, each stored once at most, bound the table */
static Entry *add(Loader *L, const Entry *e)
{
  if (L->n == TABLE_MAX) {
    fail(L, "%s: more than %d keys", L->path, TABLE_MAX);
    return NULL;
  }
  L->e[L->n] = *e;
  return &L->e[L->n++];
}
#line 950 "paper/scene.nw"
/* tell a NUL byte on the current line */
static int nul_byte(Loader *L)
{
  return fail(L, "%s: line %d: a NUL byte: a scene file is text (ASCII or "
              "UTF-8, not UTF-16)", L->path, L->line);
}
#line 970 "paper/scene.nw"
/* whether buf, the start of a line, is or has begun a comment */
static int in_comment(const char *buf, int line)
{
  const char *p = buf;
  if (line == 1 && strncmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
  p += strspn(p, " \t\r\v\f");
  if (*p == ';' || *p == '#') return 1;
  for (; *p; p++)
    if (*p == ';' && isspace((unsigned char)p[-1])) return 1;
  return 0;
}

/* the line begun in buf is longer than buf: drop the rest of a comment
   (0), or tell the line too long */
static int long_line(Loader *L, const char *buf, int size)
{
  int c;
  if (!in_comment(buf, L->line))
    return fail(L, "%s: line %d: longer than %d characters (only a comment "
                "may be longer)", L->path, L->line, size - 2);
  while ((c = getc(L->fp)) != EOF && c != '\n')
    if (c == '\0') return nul_byte(L);
  return 0;
}
#line 929 "paper/scene.nw"
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
  if (strlen(buf) < (size_t)n) return nul_byte(L), NULL;
  if (n == size - 1 && buf[n - 1] != '\n' && !feof(L->fp)
      && long_line(L, buf, size))
    return NULL;
  return buf;
}
#line 1001 "paper/scene.nw"
/* inih's handler: store section.key = val, read on line L->line */
static int on_key(void *user, const char *sec, const char *key,
                  const char *val)
{
  Loader *L = user;
  Entry e;
  const Entry *old;
  if (!key) return 1;
  if (admit(L, &e, sec, key, val)) return 0;
  
#line 1018 "paper/scene.nw"
if (L->indented && L->prev && strcmp(L->prev->sec, sec) == 0
    && strcmp(L->prev->key, key) == 0) {
  fail(L, "%s: line %d: this indented line continues the value of %s.%s: "
       "a scene value is one line (remove the indentation)", L->path,
       L->line, sec, key);
  return 0;
}
#line 1011 "paper/scene.nw"
  
#line 1029 "paper/scene.nw"
if ((old = find(L, sec, key))) {
  bad(L, &e, "duplicate key on line %d (first given on line %d)", L->line,
      old->line);
  return 0;
}
#line 1012 "paper/scene.nw"
  return (L->prev = add(L, &e)) != NULL;
}
#line 1070 "paper/scene.nw"
/* the failure just told, as STATUS_MEMORY if errno e says memory */
static int for_memory(Loader *L, int e)
{
  if (e != ENOMEM) return L->failed;
  if (L->st) L->st->code = STATUS_MEMORY;
  return L->failed = STATUS_MEMORY;
}

#line 1043 "paper/scene.nw"
/* the table = the entries of the scene file L->path */
static int read_scene(Loader *L)
{
  int rc;
  errno = 0;
  if (!(L->fp = fopen(L->path, "r"))) {
    int e = errno;
    fail(L, "%s: cannot read: %s", L->path, strerror(e));
    return for_memory(L, e);
  }
  rc = ini_parse_stream(read_line, L, on_key, L);
  if (!L->failed && ferror(L->fp)) {
    int e = errno;
    fail(L, "%s: cannot read: %s", L->path, e ? strerror(e) : "read error");
    for_memory(L, e);
  }
  fclose(L->fp);
  L->fp = NULL;
  
#line 1081 "paper/scene.nw"
if (rc > 0 && (!L->failed || rc < L->line))
  fail(L, "%s: line %d: syntax error: expected [section], key = value, "
       "a comment or a blank line", L->path, rc);
if (rc == -2 && !L->failed)
  L->failed = status_set(L->st, STATUS_MEMORY, "%s: out of memory",
                         L->path);
#line 1062 "paper/scene.nw"
  L->line = 0;
  return L->failed;
}
#line 1103 "paper/scene.nw"
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
#line 1120 "paper/scene.nw"
/* e overrides a selector: drop the file's keys meaningless with its word */
static void drop_unused(Loader *L, const Entry *e)
{
  const Key *sel = key_find(e->sec, e->key);
  const char *w = *e->val ? e->val : sel->dflt;
  Entry *old;
  int i;
  for (i = 0; w && i < NKEYS; i++)
    if (keys[i].selector && strcmp(keys[i].sec, e->sec) == 0
        && strcmp(keys[i].selector, e->key) == 0 && !key_means(&keys[i], w)
        && (old = find(L, e->sec, keys[i].key)) && !old->override)
      *old = L->e[--L->n];
}
#line 1139 "paper/scene.nw"
/* apply the override o = "section.key=value" onto the table */
static int apply_override(Loader *L, const char *o)
{
  char *copy, *eq, *dot, *sec = NULL, *key = NULL, *val = NULL;
  Entry e, *old;
  L->override = o;
  if (!(copy = malloc(strlen(o) + 1)))
    return L->failed = status_set(L->st, STATUS_MEMORY, "out of memory");
  strcpy(copy, o);
  eq = strchr(copy, '=');
  dot = strchr(copy, '.');
  
#line 1164 "paper/scene.nw"
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
#line 1151 "paper/scene.nw"
  free(copy);
  if (L->failed) return L->failed;
  drop_unused(L, &e);
  if ((old = find(L, e.sec, e.key))) {
    if (*e.val) *old = e;
    else *old = L->e[--L->n];          /* unset: the last entry fills the gap */
  } else if (*e.val) add(L, &e);
  return L->failed;
}
#line 1193 "paper/scene.nw"
/* whether s is [+-]digits[.digits][e[+-]digits] (a digit before or after
   the point), or, for an integer, [+-]digits */
static int decimal(const char *s, int integer)
{
  int digits = 0;
  s += *s == '+' || *s == '-';
  for (; isdigit((unsigned char)*s); s++) digits++;
  if (!integer && *s == '.')
    for (s++; isdigit((unsigned char)*s); s++) digits++;
  if (!digits) return 0;
  if (!integer && (*s == 'e' || *s == 'E')) {
    s++;
    s += *s == '+' || *s == '-';
    if (!isdigit((unsigned char)*s)) return 0;
    while (isdigit((unsigned char)*s)) s++;
  }
  return *s == '\0';
}

/* why str, not decimal, is no number (or integer) */
static const char *not_decimal(const char *str, int integer)
{
  const char *p = str + (*str == '+' || *str == '-');
  if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
    return "a hexadecimal number: write it in decimal";
  if (strncasecmp(p, "inf", 3) == 0 || strncasecmp(p, "nan", 3) == 0)
    return "not a finite number";
  return integer ? "not an integer" : "not a number";
}

/* x = the number str: NULL, or why str is not a number */
static const char *to_real(const char *str, double *x)
{
  if (!decimal(str, 0)) return not_decimal(str, 0);
  errno = 0;
  *x = strtod(str, NULL);
  if (errno == ERANGE) return "out of the range of a double";
  return NULL;
}
#line 1236 "paper/scene.nw"
/* k = the integer str: NULL, or why str is not an int */
static const char *to_int(const char *str, int *k)
{
  long v;
  if (!decimal(str, 1)) return not_decimal(str, 1);
  errno = 0;
  v = strtol(str, NULL, 10);
  if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
    return "out of the range of an int";
  *k = (int)v;
  return NULL;
}
#line 1252 "paper/scene.nw"
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
#line 1272 "paper/scene.nw"
/* buf = the default of k with the selector's word in L's table; NULL if
   k has none (it is required) */
static const char *loader_default(Loader *L, const Key *k, char *buf,
                                  size_t size)
{
  const Key *sel;
  const Entry *e;
  int w;
  if (!k->by) return k->dflt;
  sel = key_find(k->sec, k->selector);
  e = find(L, k->sec, k->selector);
  w = name_index(sel->words, e ? e->val : sel->dflt);
  return k->by(k->key, w < 0 ? 0 : w, buf, size);
}
#line 1289 "paper/scene.nw"
/* L->last = the entry of sec.key, or its default; NULL if missing */
static const Entry *entry(Loader *L, const char *sec, const char *key)
{
  const Entry *e = find(L, sec, key);
  char buf[32];
  const char *dflt;
  if (e) L->last = *e;
  else if (!(dflt = loader_default(L, key_find(sec, key), buf, sizeof buf))) {
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
#line 1311 "paper/scene.nw"
/* x = the number sec.key */
static int real(Loader *L, const char *sec, const char *key, double *x)
{
  const char *why;
  if (!entry(L, sec, key)) return L->failed;
  if ((why = to_real(L->last.val, x)))
    return blame(L, "%s%s", why, hint(L->last.val));
  return 0;
}
#line 1323 "paper/scene.nw"
/* k = the integer sec.key */
static int integer(Loader *L, const char *sec, const char *key, int *k)
{
  const char *why;
  if (!entry(L, sec, key)) return L->failed;
  if ((why = to_int(L->last.val, k)))
    return blame(L, "%s%s", why, hint(L->last.val));
  return 0;
}
#line 1335 "paper/scene.nw"
/* k = the index of the word sec.key among the words of its record */
static int word(Loader *L, const char *sec, const char *key, int *k)
{
  const char *const *names = key_find(sec, key)->words;
  char list[256];
  if (!entry(L, sec, key)) return L->failed;
  if ((*k = name_index(names, L->last.val)) >= 0) return 0;
  return blame(L, "unknown value (accepted: %s)",
               name_list(names, list, sizeof list));
}
#line 1351 "paper/scene.nw"
/* refuse any key of sec that means nothing with selector = w */
static int refuse_unused(Loader *L, const char *sec, const char *selector,
                         const char *w)
{
  const Entry *e;
  int i;
  for (i = 0; i < NKEYS; i++)
    if (keys[i].selector && strcmp(keys[i].sec, sec) == 0
        && strcmp(keys[i].selector, selector) == 0 && !key_means(&keys[i], w)
        && (e = find(L, sec, keys[i].key)))
      return bad(L, e, "has no effect with %s = %s", selector, w);
  return 0;
}
#line 1389 "paper/scene.nw"
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

/* refuse the load x = the value converted last, times `times`, unless
   it is 0 or in the window times E; what names it in the message */
static int check_load(Loader *L, const Scene *s, double x, double times,
                      const char *what)
{
  char r[STATUS_NUMBER];
  if (x == 0 || in_window(x * times, s->problem.E)) return 0;
  return blame(L, "%s / E = %s: a load must be 0 or lie within [1e-30, "
               "1e30] times E, where every product the solvers form is "
               "finite", what, outside(fabs(x) * times / s->problem.E, r));
}
#line 1434 "paper/scene.nw"
/* [geometry]: a < b, b - a in the window, gamma (b - a) finite */
static int read_geometry(Loader *L, Scene *s)
{
  char w[STATUS_NUMBER];
  int rc;
  if ((rc = real(L, "geometry", "a", &s->problem.a))
      || (rc = real(L, "geometry", "b", &s->problem.b)))
    return rc;
  if (!(s->problem.b > s->problem.a))
    return blame(L, "must exceed geometry.a = %s", status_number(s->problem.a, w));
  if (!isfinite(s->problem.b - s->problem.a))
    return blame(L, "the width b - a overflows a double");
  if (!in_window(s->problem.b - s->problem.a, 1))
    return blame(L, "the width b - a = %s must lie in [1e-30, 1e30], where "
                 "every product the solvers form is finite",
                 outside(s->problem.b - s->problem.a, w));
  if ((rc = real(L, "geometry", "gamma", &s->problem.gamma))) return rc;
  if (!isfinite(s->problem.gamma * (s->problem.b - s->problem.a)))
    return blame(L, "the area gamma (b - a) overflows a double");
  return 0;
}
#line 1465 "paper/scene.nw"
/* [design]: N >= 1, C0 > 0, C1 >= 0, C2 > 0 */
static int read_design(Loader *L, Scene *s)
{
  int rc;
  if ((rc = integer(L, "design", "N", &s->problem.N))) return rc;
  if (s->problem.N < 1) return blame(L, "must be >= 1 (design intervals)");
  if ((rc = real(L, "design", "C0", &s->problem.C0))) return rc;
  if (!(s->problem.C0 > 0)) return blame(L, "must be > 0 (the bound of alpha)");
  if ((rc = real(L, "design", "C1", &s->problem.C1))) return rc;
  if (!(s->problem.C1 >= 0)) return blame(L, "must be >= 0 (the bound of |alpha'|)");
  if ((rc = real(L, "design", "C2", &s->problem.C2))) return rc;
  if (!(s->problem.C2 > 0)) return blame(L, "must be > 0 (the area of the body)");
  return 0;
}
#line 1491 "paper/scene.nw"
/* [mesh]: M, R >= 1, refine >= 1, 72 N (M + R) <= INT_MAX after the
   refinement, C0 < C0prime < gamma */
static int read_mesh(Loader *L, Scene *s)
{
  char v[STATUS_NUMBER];
  int rc, k;
  if ((rc = integer(L, "mesh", "M", &s->problem.M))) return rc;
  if (s->problem.M < 1) return blame(L, "must be >= 1 (moving rows of cells)");
  if ((rc = integer(L, "mesh", "R", &s->problem.R))) return rc;
  if (s->problem.R < 1) return blame(L, "must be >= 1 (fixed rows of cells)");
  if ((rc = integer(L, "mesh", "refine", &k))) return rc;
  if (k < 1) return blame(L, "must be >= 1 (the factor of N, M and R)");
  
#line 1527 "paper/scene.nw"
if (!(72.0 * k * s->problem.N * k * ((double)s->problem.M + s->problem.R) <= INT_MAX))
  return bad(L, find(L, "mesh", k > 1 ? "refine" : "R"),
             "with design.N = %d, mesh.M = %d, mesh.R = %d and "
             "mesh.refine = %d the mesh has 2 N (M + R) = %.0f triangles, "
             "more than INT_MAX / 36 = %d: the stiffness matrix has 36 "
             "entries a triangle, counted in C ints", s->problem.N, s->problem.M, s->problem.R, k,
             2.0 * k * s->problem.N * k * ((double)s->problem.M + s->problem.R), INT_MAX / 36);
#line 1504 "paper/scene.nw"
  s->problem.N *= k, s->problem.M *= k, s->problem.R *= k;
  if ((rc = real(L, "mesh", "C0prime", &s->problem.C0prime))) return rc;
  if (!(s->problem.C0prime > s->problem.C0))
    return blame(L, "must exceed design.C0 = %s: the moving boundary must "
                 "stay below the fixed part of the mesh", status_number(s->problem.C0, v));
  if (!(s->problem.gamma > s->problem.C0prime))
    return bad(L, find(L, "geometry", "gamma"), "must exceed mesh.C0prime "
               "= %s: the fixed part of the mesh needs a height",
               status_number(s->problem.C0prime, v));
  return 0;
}
#line 1558 "paper/scene.nw"
/* B != {} iff 0 <= S <= C0 (b-a), S = gamma (b-a) - C2 */
static int check_admissible(Loader *L, Scene *s)
{
  double w = s->problem.b - s->problem.a, S = s->problem.gamma * w - s->problem.C2;
  double slack = 1e-12 * s->problem.gamma * w;
  char v[2][STATUS_NUMBER];
  if (S >= -slack && S <= s->problem.C0 * w + slack) return 0;
  return bad(L, find(L, "design", "C2"), "C0, C1, C2 admit no shape: the "
             "area under alpha would be S = gamma (b-a) - C2 = %s, outside "
             "[0, C0 (b-a)] = [0, %s]", status_number(S, v[0]),
             status_number(s->problem.C0 * w, v[1]));
}
#line 1580 "paper/scene.nw"
/* the keys of an arc: centre (arc_x1, arc_x2), arc_radius > 0 */
static int read_arc_shape(Loader *L, Shape *sh)
{
  int rc;
  sh->kind = SHAPE_ARC;
  if ((rc = real(L, "design", "arc_x1", &sh->centre[0]))
      || (rc = real(L, "design", "arc_x2", &sh->centre[1]))
      || (rc = real(L, "design", "arc_radius", &sh->radius)))
    return rc;
  if (!(sh->radius > 0)) return blame(L, "the radius must be > 0");
  return 0;
}
#line 1596 "paper/scene.nw"
/* the keys of a line: line_start at x1 = a, line_end at x1 = b */
static int read_line_shape(Loader *L, Shape *sh)
{
  int rc;
  sh->kind = SHAPE_LINE;
  if ((rc = real(L, "design", "line_start", &sh->start)))
    return rc;
  return real(L, "design", "line_end", &sh->end);
}
#line 1608 "paper/scene.nw"
/* the key of a constant */
static int read_constant_shape(Loader *L, Shape *sh)
{
  sh->kind = SHAPE_CONSTANT;
  return real(L, "design", "constant", &sh->value);
}
#line 1620 "paper/scene.nw"
/* alpha0 = the shape of the keys read by read_keys, sampled */
static int fill_formula(Loader *L, Scene *s,
                        int (*read_keys)(Loader *, Shape *))
{
  Status why = {STATUS_OK, ""};
  int rc = read_keys(L, &s->shape);
  if (!rc && design_shape(&s->problem, &s->shape, s->alpha0, &why))
    rc = blame(L, "%s", why.msg);
  return rc;
}
#line 1635 "paper/scene.nw"
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
#line 1648 "paper/scene.nw"
/* buf = path, absolute; 0 if it fits */
static int absolute(const char *path, char *buf, size_t size)
{
  char cwd[4096];
  int n;
  if (path[0] == '/') n = snprintf(buf, size, "%s", path);
  else if (!getcwd(cwd, sizeof cwd)) return 1;
  else n = snprintf(buf, size, "%s/%s", cwd, path);
  return n < 0 || (size_t)n >= size;
}
#line 1665 "paper/scene.nw"
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
#line 1695 "paper/scene.nw"
/* one line of a shape file: add its row x1 alpha to r, if it has one */
static int read_row(Loader *L, const char *path, int lineno, char *line,
                    Rows *r)
{
  char *tok, *save = NULL, *hash = strchr(line, '#');
  const char *why;
  double v[2];
  int k = 0;
  if (hash) *hash = '\0';
  for (tok = strtok_r(line, " \t\r\n", &save); tok;
       tok = strtok_r(NULL, " \t\r\n", &save), k++)
    if ((why = to_real(tok, &v[k < 2 ? k : 1])))
      return blame(L, "%s line %d: '%s' is %s", path, lineno, tok, why);
  if (k == 0) return 0;
  if (k != 2)
    return blame(L, "%s line %d: %d number%s: a row of a shape file is x1 "
                 "alpha", path, lineno, k, k == 1 ? "" : "s");
  if (rows_add(r, v[0], v[1], lineno))
    return L->failed = status_set(L->st, STATUS_MEMORY, "%s: out of memory "
                                  "for the rows of %s", L->path, path);
  return 0;
}
#line 1811 "paper/scene.nw"
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
#line 1768 "paper/scene.nw"
/* alpha0 = the rows r of the file at path on the design nodes, as they
   are or resampled; refuse rows that are no shape on [a, b] */
static int shape_from_rows(Loader *L, Scene *s, const char *path,
                           const Rows *r)
{
  const Problem *p = &s->problem;
  double tol = 1e-9 * fmax(fabs(p->a), fabs(p->b));
  int i, j, same = r->n == p->N + 1;
  if (r->n < 2)
    return blame(L, "%s has %d row%s x1 alpha: a shape needs rows at x1 = a "
                 "and at x1 = b", path, r->n, r->n == 1 ? "" : "s");
  for (j = 1; j < r->n; j++)
    if (!(r->x[j] > r->x[j - 1]))
      return blame(L, "%s line %d: x1 = %.10g does not increase (line %d "
                   "has %.10g)", path, r->line[j], r->x[j], r->line[j - 1],
                   r->x[j - 1]);
  
#line 1800 "paper/scene.nw"
if (!(fabs(r->x[0] - p->a) <= tol))
  return blame(L, "%s line %d: x1 = %.10g: a shape begins at x1 = a = %.10g",
               path, r->line[0], r->x[0], p->a);
if (!(fabs(r->x[r->n - 1] - p->b) <= tol))
  return blame(L, "%s line %d: x1 = %.10g: a shape ends at x1 = b = %.10g",
               path, r->line[r->n - 1], r->x[r->n - 1], p->b);
#line 1785 "paper/scene.nw"
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
#line 1724 "paper/scene.nw"
/* alpha0 = the shape in the file at path, on the design nodes */
static int read_shape(Loader *L, Scene *s, const char *path)
{
  FILE *fp;
  char *line = NULL;
  size_t cap = 0;
  ssize_t len;
  Rows r = {0};
  int rc = 0, lineno = 0;
  if (!(fp = fopen(path, "r"))) {
    int e = errno;
    blame(L, "cannot read %s: %s", path, strerror(e));
    return for_memory(L, e);
  }
  while (!rc && (len = getline(&line, &cap, fp)) != -1)
    rc = strlen(line) < (size_t)len
      ? blame(L, "%s line %d: a NUL byte: a shape file is text", path,
              ++lineno)
      : read_row(L, path, ++lineno, line, &r);
  if (!rc && ferror(fp)) {
    int e = errno;
    blame(L, "cannot read %s: %s", path, strerror(e));
    rc = for_memory(L, e);
  }
  free(line);
  fclose(fp);
  if (!rc) rc = shape_from_rows(L, s, path, &r);
  rows_free(&r);
  return rc;
}
#line 1829 "paper/scene.nw"
/* alpha0 = the shape in the file design.file */
static int fill_file(Loader *L, Scene *s)
{
  char path[sizeof s->shape_file];
  int rc;
  if (!entry(L, "design", "file")) return L->failed;
  if (resolve(s->path, L->last.val, path, sizeof path))
    return blame(L, "path longer than %d characters", (int)sizeof path - 1);
  if ((rc = read_shape(L, s, path))) return rc;
  if (absolute(path, s->shape_file, sizeof s->shape_file))
    return blame(L, "cannot make %s an absolute path", path);
  return 0;
}
#line 1846 "paper/scene.nw"
/* 0 <= alpha0_i < C0prime at every node */
static int check_alpha0(Loader *L, const Scene *s)
{
  char v[3][STATUS_NUMBER];
  int i;
  for (i = 0; i <= s->problem.N; i++)
    if (!(s->alpha0[i] >= 0 && s->alpha0[i] < s->problem.C0prime))
      return bad(L, find(L, "design", "initial"), "alpha0 = %s at node %d "
                 "(x1 = %s) is outside [0, C0prime) = [0, %s)",
                 status_number(s->alpha0[i], v[0]), i,
                 status_number(problem_node_x(&s->problem, i), v[1]),
                 status_number(s->problem.C0prime, v[2]));
  return 0;
}
#line 1866 "paper/scene.nw"
/* [design] initial: alpha0 at the N+1 nodes */
static int read_initial(Loader *L, Scene *s)
{
  static int (*const read_keys[])(Loader *, Shape *) = {read_arc_shape,
    read_line_shape, read_constant_shape};
  int k, rc;
  if ((rc = word(L, "design", "initial", &k)))
    return rc;
  snprintf(s->initial, sizeof s->initial, "%s", initial_names[k]);
  if ((rc = refuse_unused(L, "design", "initial", initial_names[k])))
    return rc;
  if (!(s->alpha0 = malloc(((size_t)s->problem.N + 1) * sizeof *s->alpha0)))
    return L->failed = status_set(L->st, STATUS_MEMORY, "%s: out of memory "
                                  "for %d nodes", L->path, s->problem.N + 1);
  rc = k == 3 ? fill_file(L, s) : fill_formula(L, s, read_keys[k]);
  return rc ? rc : check_alpha0(L, s);
}
#line 1894 "paper/scene.nw"
/* [material]: E > 0, -1 < nu < 1/2, the plane model */
static int read_material(Loader *L, Scene *s)
{
  int rc, k;
  if ((rc = real(L, "material", "E", &s->problem.E))) return rc;
  if (!(s->problem.E > 0)) return blame(L, "Young's modulus must be > 0");
  if (!in_window(s->problem.E, 1))
    return blame(L, "Young's modulus must lie in [1e-30, 1e30], where every "
                 "product the solvers form is finite");
  if ((rc = real(L, "material", "nu", &s->problem.nu))) return rc;
  if (!(s->problem.nu < 0.5))
    return blame(L, "nu must be < 0.5: 0.5 is the incompressible limit, "
                 "where this displacement method locks");
  if (!(s->problem.nu > -1)) return blame(L, "nu must be > -1 (stability)");
  if ((rc = word(L, "material", "model", &k)))
    return rc;
  s->problem.model = (Plane_model)k;
  return 0;
}
#line 1923 "paper/scene.nw"
/* the loaded interval [from, to] inside the side, and a non-zero P */
static int read_traction(Loader *L, Scene *s, Side_id id)
{
  const char *sec = side_names[id];
  Side *d = &s->problem.side[id];
  char v[2][STATUS_NUMBER];
  int rc;
  
#line 1945 "paper/scene.nw"
double lo = id == SIDE_TOP ? s->problem.a : s->problem.C0prime;
double hi = id == SIDE_TOP ? s->problem.b : s->problem.gamma;
const char *part = id == SIDE_TOP ? "the top side, [a, b]" :
  "the part of the side the design never moves, [C0prime, gamma]";
if ((rc = real(L, sec, "from", &d->from))) return rc;
if (!(d->from >= lo))
  return blame(L, "the loaded interval must lie in %s = [%s, %s]", part,
               status_number(lo, v[0]), status_number(hi, v[1]));
if ((rc = real(L, sec, "to", &d->to))) return rc;
if (!(d->to > d->from))
  return blame(L, "must exceed %s.from = %s", sec, status_number(d->from, v[0]));
if (!(d->to <= hi))
  return blame(L, "the loaded interval must lie in %s = [%s, %s]", part,
               status_number(lo, v[0]), status_number(hi, v[1]));
#line 1931 "paper/scene.nw"
  if ((rc = real(L, sec, "P1", &d->P[0]))
      || (rc = check_load(L, s, d->P[0], 1, "|P1|"))
      || (rc = real(L, sec, "P2", &d->P[1]))
      || (rc = check_load(L, s, d->P[1], 1, "|P2|")))
    return rc;
  if (d->P[0] == 0 && d->P[1] == 0)
    return bad(L, find(L, sec, "bc"), "the traction (%s.P1, %s.P2) is "
               "zero: use bc = free", sec, sec);
  return 0;
}
#line 1963 "paper/scene.nw"
/* [left], [right] or [top]: the condition, free when not given */
static int read_side(Loader *L, Scene *s, Side_id id)
{
  const char *sec = side_names[id];
  int k, rc;
  if ((rc = word(L, sec, "bc", &k))
      || (rc = refuse_unused(L, sec, "bc", problem_bc_names[k])))
    return rc;
  s->problem.side[id].kind = (Bc_kind)k;
  return k == BC_TRACTION ? read_traction(L, s, id) : 0;
}
#line 2034 "paper/scene.nw"
/* the three sides */
static int read_sides(Loader *L, Scene *s)
{
  int id, rc;
  for (id = 0; id < SIDE_COUNT; id++)
    if ((rc = read_side(L, s, (Side_id)id))) return rc;
  return 0;
}
#line 1991 "paper/scene.nw"
/* some side holds u1, or friction can hold the body sideways */
static int check_held(Loader *L, Scene *s)
{
  const Problem *p = &s->problem;
  Friction_hold h = friction_hold(p);
  char sides[96];
  if (friction_side_holds(p, 0)) return 0;
  snprintf(sides, sizeof sides, "left.bc = %s, right.bc = %s, top.bc = %s",
           problem_bc_name(p->side[0].kind), problem_bc_name(p->side[1].kind),
           problem_bc_name(p->side[2].kind));
  if (p->contact == CONTACT_FRICTIONLESS)
    return fail(L, "%s: %s: no side holds u1: frictionless contact cannot "
                "stop the body sliding (singular problem)", L->path, sides);
  
#line 2011 "paper/scene.nw"
if (p->contact == CONTACT_COULOMB && friction_side_holds(p, 1))
  return fail(L, "%s: %s: no side holds u1, and the top holds u2: Coulomb "
              "friction's bound, its coefficient times the normal forces, "
              "is not known before the solve (their sum is the vertical load "
              "only when no side holds u2); use contact.model = tresca, or "
              "hold u1 on a side", L->path, sides);
#line 2005 "paper/scene.nw"
  if (h.capacity > h.load) return 0;
  
#line 2020 "paper/scene.nw"
if (p->contact == CONTACT_TRESCA)
  return fail(L, "%s: %s: no side holds u1, and friction cannot hold the "
              "body: contact.g = %g Pa holds at most g (b - a) = %g N/m "
              "sideways, not more than the horizontal load of %g N/m", L->path, sides,
              p->slip_bound, h.capacity, h.load);
return fail(L, "%s: %s: no side holds u1, and friction cannot hold the "
            "body: contact.friction = %g times the vertical load %g N/m "
            "holds at most %g N/m sideways, not more than the horizontal load "
            "of %g N/m",
            L->path, sides, p->friction, h.vertical, h.capacity, h.load);
#line 2007 "paper/scene.nw"
}
#line 2077 "paper/scene.nw"
/* [contact] model, and g or friction as the law needs */
static int read_contact(Loader *L, Scene *s)
{
  static const char *const law_key[] = {NULL, "g", "friction"};
  Problem *p = &s->problem;
  double *value[] = {NULL, &p->slip_bound, &p->friction};
  int k, rc;
  if ((rc = word(L, "contact", "model", &k))
      || (rc = refuse_unused(L, "contact", "model", problem_contact_names[k])))
    return rc;
  p->contact = (Contact_law)k;
  if (k == CONTACT_FRICTIONLESS) return 0;
  if ((rc = real(L, "contact", law_key[k], value[k]))) return rc;
  if (!(*value[k] >= 0))
    return blame(L, "must be >= 0 (%s)", k == CONTACT_TRESCA ? "a slip bound "
                 "in Pa" : "a friction coefficient");
  if (k == CONTACT_TRESCA) return check_load(L, s, p->slip_bound, 1, "g");
  if (!(p->friction <= WINDOW_MAX))
    return blame(L, "must be <= 1e30: it multiplies a contact force");
  if ((rc = integer(L, "contact", "max_fixed_point", &p->max_fixed_point)))
    return rc;
  if (p->max_fixed_point < 1) return blame(L, "must be >= 1");
  return 0;
}
#line 2059 "paper/scene.nw"
/* [body_force] F, [contact] model; then what holds the body sideways */
static int read_loads(Loader *L, Scene *s)
{
  int rc;
  double w = s->problem.b - s->problem.a;
  if ((rc = real(L, "body_force", "F1", &s->problem.F[0]))
      || (rc = check_load(L, s, s->problem.F[0], w, "|F1| (b - a)"))
      || (rc = real(L, "body_force", "F2", &s->problem.F[1]))
      || (rc = check_load(L, s, s->problem.F[1], w, "|F2| (b - a)")))
    return rc;
  s->problem.has_body_force = s->problem.F[0] != 0 || s->problem.F[1] != 0;
  if ((rc = read_contact(L, s))) return rc;
  return check_held(L, s);
}
#line 2110 "paper/scene.nw"
/* [solver]: the method, 0 < tol < 1, max_iter >= 1, 0 < omega < 2 */
static int read_solver(Loader *L, Scene *s)
{
  Qp_options *o = &s->solver;
  int rc, k;
  if ((rc = word(L, "solver", "state", &k))) return rc;
  o->method = (Qp_method)k;
  if (k == QP_PSOR && s->problem.contact != CONTACT_FRICTIONLESS)
    return blame(L, "cannot take friction (contact.model = %s): a slip bound "
                 "bounds a force, and psor bounds unknowns; use pdas or cgssor",
                 problem_contact_name(s->problem.contact));
  
#line 2139 "paper/scene.nw"
if (k == QP_CGSSOR && s->problem.contact != CONTACT_FRICTIONLESS
    && !(friction_side_holds(&s->problem, 0) && friction_side_holds(&s->problem, 1)))
  return blame(L, "cannot take friction (contact.model = %s) on a body that "
               "the sides do not hold in both directions (left.bc = %s, "
               "right.bc = %s, top.bc = %s): its dual needs the stiffness "
               "seen from the contact positive definite; use pdas",
               problem_contact_name(s->problem.contact),
               problem_bc_name(s->problem.side[0].kind),
               problem_bc_name(s->problem.side[1].kind),
               problem_bc_name(s->problem.side[2].kind));
#line 2122 "paper/scene.nw"
  if ((rc = real(L, "solver", "tol", &o->tol))) return rc;
  if (!(o->tol > 0 && o->tol < 1))
    return blame(L, "must lie in (0, 1): it is a relative residual");
  if ((rc = integer(L, "solver", "max_iter", &o->max_iter))) return rc;
  if (o->max_iter < 1) return blame(L, "must be >= 1");
  if ((rc = real(L, "solver", "omega", &o->omega))) return rc;
  if (!(o->omega > 0 && o->omega < 2))
    return blame(L, "must lie in (0, 2), where SOR converges");
  return 0;
}
#line 2161 "paper/scene.nw"
/* [optimizer]: the method, its metric, 0 < tol < 1, max_iter >= 1 */
static int read_optimizer(Loader *L, Scene *s)
{
  Opt_options *o = &s->optimizer;
  int rc, k;
  if ((rc = word(L, "optimizer", "method", &k))
      || (rc = refuse_unused(L, "optimizer", "method", opt_method_names[k])))
    return rc;
  o->method = (Opt_method)k;
  o->metric = opt_options_default(o->method).metric;
  if (o->method != OPT_NEWTON) {
    if ((rc = word(L, "optimizer", "metric", &k))) return rc;
    o->metric = (Opt_metric)k;
  }
  if (o->method == OPT_PROJGRAD && o->metric == OPT_METRIC_SCHUR)
    return blame(L, "schur needs optimizer.method = slsqp: Algorithm 4.1 "
                 "projects in the euclidean metric");
  if ((rc = real(L, "optimizer", "tol", &o->tol))) return rc;
  if (!(o->tol > 0 && o->tol < 1))
    return blame(L, "must lie in (0, 1): it is a relative measure");
  if ((rc = integer(L, "optimizer", "max_iter", &o->max_iter))) return rc;
  if (o->max_iter < 1) return blame(L, "must be >= 1");
  return 0;
}
#line 2195 "paper/scene.nw"
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
#line 2212 "paper/scene.nw"
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
#line 2235 "paper/scene.nw"
void scene_free(Scene *s)
{
  if (!s) return;
  free(s->alpha0);
  s->alpha0 = NULL;
}
#line 2252 "paper/scene.nw"
/* buf = the default of k as printed: its own, "required", or one for each
   word of its selector, "V (w, w), V (w)", or "V" if the same for all */
static const char *default_text(const Key *k, char *buf, size_t size)
{
  const char *const *w;
  char v[8][32];
  int i, j, n, distinct = 0;
  if (!k->by) return k->dflt ? k->dflt : "required";
  w = key_find(k->sec, k->selector)->words;
  for (n = 0; w[n] && n < 8; n++)
    if (key_means(k, w[n])) k->by(k->key, n, v[n], sizeof v[n]);
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
#line 2284 "paper/scene.nw"
/* buf = the values k accepts, as printed */
static const char *accepted_text(const Key *k, char *buf, size_t size)
{
  if (k->accepted) return k->accepted;
  return name_list(k->words, buf, size);
}

/* buf = the meaning of k, and the words of its selector it needs */
static const char *meaning_text(const Key *k, char *buf, size_t size)
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
  cat(buf, size, ")");
  return buf;
}
#line 2312 "paper/scene.nw"
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
#line 2330 "paper/scene.nw"
void scene_keys_print(FILE *f, int latex_table)
{
  char name[40], d[128], a[128], m[256];
  int i;
  if (latex_table)
    fputs("% the keys of a scene: written by contactopt keys --latex\n"
          "{\\footnotesize\\setlength{\\tabcolsep}{3pt}\n"
          "\\begin{longtable}{@{}llp{2.1cm}p{3.6cm}p{6.2cm}@{}}\n\\toprule\n"
          "key & unit & default & accepted & meaning\\tabularnewline\n"
          "\\midrule\\endhead\n\\bottomrule\\endfoot\n", f);
  else
    fprintf(f, "%-20s  %-5s  %-12s  %-31s  %s\n", "section.key", "unit",
            "default", "accepted", "meaning");
  for (i = 0; i < NKEYS; i++) {
    snprintf(name, sizeof name, "%s.%s", keys[i].sec, keys[i].key);
    if (!latex_table) {
      fprintf(f, "%-20s  %-5s  %-12s  %-31s  %s\n", name, keys[i].unit,
              default_text(&keys[i], d, sizeof d),
              accepted_text(&keys[i], a, sizeof a),
              meaning_text(&keys[i], m, sizeof m));
      continue;
    }
    
#line 2359 "paper/scene.nw"
fputs("\\texttt{", f), latex(f, name), fputs("} & ", f);
latex(f, keys[i].unit), fputs(" & \\raggedright ", f);
latex(f, default_text(&keys[i], d, sizeof d));
fputs(" & \\raggedright ", f), latex(f, accepted_text(&keys[i], a, sizeof a));
fputs(" & \\raggedright ", f), latex(f, meaning_text(&keys[i], m, sizeof m));
fputs("\\tabularnewline\n", f);
#line 2353 "paper/scene.nw"
  }
  if (latex_table) fputs("\\end{longtable}}\n", f);
}
#line 2376 "paper/scene.nw"
/* buf = the value of k in s, as a scene writes it */
static const char *scene_value(const Scene *s, const Key *k, char *buf,
                               size_t size)
{
  const char *at = (const char *)s + k->at;
  double x;
  int v;
  if (k->at == AT_DEFAULT) return k->dflt;
  if (k->type == KEY_TEXT) return at;
  if (k->type == KEY_REAL) return memcpy(&x, at, sizeof x), status_number(x, buf);
  memcpy(&v, at, sizeof v);
  if (k->type == KEY_WORD) return k->words[v];
  snprintf(buf, size, "%d", v);
  return buf;
}
#line 2399 "paper/scene.nw"
int scene_write(const Scene *s, FILE *f, Status *st)
{
  char buf[64], sel[64];
  int i;
  fprintf(f, "; the effective scene of %s,\n; written by contactopt: every "
          "key after the overrides, its defaults written, N, M, R refined\n",
          s->path);
  for (i = 0; i < NKEYS; i++) {
    const Key *k = &keys[i];
    const char *v = scene_value(s, k, buf, sizeof buf);
    if (i == 0 || strcmp(k->sec, keys[i - 1].sec) != 0)
      fprintf(f, "\n[%s]\n", k->sec);
    if (k->selector && !key_means(k, scene_value(s, key_find(k->sec,
                                  k->selector), sel, sizeof sel)))
      continue;
    if (strlen(k->key) + 3 + strlen(v) > INI_MAX_LINE - 2)
      return status_set(st, STATUS_INPUT, "%s: %s.%s: %d characters, more "
                        "than a line of a scene holds (%d)", s->path, k->sec,
                        k->key, (int)strlen(v), INI_MAX_LINE - 2);
    if (in_comment(v, 0) || (*v && (isspace((unsigned char)v[0])
                                    || isspace((unsigned char)v[strlen(v) - 1]))))
      return status_set(st, STATUS_INPUT, "%s: %s.%s: \"%s\" would not read "
                        "back from a scene (a ';' after a blank begins a "
                        "comment, blanks at the ends are trimmed)", s->path, k->sec,
                        k->key, v);
    fprintf(f, "%s = %s\n", k->key, v);
  }
  if (fflush(f) || ferror(f))
    return status_set(st, STATUS_SYSTEM, "%s: cannot write the effective "
                      "scene", s->path);
  return STATUS_OK;
}
