#line 343 "paper/coulomb.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "coulomb.h"
#line 188 "paper/coulomb.nw"
#define COULOMB_STALL 10  /* rounds without halving the change: a stall */

static void coulomb_bounds(const Problem *p, const Fem_dofs *d, const double *T,
                           double *slip);
static void coulomb_start(const Problem *p, const Mesh *m, const Fem_dofs *d,
                          const double *b, double *slip);
static int coulomb_goes_on(const Coulomb_fixed_point *fp, int rounding,
                           double before);
static int coulomb_failed(const Model *md, const Coulomb_fixed_point *fp,
                          int stalled, double mark, Status *st);
static double coulomb_change(const double *old, const double *T, int nc);
#line 213 "paper/coulomb.nw"
int coulomb_fixed_point(Model *md, int (*state)(Model *, Status *),
                        double *slip, int rounding, Coulomb_fixed_point *fp,
                        Status *st)
{
  const Problem *p = model_problem(md);
  const Fem_dofs *d = model_dofs(md);
  int nc = d->nc, rc, stalled = 0;
  double *Tn = malloc((nc + 1) * sizeof *Tn), mark = INFINITY;
  fp->steps = 0;
  if (!Tn) return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
  memset(slip, 0, (d->nt + 1) * sizeof *slip);
  if (!friction_side_holds(p, 0))
    coulomb_start(p, model_mesh(md), d, model_load(md), slip);
  rc = state(md, st);
  fp->iterations = 0, fp->residual = INFINITY;
  double before = INFINITY;           /* the change of the round before */
  while (!rc && coulomb_goes_on(fp, rounding, before)
         && fp->iterations < p->max_fixed_point
         && stalled < COULOMB_STALL) {
    before = fp->residual;
    memcpy(Tn, model_forces(md), nc * sizeof *Tn);
    coulomb_bounds(p, d, Tn, slip);
    fp->steps += model_report(md)->iterations;
    rc = state(md, st);
    fp->iterations++;
    fp->residual = coulomb_change(Tn, model_forces(md), nc);
    if (fp->residual <= mark / 2) mark = fp->residual, stalled = 0;
    else stalled++;
  }
  free(Tn);
  if (!rc && fp->residual > fp->tol)
    rc = coulomb_failed(md, fp, stalled, mark, st);
  return rc;
}
#line 257 "paper/coulomb.nw"
static int coulomb_goes_on(const Coulomb_fixed_point *fp, int rounding,
                           double before)
{
  double r = fp->residual;
  if (r > fp->tol) return 1;
  return rounding && r > 0 && r <= before / 2;
}
#line 268 "paper/coulomb.nw"
static int coulomb_failed(const Model *md, const Coulomb_fixed_point *fp,
                          int stalled, double mark, Status *st)
{
  if (stalled >= COULOMB_STALL)
    return status_set(st, STATUS_NUMERIC, "coulomb: the fixed point stopped "
      "converging: the change of the normal forces did not halve in its last "
      "%d of %d iterations (from %.3g to %.3g relative, > solver.tol = %.3g); "
      "successive approximations converge only for a small enough friction "
      "(here %g)", stalled, fp->iterations, mark, fp->residual, fp->tol,
      model_problem(md)->friction);
  return status_set(st, STATUS_NUMERIC, "coulomb: the fixed point did not "
    "converge in %d iterations (contact.max_fixed_point): the normal forces "
    "still change by %.3g relative > solver.tol = %.3g; successive "
    "approximations converge only for a small enough friction (here %g)",
    fp->iterations, fp->residual, fp->tol, model_problem(md)->friction);
}
#line 288 "paper/coulomb.nw"
static double coulomb_change(const double *old, const double *T, int nc)
{
  double diff = 0, size = 0;
  for (int c = 0; c < nc; c++)
    diff = fmax(diff, fabs(T[c] - old[c])),
    size = fmax(size, fmax(fabs(T[c]), fabs(old[c])));
  return diff == 0 ? 0 : diff / size;
}
#line 305 "paper/coulomb.nw"
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
#line 323 "paper/coulomb.nw"
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
#line 442 "paper/coulomb.nw"
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
  const Fem_dofs *d = model_dofs(md);
  size_t n = d->n, nc = d->nc, nt = d->nt;
  *w = (Coulomb_scratch) { malloc(n * sizeof(double)), malloc(nc + nt + 1),
                        malloc((nt + 1) * sizeof(int)), malloc((nt + 1) * sizeof(int)),
                        malloc((nt + 1) * sizeof(double)),
                        malloc((nt * nt + 1) * sizeof(double)),
                        calloc(nc + 1, sizeof(double)),
                        malloc(model_mesh(md)->ncol * sizeof(double)) };
  if (w->lam && w->held && w->k && w->c && w->v && w->S && w->mu && w->G2)
    return STATUS_OK;
  scratch_free(w);
  return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
}
#line 355 "paper/coulomb.nw"
/* the m pairs (k[a], c[a]) of a sliding tangential unknown k and the
   normal unknown c at its node, held with T_c > 0; returns m */
static int coulomb_pairs(const Model *md, const char *held, int *kk, int *cc)
{
  const Fem_dofs *d = model_dofs(md);
  const double *T = model_forces(md);
  int c = 0, m = 0;
  for (int k = 0; k < d->nt; k++) {
    while (c < d->nc && d->contact_col[c] < d->tangent_col[k]) c++;
    if (c < d->nc && d->contact_col[c] == d->tangent_col[k] && held[c]
        && !held[d->nc + k] && T[c] > 0 && T[d->nc + k] != 0)
      kk[m] = k, cc[m++] = c;
  }
  return m;
}
#line 378 "paper/coulomb.nw"
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
  const Fem_dofs *d = model_dofs(md);
  double *e = calloc(2 * (size_t) d->n, sizeof *e), *q = e + d->n;
  if (!e) return status_set(st, STATUS_MEMORY, "coulomb: out of memory");
  int rc = STATUS_OK;
  for (int b = 0; !rc && b < m; b++) {
    int t = d->tangent[kk[b]];
    e[t] = model_forces(md)[d->nc + kk[b]] > 0 ? 1 : -1;     /* -sigma = sign T_t */
    rc = qp_adjoint(model_solver(md), e, q, NULL, st);
    e[t] = 0;
    for (int a = 0; !rc && a < m; a++)
      S[(size_t) a * m + b] = row_times(model_stiffness(md), d->contact[cc[a]], q);
  }
  free(e);
  return rc;
}
#line 414 "paper/coulomb.nw"
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
#line 481 "paper/coulomb.nw"
/* v[a] = friction dJ/ds at the slide k[a]: the explicit |u1| of the energy and
   -sigma lam_t through the state */
static void coulomb_rhs(const Model *md, const Objective *o, int m,
                        Coulomb_scratch *w)
{
  const Fem_dofs *d = model_dofs(md);
  const double *Q = model_state(md), *T = model_forces(md);
  for (int a = 0; a < m; a++) {
    int t = d->tangent[w->k[a]];
    double sigma = T[d->nc + w->k[a]] > 0 ? -1 : 1;
    w->v[a] = model_problem(md)->friction * (objective_is_energy(o->kind) * fabs(Q[t])
                                       - sigma * w->lam[t]);
  }
}

static int coulomb_terms(const Model *md, const Objective *o,
                         Coulomb_scratch *w, double *G, Status *st)
{
  double friction = model_problem(md)->friction;
  int rc = objective_gradient_fixed(md, o, NULL, w->lam, w->held, G, NULL, st);
  int m = rc ? 0 : coulomb_pairs(md, w->held, w->k, w->c);
  if (rc || m == 0 || friction == 0) return rc;
  coulomb_rhs(md, o, m, w);
  if ((rc = coulomb_sensitivity(md, m, w->k, w->c, w->S, st))
      || (rc = coulomb_multiplier(m, friction, w->S, w->v, st))) return rc;
  for (int a = 0; a < m; a++) w->mu[w->c[a]] = w->v[a];
  if ((rc = objective_gradient_fixed(md, NULL, w->mu, NULL, NULL, w->G2, NULL, st)))
    return rc;
  for (int i = 0; i < model_mesh(md)->ncol; i++) G[i] += w->G2[i];
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
