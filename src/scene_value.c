#line 1626 "paper/scene.nw"
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "scene_private.h"
#line 1656 "paper/scene.nw"
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
const char *scene_to_real(const char *str, double *x)
{
  if (!decimal(str, 0)) return not_decimal(str, 0);
  errno = 0;
  *x = strtod(str, NULL);
  if (errno == ERANGE) return "out of the range of a double";
  return NULL;
}
#line 1699 "paper/scene.nw"
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
#line 1715 "paper/scene.nw"
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
#line 1735 "paper/scene.nw"
/* buf = the default of k with the selector's word in L's table; NULL if
   k has none (it is required) */
static const char *loader_default(Scene_loader *L, const Scene_key *k, char *buf,
                                  size_t size)
{
  const Scene_key *sel;
  const Scene_entry *e;
  int w;
  if (!k->by) return k->dflt;
  sel = scene_key_find(k->sec, k->selector);
  e = scene_find(L, k->sec, k->selector);
  w = scene_name_index(sel->words, e ? e->val : sel->dflt);
  return k->by(k->key, w < 0 ? 0 : w, buf, size);
}
#line 1752 "paper/scene.nw"
/* L->last = the entry of sec.key, or its default; NULL if missing */
const Scene_entry *scene_entry(Scene_loader *L, const char *sec, const char *key)
{
  const Scene_entry *e = scene_find(L, sec, key);
  char buf[32];
  const char *dflt;
  if (e) L->last = *e;
  else if (!(dflt = loader_default(L, scene_key_find(sec, key), buf, sizeof buf))) {
    scene_fail(L, "%s: %s.%s: missing required key", L->path, sec, key);
    return NULL;
  } else {
    memset(&L->last, 0, sizeof L->last);
    snprintf(L->last.sec, sizeof L->last.sec, "%s", sec);
    snprintf(L->last.key, sizeof L->last.key, "%s", key);
    snprintf(L->last.val, sizeof L->last.val, "%s", dflt);
  }
  return &L->last;
}
#line 1774 "paper/scene.nw"
/* x = the number sec.key */
static int scene_real(Scene_loader *L, const char *sec, const char *key, double *x)
{
  const char *why;
  if (!scene_entry(L, sec, key)) return L->failed;
  if ((why = scene_to_real(L->last.val, x)))
    return scene_blame(L, "%s%s", why, hint(L->last.val));
  return 0;
}
#line 1786 "paper/scene.nw"
/* k = the integer sec.key */
int scene_integer(Scene_loader *L, const char *sec, const char *key, int *k)
{
  const char *why;
  if (!scene_entry(L, sec, key)) return L->failed;
  if ((why = to_int(L->last.val, k)))
    return scene_blame(L, "%s%s", why, hint(L->last.val));
  return 0;
}
#line 1798 "paper/scene.nw"
/* k = the index of the word sec.key among the words of its record */
int scene_word(Scene_loader *L, const char *sec, const char *key, int *k)
{
  const char *const *names = scene_key_find(sec, key)->words;
  char list[256];
  if (!scene_entry(L, sec, key)) return L->failed;
  if ((*k = scene_name_index(names, L->last.val)) >= 0) return 0;
  return scene_blame(L, "unknown value (accepted: %s)",
                     scene_name_list(names, list, sizeof list));
}
#line 1823 "paper/scene.nw"
/* the field of s that sec.key's record names = the value of sec.key */
int scene_get(Scene_loader *L, Scene *s, const char *sec, const char *key)
{
  const Scene_key *k = scene_key_find(sec, key);
  int slot = scene_slot(L, sec);
  char *at = (char *)s + k->at;
  double x;
  int v, rc;
  if (slot > 0) at += (size_t)slot * scene_named[scene_named_kind(sec, NULL)].stride;
  if (k->type == KEY_REAL) {
    if (!(rc = scene_real(L, sec, key, &x))) memcpy(at, &x, sizeof x);
  } else if (!(rc = k->type == KEY_INT ? scene_integer(L, sec, key, &v)
                                       : scene_word(L, sec, key, &v)))
    memcpy(at, &v, sizeof v);
  return rc;
}
#line 1845 "paper/scene.nw"
/* refuse any key of sec that means nothing with selector = w */
int scene_refuse_unused(Scene_loader *L, const char *sec, const char *selector,
                        const char *w)
{
  const Scene_entry *e;
  const char *table = scene_table_section(sec);
  int i;
  for (i = 0; i < SCENE_NKEYS; i++)
    if (scene_keys[i].selector && strcmp(scene_keys[i].sec, table) == 0
        && strcmp(scene_keys[i].selector, selector) == 0
        && !scene_key_means(&scene_keys[i], w)
        && (e = scene_find(L, sec, scene_keys[i].key)))
      return scene_bad(L, e, "has no effect with %s = %s", selector, w);
  return 0;
}
