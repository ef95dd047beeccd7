#line 112 "paper/grad.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grad.h"
#line 170 "paper/grad.nw"
static void grad_element(const Model *md, int t, double *G);
static double grad_element_height(const double gy[3], const double q[6],
                                  const double e[3], const double De[3],
                                  double d, int m);
static double grad_body_force(const double F[2], const double q[6],
                              double gy_m);

int grad_energy(const Model *md, double *G, Status *st)
{
  if (!model_solved(md))
    return status_set(st, STATUS_INPUT, "gradient: no state has been solved");
  if (model_problem(md)->contact == CONTACT_COULOMB)
    return status_set(st, STATUS_INPUT, "gradient: (4.8) is the energy's "
                      "without Coulomb friction (objective_evaluate: J_F's)");
  const Mesh *m = model_mesh(md);
  const Fem_dofs *d = model_dofs(md);
  const double *T = model_forces(md);
  memset(G, 0, m->ncol * sizeof *G);
  for (int c = 0; c < d->nc; c++)          /* -sum T_i V_i of (4.8) */
    G[d->contact_col[c]] -= T[c];
  int moving = 2 * m->N * m->M;      /* triangles below C0' */
  for (int t = 0; t < moving; t++) grad_element(md, t, G);
  if (model_problem(md)->contact == CONTACT_TRESCA)      /* Section friction */
    friction_gradient(model_problem(md), m, d, model_state(md), G);
  return STATUS_OK;
}
#line 213 "paper/grad.nw"
static void grad_element(const Model *md, int t, double *G)
{
  const Mesh *m = model_mesh(md);
  const Fem_hooke *h = model_hooke(md) + mesh_material(m, t);
  const Problem *p = model_problem(md);
  double xy[6], q[6], gx[3], gy[3], e[3], De[3];
  long double el[3];
  fem_element_xy(m, t, xy);
  fem_element_q(m, model_dofs(md), model_state(md), t, q);
  fem_element_gradients(xy, gx, gy);
  double d = xy[0] * gx[0] + xy[2] * gx[1] + xy[4] * gx[2];   /* 2|T| */
  fem_element_strain(gx, gy, q, el);
  for (int r = 0; r < 3; r++) e[r] = (double) el[r];
  for (int r = 0; r < 3; r++)
    De[r] = h->D[r][0] * e[0] + h->D[r][1] * e[1] + h->D[r][2] * e[2];
  for (int v = 0; v < 3; v++) {
    int node = m->tri[3 * t + v];
    double rate = mesh_motion(m, node);
    if (rate == 0) continue;
    double de_dy = grad_element_height(gy, q, e, De, d, v);
    if (p->has_body_force) de_dy -= grad_body_force(p->body_force, q, gy[v]);
    G[node % m->ncol] += rate * de_dy;
  }
}
#line 242 "paper/grad.nw"
static double grad_element_height(const double gy[3], const double q[6],
                                  const double e[3], const double De[3],
                                  double d, int m)
{
  int up = (m + 2) % 3, down = (m + 1) % 3;     /* k with k+1 = m, k+2 = m */
  double de0 = q[2 * up] - q[2 * down];          /* d e~_11 / d y_m */
  double de2 = q[2 * up + 1] - q[2 * down + 1];  /* d e~_12 / d y_m */
  double energy2 = e[0] * De[0] + e[1] * De[1] + e[2] * De[2];
  return (De[0] * de0 + De[2] * de2) / (2 * d) - energy2 * gy[m] / (4 * d * d);
}
#line 256 "paper/grad.nw"
static double grad_body_force(const double F[2], const double q[6],
                              double gy_m)
{
  double work = 0;
  for (int v = 0; v < 3; v++) work += F[0] * q[2 * v] + F[1] * q[2 * v + 1];
  return work * gy_m / 6;
}
