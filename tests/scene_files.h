/* scene_files.h: the small scenes that the scene tests write
   (tests/test_scene.c, test_scene_errors.c): Example 5.2 as the base of
   every edited scene, the files written into a temporary folder and
   removed at the end, and the expectation of a refusal: status 2, nothing
   allocated, one line naming the file, the key and the reason. */
#ifndef CONTACTOPT_TEST_SCENE_FILES_H
#define CONTACTOPT_TEST_SCENE_FILES_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "part_geometry.h"
#include "scene.h"

static char tmpdir[] = "/tmp/test_scene.XXXXXX";
static char made[256][256];   /* files written in tmpdir, removed at the end */
static int nmade;

/* The base of every bad scene: Example 5.2, one key a line, line numbers
   as in the comment. */
static const char base[] =
  "[geometry]\na = 0\nb = 4\ngamma = 1\n"                         /* 1-4 */
  "[design]\nN = 16\nC0 = 0.05\nC1 = 0.025\nC2 = 3.91\n"          /* 5-9 */
  "initial = line\nline_start = 0\nline_end = 0.05\n"             /* 10-12 */
  "[mesh]\nM = 1\nR = 3\nC0prime = 0.25\n"                        /* 13-16 */
  "[material]\nE = 2.15e11\nnu = 0.29\n"                          /* 17-19 */
  "[left]\nbc = clamped\n[right]\nbc = roller\n"                  /* 20-23 */
  "[top]\nbc = traction\nfrom = 2\nto = 4\nP2 = -5.75e8\n";       /* 24-28 */

/* A part: the base without the rectangle's keys (gamma, R, the top), C2
   the strip's area, the geometry of tests/part_geometry.h beside it
   (meshed as the scene loads), three of its named curves and one of its
   named surfaces, the curves in the order top, bore, seat. */
static const char part_base[] =
  "[geometry]\na = 0\nb = 4\n"
  "[design]\nN = 16\nC0 = 0.05\nC1 = 0.025\nC2 = 0.91\n"
  "initial = line\nline_start = 0\nline_end = 0.05\n"
  "[mesh]\nM = 1\nC0prime = 0.25\n"
  "[material]\nE = 2.15e11\nnu = 0.29\n"
  "[part]\ngeometry = part.geo\n"
  "[boundary.top]\nbc = traction\nP2 = -5.75e8\n"
  "[boundary.bore]\nbc = pressure\np = 1e7\n"
  "[material.rubber]\nE = 6e6\nnu = 0.45\n"
  "[boundary.seat]\nbc = clamped\n"
  "[left]\nbc = clamped\n[right]\nbc = roller\n";

/* write text to tmpdir/name; path = its path */
static inline void write_file(const char *name, const char *text, char *path,
                              size_t size)
{
  FILE *fp;
  snprintf(path, size, "%s/%s", tmpdir, name);
  if (!(fp = fopen(path, "w")) || fputs(text, fp) < 0 || fclose(fp)) {
    fprintf(stderr, "test_scene: cannot write %s\n", path);
    exit(1);
  }
  if (nmade < 256) snprintf(made[nmade++], sizeof made[0], "%s", path);
}

/* write the n bytes of data (NUL bytes too) to tmpdir/name; path = it */
static inline void write_bytes(const char *name, const char *data, size_t n,
                               char *path, size_t size)
{
  FILE *fp;
  snprintf(path, size, "%s/%s", tmpdir, name);
  if (!(fp = fopen(path, "wb")) || fwrite(data, 1, n, fp) != n || fclose(fp)) {
    fprintf(stderr, "test_scene: cannot write %s\n", path);
    exit(1);
  }
  if (nmade < 256) snprintf(made[nmade++], sizeof made[0], "%s", path);
}

/* out = base with its first `old` replaced by `with`; 0 if old not found */
static inline int edit(char *out, size_t size, const char *old, const char *with)
{
  const char *at = strstr(base, old);
  if (!at) return 0;
  snprintf(out, size, "%.*s%s%s", (int)(at - base), base, with,
           at + strlen(old));
  return 1;
}

/* load path with the overrides; expect status 2 and a message holding
   the path, key and word */
static inline void expect(const char *what, const char *path, int nov,
                          char *const *ov, const char *key, const char *word)
{
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc = scene_load(&s, path, nov, ov, &st);
  check(rc == STATUS_INPUT && st.code == STATUS_INPUT && !s.alpha0
        && strstr(st.msg, path) && strstr(st.msg, key)
        && strstr(st.msg, word) && !strchr(st.msg, '\n'),
        "%s: %s", what, st.msg);
  scene_free(&s);
}

/* the base scene edited, then loaded: expect an error */
static inline void expect_edit(const char *what, const char *old, const char *with,
                               const char *key, const char *word)
{
  char text[4096], path[256], name[64];
  if (!edit(text, sizeof text, old, with)) {
    check(0, "%s: the edit does not apply to the base scene", what);
    return;
  }
  snprintf(name, sizeof name, "bad%02d.scene", nmade);
  write_file(name, text, path, sizeof path);
  expect(what, path, 0, NULL, key, word);
}

/* write the shape file name holding text, and a scene (the base with
   initial = file) that names it; scene = its path */
static inline void shape_scene(const char *name, const char *text, char *scene,
                               size_t size)
{
  char path[256], with[128], body[4096], own[72];
  write_file(name, text, path, sizeof path);
  snprintf(with, sizeof with, "initial = file\nfile = %s\n", name);
  edit(body, sizeof body, "initial = line\nline_start = 0\nline_end = 0.05\n",
       with);
  snprintf(own, sizeof own, "%.60s.scene", name);
  write_file(own, body, scene, size);
}

/* write tmpdir/part.geo and tmpdir/name: the part's scene with its first
   old replaced by with (old NULL: as it is), then more; path = the scene */
static inline void part_scene(const char *name, const char *old,
                              const char *with, const char *more, char *path,
                              size_t size)
{
  char text[8192], geo[256];
  const char *at = old ? strstr(part_base, old) : NULL;
  if (old && !at) {
    fprintf(stderr, "test_scene: %s: the edit does not apply\n", name);
    exit(1);
  }
  if (at)
    snprintf(text, sizeof text, "%.*s%s%s%s", (int)(at - part_base), part_base,
             with, at + strlen(old), more ? more : "");
  else snprintf(text, sizeof text, "%s%s", part_base, more ? more : "");
  static int geo_made;
  if (!geo_made++)
    write_file("part.geo", PART_GEO, geo, sizeof geo);
  write_file(name, text, path, size);
}

/* make the temporary folder; 0 if it cannot be made */
static inline int scene_files_begin(void)
{
  if (mkdtemp(tmpdir)) return 1;
  perror("test_scene: mkdtemp");
  return 0;
}

/* remove the files written and the folder */
static inline void scene_files_end(void)
{
  for (int i = 0; i < nmade; i++) unlink(made[i]);
  rmdir(tmpdir);
}
#endif
