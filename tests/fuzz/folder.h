/* folder.h: the folder of the fuzzing harnesses fuzz_scene.c and
   fuzz_shape.c, made once under /dev/shm when it exists (scene_load reads
   a path, not memory): `path` the scene file, `shape` the shape file
   shape.dat beside it; removed at exit. */
#ifndef CONTACTOPT_FUZZ_FOLDER_H
#define CONTACTOPT_FUZZ_FOLDER_H
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static char dir[256];          /* the folder */
static char path[300];         /* the scene file */
static char shape[300];        /* the shape file, shape.dat */

/* remove the files and the folder made by make_folder */
static void cleanup(void)
{
  unlink(path);
  unlink(shape);
  rmdir(dir);
}

/* make the folder contactopt-NAME.XXXXXX and the paths in it; exit on failure */
static void make_folder(const char *name, const char *scene)
{
  const char *base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  snprintf(dir, sizeof dir, "%s/contactopt-%s.XXXXXX", base, name);
  if (!mkdtemp(dir)) {
    perror("fuzz: mkdtemp");
    exit(1);
  }
  snprintf(path, sizeof path, "%s/%s", dir, scene);
  snprintf(shape, sizeof shape, "%s/shape.dat", dir);
  atexit(cleanup);
}
#endif
