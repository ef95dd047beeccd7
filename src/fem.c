#line 150 "paper/fem.nw"
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fem.h"
#line 165 "paper/fem.nw"
static void fem_hold_side(const Mesh *m, Problem_side_id side, Problem_bc_kind kind, int *held);
static int fem_side_holds(Problem_side_id side, Problem_bc_kind kind, int c);
static void fem_hold_curves(const Mesh *m, const Problem *p, int *held);

Fem_dofs *fem_dofs_new(const Mesh *m, const Problem *p, Status *st)
{
  Fem_dofs *d = calloc(1, sizeof *d);
  if (!d) { status_set(st, STATUS_MEMORY, "dofs: out of memory"); return NULL; }
  d->ndof = 2 * m->nnodes;
  d->unknown = calloc(d->ndof, sizeof *d->unknown);
  d->contact = malloc(m->ncol * sizeof *d->contact);
  d->contact_col = malloc(m->ncol * sizeof *d->contact_col);
  d->tangent = malloc(m->ncol * sizeof *d->tangent);
  d->tangent_col = malloc(m->ncol * sizeof *d->tangent_col);
  if (!d->unknown || !d->contact || !d->contact_col || !d->tangent
      || !d->tangent_col) {
    fem_dofs_free(d);
    status_set(st, STATUS_MEMORY, "dofs: out of memory");
    return NULL;
  }
  for (int side = 0; side < SIDE_COUNT; side++)
    fem_hold_side(m, side, p->side[side].kind, d->unknown);
  fem_hold_curves(m, p, d->unknown);
  
#line 195 "paper/fem.nw"
for (int k = 0; k < d->ndof; k++)
  d->unknown[k] = d->unknown[k] < 0 ? -1 : d->n++;
for (int i = 0; i < m->ncol; i++)
  if (d->unknown[2 * i + 1] >= 0) {      /* u2 of A_i, node i of row 0 */
    d->contact[d->nc] = d->unknown[2 * i + 1];
    d->contact_col[d->nc++] = i;
  }
for (int i = 0; p->contact != CONTACT_FRICTIONLESS && i < m->ncol; i++)
  if (d->unknown[2 * i] >= 0) {          /* u1 of A_i: it may slip */
    d->tangent[d->nt] = d->unknown[2 * i];
    d->tangent_col[d->nt++] = i;
  }
#line 189 "paper/fem.nw"
  return d;
}
#line 211 "paper/fem.nw"
static void fem_hold_side(const Mesh *m, Problem_side_id side, Problem_bc_kind kind, int *held)
{
  if (kind != BC_CLAMPED && kind != BC_ROLLER) return;
  if (side == SIDE_TOP && m->material) return;      /* a part: no top side */
  int count = side == SIDE_TOP ? m->ncol : m->nrow;
  for (int s = 0; s < count; s++) {
    int k = side == SIDE_TOP ? (m->nrow - 1) * m->ncol + s
          : s * m->ncol + (side == SIDE_LEFT ? 0 : m->N);
    for (int c = 0; c < 2; c++)
      if (fem_side_holds(side, kind, c)) held[2 * k + c] = -1;
  }
}
#line 228 "paper/fem.nw"
static int fem_side_holds(Problem_side_id side, Problem_bc_kind kind, int c)
{
  int normal = side == SIDE_TOP ? 1 : 0;
  return kind == BC_CLAMPED || (kind == BC_ROLLER && c == normal);
}
#line 240 "paper/fem.nw"
static int fem_edge_holds(const Mesh *m, const Problem *p, int e, int c)
{
  int s = m->edge_curve[e];
  if (s < 0) return 0;
  Problem_bc_kind kind = p->part.curve[s].kind;
  const double *x = m->xy + 2 * m->edge[2 * e], *y = m->xy + 2 * m->edge[2 * e + 1];
  int normal = fabs(y[0] - x[0]) >= fabs(y[1] - x[1]) ? 1 : 0;
  return kind == BC_CLAMPED || (kind == BC_ROLLER && c == normal);
}

static void fem_hold_curves(const Mesh *m, const Problem *p, int *held)
{
  for (int e = 0; e < m->nedge; e++)
    for (int c = 0; c < 2; c++)
      if (fem_edge_holds(m, p, e, c))
        for (int v = 0; v < 2; v++) held[2 * m->edge[2 * e + v] + c] = -1;
}

#line 259 "paper/fem.nw"
void fem_dofs_free(Fem_dofs *d)
{
  if (!d) return;
  free(d->unknown);
  free(d->contact);
  free(d->contact_col);
  free(d->tangent);
  free(d->tangent_col);
  free(d);
}
#line 303 "paper/fem.nw"
static Fem_hooke fem_hooke_isotropic(const Problem_material *m,
                                     Problem_plane_model model);
static Fem_hooke fem_hooke_orthotropic(const Problem_material *m,
                                       Problem_plane_model model);

Fem_hooke fem_hooke(const Problem *p)
{
  return fem_hooke_of(&p->material, p->model);
}

Fem_hooke fem_hooke_of(const Problem_material *m, Problem_plane_model model)
{
  return m->kind == MATERIAL_ORTHOTROPIC ? fem_hooke_orthotropic(m, model)
                                         : fem_hooke_isotropic(m, model);
}
#line 323 "paper/fem.nw"
static Fem_hooke fem_hooke_isotropic(const Problem_material *m,
                                     Problem_plane_model model)
{
  Fem_hooke H;
  double (*D)[3] = H.D;
  double mu = m->young / (2 * (1 + m->nu));
  double lambda = model == MODEL_PLANE_STRAIN
    ? m->young * m->nu / ((1 + m->nu) * (1 - 2 * m->nu))
    : m->young * m->nu / (1 - m->nu * m->nu);
  memset(&H, 0, sizeof H);
  D[0][0] = D[1][1] = lambda + 2 * mu;
  D[0][1] = D[1][0] = lambda;
  D[2][2] = mu;
  if (model == MODEL_PLANE_STRAIN) H.D33[0] = H.D33[1] = lambda;
  return H;
}
#line 375 "paper/fem.nw"
/* S = the normal block (11, 22) of the plane model's compliance in the
   material's axes; nu3 = (nu31, nu32): tau33 = nu3 . (tau11, tau22) in
   plane strain, 0 in plane stress */
static void fem_orthotropic_compliance(const Problem_material *m,
                                       Problem_plane_model model,
                                       double S[2][2], double nu3[2])
{
  double S11 = 1 / m->E1, S12 = -m->nu12 / m->E1, S22 = 1 / m->E2;
  nu3[0] = nu3[1] = 0;
  if (model == MODEL_PLANE_STRAIN) {
    double S13 = -m->nu13 / m->E1, S23 = -m->nu23 / m->E2, S33 = 1 / m->E3;
    S11 -= S13 * S13 / S33;
    S12 -= S13 * S23 / S33;
    S22 -= S23 * S23 / S33;
    nu3[0] = -S13 / S33, nu3[1] = -S23 / S33;
  }
  S[0][0] = S11, S[0][1] = S[1][0] = S12, S[1][1] = S22;
}
#line 396 "paper/fem.nw"
/* Q = the stiffness of the plane model in the material's axes, and nu3 */
static void fem_orthotropic_axes(const Problem_material *m,
                                 Problem_plane_model model,
                                 double Q[3][3], double nu3[2])
{
  double S[2][2];
  fem_orthotropic_compliance(m, model, S, nu3);
  double det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
  memset(Q, 0, 3 * sizeof Q[0]);
  Q[0][0] = S[1][1] / det, Q[1][1] = S[0][0] / det;
  Q[0][1] = Q[1][0] = -S[0][1] / det;
  Q[2][2] = m->G12;
}
#line 433 "paper/fem.nw"
static void fem_cos_sin_degrees(double degrees, double *c, double *s);

static Fem_hooke fem_hooke_orthotropic(const Problem_material *m,
                                       Problem_plane_model model)
{
  Fem_hooke H;
  double Q[3][3], nu3[2], c, s, QT[3][3];
  fem_orthotropic_axes(m, model, Q, nu3);
  fem_cos_sin_degrees(m->angle, &c, &s);
  double T[3][3] = { { c * c, s * s, c * s }, { s * s, c * c, -c * s },
                     { -2 * c * s, 2 * c * s, c * c - s * s } };
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      QT[i][j] = Q[i][0] * T[0][j] + Q[i][1] * T[1][j] + Q[i][2] * T[2][j];
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++)
      H.D[i][j] = H.D[j][i] = T[0][i] * QT[0][j] + T[1][i] * QT[1][j]
                              + T[2][i] * QT[2][j];
  for (int j = 0; j < 3; j++)
    H.D33[j] = model == MODEL_PLANE_STRAIN ? nu3[0] * QT[0][j] + nu3[1] * QT[1][j] : 0;
  return H;
}
#line 466 "paper/fem.nw"
static void fem_cos_sin_degrees(double degrees, double *c, double *s)
{
  double r = fmod(degrees, 360), q = nearbyint(r / 90);
  double t = (r - 90 * q) * (acos(-1.0) / 180), c0 = cos(t), s0 = sin(t);
  switch (((int) q % 4 + 4) % 4) {
  case 0: *c = c0, *s = s0; break;
  case 1: *c = -s0, *s = c0; break;
  case 2: *c = -c0, *s = -s0; break;
  default: *c = s0, *s = -c0; break;
  }
}
#line 515 "paper/fem.nw"
static const char *fem_isotropic_refusal(const Problem_material *m,
                                         char *buf, size_t size);
static const char *fem_orthotropic_refusal(const Problem_material *m,
                                           Problem_plane_model model,
                                           char *buf, size_t size);

const char *fem_material_refusal(const Problem_material *m,
                                 Problem_plane_model model, char *buf,
                                 size_t size)
{
  return m->kind == MATERIAL_ORTHOTROPIC
       ? fem_orthotropic_refusal(m, model, buf, size)
       : fem_isotropic_refusal(m, buf, size);
}
#line 532 "paper/fem.nw"
static const char *fem_refuse(char *buf, size_t size, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, size, fmt, ap);
  va_end(ap);
  return buf;
}

/* |x| in the scene's window [1e-30, 1e30], with its allowance of rounding */
static int fem_in_window(double x)
{
  double r = fabs(x), rounding = 4 * DBL_EPSILON;
  return r >= 1e-30 * (1 - rounding) && r <= 1e30 * (1 + rounding);
}

static const char *fem_isotropic_refusal(const Problem_material *m,
                                         char *buf, size_t size)
{
  const char *window = "Young's modulus must lie in [1e-30, 1e30], where "
                       "every product the solvers form is finite";
  if (!(m->young > 0)) return fem_refuse(buf, size, "Young's modulus must be > 0");
  if (!fem_in_window(m->young)) return fem_refuse(buf, size, "%s", window);
  if (!(m->nu < 0.5))
    return fem_refuse(buf, size, "nu must be < 0.5: 0.5 is the incompressible "
                      "limit, where this displacement method locks");
  if (!(m->nu > -1)) return fem_refuse(buf, size, "nu must be > -1 (stability)");
  return NULL;
}
#line 567 "paper/fem.nw"
static const char *fem_poisson_refusal(const Problem_material *m,
                                       Problem_plane_model model,
                                       char *buf, size_t size);
static int fem_definite(const Problem_material *m, Problem_plane_model model);

static const char *fem_orthotropic_refusal(const Problem_material *m,
                                           Problem_plane_model model,
                                           char *buf, size_t size)
{
  const char *name[8] = { "E1", "E2", "nu12", "G12", "angle", "E3", "nu13", "nu23" };
  double value[8] = { m->E1, m->E2, m->nu12, m->G12, m->angle, m->E3, m->nu13, m->nu23 };
  int n = model == MODEL_PLANE_STRAIN ? 8 : 5;
  for (int k = 0; k < n; k++) {
    int modulus = k == 0 || k == 1 || k == 3 || k == 5;
    if (!isfinite(value[k]))
      return fem_refuse(buf, size, "%s must be finite", name[k]);
    if (modulus && !(value[k] > 0))
      return fem_refuse(buf, size, "%s must be > 0", name[k]);
    if (modulus && !fem_in_window(value[k]))
      return fem_refuse(buf, size, "%s must lie in [1e-30, 1e30], where every "
                        "product the solvers form is finite", name[k]);
  }
  const char *why = fem_poisson_refusal(m, model, buf, size);
  if (!why && !fem_definite(m, model))
    why = fem_refuse(buf, size, "the material is too near the limit of "
                     "ellipticity: its D is not positive definite in floating point");
  return why;
}
#line 599 "paper/fem.nw"
static const char *fem_poisson_refusal(const Problem_material *m,
                                       Problem_plane_model model,
                                       char *buf, size_t size)
{
  const char *name[3][3] = { { "nu12", "E1", "E2" }, { "nu13", "E1", "E3" },
                             { "nu23", "E2", "E3" } };
  double pair[3][3] = { { m->nu12, m->E1, m->E2 }, { m->nu13, m->E1, m->E3 },
                        { m->nu23, m->E2, m->E3 } };
  int n = model == MODEL_PLANE_STRAIN ? 3 : 1;
  for (int k = 0; k < n; k++)
    if (!(pair[k][0] * pair[k][0] * (pair[k][2] / pair[k][1]) < 1))
      return fem_refuse(buf, size, "%s must satisfy |%s| < sqrt(%s/%s) = %.6g "
                        "(ellipticity)", name[k][0], name[k][0], name[k][1],
                        name[k][2], sqrt(pair[k][1] / pair[k][2]));
  if (n == 1) return NULL;
  
#line 620 "paper/fem.nw"
double nu21 = m->nu12 * m->E2 / m->E1, nu31 = m->nu13 * m->E3 / m->E1,
       nu32 = m->nu23 * m->E3 / m->E2;
double delta = 1 - m->nu12 * nu21 - m->nu13 * nu31 - m->nu23 * nu32
             - 2 * nu21 * nu32 * m->nu13;
if (!(delta > 0))
  return fem_refuse(buf, size, "the Poisson ratios must satisfy 1 - nu12 nu21 "
                    "- nu13 nu31 - nu23 nu32 - 2 nu21 nu32 nu13 > 0 "
                    "(ellipticity in plane strain), not %.3g", delta);
#line 615 "paper/fem.nw"
  return NULL;
}
#line 631 "paper/fem.nw"
/* D of m finite and positive definite: its leading minors > 0 */
static int fem_definite(const Problem_material *m, Problem_plane_model model)
{
  Fem_hooke H = fem_hooke_of(m, model);
  long double d[3][3];
  for (int k = 0; k < 9; k++) {
    if (!isfinite(H.D[k / 3][k % 3])) return 0;
    d[k / 3][k % 3] = H.D[k / 3][k % 3];
  }
  long double m2 = d[0][0] * d[1][1] - d[0][1] * d[1][0];
  long double m3 = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1])
                 - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0])
                 + d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  return d[0][0] > 0 && m2 > 0 && m3 > 0;
}
#line 696 "paper/fem.nw"
static void fem_element_dofs(const Mesh *m, const Fem_dofs *d, int t, int g[6]);

void fem_element_xy(const Mesh *m, int t, double xy[6])
{
  for (int k = 0; k < 3; k++) {
    xy[2 * k] = m->xy[2 * m->tri[3 * t + k]];
    xy[2 * k + 1] = m->xy[2 * m->tri[3 * t + k] + 1];
  }
}

void fem_element_q(const Mesh *m, const Fem_dofs *d, const double *Q, int t,
                   double q[6])
{
  int g[6];
  fem_element_dofs(m, d, t, g);
  for (int r = 0; r < 6; r++) q[r] = g[r] >= 0 ? Q[g[r]] : 0;
}
#line 717 "paper/fem.nw"
double fem_element_gradients(const double xy[6], double gx[3], double gy[3])
{
  for (int k = 0; k < 3; k++) {
    int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    gx[k] = xy[2 * k1 + 1] - xy[2 * k2 + 1];
    gy[k] = xy[2 * k2] - xy[2 * k1];
  }
  return (xy[2] - xy[0]) * (xy[5] - xy[1]) - (xy[4] - xy[0]) * (xy[3] - xy[1]);
}
#line 730 "paper/fem.nw"
void fem_element_strain(const double gx[3], const double gy[3],
                        const double q[6], long double e[3])
{
  e[0] = e[1] = e[2] = 0;
  for (int k = 0; k < 3; k++) {
    e[0] += (long double) gx[k] * q[2 * k];
    e[1] += (long double) gy[k] * q[2 * k + 1];
    e[2] += (long double) gy[k] * q[2 * k];
    e[2] += (long double) gx[k] * q[2 * k + 1];
  }
}
#line 748 "paper/fem.nw"
double fem_triangle_strain(const Mesh *m, const Fem_dofs *d, const double *Q,
                           int t, long double e[3])
{
  double xy[6], q[6], gx[3], gy[3];
  fem_element_xy(m, t, xy);
  fem_element_q(m, d, Q, t, q);
  double a2 = fem_element_gradients(xy, gx, gy);
  for (int k = 0; k < 3; k++) gx[k] /= a2, gy[k] /= a2;
  fem_element_strain(gx, gy, q, e);
  return a2;
}

void fem_element_stress(const Fem_hooke *H, const long double e[3], long double s[3])
{
  for (int r = 0; r < 3; r++) {
    s[r] = 0;
    for (int c = 0; c < 3; c++) s[r] += (long double) H->D[r][c] * e[c];
  }
}
#line 774 "paper/fem.nw"
long double fem_element_stress33(const Fem_hooke *H, const long double e[3])
{
  const double *d = H->D33;
  if (d[1] == d[0] && d[2] == 0) return d[0] * (e[0] + e[1]);
  return d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
}
#line 789 "paper/fem.nw"
/* B of the triangle xy; returns twice its area */
static double fem_element_B(const double xy[6], double B[3][6])
{
  double gx[3], gy[3], area2 = fem_element_gradients(xy, gx, gy);
  memset(B, 0, 3 * sizeof B[0]);
  for (int k = 0; k < 3; k++) {
    B[0][2 * k] = gx[k] / area2; B[1][2 * k + 1] = gy[k] / area2;
    B[2][2 * k] = gy[k] / area2; B[2][2 * k + 1] = gx[k] / area2;
  }
  return area2;
}
#line 803 "paper/fem.nw"
void fem_element_stiffness(const double xy[6], const Fem_hooke *H,
                           double K[6][6])
{
  double B[3][6], area2 = fem_element_B(xy, B);
  
#line 812 "paper/fem.nw"
double DB[3][6];
const double (*D)[3] = H->D;
for (int r = 0; r < 3; r++)
  for (int c = 0; c < 6; c++)
    DB[r][c] = D[r][0] * B[0][c] + D[r][1] * B[1][c] + D[r][2] * B[2][c];
for (int r = 0; r < 6; r++)
  for (int c = 0; c < 6; c++)
    K[r][c] = 0.5 * area2 * (B[0][r] * DB[0][c] + B[1][r] * DB[1][c]
                            + B[2][r] * DB[2][c]);
#line 808 "paper/fem.nw"
}
#line 865 "paper/fem.nw"
static int fem_neighbours(const Mesh *m, int **adj_p, int **adj)
{
  int n = m->nnodes, *p = calloc(n + 1, sizeof *p), *next = malloc(n * sizeof *next);
  int *a = malloc(9 * (size_t) m->ntri * sizeof *a), out = 0;
  *adj_p = p, *adj = a;
  if (!p || !next || !a) { free(next); return -1; }
  for (int t = 0; t < 3 * m->ntri; t++) p[m->tri[t] + 1] += 3;
  for (int k = 0; k < n; k++) p[k + 1] += p[k], next[k] = p[k];
  for (int t = 0; t < m->ntri; t++)
    for (int v = 0; v < 3; v++)
      for (int w = 0; w < 3; w++) a[next[m->tri[3 * t + v]]++] = m->tri[3 * t + w];
  free(next);
  for (int k = 0, from = 0; k < n; k++) {
    int to = p[k + 1];
    
#line 887 "paper/fem.nw"
for (int q = from + 1; q < to; q++)
  for (int r = q, v = a[q]; r > from && a[r - 1] > v; r--) a[r] = a[r - 1], a[r - 1] = v;
for (int q = from; q < to; q++)
  if (q == from || a[q] != a[q - 1]) a[out++] = a[q];
#line 880 "paper/fem.nw"
    p[k + 1] = out, from = to;
  }
  return 0;
}
#line 895 "paper/fem.nw"
static int fem_column(const Fem_dofs *d, const int *adj_p, const int *adj, int b,
                      Sparse_index *rows)
{
  int n = 0;
  for (int q = adj_p[b]; q < adj_p[b + 1]; q++)
    for (int c = 0; c < 2; c++)
      if (d->unknown[2 * adj[q] + c] >= 0) {
        if (rows) rows[n] = d->unknown[2 * adj[q] + c];
        n++;
      }
  return n;
}

static size_t fem_pattern(const Fem_dofs *d, const int *adj_p, const int *adj,
                          void *Ap, void *Ai)
{
  Sparse_index *p = Ap, *i = Ai;
  size_t nnz = 0;
  for (int k = 0, col = 0; k < d->ndof; k++)
    if (d->unknown[k] >= 0) {
      if (p) p[col] = (Sparse_index) nnz;
      nnz += fem_column(d, adj_p, adj, k / 2, i ? i + nnz : NULL);
      if (p) p[++col] = (Sparse_index) nnz;
    }
  return nnz;
}

#line 843 "paper/fem.nw"
cholmod_sparse *fem_stiffness_new(const Mesh *m, const Fem_dofs *d,
                                  cholmod_common *cm, Status *st)
{
  int *adj_p = NULL, *adj = NULL;
  cholmod_sparse *A = NULL;
  if (!fem_neighbours(m, &adj_p, &adj)) {
    size_t nnz = fem_pattern(d, adj_p, adj, NULL, NULL);
    A = cholmod_l_allocate_sparse(d->n, d->n, nnz, 1, 1, 0, CHOLMOD_REAL, cm);
    if (A) fem_pattern(d, adj_p, adj, A->p, A->i);
  }
  free(adj_p), free(adj);
  if (!A) status_set(st, STATUS_MEMORY, "stiffness: out of memory");
  return A;
}
#line 925 "paper/fem.nw"
static void fem_element_dofs(const Mesh *m, const Fem_dofs *d, int t, int g[6])
{
  for (int k = 0; k < 3; k++) {
    int node = m->tri[3 * t + k];
    g[2 * k] = d->unknown[2 * node];
    g[2 * k + 1] = d->unknown[2 * node + 1];
  }
}
#line 938 "paper/fem.nw"
/* the index of row r in column c of A's pattern, -1 if it is not there */
static Sparse_index fem_entry(const cholmod_sparse *A, int r, int c)
{
  const Sparse_index *Ap = A->p, *Ai = A->i;
  Sparse_index lo = Ap[c], hi = Ap[c + 1] - 1;
  while (lo < hi) {
    Sparse_index mid = (lo + hi) / 2;
    if (Ai[mid] < r) lo = mid + 1; else hi = mid;
  }
  return lo <= hi && Ai[lo] == r ? lo : -1;
}
#line 964 "paper/fem.nw"
/* adds K's rows r0, r0+1 and columns c0, c0+1 (held unknowns skipped)
   into A at the unknowns gr (rows) and gc (columns); -1 when an entry is
   not in A's pattern */
static int fem_add_block(cholmod_sparse *A, double K[6][6], int r0, int c0,
                         const int gr[2], const int gc[2])
{
  const Sparse_index *Ap = A->p, *Ai = A->i;
  double *Ax = A->x;
  int r1 = gr[0] >= 0 ? 0 : 1, c1 = gc[0] >= 0 ? 0 : 1;
  if (gr[r1] < 0 || gc[c1] < 0) return 0;          /* the vertex is held */
  Sparse_index first = fem_entry(A, gr[r1], gc[c1]);
  if (first < 0) return -1;
  for (int c = c1; c < 2; c++)
    for (int r = r1; r < 2; r++) {
      if (gc[c] < 0 || gr[r] < 0) continue;
      Sparse_index q = first - Ap[gc[c1]] + Ap[gc[c]] + gr[r] - gr[r1];
      if (q >= Ap[gc[c] + 1] || Ai[q] != gr[r]) return -1;
      Ax[q] += K[r0 + r][c0 + c];
    }
  return 0;
}
#line 990 "paper/fem.nw"
int fem_stiffness_fill(cholmod_sparse *A, const Mesh *m, const Fem_dofs *d,
                       const Fem_hooke *H, Status *st)
{
  memset(A->x, 0, (size_t) ((Sparse_index *) A->p)[A->ncol] * sizeof(double));
  for (int t = 0; t < m->ntri; t++) {
    double xy[6], K[6][6];
    int g[6];
    fem_element_xy(m, t, xy);
    fem_element_dofs(m, d, t, g);
    fem_element_stiffness(xy, H + mesh_material(m, t), K);
    
#line 1007 "paper/fem.nw"
for (int k = 0; k < 3; k++)
  for (int l = 0; l < 3; l++)
    if (fem_add_block(A, K, 2 * l, 2 * k, g + 2 * l, g + 2 * k))
      return status_set(st, STATUS_SYSTEM,
                        "stiffness: pattern does not match the mesh");
#line 1001 "paper/fem.nw"
  }
  return STATUS_OK;
}
#line 1023 "paper/fem.nw"
static void fem_assemble_load(const Mesh *m, const Fem_dofs *d, const Problem *p,
                              int held, double *b);

void fem_load(const Mesh *m, const Fem_dofs *d, const Problem *p, double *b)
{
  memset(b, 0, d->n * sizeof *b);
  fem_assemble_load(m, d, p, 0, b);
}
#line 1039 "paper/fem.nw"
static void fem_add_body_force(const Mesh *m, const Fem_dofs *d, const double F[2],
                               int held, double *b);
static void fem_add_traction(const Mesh *m, const Fem_dofs *d, Problem_side_id side,
                             const Problem_side *load, int held, double *b);
static void fem_add_curve_loads(const Mesh *m, const Fem_dofs *d,
                                const Problem *p, int held, double *b);

static void fem_assemble_load(const Mesh *m, const Fem_dofs *d, const Problem *p,
                              int held, double *b)
{
  if (p->has_body_force) fem_add_body_force(m, d, p->body_force, held, b);
  for (int side = 0; side < SIDE_COUNT; side++)
    if (p->side[side].kind == BC_TRACTION)
      fem_add_traction(m, d, side, &p->side[side], held, b);
  if (m->nedge) fem_add_curve_loads(m, d, p, held, b);
}
#line 1059 "paper/fem.nw"
static void fem_add_force(const Fem_dofs *d, int node, const double f[2], double w,
                          int held, double *b)
{
  for (int c = 0; c < 2; c++) {
    int k = 2 * node + c, u = d->unknown[k];
    if (!held && u >= 0) b[u] += w * f[c];
    if (held && u < 0) b[k] += w * f[c];
  }
}
#line 1071 "paper/fem.nw"
static void fem_add_body_force(const Mesh *m, const Fem_dofs *d, const double F[2],
                               int held, double *b)
{
  for (int t = 0; t < m->ntri; t++)
    for (int k = 0; k < 3; k++)
      fem_add_force(d, m->tri[3 * t + k], F, mesh_area(m, t) / 3, held, b);
}
#line 1085 "paper/fem.nw"
static void fem_add_traction(const Mesh *m, const Fem_dofs *d, Problem_side_id side,
                             const Problem_side *load, int held, double *b)
{
  int top = side == SIDE_TOP, count = top ? m->N : m->nrow - 1;
  for (int e = 0; e < count; e++) {
    int p = top ? (m->nrow - 1) * m->ncol + e
                : e * m->ncol + (side == SIDE_LEFT ? 0 : m->N);
    int q = top ? p + 1 : p + m->ncol;
    double s0 = m->xy[2 * p + !top], s1 = m->xy[2 * q + !top];
    double t0 = (fmax(s0, load->from) - s0) / (s1 - s0);
    double t1 = (fmin(s1, load->to) - s0) / (s1 - s0);
    if (t1 <= t0) continue;
    double L = s1 - s0;
    fem_add_force(d, p, load->P, L * ((t1 - t0) - (t1 * t1 - t0 * t0) / 2), held, b);
    fem_add_force(d, q, load->P, L * (t1 * t1 - t0 * t0) / 2, held, b);
  }
}
#line 1110 "paper/fem.nw"
static int fem_curve_force(const Mesh *m, const Problem *p, int e, double f[2])
{
  if (m->edge_curve[e] < 0) return 0;
  const Problem_curve *cv = &p->part.curve[m->edge_curve[e]];
  const double *x = m->xy + 2 * m->edge[2 * e], *y = m->xy + 2 * m->edge[2 * e + 1];
  double len = hypot(y[0] - x[0], y[1] - x[1]);
  if (cv->kind == BC_TRACTION) f[0] = cv->P[0] * len, f[1] = cv->P[1] * len;
  else if (cv->kind == BC_PRESSURE)
    f[0] = -cv->pressure * (y[1] - x[1]), f[1] = cv->pressure * (y[0] - x[0]);
  else return 0;
  return 1;
}

static void fem_add_curve_loads(const Mesh *m, const Fem_dofs *d,
                                const Problem *p, int held, double *b)
{
  double f[2];
  for (int e = 0; e < m->nedge; e++)
    if (fem_curve_force(m, p, e, f))
      for (int v = 0; v < 2; v++) fem_add_force(d, m->edge[2 * e + v], f, 0.5, held, b);
}

void fem_curve_resultant(const Mesh *m, const Problem *p, double L[2])
{
  double f[2];
  L[0] = L[1] = 0;
  for (int e = 0; e < m->nedge; e++)
    if (fem_curve_force(m, p, e, f)) L[0] += f[0], L[1] += f[1];
}
#line 1179 "paper/fem.nw"
void fem_reactions(const Mesh *m, const Fem_dofs *d, const Fem_hooke *H,
                   const Problem *p, const double *Q, double *r)
{
  memset(r, 0, d->ndof * sizeof *r);
  fem_assemble_load(m, d, p, 1, r);
  for (int k = 0; k < d->ndof; k++) r[k] = -r[k];
  for (int t = 0; t < m->ntri; t++) {
    int g[6];
    fem_element_dofs(m, d, t, g);
    if (g[0] >= 0 && g[1] >= 0 && g[2] >= 0 && g[3] >= 0 && g[4] >= 0 && g[5] >= 0)
      continue;                          /* no held vertex component */
    
#line 1196 "paper/fem.nw"
double xy[6], K[6][6], q[6];
fem_element_xy(m, t, xy);
fem_element_stiffness(xy, H + mesh_material(m, t), K);
fem_element_q(m, d, Q, t, q);
for (int a = 0; a < 6; a++)
  if (g[a] < 0) {
    long double s = 0;
    for (int c = 0; c < 6; c++) s += (long double) K[a][c] * q[c];
    r[2 * m->tri[3 * t + a / 2] + a % 2] += (double) s;
  }
#line 1191 "paper/fem.nw"
  }
}
#line 1211 "paper/fem.nw"
static int fem_reaction_curve(const Mesh *m, const Problem *p, int node, int c)
{
  for (int e = 0; e < m->nedge; e++)
    if ((m->edge[2 * e] == node || m->edge[2 * e + 1] == node)
        && fem_edge_holds(m, p, e, c))
      return SIDE_COUNT + m->edge_curve[e];
  return -1;
}
#line 1230 "paper/fem.nw"
int fem_reaction_side(const Mesh *m, const Problem *p, int k)
{
  int node = k / 2, c = k % 2, i = node % m->ncol, j = node / m->ncol;
  Problem_side_id on[SIDE_COUNT];
  int n = 0, owner = -1;
  if (j >= m->nrow) return fem_reaction_curve(m, p, node, c);
  if (i == 0) on[n++] = SIDE_LEFT;
  if (i == m->N) on[n++] = SIDE_RIGHT;
  if (j == m->nrow - 1 && !m->material) on[n++] = SIDE_TOP;
  for (int s = 0; s < n; s++)
    if (fem_side_holds(on[s], p->side[on[s]].kind, c)
        && (owner < 0 || c == (on[s] == SIDE_TOP ? 1 : 0)))
      owner = on[s];
  if (owner < 0 && m->nedge) owner = fem_reaction_curve(m, p, node, c);
  return owner;
}
#line 1273 "paper/fem.nw"
double fem_energy(const Mesh *m, const Fem_dofs *d, const Fem_hooke *H,
                  const double *b, const double *Q)
{
  long double U = 0, W = 0;
  for (int t = 0; t < m->ntri; t++) {
    
#line 1287 "paper/fem.nw"
long double e[3], sigma[3];
long double area2 = fem_triangle_strain(m, d, Q, t, e);
fem_element_stress(H + mesh_material(m, t), e, sigma);
for (int r = 0; r < 3; r++)
  U += area2 / 4 * e[r] * sigma[r];     /* 1/2 |T| e'De, |T| = area2/2 */
#line 1279 "paper/fem.nw"
  }
  for (int i = 0; i < d->n; i++) W += (long double) b[i] * Q[i];
  return (double) (U - W);
}
