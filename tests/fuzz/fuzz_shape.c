/* fuzz_shape.c: libFuzzer harness for the shape-file reader of the scene
   loader (design.initial = file, paper/scene.nw).  Built and run by
   `make fuzz-shape` (rules in tests/fuzz/fuzz.mk) with AddressSanitizer,
   UBSan and LeakSanitizer.

   An input is the text of a shape file.  It is written as shape.dat beside
   a fixed scene on [0, 4] that names it (made once, under /dev/shm when it
   exists), and the scene is loaded three times: at the scene's N = 16, at
   N = 3 and at N = 40 (the rows resampled or taken as they are).  After each
   load the contract of scene_load (contract.h) is checked; a shape file
   with a NUL byte is not text and must be refused. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "scene.h"
#include "contract.h"
#include "folder.h"


static const char scene_text[] =
  "[geometry]\na = 0\nb = 4\ngamma = 1\n"
  "[design]\nN = 16\nC0 = 0.05\nC1 = 0.025\nC2 = 3.91\ninitial = file\n"
  "file = shape.dat\n"
  "[mesh]\nM = 1\nR = 3\nC0prime = 0.25\n"
  "[material]\nE = 2.15e11\nnu = 0.29\n"
  "[left]\nbc = clamped\n[right]\nbc = roller\n"
  "[top]\nbc = traction\nfrom = 2\nto = 4\nP2 = -5.75e8\n";

/* make the folder and the scene file, once */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  FILE *fp;
  (void)argc;
  (void)argv;
  make_folder("fuzz-shape", "shape.scene");
  if (!(fp = fopen(path, "w")) || fputs(scene_text, fp) == EOF || fclose(fp)) {
    perror("fuzz_shape: shape.scene");
    exit(1);
  }
  return 0;
}

/* load the scene with the overrides, check, free; binary: the shape file
   holds a NUL byte */
static void load(int n, char *const *override, int binary)
{
  Scene s;
  Status st = {STATUS_OK, ""};
  int rc = scene_load(&s, path, n, override, &st);
  check_contract(rc, &s, &st, path, binary);
  scene_free(&s);
}

static char *const coarse[] = {"design.N=3"};
static char *const fine[] = {"design.N=40"};

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
  FILE *fp;
  int binary = memchr(data, '\0', size) != NULL;
  if (!(fp = fopen(shape, "wb"))) abort();
  if (fwrite(data, 1, size, fp) != size) abort();
  if (fclose(fp)) abort();
  load(0, NULL, binary);
  load(1, coarse, binary);
  load(1, fine, binary);
  return 0;
}
