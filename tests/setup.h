/* setup.h: what every test program of the model does first. */
#ifndef CONTACTOPT_TEST_SETUP_H
#define CONTACTOPT_TEST_SETUP_H
#include <stdio.h>
#include "sparse.h"
#include <gsl/gsl_errno.h>
#include "scene.h"

/* CHOLMOD started and quiet, GSL's error handler off: the library reports
   every failure through its Status, as the program does */
static inline void test_start(cholmod_common *cm)
{
  cholmod_l_start(cm);
  cm->print = 0;
  gsl_set_error_handler_off();
}

/* the scene at path refined k times (-s mesh.refine=k), as make accuracy
   and make bench refine it */
static inline int load_refined(Scene *s, const char *path, int k, Status *st)
{
  char over[32], *ov[1] = { over };
  snprintf(over, sizeof over, "mesh.refine=%d", k);
  return scene_load(s, path, 1, ov, st);
}
#endif
