#line 3330 "paper/scene.nw"
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <ini.h>
#include "scene_private.h"

#line 3352 "paper/scene.nw"
/* buf = the value of k in s, its slot off bytes further, as a scene
   writes it */
static const char *scene_value(const Scene *s, const Scene_key *k, size_t off,
                               char *buf, size_t size)
{
  const char *at = (const char *)s + k->at + off;
  double x;
  int v, part = s->problem.part.geometry[0] != '\0';
  if (k->type == KEY_TEXT) return at;
  if (k->type == KEY_REAL) return memcpy(&x, at, sizeof x), status_number(x, buf);
  memcpy(&v, at, sizeof v);
  if (k->type == KEY_WORD) return k->words[v];
  if (k->at == AT(problem.part.refine) && !part) v = 1;
  else if (part && (k->at == AT(problem.N) || k->at == AT(problem.M)))
    v /= s->problem.part.refine;
  snprintf(buf, size, "%d", v);
  return buf;
}
#line 3377 "paper/scene.nw"
/* whether the key k of the slot off bytes further means something in s */
static int written(const Scene *s, const Scene_key *k, size_t off, const char *v)
{
  char sel[64];
  if (k->selector && !scene_key_means(k, scene_value(s, scene_key_find(k->sec,
                                  k->selector), off, sel, sizeof sel)))
    return 0;
  if (k->strain && s->problem.model != MODEL_PLANE_STRAIN) return 0;
  if (k->rectangle && s->problem.part.geometry[0]) return 0;
  return !k->quiet || strcmp(v, k->dflt) != 0;
}
#line 3396 "paper/scene.nw"
/* write the records from..to-1 of the section sec, its slot off bytes
   further */
static int write_section(const Scene *s, FILE *f, int from, int to,
                         const char *sec, size_t off, Status *st)
{
  char buf[64];
  int i, said = 0;
  for (i = from; i < to; i++) {
    const Scene_key *k = &scene_keys[i];
    const char *v = scene_value(s, k, off, buf, sizeof buf);
    if (!written(s, k, off, v)) continue;
    if (strlen(k->key) + 3 + strlen(v) > INI_MAX_LINE - 2)
      return status_set(st, STATUS_INPUT, "%s: %s.%s: %d characters, more "
                        "than a line of a scene holds (%d)", s->path, sec,
                        k->key, (int)strlen(v), INI_MAX_LINE - 2);
    if (scene_in_comment(v, 0) || (*v && (isspace((unsigned char)v[0])
                                    || isspace((unsigned char)v[strlen(v) - 1]))))
      return status_set(st, STATUS_INPUT, "%s: %s.%s: \"%s\" would not read "
                        "back from a scene (a ';' after a blank begins a "
                        "comment, blanks at the ends are trimmed)", s->path, sec,
                        k->key, v);
    if (!said++) fprintf(f, "\n[%s]\n", sec);
    fprintf(f, "%s = %s\n", k->key, v);
  }
  return STATUS_OK;
}
#line 3427 "paper/scene.nw"
/* the records from..to-1 of a named kind, for each of its slots in s */
static int write_named(const Scene *s, FILE *f, int from, int to, int kind,
                       Status *st)
{
  const Problem_part *part = &s->problem.part;
  char sec[PROBLEM_NAME + 16];
  int j, n = kind == SCENE_BOUNDARY ? part->ncurve : part->nregion, rc;
  for (j = 0; j < n; j++) {
    snprintf(sec, sizeof sec, "%s.%s", scene_named[kind].prefix,
             kind == SCENE_BOUNDARY ? part->curve[j].name : part->region[j].name);
    if ((rc = write_section(s, f, from, to, sec, (size_t)j * scene_named[kind].stride,
                            st)))
      return rc;
  }
  return STATUS_OK;
}

int scene_write(const Scene *s, FILE *f, Status *st)
{
  int i, to, kind, rc;
  fprintf(f, "; the effective scene of %s,\n; written by contactopt: every "
          "key after the overrides, its defaults written, %s\n", s->path,
          s->problem.part.geometry[0] ? "N, M with their mesh.refine"
                                      : "N, M, R refined");
  for (i = 0; i < SCENE_NKEYS; i = to) {
    for (to = i + 1; to < SCENE_NKEYS
                     && strcmp(scene_keys[to].sec, scene_keys[i].sec) == 0; to++)
      continue;
    kind = scene_named_kind(scene_keys[i].sec, NULL);
    rc = kind >= 0 ? write_named(s, f, i, to, kind, st)
                   : write_section(s, f, i, to, scene_keys[i].sec, 0, st);
    if (rc) return rc;
  }
  if (fflush(f) || ferror(f))
    return status_set(st, STATUS_SYSTEM, "%s: cannot write the effective "
                      "scene", s->path);
  return STATUS_OK;
}
