/* test_part_physics: the patch test on a part of the user's own (issue
   37's checks).  The body is Example 5.1's strip (a = 0, b = 4, C0prime
   = 0.25, N = 16) under tests/parts/bore.geo, the band up to gamma = 1
   with a circular bore, meshed by gmsh and joined to the strip.  For a
   linear displacement u = G x + c the strain eps = (G11, G22, G12 + G21)
   is constant and so is the stress sigma = D eps; the exact solution of
   the elasticity problem with the tractions sigma n on the whole
   boundary is u, and linear triangles reproduce it exactly.  So the
   program's assembled stiffness (fem_stiffness_fill, every DOF free)
   times u must be, to rounding:
     0 at every node inside the body (on no boundary edge), and
     at a boundary node, the consistent load of the constant traction:
     sum over the boundary edges at the node of sigma n |edge| / 2.
   The boundary edges are found here from the triangles alone (the
   edges of one triangle only, oriented as it is, the body on their
   left), not from the mesh's own lists, and D is computed here from the
   engineering constants: for the orthotropic material, Q in its axes
   rotated by T' Q T, with T the engineering strains' rotation, and
   compared with fem_hooke_of's D first.  Isotropic and orthotropic at
   30 degrees, plane stress and plane strain (isotropic), on a flat and
   on a curved design. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "setup.h"
#include "problem.h"
#include "mesh.h"
#include "fem.h"

static const double PI = 3.14159265358979323846;

static Problem patch_problem(void)
{
  Problem p;
  char cwd[2048];
  memset(&p, 0, sizeof p);
  p.a = 0; p.b = 4; p.gamma = 1; p.N = 16; p.M = 1; p.R = 3;
  p.C0 = 0.05; p.C1 = 0.025; p.C0prime = 0.25;
  p.material.young = 2.15e11; p.material.nu = 0.29;
  p.part.refine = 1;
  snprintf(p.part.geometry, sizeof p.part.geometry, "%s/tests/parts/bore.geo",
           getcwd(cwd, sizeof cwd) ? cwd : ".");
  return p;
}

/* D of the engineering constants: isotropic (plane stress or strain) */
static void isotropic_D(double E, double nu, Problem_plane_model model, double D[3][3])
{
  double En = E, nun = nu;            /* plane strain: E/(1-nu^2), nu/(1-nu) */
  if (model == MODEL_PLANE_STRAIN) En = E / (1 - nu * nu), nun = nu / (1 - nu);
  double f = En / (1 - nun * nun);
  memset(D, 0, 9 * sizeof D[0][0]);
  D[0][0] = D[1][1] = f;
  D[0][1] = D[1][0] = f * nun;
  D[2][2] = En / (2 * (1 + nun));
}

/* orthotropic in plane stress, axis 1 at theta degrees from x1: D = T' Q T */
static void orthotropic_D(const Problem_material *m, double D[3][3])
{
  double nu21 = m->nu12 * m->E2 / m->E1, f = 1 - m->nu12 * nu21;
  double Q[3][3] = { { m->E1 / f, m->nu12 * m->E2 / f, 0 },
                     { m->nu12 * m->E2 / f, m->E2 / f, 0 }, { 0, 0, m->G12 } };
  double c = cos(m->angle * PI / 180), s = sin(m->angle * PI / 180);
  /* material engineering strains = T global ones (e11, e22, g12) */
  double T[3][3] = { { c * c, s * s, c * s }, { s * s, c * c, -c * s },
                     { -2 * c * s, 2 * c * s, c * c - s * s } };
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      D[i][j] = 0;
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) D[i][j] += T[k][i] * Q[k][l] * T[l][j];
    }
}

static double D_difference(double A[3][3], double B[3][3])
{
  double diff = 0, size = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      diff = fmax(diff, fabs(A[i][j] - B[i][j]));
      size = fmax(size, fabs(B[i][j]));
    }
  return diff / size;
}

/* the body's boundary edges from the triangles: an edge (p, q) of a
   triangle, counter-clockwise, whose reverse (q, p) no triangle has */
static int boundary_edges(const Mesh *m, int *edge)
{
  int n = 0;
  for (int t = 0; t < m->ntri; t++)
    for (int k = 0; k < 3; k++) {
      int p = m->tri[3 * t + k], q = m->tri[3 * t + (k + 1) % 3], shared = 0;
      for (int u = 0; u < m->ntri && !shared; u++)
        for (int l = 0; l < 3; l++)
          if (m->tri[3 * u + l] == q && m->tri[3 * u + (l + 1) % 3] == p) shared = 1;
      if (!shared) edge[2 * n] = p, edge[2 * n + 1] = q, n++;
    }
  return n;
}

/* one patch test: the worst residual at inner nodes and at boundary
   nodes, relative to max_k sum_l |K_kl| |u_l| */
static void patch(const char *what, const Mesh *m, const Fem_dofs *d,
                  const Fem_hooke *H, double D[3][3], cholmod_common *cm)
{
  Status st = { 0, "" };
  const double G[2][2] = { { 1.3e-3, -0.7e-3 }, { 0.4e-3, -2.1e-3 } }, c[2] = { 2e-4, -3e-4 };
  cholmod_sparse *A = fem_stiffness_new(m, d, cm, &st);
  if (!check(A && fem_stiffness_fill(A, m, d, H, &st) == STATUS_OK,
             "%s: the stiffness assembled (%s)", what, st.msg)) return;
  cholmod_dense *U = cholmod_l_zeros(d->n, 1, CHOLMOD_REAL, cm);
  cholmod_dense *F = cholmod_l_zeros(d->n, 1, CHOLMOD_REAL, cm);
  cholmod_dense *Ua = cholmod_l_zeros(d->n, 1, CHOLMOD_REAL, cm);
  cholmod_dense *S = cholmod_l_zeros(d->n, 1, CHOLMOD_REAL, cm);
  cholmod_sparse *Aa = cholmod_l_copy(A, 1, 1, cm);
  double *u = U->x, *ua = Ua->x, one[2] = { 1, 0 }, zero[2] = { 0, 0 };
  for (int k = 0; k < m->nnodes; k++)
    for (int i = 0; i < 2; i++) {
      u[2 * k + i] = G[i][0] * m->xy[2 * k] + G[i][1] * m->xy[2 * k + 1] + c[i];
      ua[2 * k + i] = fabs(u[2 * k + i]);
    }
  double *ax = Aa->x;
  for (size_t k = 0; k < Aa->nzmax; k++) ax[k] = fabs(ax[k]);
  cholmod_l_sdmult(A, 0, one, zero, U, F, cm);
  cholmod_l_sdmult(Aa, 0, one, zero, Ua, S, cm);
  double scale = 0, *f = F->x;
  for (int k = 0; k < d->n; k++) scale = fmax(scale, ((double *) S->x)[k]);
  /* the consistent load of sigma n on the boundary */
  double eps[3] = { G[0][0], G[1][1], G[0][1] + G[1][0] }, sig[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) sig[i] += D[i][j] * eps[j];
  double *g = calloc(2 * m->nnodes, sizeof *g);
  int *edge = malloc(6 * m->ntri * sizeof *edge), *on = calloc(m->nnodes, sizeof *on);
  int ne = boundary_edges(m, edge), holes = 0;
  for (int e = 0; e < ne; e++) {
    int p = edge[2 * e], q = edge[2 * e + 1];
    /* the outward normal times the length: the body on the left of p -> q */
    double n1 = m->xy[2 * q + 1] - m->xy[2 * p + 1], n2 = -(m->xy[2 * q] - m->xy[2 * p]);
    double t1 = sig[0] * n1 + sig[2] * n2, t2 = sig[2] * n1 + sig[1] * n2;
    g[2 * p] += t1 / 2, g[2 * p + 1] += t2 / 2, g[2 * q] += t1 / 2, g[2 * q + 1] += t2 / 2;
    on[p] = on[q] = 1;
    double x = 0.5 * (m->xy[2 * p] + m->xy[2 * q]), y = 0.5 * (m->xy[2 * p + 1] + m->xy[2 * q + 1]);
    holes += hypot(x - 2, y - 0.625) < 0.21;
  }
  double inner = 0, outer = 0;
  int ninner = 0;
  for (int k = 0; k < m->nnodes; k++)
    for (int i = 0; i < 2; i++) {
      double r = fabs(f[2 * k + i] - g[2 * k + i]) / scale;
      if (on[k]) outer = fmax(outer, r);
      else inner = fmax(inner, r), ninner += i == 0;
    }
  check(holes > 8, "%s: the bore's edges are on the boundary (%d of %d edges)", what, holes, ne);
  check(inner <= 1e-12, "%s: K u = 0 at the %d inner nodes, %.1e of max |K||u| <= 1e-12",
        what, ninner, inner);
  check(outer <= 1e-12, "%s: K u = the load of sigma n at the %d boundary nodes, %.1e <= 1e-12",
        what, m->nnodes - ninner, outer);
  free(g), free(edge), free(on);
  cholmod_l_free_dense(&U, cm), cholmod_l_free_dense(&F, cm);
  cholmod_l_free_dense(&Ua, cm), cholmod_l_free_dense(&S, cm);
  cholmod_l_free_sparse(&A, cm), cholmod_l_free_sparse(&Aa, cm);
}

/* the design: flat at 0.02, or the arc of Example 5.1 */
static void design(const Problem *p, int curved, double *X)
{
  for (int i = 0; i <= p->N; i++) {
    double x = problem_node_x(p, i), R = 160.025;
    X[i] = curved ? R - sqrt(R * R - (x - 4) * (x - 4)) : 0.02;
  }
}

static void material_cases(Problem *p, int curved, cholmod_common *cm)
{
  Status st = { 0, "" };
  Mesh *m = mesh_new(p, &st);
  if (!check(m != NULL, "bore.geo meshed (%s)", st.msg)) return;
  double *X = malloc((p->N + 1) * sizeof *X);
  design(p, curved, X);
  if (!check(mesh_move(m, X, &st) == STATUS_OK, "mesh moved (%s)", st.msg)) return;
  Fem_dofs *d = fem_dofs_new(m, p, &st);
  check(d && d->n == d->ndof, "no side holds anything: every DOF an unknown");
  Problem_material iso = p->material, ort = iso;
  ort.kind = MATERIAL_ORTHOTROPIC;
  ort.E1 = 1.4e11, ort.E2 = 1e10, ort.nu12 = 0.3, ort.G12 = 5e9, ort.angle = 30;
  ort.E3 = 1e10, ort.nu13 = 0.3, ort.nu23 = 0.4;
  Fem_hooke H[PROBLEM_NAMED + 1];
  double D[3][3];
  const char *shape = curved ? "curved" : "flat";
  char what[128];
  for (int model = 0; model < 2; model++) {
    Fem_hooke h = fem_hooke_of(&iso, model);
    isotropic_D(iso.young, iso.nu, model, D);
    check(D_difference(h.D, D) <= 1e-14, "isotropic %s: D from E, nu", problem_model_name(model));
    for (int s = 0; s <= PROBLEM_NAMED; s++) H[s] = h;
    snprintf(what, sizeof what, "isotropic %s, %s", problem_model_name(model), shape);
    patch(what, m, d, H, D, cm);
  }
  Fem_hooke h = fem_hooke_of(&ort, MODEL_PLANE_STRESS);
  orthotropic_D(&ort, D);
  check(D_difference(h.D, D) <= 1e-13, "orthotropic at 30 degrees: D = T' Q T, %.1e",
        D_difference(h.D, D));
  for (int s = 0; s <= PROBLEM_NAMED; s++) H[s] = h;
  snprintf(what, sizeof what, "orthotropic at 30 degrees, plane stress, %s", shape);
  patch(what, m, d, H, D, cm);
  /* plane strain: the patch test with the program's own D (the
     reduction by E3, nu13, nu23 is checked in test_fem) */
  h = fem_hooke_of(&ort, MODEL_PLANE_STRAIN);
  for (int s = 0; s <= PROBLEM_NAMED; s++) H[s] = h;
  snprintf(what, sizeof what, "orthotropic at 30 degrees, plane strain, %s", shape);
  patch(what, m, d, H, h.D, cm);
  fem_dofs_free(d);
  free(X);
  mesh_free(m);
}

int main(void)
{
  cholmod_common cm;
  test_start(&cm);
  Problem p = patch_problem();
  material_cases(&p, 0, &cm);
  material_cases(&p, 1, &cm);
  cholmod_l_finish(&cm);
  return check_done();
}
