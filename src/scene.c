#line 795 "paper/scene.nw"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_private.h"
#line 830 "paper/scene.nw"
/* tell "fmt ..." as the failure of L, STATUS_INPUT */
static PRINTF_LIKE(2, 0)
int vfail(Loader *L, const char *fmt, va_list ap)
{
  char msg[sizeof ((Status *)0)->msg];
  vsnprintf(msg, sizeof msg, fmt, ap);
  return L->failed = status_set(L->st, STATUS_INPUT, "%s", msg);
}

PRINTF_LIKE(2, 3)
int scene_fail(Loader *L, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vfail(L, fmt, ap);
  va_end(ap);
  return L->failed;
}
#line 852 "paper/scene.nw"
/* buf = the scene path, and the override if one set the value */
void scene_origin(const Loader *L, const char *override, char *buf,
                  size_t size)
{
  if (override) snprintf(buf, size, "%s (-s %s)", L->path, override);
  else snprintf(buf, size, "%s", L->path);
}
#line 863 "paper/scene.nw"
/* tell "ORIGIN: section.key = value: reason" about e */
static PRINTF_LIKE(3, 0)
int vbad(Loader *L, const Entry *e, const char *fmt, va_list ap)
{
  char where[640], why[512];
  scene_origin(L, e->override, where, sizeof where);
  vsnprintf(why, sizeof why, fmt, ap);
  return scene_fail(L, "%s: %s.%s = %s: %s", where, e->sec, e->key, e->val, why);
}
#line 876 "paper/scene.nw"
PRINTF_LIKE(3, 4)
int scene_bad(Loader *L, const Entry *e, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vbad(L, e, fmt, ap);
  va_end(ap);
  return L->failed;
}

PRINTF_LIKE(2, 3)
int scene_blame(Loader *L, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vbad(L, &L->last, fmt, ap);
  va_end(ap);
  return L->failed;
}
#line 2497 "paper/scene.nw"
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
  rc = scene_read_file(&L);
  for (i = 0; !rc && i < noverride; i++) rc = scene_apply_override(&L, override[i]);
  if (!rc) rc = scene_convert(&L, s);
  if (rc) scene_free(s);
  return rc;
}
#line 2520 "paper/scene.nw"
void scene_free(Scene *s)
{
  if (!s) return;
  free(s->alpha0);
  s->alpha0 = NULL;
}
