#line 344 "paper/friction.nw"
#ifndef CONTACTOPT_FRICTION_H
#define CONTACTOPT_FRICTION_H
#include "problem.h"
#include "mesh.h"
#include "fem.h"

#line 357 "paper/friction.nw"
/* given friction: slip[k] = g omega_i, omega_i the tributary length of
   the node i = d->tangent_col[k] */
void friction_tresca_bounds(const Problem *p, const Mesh *m, const Fem_dofs *d,
                            double *slip);
/* the work of friction, sum_k slip[k] |u1| at the tangential unknowns */
double friction_work(const Fem_dofs *d, const double *slip, const double *Q);
/* G += g d/dX sum_k omega_k(X) |u1_k|: given friction's part of the
   gradient, at the design of the mesh */
void friction_gradient(const Problem *p, const Mesh *m, const Fem_dofs *d,
                       const double *Q, double *G);
#line 374 "paper/friction.nw"
/* 1 if some side or a part's curve holds u1 (component 0) or u2
   (component 1): a clamp holds both, a roller on the left or the right u1,
   on the top u2, on a part's curve its normal component */
int friction_side_holds(const Problem *p, int component);

/* what friction can hold sideways against the horizontal load */
typedef struct {
  double capacity;  /* N/m: the largest total tangential force: g (b - a),
                       friction W, or 0 without friction */
  double load;      /* N/m: |L1|, the total horizontal load */
  double vertical;  /* N/m: W, the total load that presses the body down */
} Friction_hold;
/* capacity and loads at the design the mesh admits where the margin
   capacity - load is least */
Friction_hold friction_hold(const Problem *p);
#line 351 "paper/friction.nw"
#endif
