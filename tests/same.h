/* same.h: whether two loaded scenes are the same, bit for bit, in every
   field but their path: the problem, the options of both solvers, the
   initial shape's kind, formula and file, and the initial design. */
#ifndef CONTACTOPT_TEST_SAME_H
#define CONTACTOPT_TEST_SAME_H
#include <string.h>
#include "scene.h"

/* the name of the first field in which a and b differ, or NULL */
static const char *scene_differs(const Scene *a, const Scene *b)
{
  if (memcmp(&a->problem, &b->problem, sizeof a->problem)) return "problem";
  if (memcmp(&a->solver, &b->solver, sizeof a->solver)) return "solver";
  if (memcmp(&a->optimizer, &b->optimizer, sizeof a->optimizer))
    return "optimizer";
  if (strcmp(a->initial, b->initial)) return "initial";
  if (memcmp(&a->shape, &b->shape, sizeof a->shape)) return "shape";
  if (strcmp(a->shape_file, b->shape_file)) return "shape_file";
  if (!a->alpha0 || !b->alpha0
      || memcmp(a->alpha0, b->alpha0, (a->problem.N + 1) * sizeof *a->alpha0))
    return "alpha0";
  return NULL;
}
#endif
