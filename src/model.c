#line 234 "paper/model.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "resources.h"
#include "held.h"
#include "model_private.h"
#line 229 "paper/model.nw"
static int model_solve_state(Model *md, Status *st);
static int model_pressed(const Model *md, Status *st);
#line 246 "paper/model.nw"
/* Hooke's law of each material: the problem's, then each region's */
static Fem_hooke *model_hookes(const Problem *p)
{
  Fem_hooke *H = malloc((1 + (size_t) p->part.nregion) * sizeof *H);
  if (!H) return NULL;
  H[0] = fem_hooke(p);
  for (int r = 0; r < p->part.nregion; r++)
    H[1 + r] = fem_hooke_of(&p->part.region[r].material, p->model);
  return H;
}

Model *model_new(const Problem *p, const Qp_options *solver,
                 cholmod_common *cm, Status *st)
{
  Model *md = calloc(1, sizeof *md);
  if (!md) { status_set(st, STATUS_MEMORY, "model: out of memory"); return NULL; }
  md->problem = p;
  md->cm = cm;
  if (!(md->hooke = model_hookes(p))) {
    model_free(md);
    status_set(st, STATUS_MEMORY, "model: out of memory");
    return NULL;
  }
  if (!(md->mesh = mesh_new(p, st)) || !(md->dofs = fem_dofs_new(md->mesh, p, st))
      || !(md->A = fem_stiffness_new(md->mesh, md->dofs, cm, st))) {
    model_free(md);
    return NULL;
  }
  
#line 281 "paper/model.nw"
int n = md->dofs->n, nc = md->dofs->nc, nt = md->dofs->nt;
md->b = malloc(n * sizeof *md->b);
md->Q = calloc(n, sizeof *md->Q);
md->lo = malloc((nc ? nc : 1) * sizeof *md->lo);
md->T = calloc(nc + nt + 1, sizeof *md->T);
md->slip = calloc(nt + 1, sizeof *md->slip);
md->fixed_point.tol = solver->tol;
if (!md->b || !md->Q || !md->lo || !md->T || !md->slip) {
  model_free(md);
  status_set(st, STATUS_MEMORY, "model: out of memory for %d unknowns", n);
  return NULL;
}
#line 275 "paper/model.nw"
  
#line 296 "paper/model.nw"
md->qp = (Qp) { md->A, md->b, nc, md->dofs->contact, md->lo,
                nt, md->dofs->tangent, md->slip, nt && !friction_side_holds(p, 0) };
if (!(md->solver = qp_alloc(&md->qp, solver, cm, st))) {
  model_free(md);
  return NULL;
}
#line 276 "paper/model.nw"
  return md;
}
#line 319 "paper/model.nw"
static int model_solve_with(Model *md, const double *X, int rounding,
                            Status *st)
{
  double start = resources_clock();
  int rc;
  if ((rc = mesh_move(md->mesh, X, st))
      || (rc = fem_stiffness_fill(md->A, md->mesh, md->dofs, md->hooke, st)))
    return rc;
  fem_load(md->mesh, md->dofs, md->problem, md->b);
  for (int c = 0; c < md->dofs->nc; c++) md->lo[c] = -X[md->dofs->contact_col[c]];
  if (md->problem->contact == CONTACT_TRESCA)
    friction_tresca_bounds(md->problem, md->mesh, md->dofs, md->slip);
  if ((rc = held_check(md->problem, md->mesh, md->dofs, md->b,
                       md->problem->contact == CONTACT_TRESCA ? md->slip : NULL,
                       md->checked ? STATUS_NUMERIC : STATUS_INPUT, st)))
    return rc;
  md->checked = 1;
  if (md->problem->contact != CONTACT_COULOMB) rc = model_solve_state(md, st);
  else {
    rc = coulomb_fixed_point(md, model_solve_state, md->slip, rounding,
                             &md->fixed_point, st);
    md->report.iterations += md->fixed_point.steps;
  }
  md->energy = fem_energy(md->mesh, md->dofs, md->hooke, md->b, md->Q);
  if (md->dofs->nt) {
    md->friction_energy = friction_work(md->dofs, md->slip, md->Q);
    md->energy += md->friction_energy;
  }
  md->seconds = resources_clock() - start;
  return rc;
}

int model_solve(Model *md, const double *X, Status *st)
{
  return model_solve_with(md, X, 0, st);
}

int model_solve_to_rounding(Model *md, const double *X, Status *st)
{
  return model_solve_with(md, X, 1, st);
}
#line 364 "paper/model.nw"
static int model_solve_state(Model *md, Status *st)
{
  int rc = qp_solve(md->solver, md->solved || md->guessed ? md->Q : NULL,
                    md->Q, md->T, &md->report, st);
  if (!rc) rc = model_pressed(md, st);
  md->solved = rc == STATUS_OK, md->guessed = 0;
  return rc;
}
#line 377 "paper/model.nw"
static int model_pressed(const Model *md, Status *st)
{
  if (!held_lift_free(md->problem)) return 0;
  for (int c = 0; c < md->dofs->nc; c++)
    if (md->T[c] > 0) return 0;
  return status_set(st, STATUS_NUMERIC, "the body is not held: the state solve "
                    "ended with no node pressed onto the foundation, and no side "
                    "holds u2");
}
#line 401 "paper/model.nw"
void model_contact_gaps(const Model *md, double *gap)
{
  for (int i = 0; i <= md->problem->N; i++) gap[i] = NAN;
  for (int c = 0; c < md->dofs->nc; c++)
    gap[md->dofs->contact_col[c]] = md->Q[md->dofs->contact[c]] - md->lo[c];
}

void model_guess_contact(Model *md, const double *X, const double *gap)
{
  for (int c = 0; c < md->dofs->nc; c++) {
    int i = md->dofs->contact_col[c];
    if (!isnan(gap[i])) md->Q[md->dofs->contact[c]] = -X[i] + fmax(gap[i], 0);
  }
  md->guessed = 1;
}
#line 430 "paper/model.nw"
double model_pressure(const Model *md, int c)
{
  return md->T[c] / mesh_tributary(md->mesh, md->dofs->contact_col[c]);
}
#line 438 "paper/model.nw"
double model_pressure_cv(const Model *md)
{
  double sum = 0, sum2 = 0;
  int count = 0;
  for (int c = 0; c < md->dofs->nc; c++)
    if (md->Q[md->dofs->contact[c]] <= md->lo[c] && md->T[c] > 0) {
      double p = model_pressure(md, c);
      sum += p; sum2 += p * p; count++;
    }
  if (count == 0) return 0;                  /* no contact, no spread */
  double mean = sum / count, var = fmax(sum2 / count - mean * mean, 0);
  return sqrt(var) / mean;
}
#line 457 "paper/model.nw"
void model_release(Model *md)
{
  if (md) qp_release(md->solver);
}

void model_free(Model *md)
{
  if (!md) return;
  qp_free(md->solver);
  cholmod_l_free_sparse(&md->A, md->cm);
  mesh_free(md->mesh);
  free(md->hooke);
  fem_dofs_free(md->dofs);
  free(md->b); free(md->Q); free(md->lo); free(md->T); free(md->slip);
  free(md);
}
#line 500 "paper/model.nw"
int model_contact_stiffness(Model *md, double *S, Status *st)
{
  const Fem_dofs *d = md->dofs;
  int nc = d->nc, N1 = md->problem->N + 1, rc;
  if (nc == 0)                         /* every contact node held: nothing to see */
    return status_set(st, STATUS_INPUT, "contact stiffness: no contact node is "
                      "free to move; use optimizer.metric = euclidean");
  double *Scc = malloc((size_t) nc * nc * sizeof *Scc), mean = 0;
  if (!Scc) return status_set(st, STATUS_MEMORY, "contact stiffness: out of memory");
  if ((rc = qp_schur(md->solver, 1e-6, Scc, st))) { free(Scc); return rc; }
  for (int c = 0; c < nc; c++) mean += Scc[(size_t) c * nc + c] / nc;
  
#line 519 "paper/model.nw"
memset(S, 0, (size_t) N1 * N1 * sizeof *S);
for (int i = 0; i < N1; i++) S[(size_t) i * N1 + i] = mean;
for (int c = 0; c < nc; c++)
  for (int e = 0; e < nc; e++)
    S[(size_t) d->contact_col[c] * N1 + d->contact_col[e]] = Scc[(size_t) c * nc + e];
#line 512 "paper/model.nw"
  free(Scc);
  return STATUS_OK;
}
#line 587 "paper/model.nw"
int model_summary(const Model *md, Model_summary *sum, Status *st)
{
  const Fem_dofs *d = md->dofs;
  double *r = malloc(d->ndof * sizeof *r);
  if (!r) return status_set(st, STATUS_MEMORY, "summary: out of memory "
                            "for the reactions of %d DOFs", d->ndof);
  memset(sum, 0, sizeof *sum);
  fem_reactions(md->mesh, d, md->hooke, md->problem, md->Q, r);
  
#line 608 "paper/model.nw"
for (int k = 0; k < d->ndof; k++) {
  int side = d->unknown[k] < 0 ? fem_reaction_side(md->mesh, md->problem, k) : -1;
  if (side >= 0) sum->reaction[side][k % 2] += r[k];
}
#line 596 "paper/model.nw"
  free(r);
  
#line 615 "paper/model.nw"
for (int c = 0; c < d->nc; c++)
  if (md->Q[d->contact[c]] <= md->lo[c]) {
    sum->pressure_max = fmax(sum->pressure_max, model_pressure(md, c));
    sum->contact_length += mesh_tributary(md->mesh, d->contact_col[c]);
  }
#line 598 "paper/model.nw"
  for (int t = 0; t < md->mesh->ntri; t++) {
    double s[5];
    model_stress(md, t, s);
    sum->von_mises_max = fmax(sum->von_mises_max, s[4]);
  }
  return STATUS_OK;
}
#line 643 "paper/model.nw"
void model_stress(const Model *md, int t, double s[5])
{
  long double e[3], sigma[3];
  fem_triangle_strain(md->mesh, md->dofs, md->Q, t, e);
  const Fem_hooke *H = md->hooke + mesh_material(md->mesh, t);
  fem_element_stress(H, e, sigma);
  for (int r = 0; r < 3; r++) s[r] = (double) sigma[r];
  s[3] = md->problem->model == MODEL_PLANE_STRAIN
       ? (double) fem_element_stress33(H, e) : 0.0;
  s[4] = sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[3]) * (s[1] - s[3])
                     + (s[3] - s[0]) * (s[3] - s[0])) + 3 * s[2] * s[2]);
}
#line 663 "paper/model.nw"
double model_displacement_max(const Model *md)
{
  double u = 0;
  for (int i = 0; i < md->dofs->n; i++) u = fmax(u, fabs(md->Q[i]));
  return u;
}
#line 677 "paper/model.nw"
int model_contact_count(const Model *md) { return md->dofs->nc; }

const int *model_contact_columns(const Model *md) { return md->dofs->contact_col; }

int model_contact_state(Model *md, double *S, double *v, double *T, Status *st)
{
  int m = md->dofs->nc, rc;
  if (m > 0 && (rc = qp_schur(md->solver, 0, S, st))) return rc;
  for (int c = 0; c < m; c++) v[c] = md->Q[md->dofs->contact[c]], T[c] = md->T[c];
  return STATUS_OK;
}
#line 694 "paper/model.nw"
/* eps (U + sum_i |b_i Q_i| + friction), E = U - b'Q + friction, U >= 0 */
double model_energy_rounding(const Model *md)
{
  long double W = 0, Wabs = 0;
  for (int i = 0; i < md->dofs->n; i++) {
    long double bq = (long double) md->b[i] * md->Q[i];
    W += bq, Wabs += fabsl(bq);
  }
  long double U = md->energy - md->friction_energy + W;
  return DBL_EPSILON * (double) (fabsl(U) + Wabs + fabs(md->friction_energy));
}
