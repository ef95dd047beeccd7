#line 324 "paper/coulomb.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "coulomb.h"
#line 174 "paper/coulomb.nw"
#define COULOMB_STALL 10  /* rounds without halving the change: a stall */

static void coulomb_bounds(const Problem *p, const Fem_dofs *d, const double *T,
                           double *slip);
static void coulomb_start(const Problem *p, const Mesh *m, const Fem_dofs *d,
                          const double *b, double *slip);
static int coulomb_goes_on(const Model *md, int rounding, double before);
static int coulomb_failed(const Model *md, int stalled, double mark, Status *st);
static double coulomb_change(const double *old, const double *T, int nc);
#line 197 "paper/coulomb.nw"
int coulomb_fixed_point(Model *md, int (*state)(Model *, Status *),
                        int rounding, Status *st)
{
  const Problem *p = md->problem;
  int nc = md->dofs->nc, rc, steps = 0, stalled = 0;
  double *Tn = malloc((nc + 1) * sizeof *Tn), mark = INFINITY;
  if (!Tn) return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
  memset(md->slip, 0, (md->dofs->nt + 1) * sizeof *md->slip);
  if (!friction_side_holds(p, 0))
    coulomb_start(p, md->mesh, md->dofs, md->b, md->slip);
  rc = state(md, st);
  md->fixed_point_iterations = 0, md->fixed_point_residual = INFINITY;
  double before = INFINITY;           /* the change of the round before */
  while (!rc && coulomb_goes_on(md, rounding, before)
         && md->fixed_point_iterations < p->max_fixed_point
         && stalled < COULOMB_STALL) {
    before = md->fixed_point_residual;
    memcpy(Tn, md->T, nc * sizeof *Tn);
    coulomb_bounds(p, md->dofs, Tn, md->slip);
    steps += md->report.iterations;
    rc = state(md, st);
    md->fixed_point_iterations++;
    md->fixed_point_residual = coulomb_change(Tn, md->T, nc);
    if (md->fixed_point_residual <= mark / 2) mark = md->fixed_point_residual, stalled = 0;
    else stalled++;
  }
  free(Tn);
  md->report.iterations += steps;
  if (!rc && md->fixed_point_residual > md->fixed_point_tol)
    rc = coulomb_failed(md, stalled, mark, st);
  return rc;
}
#line 239 "paper/coulomb.nw"
static int coulomb_goes_on(const Model *md, int rounding, double before)
{
  double r = md->fixed_point_residual;
  if (r > md->fixed_point_tol) return 1;
  return rounding && r > 0 && r <= before / 2;
}
#line 249 "paper/coulomb.nw"
static int coulomb_failed(const Model *md, int stalled, double mark, Status *st)
{
  if (stalled >= COULOMB_STALL)
    return status_set(st, STATUS_NUMERIC, "coulomb: the fixed point stopped "
      "converging: the change of the normal forces did not halve in its last "
      "%d of %d iterations (from %.3g to %.3g relative, > solver.tol = %.3g); "
      "successive approximations converge only for a small enough friction "
      "(here %g)", stalled, md->fixed_point_iterations, mark,
      md->fixed_point_residual, md->fixed_point_tol, md->problem->friction);
  return status_set(st, STATUS_NUMERIC, "coulomb: the fixed point did not "
    "converge in %d iterations (contact.max_fixed_point): the normal forces "
    "still change by %.3g relative > solver.tol = %.3g; successive "
    "approximations converge only for a small enough friction (here %g)",
    md->fixed_point_iterations, md->fixed_point_residual,
    md->fixed_point_tol, md->problem->friction);
}
#line 269 "paper/coulomb.nw"
static double coulomb_change(const double *old, const double *T, int nc)
{
  double diff = 0, size = 0;
  for (int c = 0; c < nc; c++)
    diff = fmax(diff, fabs(T[c] - old[c])),
    size = fmax(size, fmax(fabs(T[c]), fabs(old[c])));
  return diff == 0 ? 0 : diff / size;
}
#line 286 "paper/coulomb.nw"
static void coulomb_bounds(const Problem *p, const Fem_dofs *d, const double *T,
                           double *slip)
{
  int c = 0;
  for (int k = 0; k < d->nt; k++) {
    while (c < d->nc && d->contact_col[c] < d->tangent_col[k]) c++;
    int here = c < d->nc && d->contact_col[c] == d->tangent_col[k];
    slip[k] = here ? p->friction * fmax(T[c], 0) : 0;
  }
}
#line 304 "paper/coulomb.nw"
static void coulomb_start(const Problem *p, const Mesh *m, const Fem_dofs *d,
                          const double *b, double *slip)
{
  double W = 0, length = 0;
  for (int k = 1; k < d->ndof; k += 2)
    if (d->unknown[k] >= 0) W -= b[d->unknown[k]];
  for (int k = 0; k < d->nt; k++)
    length += slip[k] = mesh_tributary(m, d->tangent_col[k]);
  for (int k = 0; k < d->nt; k++) slip[k] *= p->friction * W / length;
}
#line 422 "paper/coulomb.nw"
typedef struct {
  double *lam;  /* n: the adjoint of the objective at fixed bounds */
  char *held;   /* nc + nt: the state's held sets */
  int *k, *c;   /* m <= nt: the pairs of coulomb_pairs */
  double *v;    /* m: friction dJ/ds_k, then mu */
  double *S;    /* m x m: dT/ds, then I - friction dT/ds */
  double *mu;   /* nc: mu on the normal unknowns */
  double *G2;   /* N + 1: the gradient of mu'T at fixed bounds */
} Coulomb_scratch;

static void scratch_free(Coulomb_scratch *w)
{
  free(w->lam), free(w->held), free(w->k), free(w->c);
  free(w->v), free(w->S), free(w->mu), free(w->G2);
}

static int scratch_alloc(const Model *md, Coulomb_scratch *w, Status *st)
{
  size_t n = md->dofs->n, nc = md->dofs->nc, nt = md->dofs->nt;
  *w = (Coulomb_scratch) { malloc(n * sizeof(double)), malloc(nc + nt + 1),
                           malloc((nt + 1) * sizeof(int)), malloc((nt + 1) * sizeof(int)),
                           malloc((nt + 1) * sizeof(double)),
                           malloc((nt * nt + 1) * sizeof(double)),
                           calloc(nc + 1, sizeof(double)),
                           malloc(md->mesh->ncol * sizeof(double)) };
  if (w->lam && w->held && w->k && w->c && w->v && w->S && w->mu && w->G2)
    return STATUS_OK;
  scratch_free(w);
  return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
}
#line 336 "paper/coulomb.nw"
/* the m pairs (k[a], c[a]) of a sliding tangential unknown k and the
   normal unknown c at its node, held with T_c > 0; returns m */
static int coulomb_pairs(const Model *md, const char *held, int *kk, int *cc)
{
  const Fem_dofs *d = md->dofs;
  int c = 0, m = 0;
  for (int k = 0; k < d->nt; k++) {
    while (c < d->nc && d->contact_col[c] < d->tangent_col[k]) c++;
    if (c < d->nc && d->contact_col[c] == d->tangent_col[k] && held[c]
        && !held[d->nc + k] && md->T[c] > 0 && md->T[d->nc + k] != 0)
      kk[m] = k, cc[m++] = c;
  }
  return m;
}
#line 358 "paper/coulomb.nw"
/* (A q)_j, A stored with both triangles */
static double row_times(const cholmod_sparse *A, int j, const double *q)
{
  const Sparse_index *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x;
  double s = 0;
  for (int p = Ap[j]; p < Ap[j + 1]; p++) s += Ax[p] * q[Ai[p]];
  return s;
}

/* S (m x m, row-major) = dT_c[a] / ds_k[b] on the state's sets: the
   state's answer to the load -sigma_b of the slide at k[b] */
static int coulomb_sensitivity(const Model *md, int m, const int *kk,
                               const int *cc, double *S, Status *st)
{
  const Fem_dofs *d = md->dofs;
  double *e = calloc(2 * (size_t) d->n, sizeof *e), *q = e + d->n;
  if (!e) return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
  int rc = STATUS_OK;
  for (int b = 0; !rc && b < m; b++) {
    int t = d->tangent[kk[b]];
    e[t] = md->T[d->nc + kk[b]] > 0 ? 1 : -1;     /* -sigma = sign T_t */
    rc = qp_adjoint(md->solver, e, q, NULL, st);
    e[t] = 0;
    for (int a = 0; !rc && a < m; a++)
      S[(size_t) a * m + b] = row_times(md->A, d->contact[cc[a]], q);
  }
  free(e);
  return rc;
}
#line 394 "paper/coulomb.nw"
/* v (m) := mu, (I - friction S)' mu = v, by LU; S is overwritten */
static int coulomb_multiplier(int m, double friction, double *S, double *v,
                              Status *st)
{
  for (int a = 0; a < m; a++)                  /* S := (I - friction S)' */
    for (int b = 0; b <= a; b++) {
      double x = S[(size_t) a * m + b], y = S[(size_t) b * m + a];
      S[(size_t) a * m + b] = (a == b) - friction * y;
      S[(size_t) b * m + a] = (a == b) - friction * x;
    }
  gsl_matrix_view M = gsl_matrix_view_array(S, m, m);
  gsl_vector_view x = gsl_vector_view_array(v, m);
  gsl_permutation *p = gsl_permutation_alloc(m);
  int sign, rc = STATUS_OK;
  if (!p) return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
  if (gsl_linalg_LU_decomp(&M.matrix, p, &sign)
      || !(gsl_linalg_LU_lndet(&M.matrix) > -700)
      || gsl_linalg_LU_svx(&M.matrix, p, &x.vector))
    rc = status_set(st, STATUS_NUMERIC, "coulomb: the fixed point's derivative "
                    "I - F dT/ds is singular on the state's sets");
  gsl_permutation_free(p);
  return rc;
}
#line 460 "paper/coulomb.nw"
/* v[a] = friction dJ/ds at the slide k[a]: the explicit |u1| of the energy and
   -sigma lam_t through the state */
static void coulomb_rhs(const Model *md, const Objective *o, int m,
                        Coulomb_scratch *w)
{
  const Fem_dofs *d = md->dofs;
  for (int a = 0; a < m; a++) {
    int t = d->tangent[w->k[a]];
    double sigma = md->T[d->nc + w->k[a]] > 0 ? -1 : 1;
    w->v[a] = md->problem->friction * (objective_is_energy(o->kind) * fabs(md->Q[t])
                                       - sigma * w->lam[t]);
  }
}

static int coulomb_terms(const Model *md, const Objective *o,
                         Coulomb_scratch *w, double *G, Status *st)
{
  double friction = md->problem->friction;
  int rc = objective_gradient_fixed(md, o, NULL, w->lam, w->held, G, NULL, st);
  int m = rc ? 0 : coulomb_pairs(md, w->held, w->k, w->c);
  if (rc || m == 0 || friction == 0) return rc;
  coulomb_rhs(md, o, m, w);
  if ((rc = coulomb_sensitivity(md, m, w->k, w->c, w->S, st))
      || (rc = coulomb_multiplier(m, friction, w->S, w->v, st))) return rc;
  for (int a = 0; a < m; a++) w->mu[w->c[a]] = w->v[a];
  if ((rc = objective_gradient_fixed(md, NULL, w->mu, NULL, NULL, w->G2, NULL, st)))
    return rc;
  for (int i = 0; i < md->mesh->ncol; i++) G[i] += w->G2[i];
  return STATUS_OK;
}

int coulomb_gradient(const Model *md, const Objective *o, double *G, Status *st)
{
  Coulomb_scratch w;
  int rc = scratch_alloc(md, &w, st);
  if (rc) return rc;
  rc = coulomb_terms(md, o, &w, G, st);
  scratch_free(&w);
  return rc;
}
