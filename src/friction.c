#line 172 "paper/friction.nw"
#include <math.h>
#include "friction.h"

#line 182 "paper/friction.nw"
void friction_tresca_bounds(const Problem *p, const Mesh *m, const Dofs *d,
                            double *slip)
{
  for (int k = 0; k < d->nt; k++)
    slip[k] = p->slip_bound * mesh_tributary(m, d->tangent_col[k]);
}
#line 193 "paper/friction.nw"
void friction_coulomb_bounds(const Problem *p, const Dofs *d,
                             const double *T, double *slip)
{
  int c = 0;
  for (int k = 0; k < d->nt; k++) {
    while (c < d->nc && d->contact_col[c] < d->tangent_col[k]) c++;
    int here = c < d->nc && d->contact_col[c] == d->tangent_col[k];
    slip[k] = here ? p->friction * fmax(T[c], 0) : 0;
  }
}
#line 206 "paper/friction.nw"
double friction_work(const Dofs *d, const double *slip, const double *Q)
{
  double w = 0;
  for (int k = 0; k < d->nt; k++) w += slip[k] * fabs(Q[d->tangent[k]]);
  return w;
}
#line 218 "paper/friction.nw"
void friction_gradient(const Problem *p, const Mesh *m, const Dofs *d,
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
