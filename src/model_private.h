#line 121 "paper/model.nw"
#ifndef CONTACTOPT_MODEL_PRIVATE_H
#define CONTACTOPT_MODEL_PRIVATE_H
#include "model.h"
#include "coulomb.h"

#line 131 "paper/model.nw"
struct Model {
  const Problem *problem; /* the problem (not owned) */
  cholmod_common *cm;   /* CHOLMOD's workspace (not owned) */
  Mesh *mesh;           /* moved to the last design solved */
  Fem_dofs *dofs;       /* unknowns and contact DOFs I */
  Fem_hooke *hooke;     /* Hooke's law of each material, indexed by
                           mesh_material: the problem's, then a part's
                           regions' (1 + part.nregion) */
  cholmod_sparse *A;    /* A(X), n x n */
  double *b;            /* n: F(X) + P(X) */
  double *lo;           /* nc: the bounds -X_i of the contact DOFs */
  Qp qp;                /* the state problem (4.3) over A, b, lo */
  Qp_workspace *solver; /* its solver, reused from design to design */
  double *Q;            /* n: the state Q(X) */
  double *T;            /* nc + nt: the contact forces T_i >= 0, then
                           (friction) the tangential ones */
  double *slip;         /* nt: the slip bounds of friction (N/m) */
  double energy;        /* E(X) = 1/2 Q'AQ - (F+P)'Q + friction_energy */
  double friction_energy; /* sum slip_k |u1_k|; 0 without friction */
  Coulomb_fixed_point fixed_point; /* Coulomb: the course of the fixed
                                      point of the last solve */
  Qp_report report;     /* of the last state solve (Coulomb: iterations
                           summed over the fixed point) */
  double seconds;       /* wall time of the last model_solve */
  int solved;           /* Q holds a state: warm start the next solve */
  int checked;          /* held_check passed once: the scene's design */
  int guessed;          /* Q's contact unknowns hold a guess (below):
                           warm start the next solve from it */
};
#line 127 "paper/model.nw"
#endif
