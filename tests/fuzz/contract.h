/* contract.h: the contract of scene_load (src/scene.h), checked after each
   load by the fuzzing harnesses fuzz_scene.c and fuzz_shape.c; a breach
   aborts, which libFuzzer reports as a crash.  `path` is the scene file
   loaded; `binary` says whether the scene text held a NUL byte. */
#ifndef CONTACTOPT_FUZZ_CONTRACT_H
#define CONTACTOPT_FUZZ_CONTRACT_H
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"

/* whether m is a material as the loader checks it */
static int material_ok(const Problem_material *m)
{
  if (m->kind == MATERIAL_ISOTROPIC)
    return m->young > 0 && m->nu > -1 && m->nu < 0.5;
  return m->kind == MATERIAL_ORTHOTROPIC && m->E1 > 0 && m->E2 > 0 && m->G12 > 0
         && m->nu12 * m->nu12 < m->E1 / m->E2 && isfinite(m->angle);
}

/* whether the part of p is as the loader leaves it: none, all zero; or
   an absolute path, R = 0, gamma = C0prime, its curves loaded where they
   carry a load, its surfaces' materials checked */
static int part_ok(const Problem *p)
{
  const Problem_part *q = &p->part;
  int j;
  if (!q->geometry[0]) return q->refine == 0 && q->ncurve == 0 && q->nregion == 0;
  if (q->geometry[0] != '/' || q->refine < 1 || p->R != 0 || p->gamma != p->C0prime
      || q->ncurve < 0 || q->ncurve > PROBLEM_NAMED || q->nregion < 0
      || q->nregion > PROBLEM_NAMED || p->side[SIDE_TOP].kind != BC_FREE)
    return 0;
  for (j = 0; j < q->ncurve; j++)
    if (!q->curve[j].name[0]
        || (q->curve[j].kind == BC_TRACTION && q->curve[j].P[0] == 0
            && q->curve[j].P[1] == 0)
        || (q->curve[j].kind == BC_PRESSURE && q->curve[j].pressure == 0))
      return 0;
  for (j = 0; j < q->nregion; j++)
    if (!q->region[j].name[0] || !material_ok(&q->region[j].material)) return 0;
  return 1;
}

/* the contract of scene_load after it returned rc; abort on a breach */
static void check_contract(int rc, const Scene *s, const Status *st,
                           const char *path, int binary)
{
  int i, part = s->problem.part.geometry[0] != '\0';
  if (rc == STATUS_OK) {
    if (binary || st->code != STATUS_OK || !s->alpha0 || s->problem.N < 1
        || s->problem.M < 1 || (!part && s->problem.R < 1) || !part_ok(&s->problem)
        || !(72.0 * s->problem.N * ((double)s->problem.M + s->problem.R) <= INT_MAX)
        || !(s->problem.a < s->problem.b) || !isfinite(s->problem.gamma * (s->problem.b - s->problem.a))
        || !(s->problem.C0 > 0) || !(s->problem.C1 >= 0) || !(s->problem.C2 > 0) || !(s->problem.C0 < s->problem.C0prime)
        || (!part && !(s->problem.C0prime < s->problem.gamma))
        || !material_ok(&s->problem.material) || !(s->solver.tol > 0 && s->solver.tol < 1)
        || s->solver.max_iter < 1 || !(s->solver.omega > 0 && s->solver.omega < 2)
        || !(s->optimizer.tol > 0 && s->optimizer.tol < 1) || s->optimizer.max_iter < 1
        || strcmp(s->path, path) != 0)
      abort();
    for (i = 0; i <= s->problem.N; i++)
      if (!isfinite(s->alpha0[i]) || !(s->alpha0[i] >= 0)
          || !(s->alpha0[i] < s->problem.C0prime))
        abort();
    for (i = 0; i < SIDE_COUNT; i++)
      if (s->problem.side[i].kind == BC_TRACTION
          && (!(s->problem.side[i].from < s->problem.side[i].to)
              || (s->problem.side[i].P[0] == 0 && s->problem.side[i].P[1] == 0)))
        abort();
    if (strcmp(qp_method_name(s->solver.method), "?") == 0
        || strcmp(opt_method_name(s->optimizer.method), "?") == 0
        || strcmp(problem_model_name(s->problem.model), "?") == 0)
      abort();
    return;
  }
  if ((rc != STATUS_INPUT && rc != STATUS_SYSTEM) || (int)st->code != rc
      || s->alpha0 || !st->msg[0] || strchr(st->msg, '\n'))
    abort();
  if (rc == STATUS_INPUT && strncmp(st->msg, path, strlen(path)) != 0)
    abort();
}

#endif
