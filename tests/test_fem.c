/* test_fem: the P1 elasticity operator (paper/fem.nw), the matrix A of (4.3).
   Patch test: a linear displacement field has constant stress, so the
   assembled operator applied to it vanishes at interior nodes and equals
   the consistent nodal forces of the boundary tractions sigma.n elsewhere;
   rigid motions have zero stiffness; the pattern of A is that of 36
   triplets per element summed by CHOLMOD, entry for entry; the reactions
   of the held sides balance the loads and the residual for any u.
   Hooke's law of an isotropic or a turned orthotropic material against
   the theory (the isotropic limit, the quarter and half turns, the
   rotated compliance, the 3D compliance), D symmetric and positive
   definite, every refusal of a material provoked, and the patch test
   with a turned orthotropic material.  The mesh itself: test_mesh.c. */
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
                          const char *name)
{
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

/* the patch test of A, in a plane model, with the free body's isotropic
   material or with material */
static void patch_test(Problem_plane_model model, const Problem_material *material)
{
  int N = 16, M = 2, R = 3;
  Problem s = free_body(N, M, R, model);
  char name[64];
  snprintf(name, sizeof name, "%s%s", model == MODEL_PLANE_STRAIN ? "plane strain" : "plane stress",
           material ? ", a turned orthotropic material" : "");
  if (material) s.material = *material;
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
  check(err <= 1e-12 * scale, "%s: patch test of A (4.3): |A u_lin - f_boundary| / |f| = %.2e",
        name, err / scale);
  for (int mode = 0; mode < 3; mode++) {         /* two translations, a rotation */
    for (int k = 0; k < m->nnodes; k++) {
      double x = m->xy[2 * k], y = m->xy[2 * k + 1];
      u[2 * k] = mode == 0 ? 1 : mode == 1 ? 0 : -y;
      u[2 * k + 1] = mode == 0 ? 0 : mode == 1 ? 1 : x;
    }
    qp_matvec(A, u, r);
    double amax = 0;
    for (Sparse_index p = 0; p < ((Sparse_index *) A->p)[A->ncol]; p++) amax = fmax(amax, fabs(((double *) A->x)[p]));
    check(norm_inf(r, d->n) <= 1e-12 * amax * 4, "%s: rigid motion %d has zero stiffness in A (4.3) (%.2e)",
          name, mode, norm_inf(r, d->n) / amax);
  }
  energy_checks(m, d, &H, A, grad, name);
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

/* ---- Hooke's law of a material (fem_hooke_of) and its admission
   (fem_material_refusal), against the theory of orthotropic elasticity:
   Jones, Mechanics of Composite Materials (1999), Sections 2.3 to 2.6 */

static Problem_material orthotropic(double E1, double E2, double nu12, double G12,
                                    double E3, double nu13, double nu23, double angle)
{
  Problem_material m;
  memset(&m, 0, sizeof m);
  m.kind = MATERIAL_ORTHOTROPIC;
  m.E1 = E1, m.E2 = E2, m.nu12 = nu12, m.G12 = G12;
  m.E3 = E3, m.nu13 = nu13, m.nu23 = nu23, m.angle = angle;
  return m;
}

/* a carbon-epoxy-like lamina: stiff along 1, E3 near E2 */
static Problem_material lamina(double angle)
{
  return orthotropic(1.4e11, 1.0e10, 0.3, 5e9, 1.2e10, 0.28, 0.45, angle);
}

static const char *model_name(Problem_plane_model model)
{
  return model == MODEL_PLANE_STRAIN ? "plane strain" : "plane stress";
}

/* max |A - B| over D and D33, relative to max |B.D| */
static double hooke_diff(const Fem_hooke *A, const Fem_hooke *B)
{
  double d = 0, scale = 0;
  for (int r = 0; r < 3; r++) {
    for (int c = 0; c < 3; c++) {
      d = fmax(d, fabs(A->D[r][c] - B->D[r][c]));
      scale = fmax(scale, fabs(B->D[r][c]));
    }
    d = fmax(d, fabs(A->D33[r] - B->D33[r]));
  }
  return d / scale;
}

/* X = the inverse of the symmetric 3 x 3 matrix A, by cofactors */
static void inverse3(const double A[3][3], double X[3][3])
{
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      X[r][c] = A[r1][c1] * A[r2][c2] - A[r1][c2] * A[r2][c1];
    }
  double det = A[0][0] * X[0][0] + A[0][1] * X[1][0] + A[0][2] * X[2][0];
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) X[r][c] /= det;
}

/* (a) equal constants, G12 = E/(2(1+nu)), E3 = E, nu13 = nu23 = nu: the
   isotropic law, at any angle, in both models */
static void hooke_isotropic_limit(Problem_plane_model model)
{
  double E = 2.15e11, nu = 0.29, angles[] = { 0, 17, 45, 90, 133.7, -200, 1234.5 }, worst = 0;
  Problem_material iso = { .kind = MATERIAL_ISOTROPIC, .young = E, .nu = nu };
  Fem_hooke H0 = fem_hooke_of(&iso, model);
  for (int k = 0; k < 7; k++) {
    Problem_material m = orthotropic(E, E, nu, E / (2 * (1 + nu)), E, nu, nu, angles[k]);
    Fem_hooke H = fem_hooke_of(&m, model);
    worst = fmax(worst, hooke_diff(&H, &H0));
  }
  check(worst <= 1e-14, "%s: an orthotropic material with isotropic constants has the "
        "isotropic D and D33 at 7 angles (rel. %.1e)", model_name(model), worst);
}

/* (b) axes turned by 90 degrees: the material with 1 and 2 swapped,
   nu12 -> nu21 = nu12 E2/E1, nu13 <-> nu23; also at 90 + 30 against the
   swapped one at 30 */
static void hooke_quarter_turn(Problem_plane_model model)
{
  Problem_material m = lamina(0);
  Problem_material w = orthotropic(m.E2, m.E1, m.nu12 * m.E2 / m.E1, m.G12,
                                   m.E3, m.nu23, m.nu13, 0);
  double worst = 0, base[] = { 0, 30, -71.3 };
  for (int k = 0; k < 3; k++) {
    m.angle = base[k] + 90, w.angle = base[k];
    Fem_hooke A = fem_hooke_of(&m, model), B = fem_hooke_of(&w, model);
    worst = fmax(worst, hooke_diff(&A, &B));
  }
  check(worst <= 1e-14, "%s: axes turned by 90 degrees are the swapped material "
        "(E1 <-> E2, nu21, nu13 <-> nu23), at 3 angles (rel. %.1e)",
        model_name(model), worst);
}

/* (c) half a turn changes nothing; the compliance D^-1 at an angle is the
   rotated compliance of the theory (Jones, Section 2.6), with S the plane
   model's compliance in the material's axes (in plane strain the
   condensed S'_ij = S_ij - S_i3 S_3j / S_33, written out in the
   engineering constants) */
static void hooke_rotated_compliance(Problem_plane_model model)
{
  Problem_material m = lamina(0);
  double nu21 = m.nu12 * m.E2 / m.E1, nu31 = m.nu13 * m.E3 / m.E1, nu32 = m.nu23 * m.E3 / m.E2;
  int strain = model == MODEL_PLANE_STRAIN;
  double S11 = strain ? (1 - m.nu13 * nu31) / m.E1 : 1 / m.E1;
  double S22 = strain ? (1 - m.nu23 * nu32) / m.E2 : 1 / m.E2;
  double S12 = strain ? -(m.nu12 + m.nu13 * nu32) / m.E1 : -m.nu12 / m.E1;
  double S66 = 1 / m.G12, half = 0, worst = 0, ex = 0;
  (void) nu21;
  double angles[] = { 0, 10, 30, 45, 60, 90, 120, 165, -37 };
  for (int k = 0; k < 9; k++) {
    double t = angles[k] * acos(-1.0) / 180, c = cos(t), s = sin(t), X[3][3];
    double c2 = c * c, s2 = s * s;
    m.angle = angles[k];
    Fem_hooke H = fem_hooke_of(&m, model);
    m.angle = angles[k] + 180;
    Fem_hooke H2 = fem_hooke_of(&m, model);
    half = fmax(half, hooke_diff(&H2, &H));
    inverse3((const double (*)[3]) H.D, X);
    double want[3][3];
    want[0][0] = S11 * c2 * c2 + (2 * S12 + S66) * s2 * c2 + S22 * s2 * s2;
    want[1][1] = S11 * s2 * s2 + (2 * S12 + S66) * s2 * c2 + S22 * c2 * c2;
    want[0][1] = S12 * (s2 * s2 + c2 * c2) + (S11 + S22 - S66) * s2 * c2;
    want[2][2] = 2 * (2 * S11 + 2 * S22 - 4 * S12 - S66) * s2 * c2 + S66 * (s2 * s2 + c2 * c2);
    want[0][2] = (2 * S11 - 2 * S12 - S66) * s * c2 * c - (2 * S22 - 2 * S12 - S66) * s2 * s * c;
    want[1][2] = (2 * S11 - 2 * S12 - S66) * s2 * s * c - (2 * S22 - 2 * S12 - S66) * s * c2 * c;
    double scale = fmax(S66, fmax(S11, S22));
    for (int r = 0; r < 3; r++)
      for (int q = r; q < 3; q++) worst = fmax(worst, fabs(X[r][q] - want[r][q]) / scale);
    ex = fmax(ex, fabs(X[0][0] - want[0][0]) / want[0][0]);
  }
  check(half <= 1e-14, "%s: axes turned by 180 degrees give the same D at 9 angles (rel. %.1e)",
        model_name(model), half);
  check(ex <= 1e-14, "%s: 1/E_x(theta) = cos^4 S11 + (2 S12 + 1/G12) sin^2 cos^2 + sin^4 S22 "
        "from D^-1 at 9 angles (rel. %.1e)", model_name(model), ex);
  check(worst <= 1e-14, "%s: D^-1 is the rotated compliance of Jones, Section 2.6, all six entries, "
        "at 9 angles (rel. %.1e of its largest)", model_name(model), worst);
}

/* the stress of D (and D33) at the strain e, turned into the material's
   axes n = (c, s), t = (-s, c) as a tensor, put through the
   three-dimensional compliance S of the engineering constants, gives
   back the strain turned the same way, with e33 = 0 in plane strain
   (in plane stress s33 = 0 and e33 is free); it also fixes the sense of
   the angle (counter-clockwise from x1 to axis 1). Returns the largest
   error relative to the strain. */
static double hooke_strain_back(const Problem_material *law, const Problem_material *m,
                                Problem_plane_model model, const double e[3])
{
  Fem_hooke H = fem_hooke_of(law, model);
  double sg[3], s33 = 0, t = m->angle * acos(-1.0) / 180, n[2] = { cos(t), sin(t) },
         q[2] = { -sin(t), cos(t) };
  for (int r = 0; r < 3; r++) {
    sg[r] = H.D[r][0] * e[0] + H.D[r][1] * e[1] + H.D[r][2] * e[2];
    s33 += H.D33[r] * e[r];
  }
  double sig[2][2] = { { sg[0], sg[2] }, { sg[2], sg[1] } };
  double eps[2][2] = { { e[0], e[2] / 2 }, { e[2] / 2, e[1] } };
  double s11 = 0, s22 = 0, s12 = 0, e11 = 0, e22 = 0, e12 = 0;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) {
      s11 += n[i] * sig[i][j] * n[j], s22 += q[i] * sig[i][j] * q[j], s12 += n[i] * sig[i][j] * q[j];
      e11 += n[i] * eps[i][j] * n[j], e22 += q[i] * eps[i][j] * q[j], e12 += n[i] * eps[i][j] * q[j];
    }
  double f11 = s11 / m->E1 - m->nu12 * s22 / m->E1 - m->nu13 * s33 / m->E1;
  double f22 = -m->nu12 * s11 / m->E1 + s22 / m->E2 - m->nu23 * s33 / m->E2;
  double f33 = -m->nu13 * s11 / m->E1 - m->nu23 * s22 / m->E2 + s33 / m->E3;
  double f12 = s12 / m->G12, scale = fmax(fabs(e[0]), fmax(fabs(e[1]), fabs(e[2])));
  double err = fmax(fabs(f11 - e11), fmax(fabs(f22 - e22), fabs(f12 - 2 * e12)));
  if (model == MODEL_PLANE_STRAIN) err = fmax(err, fabs(f33));
  else err = fmax(err, fabs(s33));
  return err / scale;
}

static void hooke_three_dimensional(Problem_plane_model model)
{
  double e[3] = { 1e-3, -4e-4, 7e-4 }, worst = 0, angles[] = { 0, 25, -60, 90, 200 };
  for (int k = 0; k < 5; k++) {
    Problem_material m = lamina(angles[k]);
    worst = fmax(worst, hooke_strain_back(&m, &m, model, e));
  }
  check(worst <= 1e-13, "%s: the 3D compliance of the engineering constants turns the stress "
        "(D e, s33 = D33 e) back into the strain turned to the material's axes, "
        "e33 = 0 in plane strain, at 5 angles (rel. %.1e)", model_name(model), worst);
  Problem_material iso = { .kind = MATERIAL_ISOTROPIC, .young = 2.15e11, .nu = 0.29 };
  Problem_material same = orthotropic(2.15e11, 2.15e11, 0.29, 2.15e11 / (2 * (1 + 0.29)),
                                      2.15e11, 0.29, 0.29, 0);
  double err = hooke_strain_back(&iso, &same, model, e);
  check(err <= 1e-13, "%s: the same for the isotropic law (s33 = nu (s11 + s22) in plane "
        "strain, 0 in plane stress) (rel. %.1e)", model_name(model), err);
}

/* (d) D symmetric to the bit and positive definite (leading minors), for
   admitted materials at several angles */
static void hooke_definite(Problem_plane_model model)
{
  Problem_material ms[4] = { lamina(0), lamina(33), orthotropic(3e9, 9e9, -0.4, 1e9, 2e9, 0.1, 0.6, -120),
                             orthotropic(1e10, 1e10, 0.49, 1e8, 1e10, 0.49, 0.49, 45) };
  int symmetric = 1, definite = 1, across = 1;
  char buf[256];
  for (int k = 0; k < 4; k++) {
    check(fem_material_refusal(&ms[k], model, buf, sizeof buf) == NULL,
          "%s: orthotropic material %d is admitted", model_name(model), k);
    Fem_hooke H = fem_hooke_of(&ms[k], model);
    double (*D)[3] = H.D;
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) symmetric &= memcmp(&D[r][c], &D[c][r], sizeof(double)) == 0;
    long double m2 = (long double) D[0][0] * D[1][1] - (long double) D[0][1] * D[1][0];
    long double m3 = D[0][0] * ((long double) D[1][1] * D[2][2] - (long double) D[1][2] * D[2][1])
                   - D[0][1] * ((long double) D[1][0] * D[2][2] - (long double) D[1][2] * D[2][0])
                   + D[0][2] * ((long double) D[1][0] * D[2][1] - (long double) D[1][1] * D[2][0]);
    definite &= D[0][0] > 0 && m2 > 0 && m3 > 0;
    for (int r = 0; r < 3 && model == MODEL_PLANE_STRESS; r++)   /* +0, to the bit */
      across &= memcmp(&H.D33[r], &(double) { 0 }, sizeof(double)) == 0;
  }
  if (model == MODEL_PLANE_STRESS)
    check(across, "plane stress: D33 is +0 (4 materials)");
  check(symmetric, "%s: D is symmetric to the bit (4 materials)", model_name(model));
  check(definite, "%s: D is positive definite, its leading minors > 0 (4 materials)",
        model_name(model));
}

/* (e) every reason of fem_material_refusal, provoked */
static void refusal(Problem_material m, Problem_plane_model model, const char *want)
{
  char buf[256];
  memset(buf, 'x', sizeof buf);
  const char *why = fem_material_refusal(&m, model, buf, sizeof buf);
  if (!want) {
    check(why == NULL, "%s: admitted (%s)", model_name(model), why ? why : "");
    return;
  }
  check(why == buf && strstr(buf, want) && !strchr(buf, '\n'),
        "%s: refused with '%s' (%s)", model_name(model), want, why ? why : "admitted");
}

static void material_refusals(void)
{
  Problem_plane_model ps = MODEL_PLANE_STRESS, pe = MODEL_PLANE_STRAIN;
  Problem_material iso = { .kind = MATERIAL_ISOTROPIC, .young = 2.15e11, .nu = 0.29 }, m;
  refusal(iso, ps, NULL), refusal(iso, pe, NULL);
  m = iso, m.young = 0, refusal(m, ps, "Young's modulus must be > 0");
  m = iso, m.young = NAN, refusal(m, pe, "Young's modulus must be > 0");
  m = iso, m.young = 1e31, refusal(m, ps, "Young's modulus must lie in [1e-30, 1e30]");
  m = iso, m.nu = 0.5, refusal(m, ps, "nu must be < 0.5: 0.5 is the incompressible limit");
  m = iso, m.nu = -1, refusal(m, pe, "nu must be > -1 (stability)");
  refusal(lamina(30), ps, NULL), refusal(lamina(30), pe, NULL);
  m = lamina(30), m.E1 = NAN, refusal(m, ps, "E1 must be finite");
  m = lamina(30), m.angle = INFINITY, refusal(m, ps, "angle must be finite");
  m = lamina(30), m.E2 = -1e9, refusal(m, pe, "E2 must be > 0");
  m = lamina(30), m.G12 = 0, refusal(m, ps, "G12 must be > 0");
  m = lamina(30), m.G12 = 2e30, refusal(m, ps, "G12 must lie in [1e-30, 1e30]");
  m = lamina(30), m.E1 = 1e-31, refusal(m, pe, "E1 must lie in [1e-30, 1e30]");
  m = lamina(30), m.E3 = 0, refusal(m, pe, "E3 must be > 0"), refusal(m, ps, NULL);
  m = lamina(30), m.nu13 = NAN, refusal(m, pe, "nu13 must be finite"), refusal(m, ps, NULL);
  m = lamina(30), m.nu12 = 1.01 * sqrt(m.E1 / m.E2);
  refusal(m, ps, "nu12 must satisfy |nu12| < sqrt(E1/E2)"), refusal(m, pe, "nu12 must satisfy");
  m = lamina(30), m.nu12 = 0.99 * sqrt(m.E1 / m.E2), refusal(m, ps, NULL);
  m = lamina(30), m.nu13 = -1.01 * sqrt(m.E1 / m.E3), refusal(m, pe, "nu13 must satisfy |nu13| < sqrt(E1/E3)");
  m = lamina(30), m.nu23 = 1.01 * sqrt(m.E2 / m.E3), refusal(m, pe, "nu23 must satisfy |nu23| < sqrt(E2/E3)");
  refusal(m, ps, NULL);
  m = orthotropic(1e10, 1e10, 0.6, 3e9, 1e10, 0.6, 0.6, 0);   /* each pair < 1, Delta < 0 */
  refusal(m, pe, "the Poisson ratios must satisfy 1 - nu12 nu21"), refusal(m, ps, NULL);
  m = orthotropic(1e10, 1e10, -0.9, 3e9, 1e10, -0.9, -0.9, 0);  /* Delta = 0.028 */
  refusal(m, pe, NULL);
  /* Delta = 0 in exact arithmetic (1 - 0.0045 - 0.0045 - 0.982081 - 0.008919),
     1.2e-16 once rounded: the conditions pass, the rounded D is not definite */
  m = orthotropic(2e11, 1e10, 0.3, 5e9, 1e10, 0.3, 0.991, 0);
  refusal(m, pe, "the material is too near the limit of ellipticity"), refusal(m, ps, NULL);
}

/* (f) the patch test with a turned orthotropic material */
static void material_patch_tests(void)
{
  Problem_material m = lamina(30);
  patch_test(MODEL_PLANE_STRESS, &m);
  patch_test(MODEL_PLANE_STRAIN, &m);
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
  patch_test(MODEL_PLANE_STRESS, NULL);
  patch_test(MODEL_PLANE_STRAIN, NULL);
  traction_load();
  for (Problem_plane_model model = MODEL_PLANE_STRESS; model <= MODEL_PLANE_STRAIN; model++) {
    hooke_isotropic_limit(model);
    hooke_quarter_turn(model);
    hooke_rotated_compliance(model);
    hooke_three_dimensional(model);
    hooke_definite(model);
  }
  material_refusals();
  material_patch_tests();
  return check_done();
}
