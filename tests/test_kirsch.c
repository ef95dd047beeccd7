/* test_kirsch: Kirsch's hole.  tests/scenes/kirsch.scene presses the
   block of tests/parts/kirsch.geo (4 m by 4 m above the strip, a hole of
   radius r = 0.1 m at its centre) by a uniform pressure p onto a flat
   frictionless foundation, u1 held on the left by rollers: far from the
   hole the stress is uniaxial, sigma22 = -p, and Kirsch's solution for
   a hole in an infinite plate (2r/W = 1/20 here: the finite
   width raises the factor by under half a percent, by Heywood's fit of
   Howland's solution) gives the hoop stress sigma22 = -3p at the
   hole's sides (xc +- r, yc), where the hoop direction is x2.  Measured:
   the area-weighted mean of sigma22 over the triangles that touch the
   node at (xc +- r, yc), the mean of the two sides, over -p.  The test
   (no argument) solves at mesh.refine = 1 and 2 and asserts the error
   |ratio - 3| decreases and is within 10 % at refine 2; with arguments
   K1 K2 ... it prints the table "refine triangles ratio error" of
   those levels (src/hard-parts.sh runs it for make figures). */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "case.h"

static const double xc = 2, yc = 2.25, r = 0.1, p = 1e8;

/* the mean sigma22 of the triangles touching the node nearest (x, y) */
static double node_sigma22(const Model *md, double x, double y, double *dist)
{
  const Mesh *m = model_mesh(md);
  int best = 0;
  for (int k = 1; k < m->nnodes; k++)
    if (hypot(m->xy[2 * k] - x, m->xy[2 * k + 1] - y)
        < hypot(m->xy[2 * best] - x, m->xy[2 * best + 1] - y)) best = k;
  *dist = hypot(m->xy[2 * best] - x, m->xy[2 * best + 1] - y);
  double sum = 0, area = 0;
  for (int t = 0; t < m->ntri; t++)
    for (int k = 0; k < 3; k++)
      if (m->tri[3 * t + k] == best) {
        double s[5], A = fabs(mesh_area(m, t));
        model_stress(md, t, s);
        sum += A * s[1], area += A;
      }
  return sum / area;
}

/* the ratio of the hoop stress at the hole's sides to the far stress -p */
static int kirsch(int refine, double *ratio, int *ntri)
{
  Case c;
  char over[32], *ov[1] = { over };
  snprintf(over, sizeof over, "mesh.refine=%d", refine);
  int ok = !case_load(&c, "tests/scenes/kirsch.scene", 1, ov) && !case_model(&c)
           && !case_solve(&c);
  if (ok) {
    double d1, d2;
    double s = 0.5 * (node_sigma22(c.md, xc + r, yc, &d1) + node_sigma22(c.md, xc - r, yc, &d2));
    *ratio = s / -p;
    *ntri = model_mesh(c.md)->ntri;
    ok = d1 < 1e-12 && d2 < 1e-12;
  } else fprintf(stderr, "refine %d: %s\n", refine, c.st.msg);
  close_case(&c);
  return ok;
}

int main(int argc, char **argv)
{
  if (argc > 1) {
    printf("# refine triangles ratio error\n");
    for (int i = 1; i < argc; i++) {
      double ratio; int nt;
      if (!kirsch(atoi(argv[i]), &ratio, &nt)) return 1;
      printf("%d %d %.6f %.3e\n", atoi(argv[i]), nt, ratio, fabs(ratio - 3));
    }
    return 0;
  }
  double q[2]; int nt[2];
  for (int i = 0; i < 2; i++)
    if (!check(kirsch(i + 1, q + i, nt + i), "refine %d: solved, the hole's sides are nodes", i + 1))
      return check_done();
  double e1 = fabs(q[0] - 3), e2 = fabs(q[1] - 3);
  check(e2 < e1, "the hoop stress over the far stress: %.4f (%d triangles), %.4f (%d): "
        "its error from Kirsch's 3 decreases, %.3f -> %.3f", q[0], nt[0], q[1], nt[1], e1, e2);
  check(e2 < 0.3, "at refine 2 within 10 %% of Kirsch's 3: %.3f < 0.3", e2);
  return check_done();
}
