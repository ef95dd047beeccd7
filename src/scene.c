#line 3156 "paper/scene.nw"
#include <stdlib.h>
#include <string.h>
#include "scene_private.h"
#line 3165 "paper/scene.nw"
int scene_load(Scene *s, const char *path, int noverride,
               char *const *override, Status *st)
{
  Scene_loader L;
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
#line 3188 "paper/scene.nw"
void scene_free(Scene *s)
{
  if (!s) return;
  free(s->alpha0);
  s->alpha0 = NULL;
}
