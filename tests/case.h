/* case.h: a case, that is a scene loaded with overrides, its model built
   and solved at alpha0, at once or step by step, for the test programs
   that solve a scene; and two vector norms.  Each step puts its status in
   c->rc (and c->st); close_case frees what the steps made, wherever they
   stopped.  Which test uses which:
     open_case (Example 5.1 with overrides, solved): test_friction.c,
       test_cgssor.c, test_qp.c, test_coulomb.c;
     case_load, case_model, case_solve (any scene; the test checks each
       step, or changes c->s before the model, or the model before the
       solve): test_condense.c, test_grad.c, test_model.c,
       test_objective.c, test_output.c, test_coulomb.c (open_coulomb);
       case_load alone, its models one per state solver (solve_cold):
       weakly_active.h (test_pdas.c, test_psor.c, test_cgssor.c,
       test_model.c);
     case_load_refined (-s mesh.refine=k, by setup.h's load_refined):
       test_condense.c, test_model.c;
     max_abs, max_diff: test_friction.c, test_cgssor.c, test_coulomb.c.
   Two models are built outside case_model: test_scene_write.c's energy
   (of a scene written and read back; CHOLMOD by setup.h's test_start)
   and test_cgssor.c's, on a case's scene with a state solver that the
   scene refuses. */
#ifndef CONTACTOPT_TEST_CASE_H
#define CONTACTOPT_TEST_CASE_H
#include <math.h>
#include <string.h>
#include "setup.h"
#include "scene.h"
#include "model.h"

#define EX51 "data/example-5.1.scene"

typedef struct {
  Scene s;
  cholmod_common cm;
  Model *md;
  int rc;
  Status st;
} Case;

/* CHOLMOD started (test_start) and the scene at path loaded with the n
   overrides ov; no model yet, so that the caller may change c->s */
static inline int case_load(Case *c, const char *path, int n, char **ov)
{
  memset(c, 0, sizeof *c);
  test_start(&c->cm);
  return c->rc = scene_load(&c->s, path, n, ov, &c->st);
}

/* the same, the scene refined k times (load_refined) */
static inline int case_load_refined(Case *c, const char *path, int k)
{
  memset(c, 0, sizeof *c);
  test_start(&c->cm);
  return c->rc = load_refined(&c->s, path, k, &c->st);
}

/* the model of c->s's problem and state solver, anew (after the caller
   changed c->s) if c has one */
static inline int case_model(Case *c)
{
  model_free(c->md);
  if (!(c->md = model_new(&c->s.problem, &c->s.solver, &c->cm, &c->st)))
    return c->rc = c->st.code;
  return c->rc = 0;
}

/* the model solved at the scene's alpha0 */
static inline int case_solve(Case *c)
{
  return c->rc = model_solve(c->md, c->s.alpha0, &c->st);
}

/* EX51 with the overrides, its model solved at alpha0 */
static inline int open_case(Case *c, int n, char **ov)
{
  if (case_load(c, EX51, n, ov) || case_model(c)) return c->rc;
  return case_solve(c);
}

static inline void close_case(Case *c)
{
  model_free(c->md);
  if (c->s.alpha0) scene_free(&c->s);
  cholmod_l_finish(&c->cm);
}

static inline double max_abs(const double *v, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
  return m;
}

static inline double max_diff(const double *u, const double *v, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(u[i] - v[i]));
  return m;
}
#endif
