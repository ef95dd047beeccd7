#line 394 "paper/friction.nw"
#include <math.h>
#include "friction.h"
#line 400 "paper/friction.nw"
void friction_tresca_bounds(const Problem *p, const Mesh *m, const Fem_dofs *d,
                            double *slip)
{
  for (int k = 0; k < d->nt; k++)
    slip[k] = p->slip_bound * mesh_tributary(m, d->tangent_col[k]);
}
#line 409 "paper/friction.nw"
double friction_work(const Fem_dofs *d, const double *slip, const double *Q)
{
  double w = 0;
  for (int k = 0; k < d->nt; k++) w += slip[k] * fabs(Q[d->tangent[k]]);
  return w;
}
#line 421 "paper/friction.nw"
void friction_gradient(const Problem *p, const Mesh *m, const Fem_dofs *d,
                       const double *Q, double *G)
{
  const double *xy = m->xy;
  for (int k = 0; k < d->nt; k++) {
    int i = d->tangent_col[k];
    double half = 0.5 * p->slip_bound * fabs(Q[d->tangent[k]]);
    for (int j = i - 1; j <= i; j++) {           /* the edge A_j A_j+1 */
      if (j < 0 || j >= m->N) continue;
      double dx = xy[2 * (j + 1)] - xy[2 * j], dy = xy[2 * (j + 1) + 1] - xy[2 * j + 1];
      double rate = half * dy / hypot(dx, dy);   /* half g |u1| d l_e / d X_j+1 */
      G[j + 1] += rate, G[j] -= rate;
    }
  }
}
#line 442 "paper/friction.nw"
int friction_side_holds(const Problem *p, int component)
{
  for (int id = 0; id < SIDE_COUNT; id++) {
    Problem_bc_kind k = p->side[id].kind;
    if (k == BC_CLAMPED || (k == BC_ROLLER && (id == SIDE_TOP) == (component == 1)))
      return 1;
  }
  for (int s = 0; s < p->part.ncurve; s++) {
    const Problem_curve *c = &p->part.curve[s];
    if (c->kind == BC_CLAMPED || (c->kind == BC_ROLLER && c->normal == component))
      return 1;
  }
  return 0;
}
#line 461 "paper/friction.nw"
/* L = the total load (L1, L2) of a body of this area, N/m */
static void total_load(const Problem *p, double area, double L[2])
{
  for (int j = 0; j < 2; j++) L[j] = p->body_force[j] * area;
  if (p->part.geometry[0])               /* a part's curves */
    for (int j = 0; j < 2; j++) L[j] += p->part.load[j];
  for (int id = 0; id < SIDE_COUNT; id++)
    if (p->side[id].kind == BC_TRACTION)
      for (int j = 0; j < 2; j++)
        L[j] += p->side[id].P[j] * (p->side[id].to - p->side[id].from);
}
#line 476 "paper/friction.nw"
Friction_hold friction_hold(const Problem *p)
{
  double w = p->b - p->a, area[2] = {(p->gamma - p->C0prime) * w, p->gamma * w};
  if (p->part.geometry[0])               /* a part over the strip */
    area[0] = p->part.area, area[1] = p->part.area + p->C0prime * w;
  Friction_hold least = {0, 0, 0};
  for (int end = 0; end < 2; end++) {
    double L[2];
    total_load(p, area[end], L);
    Friction_hold h = {0, fabs(L[0]), -L[1]};
    if (p->contact == CONTACT_TRESCA) h.capacity = p->slip_bound * w;
    if (p->contact == CONTACT_COULOMB) h.capacity = p->friction * fmax(h.vertical, 0);
    if (end == 0 || h.capacity - h.load < least.capacity - least.load) least = h;
  }
  return least;
}
