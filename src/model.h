#line 48 "paper/model.nw"
#ifndef CONTACTOPT_MODEL_H
#define CONTACTOPT_MODEL_H
#include "sparse.h"
#include "status.h"
#include "problem.h"
#include "mesh.h"
#include "fem.h"
#include "qp.h"
#include "friction.h"

#line 67 "paper/model.nw"
typedef struct Model Model;

#line 562 "paper/model.nw"
/* what a summary says of the state at the last design solved */
typedef struct {
  double reaction[SIDE_COUNT + PROBLEM_NAMED][2]; /* N/m: the force of
     each side, then of each slot of a part's curves, on the body, (x1, x2);
     0 where it holds none */
  double pressure_max;    /* Pa: the peak contact pressure over the nodes
                             in contact; 0 where none is */
  double contact_length;  /* m: the tributary lengths of the nodes in
                             contact, summed */
  double von_mises_max;   /* Pa: the largest von Mises stress of a triangle */
} Model_summary;

#line 163 "paper/model.nw"
Model *model_new(const Problem *p, const Qp_options *solver,
                 cholmod_common *cm, Status *st);
/* contact pressure at contact DOF c: T_c over the tributary length */
double model_pressure(const Model *md, int c);
/* standard deviation over mean of the pressure on the contact zone;
   0 when no node presses */
double model_pressure_cv(const Model *md);
/* max |Q_i| over the unknowns of the last state solved, m */
double model_displacement_max(const Model *md);
/* move to design X (N+1 values), assemble, solve the state from the last */
int model_solve(Model *md, const double *X, Status *st);
/* model_solve, with Coulomb's fixed point taken on past solver.tol to
   the rounding of the forces (coulomb_fixed_point): for a gradient */
int model_solve_to_rounding(Model *md, const double *X, Status *st);
/* S (N+1 x N+1, row-major): the stiffness of the body seen from its
   contact nodes at the last design solved (see below) */
int model_contact_stiffness(Model *md, double *S, Status *st);
/* the contact unknowns m and, for each, the design node it moves with */
int model_contact_count(const Model *md);
const int *model_contact_columns(const Model *md);
/* at the last design solved, over the m contact unknowns: S (m x m,
   row-major) the state solver's contact stiffness at its current sets,
   v the displacements, T the contact forces */
int model_contact_state(Model *md, double *S, double *v, double *T, Status *st);
/* the rounding of E at the last design solved (see the optimiser) */
double model_energy_rounding(const Model *md);
/* gap (N+1): the gap Q_c - lo_c of the last state solved at the design
   node of each contact unknown c, NaN at the other nodes */
void model_contact_gaps(const Model *md, double *gap);
/* the start of the next solve: the contact unknowns at the gaps gap (N+1,
   NaN: left as they are) over the design X; for PDAS (see below) */
void model_guess_contact(Model *md, const double *X, const double *gap);
/* frees the factor of the last state, which is kept; the next solve
   factorises anew (the memory of another model built meanwhile) */
void model_release(Model *md);
void model_free(Model *md);
#line 576 "paper/model.nw"
/* s = sigma11, sigma22, sigma12, sigma33 and the von Mises stress of
   triangle t at the last state solved [Pa when Young's modulus is] */
void model_stress(const Model *md, int t, double s[5]);
/* the summary of the last state solved; STATUS_MEMORY if memory runs out */
int model_summary(const Model *md, Model_summary *sum, Status *st);

#line 76 "paper/model.nw"
/* the problem the model was built for */
const Problem *model_problem(const Model *md);
/* CHOLMOD's workspace the model was built with */
cholmod_common *model_cholmod(const Model *md);
/* the mesh, moved to the last design solved */
const Mesh *model_mesh(const Model *md);
/* the unknowns and the contact DOFs I */
const Fem_dofs *model_dofs(const Model *md);
/* Hooke's laws of the materials, indexed by mesh_material */
const Fem_hooke *model_hooke(const Model *md);
/* A(X), n x n, both triangles stored */
const cholmod_sparse *model_stiffness(const Model *md);
/* n: the load F(X) + P(X) */
const double *model_load(const Model *md);
/* nc: the bounds -X_i of the contact DOFs */
const double *model_bounds(const Model *md);
/* the state problem (4.3) over A, b and the bounds */
const Qp *model_qp(const Model *md);
/* the state problem's solver, at the last state solved */
const Qp_workspace *model_solver(const Model *md);
/* n: the state Q(X) */
const double *model_state(const Model *md);
/* nc + nt: the contact forces T_i >= 0, then the tangential ones */
const double *model_forces(const Model *md);
/* nt: the slip bounds of friction (N/m) of the last state solved */
const double *model_slip(const Model *md);
/* E(X) = 1/2 Q'AQ - (F+P)'Q + the work of friction */
double model_energy(const Model *md);
/* the work of friction, sum slip_k |u1_k|; 0 without friction */
double model_friction_energy(const Model *md);
/* Coulomb: the Tresca solves of the fixed point after the first */
int model_fixed_point_iterations(const Model *md);
/* Coulomb: the last relative change of the normal forces T */
double model_fixed_point_residual(const Model *md);
/* the last state solve's report (Coulomb: iterations summed over the
   fixed point) */
const Qp_report *model_report(const Model *md);
/* the wall time of the last model_solve, s */
double model_seconds(const Model *md);
/* 1 when the last solve found a state */
int model_solved(const Model *md);
#line 63 "paper/model.nw"
#endif
