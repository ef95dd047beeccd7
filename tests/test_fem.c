/* test_fem: the P1 elasticity operator (paper/fem.nw), the matrix A of (4.3).
   Patch test: a linear displacement field has constant stress, so the
   assembled operator applied to it vanishes at interior nodes and equals
   the consistent nodal forces of the boundary tractions sigma.n elsewhere;
   rigid motions have zero stiffness; the pattern of A is that of 36
   triplets per element summed by CHOLMOD, entry for entry; the reactions
   of the held sides balance the loads and the residual for any u.  The mesh itself: test_mesh.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "setup.h"
#include "problem.h"
#include "mesh.h"
#include "fem.h"
#include "qp.h"

#include "free_body.h"

static double norm_inf(const double *v, int n)
{
  double m = 0;
  for (int k = 0; k < n; k++) m = fmax(m, fabs(v[k]));
  return m;
}

/* consistent nodal forces of the constant traction sigma.n on every
   boundary edge (outward normal of a counter-clockwise boundary) */
static void boundary_forces(const Mesh *m, const Fem_hooke *H,
                            const double grad[4], double *f)
{
  double e[3] = { grad[0], grad[3], grad[1] + grad[2] };  /* e11 e22 2e12 */
  double s[3];
  const double (*D)[3] = H->D;
  for (int r = 0; r < 3; r++) s[r] = D[r][0] * e[0] + D[r][1] * e[1] + D[r][2] * e[2];
  int n = 2 * (m->N + m->nrow - 1), *loop = malloc((n + 1) * sizeof *loop), k = 0;
  for (int i = 0; i < m->N; i++) loop[k++] = i;                              /* bottom */
  for (int j = 0; j < m->nrow - 1; j++) loop[k++] = j * m->ncol + m->N;     /* right */
  for (int i = m->N; i > 0; i--) loop[k++] = (m->nrow - 1) * m->ncol + i;  /* top */
  for (int j = m->nrow - 1; j > 0; j--) loop[k++] = j * m->ncol;            /* left */
  loop[k] = loop[0];
  memset(f, 0, 2 * m->nnodes * sizeof *f);
  for (k = 0; k < n; k++) {
    int p = loop[k], q = loop[k + 1];
    double dx = m->xy[2 * q] - m->xy[2 * p], dy = m->xy[2 * q + 1] - m->xy[2 * p + 1];
    double nx = dy, ny = -dx;                       /* outward normal times L */
    double t1 = s[0] * nx + s[2] * ny, t2 = s[2] * nx + s[1] * ny;
    f[2 * p] += t1 / 2; f[2 * p + 1] += t2 / 2;
    f[2 * q] += t1 / 2; f[2 * q + 1] += t2 / 2;
  }
  free(loop);
}

/* fem_energy, which sums strain energies element by element: exact for a
   constant strain (1/2 e'De times the area of the body), zero to the
   square of rounding for the rigid motions (as 1/2 u'Au it would be of
   the order of rounding itself), and 1/2 u'Au - b'u for any u and b */
static void energy_checks(const Mesh *m, const Fem_dofs *d, const Fem_hooke *H,
                          const cholmod_sparse *A, const double grad[4],
                          Problem_plane_model model)
{
  const char *name = model == MODEL_PLANE_STRAIN ? "plane strain" : "plane stress";
  double e[3] = { grad[0], grad[3], grad[1] + grad[2] }, area = 0, U = 0;
  double *u = malloc(d->n * sizeof *u), *b = calloc(d->n, sizeof *b),
         *Au = malloc(d->n * sizeof *Au);
  for (int t = 0; t < m->ntri; t++) {
    const int *v = m->tri + 3 * t;
    const double *p = m->xy + 2 * v[0], *q = m->xy + 2 * v[1], *s = m->xy + 2 * v[2];
    area += 0.5 * ((q[0] - p[0]) * (s[1] - p[1]) - (s[0] - p[0]) * (q[1] - p[1]));
  }
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) U += 0.5 * e[r] * H->D[r][c] * e[c] * area;
  for (int k = 0; k < m->nnodes; k++) {
    double x = m->xy[2 * k], y = m->xy[2 * k + 1];
    u[2 * k] = 1e-4 + grad[0] * x + grad[1] * y;
    u[2 * k + 1] = -2e-4 + grad[2] * x + grad[3] * y;
  }
  double E = fem_energy(m, d, H, b, u);
  check(fabs(E - U) <= 1e-13 * U, "%s: the energy of a constant strain is "
        "1/2 e'De |body| (rel. %.1e)", name, fabs(E - U) / U);
  double rigid = 0;
  for (int mode = 0; mode < 3; mode++) {         /* two translations, a rotation */
    for (int k = 0; k < m->nnodes; k++) {
      double x = m->xy[2 * k], y = m->xy[2 * k + 1];
      u[2 * k] = mode == 0 ? 1 : mode == 1 ? 0 : -y;
      u[2 * k + 1] = mode == 0 ? 0 : mode == 1 ? 1 : x;
    }
    rigid = fmax(rigid, fabs(fem_energy(m, d, H, b, u)));
  }
  double unit = H->D[0][0] * area;               /* the energy scale of unit strain */
  check(rigid <= 1e-24 * unit, "%s: rigid motions have zero energy (%.1e of "
        "the energy of a unit strain)", name, rigid / unit);
  for (int k = 0; k < d->n; k++) u[k] = 1e-3 * sin(1.7 * k), b[k] = 1e6 * cos(0.3 * k);
  qp_matvec(A, u, Au);
  long double ref = 0;
  for (int k = 0; k < d->n; k++) ref += (0.5L * Au[k] - b[k]) * u[k];
  E = fem_energy(m, d, H, b, u);
  check(fabs(E - (double) ref) <= 1e-12 * fabs((double) ref), "%s: fem_energy "
        "= 1/2 u'Au - b'u for an arbitrary u and b (rel. %.1e)", name,
        fabs(E - (double) ref) / fabs((double) ref));
  free(u), free(b), free(Au);
}

static void patch_test(Problem_plane_model model)
{
  int N = 16, M = 2, R = 3;
  Problem s = free_body(N, M, R, model);
  Status st = { 0, "" };
  cholmod_common cm;
  test_start(&cm);
  Mesh *m = mesh_new(&s, &st);
  double X[17];
  design(N, X);
  check(mesh_move(m, X, &st) == 0, "patch mesh moves to a design (%s)", st.msg);
  Fem_dofs *d = fem_dofs_new(m, &s, &st);
  check(d->n == 2 * m->nnodes && d->nc == N + 1, "a free body: every DOF is unknown");
  cholmod_sparse *A = fem_stiffness_new(m, d, &cm, &st);
  Fem_hooke H = fem_hooke(&s);
  fem_stiffness_fill(A, m, d, &H, &st);
  check(A->sorted && A->packed && A->stype == 0, "stiffness is sorted, packed, both triangles");
  double grad[4] = { 1e-3, -2e-3, 0.5e-3, 3e-3 };   /* du1/dx du1/dy du2/dx du2/dy */
  double *u = malloc(d->n * sizeof *u), *r = malloc(d->n * sizeof *r),
         *f = malloc(d->n * sizeof *f);
  for (int k = 0; k < m->nnodes; k++) {
    double x = m->xy[2 * k], y = m->xy[2 * k + 1];
    u[2 * k] = 1e-4 + grad[0] * x + grad[1] * y;
    u[2 * k + 1] = -2e-4 + grad[2] * x + grad[3] * y;
  }
  qp_matvec(A, u, r);
  boundary_forces(m, &H, grad, f);
  double scale = norm_inf(f, d->n), err = 0;
  for (int k = 0; k < d->n; k++) err = fmax(err, fabs(r[k] - f[k]));
  check(err <= 1e-12 * scale, "%s patch test of A (4.3): |A u_lin - f_boundary| / |f| = %.2e",
        model == MODEL_PLANE_STRAIN ? "plane strain" : "plane stress", err / scale);
  for (int mode = 0; mode < 3; mode++) {         /* two translations, a rotation */
    for (int k = 0; k < m->nnodes; k++) {
      double x = m->xy[2 * k], y = m->xy[2 * k + 1];
      u[2 * k] = mode == 0 ? 1 : mode == 1 ? 0 : -y;
      u[2 * k + 1] = mode == 0 ? 0 : mode == 1 ? 1 : x;
    }
    qp_matvec(A, u, r);
    double amax = 0;
    for (Sparse_index p = 0; p < ((Sparse_index *) A->p)[A->ncol]; p++) amax = fmax(amax, fabs(((double *) A->x)[p]));
    check(norm_inf(r, d->n) <= 1e-12 * amax * 4, "%s rigid motion %d has zero stiffness in A (4.3) (%.2e)",
          model == MODEL_PLANE_STRAIN ? "plane strain" : "plane stress", mode, norm_inf(r, d->n) / amax);
  }
  energy_checks(m, d, &H, A, grad, model);
  free(u); free(r); free(f);
  cholmod_l_free_sparse(&A, &cm);
  fem_dofs_free(d);
  mesh_free(m);
  cholmod_l_finish(&cm);
}

/* a consistent traction load sums to P times the loaded length, also when
   the interval ends inside an edge */
static void traction_load(void)
{
  Problem s = free_body(16, 1, 3, MODEL_PLANE_STRESS);
  s.side[SIDE_LEFT].kind = BC_CLAMPED;
  s.side[SIDE_TOP] = (Problem_side) { BC_TRACTION, 1.1, 3.3, { 2e8, -5.75e8 } };
  s.side[SIDE_RIGHT] = (Problem_side) { BC_TRACTION, 0.3, 0.9, { 1e8, 0 } };
  Status st = { 0, "" };
  Mesh *m = mesh_new(&s, &st);
  double X[17] = { 0 };
  mesh_move(m, X, &st);
  Fem_dofs *d = fem_dofs_new(m, &s, &st);
  double *b = calloc(d->n, sizeof *b), sum[2] = { 0, 0 }, moment = 0;
  fem_load(m, d, &s, b);
  for (int k = 0; k < m->nnodes; k++)
    for (int c = 0; c < 2; c++)
      if (d->unknown[2 * k + c] >= 0) {
        sum[c] += b[d->unknown[2 * k + c]];
        moment += (c ? m->xy[2 * k] : -m->xy[2 * k + 1]) * b[d->unknown[2 * k + c]];
      }
  double want1 = 2e8 * 2.2 + 1e8 * 0.6, want2 = -5.75e8 * 2.2;
  check(fabs(sum[0] - want1) < 1e-6 && fabs(sum[1] - want2) < 1e-6,
        "traction load P of (4.3) sums to P times the loaded length (%.9g, %.9g)", sum[0], sum[1]);
  /* moment about the origin of the exact distributed load */
  double want_m = -5.75e8 * (3.3 * 3.3 - 1.1 * 1.1) / 2 - 2e8 * 1.0 * 2.2
                - 1e8 * (0.9 * 0.9 - 0.3 * 0.3) / 2;
  check(fabs(moment - want_m) < 1e-6 * fabs(want_m),
        "traction load P of (4.3) has the exact first moment (%.9g vs %.9g)", moment, want_m);
  free(b);
  fem_dofs_free(d);
  mesh_free(m);
}

/* the pattern as it was made until issue 14: every element's 6 x 6
   couplings as triplets, sorted and summed by CHOLMOD */
static cholmod_sparse *triplet_pattern(const Mesh *m, const Fem_dofs *d, cholmod_common *cm)
{
  cholmod_triplet *T = cholmod_l_allocate_triplet(d->n, d->n, 36 * (size_t) m->ntri, 0,
                                                CHOLMOD_REAL, cm);
  for (int t = 0; t < m->ntri; t++)
    for (int r = 0; r < 6; r++)
      for (int c = 0; c < 6; c++) {
        int gr = d->unknown[2 * m->tri[3 * t + r / 2] + r % 2];
        int gc = d->unknown[2 * m->tri[3 * t + c / 2] + c % 2];
        if (gr < 0 || gc < 0) continue;
        ((Sparse_index *) T->i)[T->nnz] = gr, ((Sparse_index *) T->j)[T->nnz] = gc;
        ((double *) T->x)[T->nnz++] = 0;
      }
  cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, T->nnz, cm);
  cholmod_l_free_triplet(&T, cm);
  return A;
}

/* fem_stiffness_new's pattern is the triplets', on a free body and with
   clamped, roller and free sides, on several meshes */
static void pattern(int N, int M, int R, Problem_bc_kind left, Problem_bc_kind right, Problem_bc_kind top)
{
  Problem s = free_body(N, M, R, MODEL_PLANE_STRESS);
  Status st = { 0, "" };
  cholmod_common cm;
  test_start(&cm);
  s.side[SIDE_LEFT].kind = left, s.side[SIDE_RIGHT].kind = right, s.side[SIDE_TOP].kind = top;
  Mesh *m = mesh_new(&s, &st);
  Fem_dofs *d = m ? fem_dofs_new(m, &s, &st) : NULL;
  cholmod_sparse *A = d ? fem_stiffness_new(m, d, &cm, &st) : NULL;
  cholmod_sparse *B = d ? triplet_pattern(m, d, &cm) : NULL;
  int same = A && B && A->nrow == B->nrow && A->ncol == B->ncol && A->sorted && A->packed
             && A->stype == 0 && !memcmp(A->p, B->p, (A->ncol + 1) * sizeof(Sparse_index))
             && !memcmp(A->i, B->i, ((Sparse_index *) B->p)[B->ncol] * sizeof(Sparse_index));
  check(same, "N = %d, M = %d, R = %d, sides %d %d %d: the pattern of A (4.3) is the triplets' "
        "(%d unknowns, %d entries)", N, M, R, left, right, top, d ? d->n : -1,
        B ? (int) ((Sparse_index *) B->p)[B->ncol] : -1);
  cholmod_l_free_sparse(&A, &cm), cholmod_l_free_sparse(&B, &cm);
  fem_dofs_free(d), mesh_free(m);
  cholmod_l_finish(&cm);
}

/* node lies on the side o */
static int on_side(const Mesh *m, int node, int o)
{
  return o == SIDE_TOP ? node / m->ncol == m->nrow - 1
                       : node % m->ncol == (o == SIDE_LEFT ? 0 : m->N);
}

/* fem_reactions: for any displacement u (0 where held), the reactions r
   = K u - f at the held DOFs, the residuals A u - b at the unknowns and
   the applied loads (the traction times its loaded length, the body force
   times the area of the body, computed here) sum to zero in each
   component, since K annihilates the translations; and every held DOF's
   reaction goes to a side that holds it, to the one it is normal to at a
   corner held by two, so that a roller takes no tangential force */
static void reactions_balance(Problem_bc_kind left, Problem_bc_kind right, Problem_bc_kind top)
{
  int N = 16;
  Problem s = free_body(N, 2, 3, MODEL_PLANE_STRAIN);
  Problem_side load = { BC_TRACTION, 0, 4, { 1e8, -5.75e8 } }; /* the whole top */
  Problem_side side_load = { BC_TRACTION, 0.3, 0.9, { -2e8, 1e8 } };
  s.side[SIDE_LEFT] = left == BC_TRACTION ? side_load : (Problem_side) { left, 0, 0, { 0, 0 } };
  s.side[SIDE_RIGHT] = right == BC_TRACTION ? side_load : (Problem_side) { right, 0, 0, { 0, 0 } };
  s.side[SIDE_TOP] = top == BC_TRACTION ? load : (Problem_side) { top, 0, 0, { 0, 0 } };
  s.body_force[0] = 3e7, s.body_force[1] = -2e8, s.has_body_force = 1;
  Status st = { 0, "" };
  cholmod_common cm;
  test_start(&cm);
  Mesh *m = mesh_new(&s, &st);
  double X[17], area = 0, want[2], sum[2] = { 0, 0 }, scale;
  design(N, X);
  mesh_move(m, X, &st);
  Fem_dofs *d = fem_dofs_new(m, &s, &st);
  cholmod_sparse *A = fem_stiffness_new(m, d, &cm, &st);
  Fem_hooke H = fem_hooke(&s);
  fem_stiffness_fill(A, m, d, &H, &st);
  double *u = malloc(d->n * sizeof *u), *g = malloc(d->n * sizeof *g),
         *b = malloc(d->n * sizeof *b), *r = malloc(d->ndof * sizeof *r);
  for (int k = 0; k < d->n; k++) u[k] = 1e-3 * sin(0.7 * k + 0.3);
  qp_matvec(A, u, g);
  fem_load(m, d, &s, b);
  fem_reactions(m, d, &H, &s, u, r);
  for (int i = 1; i <= N; i++)            /* gamma (b - a) less the area under alpha */
    area += 0.25 * (X[i] + X[i - 1]) / 2;
  area = 1 * 4 - area;
  for (int c = 0; c < 2; c++) {
    want[c] = s.body_force[c] * area;
    if (top == BC_TRACTION) want[c] += load.P[c] * 4;
    if (left == BC_TRACTION || right == BC_TRACTION) want[c] += side_load.P[c] * 0.6;
  }
  for (int k = 0; k < d->ndof; k++)
    sum[k % 2] += d->unknown[k] < 0 ? r[k] : g[d->unknown[k]] - b[d->unknown[k]];
  scale = hypot(want[0], want[1]);
  check(fabs(sum[0] + want[0]) <= 1e-12 * scale && fabs(sum[1] + want[1]) <= 1e-12 * scale,
        "sides %d %d %d: reactions + residuals + loads = 0 for any u (%.1e, %.1e of the load)",
        left, right, top, fabs(sum[0] + want[0]) / scale, fabs(sum[1] + want[1]) / scale);
  int wrong = 0;
  for (int k = 0; k < d->ndof; k++) {
    int side = fem_reaction_side(m, &s, k), c = k % 2, normal = side == SIDE_TOP;
    if (d->unknown[k] >= 0) { wrong += side != -1; continue; }
    if (side < 0 || s.side[side].kind == BC_FREE || s.side[side].kind == BC_TRACTION
        || (s.side[side].kind == BC_ROLLER && c != normal)) { wrong++; continue; }
    for (int o = 0; o < SIDE_COUNT; o++)    /* a corner held by two: the normal one */
      if (o != side && on_side(m, k / 2, o) && c != normal
          && (s.side[o].kind == BC_CLAMPED || (s.side[o].kind == BC_ROLLER && c == (o == SIDE_TOP))))
        wrong++;
  }
  check(wrong == 0, "sides %d %d %d: each held DOF's reaction goes to a side that holds it, "
        "the normal one at a corner; a roller takes no tangential one (%d wrong)",
        left, right, top, wrong);
  free(u), free(g), free(b), free(r);
  cholmod_l_free_sparse(&A, &cm);
  fem_dofs_free(d), mesh_free(m);
  cholmod_l_finish(&cm);
}

int main(void)
{
  reactions_balance(BC_CLAMPED, BC_ROLLER, BC_TRACTION);
  reactions_balance(BC_ROLLER, BC_TRACTION, BC_CLAMPED);
  reactions_balance(BC_TRACTION, BC_CLAMPED, BC_ROLLER);
  reactions_balance(BC_ROLLER, BC_ROLLER, BC_ROLLER);
  reactions_balance(BC_CLAMPED, BC_CLAMPED, BC_CLAMPED);
  pattern(16, 1, 3, BC_FREE, BC_FREE, BC_FREE);
  pattern(16, 1, 3, BC_CLAMPED, BC_ROLLER, BC_FREE);
  pattern(7, 3, 2, BC_ROLLER, BC_CLAMPED, BC_CLAMPED);
  pattern(64, 4, 12, BC_CLAMPED, BC_ROLLER, BC_ROLLER);
  patch_test(MODEL_PLANE_STRESS);
  patch_test(MODEL_PLANE_STRAIN);
  traction_load();
  return check_done();
}
