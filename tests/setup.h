/* setup.h: what every test program of the model does first.  Which test
   uses which:
     test_start (CHOLMOD started and quiet, GSL's handler off):
       test_qp.c, test_pdas.c, test_psor.c, test_cgssor.c (on
       qp_problems.h's cm), test_fem.c, test_scene_write.c, and through
       case.h every test that opens a case (test_condense.c,
       test_coulomb.c, test_friction.c, test_grad.c, test_model.c,
       test_objective.c, test_output.c, and weakly_active.h for
       test_pdas.c, test_psor.c, test_cgssor.c, test_model.c);
     test_start_gsl (GSL's handler off alone, no CHOLMOD): test_newton.c;
     load_refined: through case.h's case_load_refined, test_condense.c
       and test_model.c.
   The test programs that neither factorise with CHOLMOD nor reach GSL's
   routines through the library start nothing: test_mesh.c,
   test_problem.c, test_threads.c (BLAS alone), test_design.c (its GSL is its own reference, whose failure should
   abort it); nor do the tests of the scene files, test_scene.c,
   test_scene_errors.c and test_scene_keys.c, which call scene_load,
   the function they test, with overrides of their own. */
#ifndef CONTACTOPT_TEST_SETUP_H
#define CONTACTOPT_TEST_SETUP_H
#include <stdio.h>
#include "sparse.h"
#include <gsl/gsl_errno.h>
#include "scene.h"

/* GSL's error handler off: the library checks GSL's codes and reports
   every failure through its Status, as the program does */
static inline void test_start_gsl(void)
{
  gsl_set_error_handler_off();
}

/* CHOLMOD started and quiet, GSL's error handler off */
static inline void test_start(cholmod_common *cm)
{
  cholmod_l_start(cm);
  cm->print = 0;
  test_start_gsl();
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
