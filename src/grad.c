#line 85 "paper/grad.nw"
#include <string.h>
#include "grad.h"

#line 93 "paper/grad.nw"
static void grad_element(const Model *md, int t, double *G);
static double grad_element_height(const double gx[3], const double gy[3],
                                  double u[3][2], const double e[3],
                                  const double De[3], double d, int m);
static double grad_body_force(const double F[2], double u[3][2],
                              double gy_m);

int grad_energy(const Model *md, double *G, Status *st)
{
  if (!md->solved)
    return status_set(st, STATUS_INPUT, "gradient: no state has been solved");
  memset(G, 0, md->mesh->ncol * sizeof *G);
  for (int c = 0; c < md->dofs->nc; c++)          /* -sum T_i V_i of (4.8) */
    G[md->dofs->contact_col[c]] -= md->T[c];
  int moving = 2 * md->mesh->N * md->mesh->M;      /* triangles below C0' */
  for (int t = 0; t < moving; t++) grad_element(md, t, G);
  return STATUS_OK;
}
#line 120 "paper/grad.nw"
static void grad_element(const Model *md, int t, double *G)
{
  const Mesh *m = md->mesh;
  double x[3], y[3], u[3][2], gx[3], gy[3], e[3], De[3];
  
#line 139 "paper/grad.nw"
for (int v = 0; v < 3; v++) {
  int node = m->tri[3 * t + v];
  x[v] = m->xy[2 * node];
  y[v] = m->xy[2 * node + 1];
  for (int c = 0; c < 2; c++) {
    int k = md->dofs->unknown[2 * node + c];
    u[v][c] = k < 0 ? 0.0 : md->Q[k];
  }
}
#line 125 "paper/grad.nw"
  
#line 151 "paper/grad.nw"
for (int k = 0; k < 3; k++) {
  gx[k] = y[(k + 1) % 3] - y[(k + 2) % 3];
  gy[k] = x[(k + 2) % 3] - x[(k + 1) % 3];
}
double d = x[0] * gx[0] + x[1] * gx[1] + x[2] * gx[2];   /* 2|T| */
e[0] = gx[0] * u[0][0] + gx[1] * u[1][0] + gx[2] * u[2][0];
e[1] = gy[0] * u[0][1] + gy[1] * u[1][1] + gy[2] * u[2][1];
e[2] = gy[0] * u[0][0] + gy[1] * u[1][0] + gy[2] * u[2][0]
     + gx[0] * u[0][1] + gx[1] * u[1][1] + gx[2] * u[2][1];
for (int r = 0; r < 3; r++)
  De[r] = md->hooke.D[r][0] * e[0] + md->hooke.D[r][1] * e[1]
        + md->hooke.D[r][2] * e[2];
#line 126 "paper/grad.nw"
  for (int v = 0; v < 3; v++) {
    int node = m->tri[3 * t + v];
    double rate = mesh_motion(m, node);
    if (rate == 0) continue;
    double de_dy = grad_element_height(gx, gy, u, e, De, d, v);
    if (md->problem->has_body_force)
      de_dy -= grad_body_force(md->problem->F, u, gy[v]);
    G[node % m->ncol] += rate * de_dy;
  }
}
#line 168 "paper/grad.nw"
static double grad_element_height(const double gx[3], const double gy[3],
                                  double u[3][2], const double e[3],
                                  const double De[3], double d, int m)
{
  (void) gx;
  int up = (m + 2) % 3, down = (m + 1) % 3;     /* k with k+1 = m, k+2 = m */
  double de0 = u[up][0] - u[down][0];            /* d e~_11 / d y_m */
  double de2 = u[up][1] - u[down][1];            /* d e~_12 / d y_m */
  double energy2 = e[0] * De[0] + e[1] * De[1] + e[2] * De[2];
  return (De[0] * de0 + De[2] * de2) / (2 * d) - energy2 * gy[m] / (4 * d * d);
}
#line 183 "paper/grad.nw"
static double grad_body_force(const double F[2], double u[3][2],
                              double gy_m)
{
  double work = 0;
  for (int v = 0; v < 3; v++) work += F[0] * u[v][0] + F[1] * u[v][1];
  return work * gy_m / 6;
}
