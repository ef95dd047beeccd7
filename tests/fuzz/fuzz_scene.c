/* fuzz_scene.c: libFuzzer harness for the scene parser and validator
   (scene_load, paper/scene.nw).  Built and run by `make fuzz` (rules in
   tests/fuzz/fuzz.mk) with AddressSanitizer, UBSan and LeakSanitizer.

   An input is the text of a scene file, optionally followed by a line
   "%%" and then override strings, one a line ("section.key=value", as
   -s gives them).  The scene part is written to a file in a folder made
   once (under /dev/shm when it exists: scene_load reads a path, not
   memory), beside a shape file of 17 rows, shape.dat, that a scene may
   name as design.file, and the geometry of the scene tests' part,
   part.geo (tests/part_geometry.h), that a scene may name as
   part.geometry.  The file is then loaded without overrides, with
   the overrides of the input, and with three fixed sets of overrides; after
   each load the contract of scene_load (src/scene.h) is checked and any
   breach aborts, which libFuzzer reports as a crash:
   - success: status 0, N, M, R >= 1, a mesh whose 2 N (M + R) triangles
     have 36 stiffness entries each that an int counts, a < b with a
     finite area gamma (b - a), C0 < C0prime < gamma, an initial shape of
     N+1 finite values in [0, C0prime), and so on;
     a scene with a NUL byte is not text and must be refused;
   - failure: status 2 (bad input) or 4 (no memory), no memory held, and
     one line of message that begins with the scene path (status 2).
   scene_free is then called twice (the interface says it is harmless). */
#define _GNU_SOURCE   /* memmem */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "scene.h"
#include "contract.h"
#include "folder.h"
#include "../part_geometry.h"

enum { MAX_OVERRIDES = 16 };

static int binary;             /* the scene part holds a NUL byte */
static char geo[300];          /* the part's geometry, part.geo */

static void remove_geo(void)
{
  unlink(geo);
}

/* make SAN=1 and the fuzzer: gmsh's parser leaks the lists it was
   building when a .geo has a syntax error (gmsh_yyparse), inside the
   library; LeakSanitizer ignores that stack alone, read by the slow
   unwinder (as in tests/test_part.c) */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "fast_unwind_on_malloc=0"; }
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:gmsh_yyparse\n"; }

/* make the folder, the shape file and the geometry, once */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  FILE *fp;
  int i;
  (void)argc;
  (void)argv;
  make_folder("fuzz", "fuzz.scene");
  if (!(fp = fopen(shape, "w"))) {
    perror("fuzz_scene: shape.dat");
    exit(1);
  }
  fprintf(fp, "# x1 alpha\n");
  for (i = 0; i <= 16; i++) fprintf(fp, "%g %g\n", 0.25 * i, 0.003125 * i);
  fclose(fp);
  snprintf(geo, sizeof geo, "%s/part.geo", dir);
  if (!(fp = fopen(geo, "w")) || fputs(PART_GEO, fp) < 0 || fclose(fp)) {
    perror("fuzz_scene: part.geo");
    exit(1);
  }
  atexit(remove_geo);   /* before the folder's cleanup, registered earlier */
  return 0;
}

/* load the scene file with the overrides, check, free */
static void load(int n, char *const *override)
{
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc = scene_load(&s, path, n, override, &st);
  check_contract(rc, &s, &st, path, binary);
  scene_free(&s);
  scene_free(&s);
}

/* the fixed sets of overrides, applied to every input */
static char *const set1[] = {"design.N=3", "mesh.M=2"};
static char *const set2[] = {"solver.state=psor", "material.model=plane_strain",
                             "solver.max_iter=", "top.P1 = 1e3"};
static char *const set3[] = {"design.initial=file", "design.file=shape.dat",
                             "design.arc_x1=", "design.arc_x2=",
                             "design.arc_radius=", "design.line_start=",
                             "design.line_end=", "design.constant="};

/* the length of the scene part of data: up to the line "%%", if any */
static size_t scene_part(const unsigned char *data, size_t size)
{
  const unsigned char *at;
  if (size >= 3 && memcmp(data, "%%\n", 3) == 0) return 0;
  at = memmem(data, size, "\n%%\n", 4);
  return at ? (size_t)(at - data) + 1 : size;
}

/* override[] = the lines of text (modified); return their number */
static int split(char *text, char **override)
{
  char *line, *save = NULL;
  int n = 0;
  for (line = strtok_r(text, "\n", &save); line && n < MAX_OVERRIDES;
       line = strtok_r(NULL, "\n", &save))
    override[n++] = line;
  return n;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
  size_t m = scene_part(data, size);
  char *text, *override[MAX_OVERRIDES];
  FILE *fp;
  int n = 0;
  if (!(fp = fopen(path, "wb"))) abort();
  if (fwrite(data, 1, m, fp) != m) abort();   /* NUL bytes included */
  binary = memchr(data, '\0', m) != NULL;
  if (fclose(fp)) abort();
  load(0, NULL);
  if (m < size) {   /* the overrides: after the line "%%" */
    if (!(text = malloc(size - m - 2))) return 0;
    memcpy(text, data + m + 3, size - m - 3);
    text[size - m - 3] = '\0';
    if ((n = split(text, override))) load(n, override);
    free(text);
  }
  load(2, set1);
  load(4, set2);
  load(8, set3);
  return 0;
}
