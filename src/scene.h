#line 135 "paper/scene.nw"
#ifndef CONTACTOPT_SCENE_H
#define CONTACTOPT_SCENE_H
#include "status.h"
#include "problem.h"
#include "qp.h"
#include "opt.h"

typedef struct {
  char path[512];        /* the scene file, as given: every message names it */
  Problem problem;       /* [geometry] [design] [mesh] [material] [left]
                            [right] [top] [body_force] */
  char initial[16];      /* design.initial: arc, line, constant or file */
  double *alpha0;        /* N+1 nodal values of the initial design (owned) */
  Qp_options solver;     /* [solver]: the state problem (4.3) */
  Opt_options optimizer; /* [optimizer]: Section 4.4, Algorithm 4.1 */
} Scene;

/* Read the scene file at path, then apply the overrides "section.key=value"
   (as given by -s on the command line), then check everything. On failure
   *s holds nothing to free and st names the file, the key and the reason. */
int scene_load(Scene *s, const char *path, int noverride,
               char *const *override, Status *st);
void scene_free(Scene *s);
#endif
