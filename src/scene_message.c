#line 1031 "paper/scene.nw"
#include <stdio.h>
#include "scene_private.h"
#line 1064 "paper/scene.nw"
/* tell "fmt ..." as the failure of L, STATUS_INPUT */
static PRINTF_LIKE(2, 0)
int vfail(Scene_loader *L, const char *fmt, va_list ap)
{
  char msg[sizeof ((Status *)0)->msg];
  vsnprintf(msg, sizeof msg, fmt, ap);
  return L->failed = status_set(L->st, STATUS_INPUT, "%s", msg);
}

PRINTF_LIKE(2, 3)
int scene_fail(Scene_loader *L, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vfail(L, fmt, ap);
  va_end(ap);
  return L->failed;
}
#line 1086 "paper/scene.nw"
/* buf = the scene path, and the override if one set the value */
void scene_origin(const Scene_loader *L, const char *override, char *buf,
                  size_t size)
{
  if (override) snprintf(buf, size, "%s (-s %s)", L->path, override);
  else snprintf(buf, size, "%s", L->path);
}
#line 1097 "paper/scene.nw"
/* tell "ORIGIN: section.key = value: reason" about e */
static PRINTF_LIKE(3, 0)
int vbad(Scene_loader *L, const Scene_entry *e, const char *fmt, va_list ap)
{
  char where[640], why[512];
  scene_origin(L, e->override, where, sizeof where);
  vsnprintf(why, sizeof why, fmt, ap);
  return scene_fail(L, "%s: %s.%s = %s: %s", where, e->sec, e->key, e->val, why);
}
#line 1110 "paper/scene.nw"
PRINTF_LIKE(3, 4)
int scene_bad(Scene_loader *L, const Scene_entry *e, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vbad(L, e, fmt, ap);
  va_end(ap);
  return L->failed;
}

PRINTF_LIKE(2, 3)
int scene_blame(Scene_loader *L, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vbad(L, &L->last, fmt, ap);
  va_end(ap);
  return L->failed;
}
