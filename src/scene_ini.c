#line 1137 "paper/scene.nw"
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ini.h>
#include "scene_private.h"
#line 1150 "paper/scene.nw"
static int nul_byte(Scene_loader *L);
static int long_line(Scene_loader *L, const char *buf, int size);
static int long_section(Scene_loader *L, const char *buf);
#line 1180 "paper/scene.nw"
/* e = sec.key = val at L's current origin, if the table of keys has them */
static int admit(Scene_loader *L, Scene_entry *e, const char *sec, const char *key,
                 const char *val)
{
  char where[640], list[256];
  scene_origin(L, L->override, where, sizeof where);
  
#line 1202 "paper/scene.nw"
if (!*sec)
  return scene_fail(L, "%s: line %d: %s = %s comes before any [section]", where,
                    L->line, key, val);
if (!scene_section_known(sec))
  return scene_fail(L, "%s: [%s]: unknown section (the sections are %s)", where,
                    sec, scene_key_names(NULL, list, sizeof list));
if (scene_named_kind(sec, NULL) == SCENE_MATERIAL && strcmp(key, "model") == 0)
  return scene_fail(L, "%s: %s.%s = %s: the plane model is the whole body's: "
                    "give it as material.model", where, sec, key, val);
if (!scene_key_find(sec, key))
  return scene_fail(L, "%s: %s.%s = %s: unknown key ([%s] has %s)", where, sec,
                    key, val, sec, scene_key_names(sec, list, sizeof list));
#line 1187 "paper/scene.nw"
  
#line 1219 "paper/scene.nw"
{
  const char *name;
  const char *named[PROBLEM_NAMED];
  int kind = scene_named_kind(sec, &name);
  if (kind >= 0 && !scene_name_ok(name))
    return scene_fail(L, "%s: %s.%s = %s: [%s]: a NAME is 1 to %d letters, "
                      "digits or _", where, sec, key, val, sec, SCENE_NAME_MAX);
  if (kind >= 0 && scene_slot(L, sec) < 0
      && scene_named_list(L, kind, named, PROBLEM_NAMED) == PROBLEM_NAMED)
    return scene_fail(L, "%s: %s.%s = %s: more than %d [%s.NAME] sections",
                      where, sec, key, val, PROBLEM_NAMED,
                      scene_named[kind].prefix);
}
#line 1188 "paper/scene.nw"
  if (strlen(val) >= sizeof e->val)
    return scene_fail(L, "%s: %s.%s: value longer than %d characters", where, sec,
                      key, (int)sizeof e->val - 1);
  snprintf(e->sec, sizeof e->sec, "%s", sec);
  snprintf(e->key, sizeof e->key, "%s", key);
  snprintf(e->val, sizeof e->val, "%s", val);
  e->line = L->line;
  e->override = L->override;
  return 0;
}
#line 1237 "paper/scene.nw"
/* the entry sec.key of the table, or NULL */
Scene_entry *scene_find(Scene_loader *L, const char *sec, const char *key)
{
  int i;
  for (i = 0; i < L->n; i++)
    if (strcmp(L->e[i].sec, sec) == 0 && strcmp(L->e[i].key, key) == 0)
      return &L->e[i];
  return NULL;
}
#line 1253 "paper/scene.nw"
/* sec[] = the sections of the named kind in the table, in the order of
   their first entries; their number (at most max) */
int scene_named_list(const Scene_loader *L, int kind, const char **sec, int max)
{
  int i, j, n = 0;
  for (i = 0; i < L->n; i++) {
    if (scene_named_kind(L->e[i].sec, NULL) != kind) continue;
    for (j = 0; j < n && strcmp(sec[j], L->e[i].sec) != 0; j++) continue;
    if (j == n && n < max) sec[n++] = L->e[i].sec;
  }
  return n;
}

/* the slot of the named section sec among those of its kind, or -1 */
int scene_slot(const Scene_loader *L, const char *sec)
{
  const char *named[PROBLEM_NAMED];
  int kind = scene_named_kind(sec, NULL), n, j;
  if (kind < 0) return -1;
  n = scene_named_list(L, kind, named, PROBLEM_NAMED);
  for (j = 0; j < n; j++)
    if (strcmp(named[j], sec) == 0) return j;
  return -1;
}
#line 1282 "paper/scene.nw"
/* append e; the keys, each stored once at most, bound the table */
static Scene_entry *add(Scene_loader *L, const Scene_entry *e)
{
  if (L->n == TABLE_MAX) {
    scene_fail(L, "%s: more than %d keys", L->path, TABLE_MAX);
    return NULL;
  }
  L->e[L->n] = *e;
  return &L->e[L->n++];
}

/* remove the entry e of the table, keeping the order of the others */
static void remove_entry(Scene_loader *L, Scene_entry *e)
{
  memmove(e, e + 1, (size_t)(L->e + --L->n - e) * sizeof *e);
}
#line 1319 "paper/scene.nw"
/* inih's reader: one line into buf, counted; NULL at the end or a failure */
static char *read_line(char *buf, int size, void *user)
{
  Scene_loader *L = user;
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
  if (long_section(L, buf)) return NULL;
  return buf;
}
#line 1341 "paper/scene.nw"
/* tell a NUL byte on the current line */
static int nul_byte(Scene_loader *L)
{
  return scene_fail(L, "%s: line %d: a NUL byte: a scene file is text (ASCII or "
                    "UTF-8, not UTF-16)", L->path, L->line);
}
#line 1361 "paper/scene.nw"
/* whether buf, the start of a line, is or has begun a comment */
int scene_in_comment(const char *buf, int line)
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
static int long_line(Scene_loader *L, const char *buf, int size)
{
  int c;
  if (!scene_in_comment(buf, L->line))
    return scene_fail(L, "%s: line %d: longer than %d characters (only a comment "
                      "may be longer)", L->path, L->line, size - 2);
  while ((c = getc(L->fp)) != EOF && c != '\n')
    if (c == '\0') return nul_byte(L);
  return 0;
}
#line 1391 "paper/scene.nw"
/* a section line [name] whose name inih would cut */
static int long_section(Scene_loader *L, const char *buf)
{
  const char *p = buf + strspn(buf, " \t"), *end;
  if (*p != '[' || !(end = strchr(p, ']')) || end - p - 1 < INIH_SECTION)
    return 0;
  return scene_fail(L, "%s: line %d: [%.*s]: a section name is at most %d "
                    "characters", L->path, L->line, (int)(end - p - 1), p + 1,
                    INIH_SECTION - 1);
}
#line 1408 "paper/scene.nw"
/* inih's handler: store section.key = val, read on line L->line */
static int on_key(void *user, const char *sec, const char *key,
                  const char *val)
{
  Scene_loader *L = user;
  Scene_entry e;
  const Scene_entry *old;
  if (!key) return 1;
  if (admit(L, &e, sec, key, val)) return 0;
  
#line 1425 "paper/scene.nw"
if (L->indented && L->prev && strcmp(L->prev->sec, sec) == 0
    && strcmp(L->prev->key, key) == 0) {
  scene_fail(L, "%s: line %d: this indented line continues the value of %s.%s: "
             "a scene value is one line (remove the indentation)", L->path,
             L->line, sec, key);
  return 0;
}
#line 1418 "paper/scene.nw"
  
#line 1436 "paper/scene.nw"
if ((old = scene_find(L, sec, key))) {
  scene_bad(L, &e, "duplicate key on line %d (first given on line %d)", L->line,
            old->line);
  return 0;
}
#line 1419 "paper/scene.nw"
  return (L->prev = add(L, &e)) != NULL;
}
#line 1477 "paper/scene.nw"
/* the failure just told, as STATUS_MEMORY if errno e says memory */
int scene_for_memory(Scene_loader *L, int e)
{
  if (e != ENOMEM) return L->failed;
  if (L->st) L->st->code = STATUS_MEMORY;
  return L->failed = STATUS_MEMORY;
}

#line 1450 "paper/scene.nw"
/* the table = the entries of the scene file L->path */
int scene_read_file(Scene_loader *L)
{
  int rc;
  errno = 0;
  if (!(L->fp = fopen(L->path, "r"))) {
    int e = errno;
    scene_fail(L, "%s: cannot read: %s", L->path, strerror(e));
    return scene_for_memory(L, e);
  }
  rc = ini_parse_stream(read_line, L, on_key, L);
  if (!L->failed && ferror(L->fp)) {
    int e = errno;
    scene_fail(L, "%s: cannot read: %s", L->path, e ? strerror(e) : "read error");
    scene_for_memory(L, e);
  }
  fclose(L->fp);
  L->fp = NULL;
  
#line 1488 "paper/scene.nw"
if (rc > 0 && (!L->failed || rc < L->line))
  scene_fail(L, "%s: line %d: syntax error: expected [section], key = value, "
             "a comment or a blank line", L->path, rc);
if (rc == -2 && !L->failed)
  L->failed = status_set(L->st, STATUS_MEMORY, "%s: out of memory",
                         L->path);
#line 1469 "paper/scene.nw"
  L->line = 0;
  return L->failed;
}
#line 1511 "paper/scene.nw"
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
#line 1531 "paper/scene.nw"
/* whether the override e switches off the entry x */
static int switched_off(const Scene_entry *e, const Scene_entry *x)
{
  const char *xs = scene_table_section(x->sec);
  const Scene_key *k = scene_key_find(x->sec, x->key);
  if (strcmp(e->sec, "material") == 0 && strcmp(e->key, "model") == 0)
    return k->strain && strcmp(e->val, "plane_strain") != 0;
  if (strcmp(e->sec, "part") != 0 || strcmp(e->key, "geometry") != 0) return 0;
  if (*e->val) return k->rectangle;
  return strcmp(xs, x->sec) != 0;     /* a named section */
}

/* e overrides a selector: drop the file's keys meaningless with its word */
static void drop_unused(Scene_loader *L, const Scene_entry *e)
{
  const Scene_key *sel = scene_key_find(e->sec, e->key);
  const char *w = *e->val ? e->val : sel->dflt;
  const char *sec = scene_table_section(e->sec);
  Scene_entry *old;
  int i;
  for (i = 0; w && i < SCENE_NKEYS; i++)
    if (scene_keys[i].selector && strcmp(scene_keys[i].sec, sec) == 0
        && strcmp(scene_keys[i].selector, e->key) == 0
        && !scene_key_means(&scene_keys[i], w)
        && (old = scene_find(L, e->sec, scene_keys[i].key)) && !old->override)
      remove_entry(L, old);
  for (i = L->n - 1; i >= 0; i--)
    if (!L->e[i].override && switched_off(e, &L->e[i]))
      remove_entry(L, &L->e[i]);
}
#line 1567 "paper/scene.nw"
/* apply the override o = "section.key=value" onto the table */
int scene_apply_override(Scene_loader *L, const char *o)
{
  char *copy, *eq, *dot = NULL, *p, *sec = NULL, *key = NULL, *val = NULL;
  Scene_entry e, *old;
  L->override = o;
  if (!(copy = malloc(strlen(o) + 1)))
    return L->failed = status_set(L->st, STATUS_MEMORY, "out of memory");
  strcpy(copy, o);
  eq = strchr(copy, '=');
  for (p = copy; eq && p < eq; p++)
    if (*p == '.') dot = p;
  
#line 1593 "paper/scene.nw"
if (eq && dot && dot < eq) {
  *eq = *dot = '\0';
  sec = trim(copy);
  key = trim(dot + 1);
  val = trim(eq + 1);
}
if (!sec || !*sec || !*key)
  scene_fail(L, "%s (-s %s): malformed override: expected section.key=value",
             L->path, o);
else
  admit(L, &e, sec, key, val);
#line 1580 "paper/scene.nw"
  free(copy);
  if (L->failed) return L->failed;
  drop_unused(L, &e);
  if ((old = scene_find(L, e.sec, e.key))) {
    if (*e.val) *old = e;
    else remove_entry(L, old);         /* unset */
  } else if (*e.val) add(L, &e);
  return L->failed;
}
