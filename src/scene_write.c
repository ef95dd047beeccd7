#line 2677 "paper/scene.nw"
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <ini.h>
#include "scene_private.h"

#line 2692 "paper/scene.nw"
/* buf = the value of k in s, as a scene writes it */
static const char *scene_value(const Scene *s, const Scene_key *k, char *buf,
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
#line 2715 "paper/scene.nw"
int scene_write(const Scene *s, FILE *f, Status *st)
{
  char buf[64], sel[64];
  int i;
  fprintf(f, "; the effective scene of %s,\n; written by contactopt: every "
          "key after the overrides, its defaults written, N, M, R refined\n",
          s->path);
  for (i = 0; i < SCENE_NKEYS; i++) {
    const Scene_key *k = &scene_keys[i];
    const char *v = scene_value(s, k, buf, sizeof buf);
    if (i == 0 || strcmp(k->sec, scene_keys[i - 1].sec) != 0)
      fprintf(f, "\n[%s]\n", k->sec);
    if (k->selector && !scene_key_means(k, scene_value(s, scene_key_find(k->sec,
                                  k->selector), sel, sizeof sel)))
      continue;
    if (strlen(k->key) + 3 + strlen(v) > INI_MAX_LINE - 2)
      return status_set(st, STATUS_INPUT, "%s: %s.%s: %d characters, more "
                        "than a line of a scene holds (%d)", s->path, k->sec,
                        k->key, (int)strlen(v), INI_MAX_LINE - 2);
    if (scene_in_comment(v, 0) || (*v && (isspace((unsigned char)v[0])
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
