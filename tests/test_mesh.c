/* test_mesh: the moving mesh (paper/mesh.nw).  The article's mesh has the
   sizes of Fig. 5.2a, every triangle positively oriented, the area of the
   body; the nodes move by (4.2); the designs that would invert a triangle
   are refused.  The operator assembled on it: test_fem.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "problem.h"
#include "mesh.h"

#include "free_body.h"

/* Fig. 5.2a: 128 triangles, 17 contact nodes; orientation; (4.2) */
static void article_mesh(void)
{
  Problem s = free_body(16, 1, 3, MODEL_PLANE_STRESS);
  Status st = { 0, "" };
  Mesh *m = mesh_new(&s, &st);
  double X[17];
  design(16, X);
  mesh_move(m, X, &st);
  check(m->ntri == 128 && m->ncol == 17, "article mesh: %d triangles, %d contact nodes (the moving points A_i, (4.1))",
        m->ntri, m->ncol);
  int positive = 1;
  for (int t = 0; t < m->ntri; t++) positive &= mesh_area(m, t) > 0;
  check(positive, "article mesh: every triangle positively oriented");
  double area = 0;
  for (int t = 0; t < m->ntri; t++) area += mesh_area(m, t);
  double trapez = 0;
  for (int i = 0; i < 16; i++) trapez += 0.25 * (X[i] + X[i + 1]) / 2;
  check(fabs(area - (4.0 - trapez)) < 1e-13, "mesh area = gamma(b-a) - h sum trapezoids, the area of B (4.4)");
  mesh_free(m);

  s = free_body(8, 4, 2, MODEL_PLANE_STRESS);
  m = mesh_new(&s, &st);
  double Y[9] = { 0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.1, 0.0, 0.03 };
  mesh_move(m, Y, &st);
  int ok = 1;
  for (int i = 0; i <= 8; i++)
    for (int j = 0; j <= 4; j++) {
      double want = Y[i] + (0.25 - Y[i]) * j / 4.0;
      ok &= fabs(m->xy[2 * (j * 9 + i) + 1] - want) < 1e-15;
      ok &= fabs(mesh_motion(m, j * 9 + i) - (1 - j / 4.0)) < 1e-15;
    }
  check(ok, "moving nodes follow (4.2): x2 = alpha + (C0' - alpha) j/M, rate 1 - j/M");
  Y[5] = 0.25;
  check(mesh_move(m, Y, &st) == STATUS_INPUT && strstr(st.msg, "inverted"),
        "alpha = C0prime is refused by (4.2): %s", st.msg);
  Y[5] = -0.01;
  check(mesh_move(m, Y, &st) == STATUS_INPUT && strstr(st.msg, "alpha_5"),
        "alpha < 0 is refused by (4.2): %s", st.msg);
  mesh_free(m);
}

int main(void)
{
  article_mesh();
  return check_done();
}
