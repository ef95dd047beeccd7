/* setup.h: what every test program of the model does first. */
#ifndef CONTACTOPT_TEST_SETUP_H
#define CONTACTOPT_TEST_SETUP_H
#include <stdio.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "scene.h"

/* CHOLMOD started and quiet, GSL's error handler off: the library reports
   every failure through its Status, as the program does */
static inline void test_start(cholmod_common *cm)
{
  cholmod_start(cm);
  cm->print = 0;
  gsl_set_error_handler_off();
}

/* the scene at path on the refined mesh N, M = N/16, R = 3N/16 (M = 1,
   R = 3 below N = 16), as make accuracy and make bench refine it */
static inline int load_refined(Scene *s, const char *path, int N, Status *st)
{
  char over[3][32], *ov[3] = { over[0], over[1], over[2] };
  snprintf(over[0], sizeof over[0], "design.N=%d", N);
  snprintf(over[1], sizeof over[1], "mesh.M=%d", N >= 16 ? N / 16 : 1);
  snprintf(over[2], sizeof over[2], "mesh.R=%d", N >= 16 ? 3 * N / 16 : 3);
  return scene_load(s, path, 3, ov, st);
}
#endif
