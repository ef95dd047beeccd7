#line 352 "paper/objective.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "objective.h"
#line 363 "paper/objective.nw"
/* g = dJ/dQ + A_{:H} t, t = dT on the held contact unknowns */
static void adjoint_rhs(const Model *md, Objective_kind kind, const double *AQ,
                        const double *dT, double *g)
{
  const Fem_dofs *d = model_dofs(md);
  const cholmod_sparse *A = model_stiffness(md);
  const Sparse_index *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x, *b = model_load(md), *Q = model_state(md);
  for (int i = 0; i < d->n; i++)
    g[i] = kind == OBJECTIVE_ENERGY ? AQ[i] - b[i]
         : kind == OBJECTIVE_COMPLIANCE ? b[i] : 0;
  if (kind == OBJECTIVE_ENERGY)            /* the slide's s sigma */
    for (int k = 0; k < d->nt; k++) {
      double u = Q[d->tangent[k]];
      g[d->tangent[k]] += model_slip(md)[k] * ((u > 0) - (u < 0));
    }
  for (int c = 0; c < d->nc; c++)
    if (dT[c] != 0)
      for (Sparse_index k = Ap[d->contact[c]]; k < Ap[d->contact[c] + 1]; k++)
        g[Ai[k]] += Ax[k] * dT[c];
}
#line 388 "paper/objective.nw"
static void held_term(const Model *md, const char *held, const double *g,
                      const double *lam, double *G)
{
  const Fem_dofs *d = model_dofs(md);
  const cholmod_sparse *A = model_stiffness(md);
  const Sparse_index *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x;
  for (int c = 0; c < d->nc; c++) {
    if (!held[c]) continue;
    int j = d->contact[c];
    double Al = 0;
    for (Sparse_index k = Ap[j]; k < Ap[j + 1]; k++) Al += Ax[k] * lam[Ai[k]];
    G[d->contact_col[c]] -= g[j] - Al;
  }
}
#line 408 "paper/objective.nw"
/* d (u'K_e q) / d y_m: eu, eq the strains (times d) of u and q, Du, Dq
   D times them, d = 2|T| */
static double bilinear_height(const double gy[3], const double u[6],
                              const double q[6], const double eu[3],
                              const double Du[3], const double Dq[3],
                              double d, int m)
{
  int up = (m + 2) % 3, down = (m + 1) % 3;
  double du0 = u[2 * up] - u[2 * down], du2 = u[2 * up + 1] - u[2 * down + 1];
  double dq0 = q[2 * up] - q[2 * down], dq2 = q[2 * up + 1] - q[2 * down + 1];
  double uDq = eu[0] * Dq[0] + eu[1] * Dq[1] + eu[2] * Dq[2];
  return (du0 * Dq[0] + du2 * Dq[2] + dq0 * Du[0] + dq2 * Du[2]) / (2 * d)
       - uDq * gy[m] / (2 * d * d);
}
#line 427 "paper/objective.nw"
/* the strain (times d) of q on the triangle, and D times it */
static void strain_of(const Model *md, int t, const double gx[3],
                      const double gy[3], const double q[6], double e[3],
                      double De[3])
{
  long double el[3];
  fem_element_strain(gx, gy, q, el);
  for (int r = 0; r < 3; r++) e[r] = (double) el[r];
  const Fem_hooke *h = model_hooke(md) + mesh_material(model_mesh(md), t);
  for (int r = 0; r < 3; r++)
    De[r] = h->D[r][0] * e[0] + h->D[r][1] * e[1] + h->D[r][2] * e[2];
}

static void triangle_terms(const Model *md, int t, const double *u,
                           const double *v, double *G)
{
  const Mesh *m = model_mesh(md);
  const Fem_dofs *dofs = model_dofs(md);
  const double *F = model_problem(md)->body_force;
  double xy[6], q[6], ue[6], ve[6], gx[3], gy[3], eq[3], Dq[3], eu[3], Du[3];
  fem_element_xy(m, t, xy);
  fem_element_q(m, dofs, model_state(md), t, q);
  fem_element_q(m, dofs, u, t, ue);
  fem_element_q(m, dofs, v, t, ve);
  fem_element_gradients(xy, gx, gy);
  double d = xy[0] * gx[0] + xy[2] * gx[1] + xy[4] * gx[2];
  strain_of(md, t, gx, gy, q, eq, Dq);
  strain_of(md, t, gx, gy, ue, eu, Du);
  for (int k = 0; k < 3; k++) {
    int node = m->tri[3 * t + k];
    double rate = mesh_motion(m, node);
    if (rate == 0) continue;
    double dy = bilinear_height(gy, ue, q, eu, Du, Dq, d, k);
    if (model_problem(md)->has_body_force)
      for (int r = 0; r < 3; r++)
        dy -= (F[0] * ve[2 * r] + F[1] * ve[2 * r + 1]) * gy[k] / 6;
    G[node % m->ncol] += rate * dy;
  }
}
#line 472 "paper/objective.nw"
/* G += sum_c dw[c] d omega_c / dX, for the columns col[c] */
static void tributary_term(const Mesh *m, int nc, const int *col,
                           const double *dw, double *G)
{
  for (int c = 0; c < nc; c++)
    for (int k = col[c] - 1; k <= col[c]; k++)
      if (k >= 0 && k < m->N) {
        double dx = m->xy[2 * (k + 1)] - m->xy[2 * k];
        double dy = m->xy[2 * (k + 1) + 1] - m->xy[2 * k + 1];
        double r = 0.5 * dw[c] * dy / hypot(dx, dy);
        G[k + 1] += r, G[k] -= r;
      }
}
#line 492 "paper/objective.nw"
static int sliding_term(const Model *md, const char *held, const double *lam,
                        double *G, Status *st)
{
  const Fem_dofs *d = model_dofs(md);
  const double *T = model_forces(md);
  double *dw = malloc(((size_t) d->nt + 1) * sizeof *dw);
  if (!dw) return status_set(st, STATUS_MEMORY, "objective: out of memory");
  for (int k = 0; k < d->nt; k++) {
    double Tk = T[d->nc + k], sigma = Tk < 0 ? 1 : Tk > 0 ? -1 : 0;
    dw[k] = held[d->nc + k] ? 0
          : -lam[d->tangent[k]] * sigma * model_problem(md)->slip_bound;
  }
  tributary_term(model_mesh(md), d->nt, d->tangent_col, dw, G);
  free(dw);
  return STATUS_OK;
}
#line 530 "paper/objective.nw"
/* eps sum_i |w_i| rho_i, rho_i = sum_j |A_ij Q_j| + |b_i| */
static double state_rounding(const Model *md, const double *w)
{
  const cholmod_sparse *A = model_stiffness(md);
  const Sparse_index *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x, *b = model_load(md), *Q = model_state(md);
  long double s = 0;
  for (int j = 0; j < model_dofs(md)->n; j++) {
    if (w[j] == 0) continue;
    long double rho = fabs(b[j]);        /* A is symmetric: column j is row j */
    for (Sparse_index k = Ap[j]; k < Ap[j + 1]; k++) rho += fabs(Ax[k] * Q[Ai[k]]);
    s += fabsl(w[j] * rho);
  }
  return DBL_EPSILON * (double) s;
}
#line 549 "paper/objective.nw"
/* G from the partials dT, dw already in v; kind OBJECTIVE_COUNT: a
   functional of T alone */
static int gradient_terms(const Model *md, Objective_kind kind, double *v,
                          char *held, double *G, double *dJ, Status *st)
{
  const Fem_dofs *d = model_dofs(md);
  const Problem *p = model_problem(md);
  const Mesh *m = model_mesh(md);
  const double *Q = model_state(md);
  int n = d->n, nc = d->nc, rc;
  double *AQ = v, *g = AQ + n, *lam = g + n, *u = lam + n, *vb = u + n;
  double *dT = vb + n, *dw = dT + nc + 1;
  qp_matvec(model_stiffness(md), Q, AQ);
  adjoint_rhs(md, kind, AQ, dT, g);
  if ((rc = qp_adjoint(model_solver(md), g, lam, held, st))) return rc;
  double a = kind == OBJECTIVE_ENERGY, s = kind == OBJECTIVE_ENERGY ? 1
           : kind == OBJECTIVE_COMPLIANCE ? -1 : 0;
  for (int i = 0; i < n; i++) u[i] = -lam[i], vb[i] = -lam[i] + s * Q[i];
  for (int c = 0; c < nc; c++)
    if (held[c]) u[d->contact[c]] += dT[c], vb[d->contact[c]] += dT[c];
  if (dJ) *dJ = state_rounding(md, u);              /* u = t - lambda here */
  for (int i = 0; i < n; i++) u[i] += 0.5 * a * Q[i];
  memset(G, 0, m->ncol * sizeof *G);
  held_term(md, held, g, lam, G);
  for (int t = 0; t < 2 * m->N * m->M; t++) triangle_terms(md, t, u, vb, G);
  tributary_term(m, nc, d->contact_col, dw, G);
  if (p->contact == CONTACT_TRESCA && (rc = sliding_term(md, held, lam, G, st)))
    return rc;
  if (a && p->contact == CONTACT_TRESCA) friction_gradient(p, m, d, Q, G);
  return STATUS_OK;
}

/* the scratch vectors of gradient_terms: 5 n, then dT and dw (nc + 1 each) */
static int gradient_scratch(const Model *md, double **v, char **held, Status *st)
{
  const Fem_dofs *d = model_dofs(md);
  size_t n = d->n, nk = d->nc + d->nt;
  *v = calloc(5 * n + 2 * nk + 2, sizeof **v);
  *held = malloc(nk + 1);
  if (*v && *held) return STATUS_OK;
  free(*v), free(*held);
  return status_set(st, STATUS_MEMORY, "objective: out of memory");
}
#line 603 "paper/objective.nw"
int objective_gradient_fixed(const Model *md, const Objective *o,
                             const double *t, double *lam, char *held_out,
                             double *G, double *state, Status *st)
{
  if (!model_solved(md))
    return status_set(st, STATUS_INPUT, "gradient: no state has been solved");
  double *v, J;
  char *held;
  const Fem_dofs *d = model_dofs(md);
  int rc = gradient_scratch(md, &v, &held, st), n = d->n, nc = d->nc;
  if (rc) return rc;
  double *dT = v + 5 * n, *dw = dT + nc + 1;
  if (o) rc = objective_partials(md, o, &J, dT, dw, st);
  for (int c = 0; t && c < nc; c++) dT[c] += t[c];
  if (!rc) rc = gradient_terms(md, o ? o->kind : OBJECTIVE_COUNT, v, held, G, state, st);
  if (!rc && lam) memcpy(lam, v + 2 * n, n * sizeof *lam);
  if (!rc && held_out) memcpy(held_out, held, d->nc + d->nt);
  free(v), free(held);
  return rc;
}
