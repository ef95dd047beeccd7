/* case.h: a scene of Example 5.1 with overrides, its model solved at
   alpha0, for the test programs of friction; and two vector norms. */
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

/* load EX51 with the overrides, build its model, solve at alpha0 */
static inline int open_case(Case *c, int n, char **ov)
{
  memset(c, 0, sizeof *c);
  test_start(&c->cm);
  if ((c->rc = scene_load(&c->s, EX51, n, ov, &c->st))) return c->rc;
  if (!(c->md = model_new(&c->s.problem, &c->s.solver, &c->cm, &c->st)))
    return c->rc = c->st.code;
  return c->rc = model_solve(c->md, c->s.alpha0, &c->st);
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
