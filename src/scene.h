#line 236 "paper/scene.nw"
#ifndef CONTACTOPT_SCENE_H
#define CONTACTOPT_SCENE_H
#include <stdio.h>
#include "status.h"
#include "problem.h"
#include "design.h"
#include "qp.h"
#include "opt.h"

typedef struct {
  char path[512];        /* the scene file, as given: every message names it */
  Problem problem;       /* [geometry] [design] [mesh] [material] [part]
                            [boundary.NAME] [material.NAME] [left] [right]
                            [top] [body_force] [contact] */
  char initial[16];      /* design.initial: arc, line, constant or file */
  Design_shape shape;    /* arc, line, constant: the formula of alpha0 */
  char shape_file[4096]; /* file: the shape file's absolute path */
  double *alpha0;        /* N+1 nodal values of the initial design (owned) */
  Qp_options solver;     /* [solver]: the state problem (4.3) */
  Opt_options optimizer; /* [optimizer]: Section 4.4, Algorithm 4.1 */
  int method_chosen;     /* optimizer.method not given: chosen by the scene */
  char note[512];        /* "", or a remark for the user (a shape resampled) */
} Scene;

/* Read the scene file at path, then apply the overrides "section.key=value"
   (as given by -s on the command line), then check everything. On failure
   *s holds nothing to free and st names the file, the key and the reason. */
int scene_load(Scene *s, const char *path, int noverride,
               char *const *override, Status *st);
void scene_free(Scene *s);
/* Write the effective scene: every key of s that means something, defaults
   included, in scene syntax; loading it gives s again, bit for bit. */
int scene_write(const Scene *s, FILE *f, Status *st);
/* Print the table of keys: section.key, unit, default, accepted values and
   meaning, one key a line (latex: as the rows of a LaTeX longtable). */
void scene_keys_print(FILE *f, int latex);
#endif
