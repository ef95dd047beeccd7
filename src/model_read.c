#line 714 "paper/model.nw"
#include "model_private.h"
const Problem *model_problem(const Model *md) { return md->problem; }
cholmod_common *model_cholmod(const Model *md) { return md->cm; }
const Mesh *model_mesh(const Model *md) { return md->mesh; }
const Fem_dofs *model_dofs(const Model *md) { return md->dofs; }
const Fem_hooke *model_hooke(const Model *md) { return md->hooke; }
const cholmod_sparse *model_stiffness(const Model *md) { return md->A; }
const double *model_load(const Model *md) { return md->b; }
const double *model_bounds(const Model *md) { return md->lo; }
const Qp *model_qp(const Model *md) { return &md->qp; }
const Qp_workspace *model_solver(const Model *md) { return md->solver; }
const double *model_state(const Model *md) { return md->Q; }
const double *model_forces(const Model *md) { return md->T; }
const double *model_slip(const Model *md) { return md->slip; }
double model_energy(const Model *md) { return md->energy; }
double model_friction_energy(const Model *md) { return md->friction_energy; }
int model_fixed_point_iterations(const Model *md) { return md->fixed_point.iterations; }
double model_fixed_point_residual(const Model *md) { return md->fixed_point.residual; }
const Qp_report *model_report(const Model *md) { return &md->report; }
double model_seconds(const Model *md) { return md->seconds; }
int model_solved(const Model *md) { return md->solved; }
