#line 140 "paper/friction.nw"
#ifndef CONTACTOPT_FRICTION_H
#define CONTACTOPT_FRICTION_H
#include "problem.h"
#include "mesh.h"
#include "fem.h"

#line 153 "paper/friction.nw"
/* given friction: slip[k] = g omega_i, omega_i the tributary length of
   the node i = d->tangent_col[k] */
void friction_tresca_bounds(const Problem *p, const Mesh *m, const Dofs *d,
                            double *slip);
/* Coulomb: slip[k] = F max(T_c, 0), T_c the normal force at the same
   node, 0 where its u2 is held */
void friction_coulomb_bounds(const Problem *p, const Dofs *d,
                             const double *T, double *slip);
/* the work of friction, sum_k slip[k] |u1| at the tangential unknowns */
double friction_work(const Dofs *d, const double *slip, const double *Q);
/* G += g d/dX sum_k omega_k(X) |u1_k|: given friction's part of the
   gradient, at the design of the mesh */
void friction_gradient(const Problem *p, const Mesh *m, const Dofs *d,
                       const double *Q, double *G);
#line 147 "paper/friction.nw"
#endif
