/* free_body.h: the free body of Example 5.1's size and material that the
   mesh and fem tests move and assemble (tests/test_mesh.c, test_fem.c),
   and a design that makes no triangle a right one. */
#ifndef CONTACTOPT_TEST_FREE_BODY_H
#define CONTACTOPT_TEST_FREE_BODY_H
#include <math.h>
#include <string.h>
#include "problem.h"

static Problem free_body(int N, int M, int R, Problem_plane_model model)
{
  Problem p;
  memset(&p, 0, sizeof p);
  p.a = 0; p.b = 4; p.gamma = 1; p.N = N; p.M = M; p.R = R;
  p.C0 = 0.05; p.C0prime = 0.25; p.material.young = 2.15e11; p.material.nu = 0.29; p.model = model;
  return p;                          /* every side free: all DOFs unknowns */
}

/* an arc-shaped, non-uniform design so that no triangle is a right one */
static void design(int N, double *X)
{
  for (int i = 0; i <= N; i++) {
    double x = 4.0 * i / N;
    X[i] = 160.025 - sqrt(160.025 * 160.025 - (x - 4) * (x - 4))
         + 0.01 * sin(3.0 * i);
    if (X[i] < 0) X[i] = 0;
  }
}
#endif
