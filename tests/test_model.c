/* test_model.c: the model (paper/model.nw).  First the energy E of two
   solvers' states, equal to rounding, the same to 1e-15 (from
   test_hard.c).  Then the stiffness of the body seen from its contact nodes,
   S = A_cc - A_ci A_ii^-1 A_ic (model_contact_stiffness, from the trailing
   block of a CAMD-ordered Cholesky factor), against the same Schur
   complement formed independently: A as a dense matrix, A_ii factorised by
   GSL, n_c dense solves.  The contact diagonals carry the documented shift
   of 1e-6 of themselves in both.  Also: S is positive definite,
   and for a body that only the foundation holds (the flat punch) S without
   the shift annihilates the vertical rigid motion, which the shift makes
   invertible.  Last, the measurement behind the Newton method's model
   (paper/newton.nw, "Where E is curved"): at the optimum of Example 5.1 the
   Hessian of E, by central differences of the gradient (4.8), against S:
   their generalised eigenvalues lie near 1 on the nodes in contact and
   near 0 (|lambda| < 1e-3) on the others. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "setup.h"
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_sort_vector.h>
#include "scene.h"
#include "model.h"
#include "grad.h"
#include "design.h"
#include "opt.h"
#include "weakly_active.h"

/* the dense Schur complement of A onto the contact unknowns, ordered by
   contact number c, the contact diagonals multiplied by 1 + shift */
static gsl_matrix *dense_schur(const Model *md, double shift)
{
  const Dofs *d = md->dofs;
  int n = d->n, nc = d->nc, ni = n - nc, *is_c = calloc(n, sizeof *is_c), *pos = malloc(n * sizeof *pos);
  gsl_matrix *A = gsl_matrix_calloc(n, n);
  const int *Ap = md->A->p, *Ai = md->A->i;
  const double *Ax = md->A->x;
  for (int j = 0; j < n; j++)
    for (int k = Ap[j]; k < Ap[j + 1]; k++) gsl_matrix_set(A, Ai[k], j, Ax[k]);
  for (int c = 0; c < nc; c++) {
    int j = d->contact[c];
    is_c[j] = 1, pos[j] = c;
    gsl_matrix_set(A, j, j, gsl_matrix_get(A, j, j) * (1 + shift));
  }
  for (int j = 0, i = 0; j < n; j++) if (!is_c[j]) pos[j] = i++;
  gsl_matrix *Aii = gsl_matrix_alloc(ni, ni), *Aic = gsl_matrix_alloc(ni, nc), *S = gsl_matrix_alloc(nc, nc);
  for (int r = 0; r < n; r++)
    for (int s = 0; s < n; s++) {
      double v = gsl_matrix_get(A, r, s);
      if (!is_c[r] && !is_c[s]) gsl_matrix_set(Aii, pos[r], pos[s], v);
      else if (!is_c[r]) gsl_matrix_set(Aic, pos[r], pos[s], v);
      else if (is_c[s]) gsl_matrix_set(S, pos[r], pos[s], v);
    }
  gsl_linalg_cholesky_decomp1(Aii);
  gsl_vector *x = gsl_vector_alloc(ni);
  for (int c = 0; c < nc; c++) {                 /* S -= A_ci (A_ii^-1 A_ic) */
    gsl_vector_view col = gsl_matrix_column(Aic, c);
    gsl_linalg_cholesky_solve(Aii, &col.vector, x);
    for (int r = 0; r < nc; r++) {
      double s = 0;
      for (int k = 0; k < ni; k++) s += gsl_matrix_get(Aic, k, r) * gsl_vector_get(x, k);
      gsl_matrix_set(S, r, c, gsl_matrix_get(S, r, c) - s);
    }
  }
  gsl_vector_free(x); gsl_matrix_free(Aii); gsl_matrix_free(Aic); gsl_matrix_free(A);
  free(is_c); free(pos);
  return S;
}

/* S by model_contact_stiffness after a solve by the given state solver:
   pdas hands over its own S, the others have it condensed apart */
static void compare(const char *path, int N, Qp_method state)
{
  Scene s;
  Status st;
  cholmod_common cm;
  test_start(&cm);
  if (!check(load_refined(&s, path, N / 16, &st) == 0, "load %s", path)) return;
  s.solver = qp_options_default(state);
  Model *md = model_new(&s.problem, &s.solver, &cm, &st);
  int n1 = N + 1, nc = md->dofs->nc;
  double *S = malloc((size_t) n1 * n1 * sizeof *S), err = 0, scale = 0;
  const char *sn = qp_method_name(state);
  check(model_solve(md, s.alpha0, &st) == 0, "%s N = %d %s: solve", path, N, sn);
  int rc = model_contact_stiffness(md, S, &st);
  check(rc == 0, "%s N = %d %s: model_contact_stiffness (%s)", path, N, sn, rc ? st.msg : "ok");
  gsl_matrix *ref = dense_schur(md, 1e-6);
  for (int c = 0; c < nc; c++)
    for (int e = 0; e < nc; e++) {
      double v = S[(size_t) md->dofs->contact_col[c] * n1 + md->dofs->contact_col[e]];
      err = fmax(err, fabs(v - gsl_matrix_get(ref, c, e)));
      scale = fmax(scale, fabs(gsl_matrix_get(ref, c, e)));
    }
  check(err <= 1e-13 * scale, "%s N = %d %s: S agrees with the dense Schur complement "
        "(%d contact unknowns; largest difference %.1e of max |S|)", path, N, sn, nc, err / scale);
  gsl_matrix_view Sv = gsl_matrix_view_array(S, n1, n1);
  check(gsl_linalg_cholesky_decomp1(&Sv.matrix) == 0, "%s N = %d %s: S is positive definite", path, N, sn);
  gsl_matrix_free(ref);
  free(S);
  model_free(md);
  scene_free(&s);
  cholmod_finish(&cm);
}

/* the flat punch: no shift, S times the vertical rigid motion is zero */
static void floating(void)
{
  Scene s;
  Status st;
  cholmod_common cm;
  test_start(&cm);
  if (!check(scene_load(&s, "tests/scenes/flat-punch.scene", 0, NULL, &st) == 0, "load flat punch")) return;
  Model *md = model_new(&s.problem, &s.solver, &cm, &st);
  model_solve(md, s.alpha0, &st);
  gsl_matrix *S = dense_schur(md, 0);
  int nc = md->dofs->nc;
  double rigid = 0, scale = 0;
  for (int r = 0; r < nc; r++) {
    double sum = 0;
    for (int c = 0; c < nc; c++) sum += gsl_matrix_get(S, r, c);
    rigid = fmax(rigid, fabs(sum));
    scale = fmax(scale, gsl_matrix_get(S, r, r));
  }
  check(rigid <= 1e-10 * scale, "flat punch: without the shift S annihilates the vertical "
        "rigid motion (|S 1| = %.1e of max S_ii): the shift is needed", rigid / scale);
  gsl_matrix_free(S);
  model_free(md);
  scene_free(&s);
  cholmod_finish(&cm);
}

/* the Hessian of E at X by differences of the gradient (4.8), step
   eps C0: central, or forward where X_j - eps C0 < 0; symmetrised */
static int fd_hessian(Model *md, double *X, int n, double step, double *H)
{
  double *Gp = malloc(2 * n * sizeof *Gp), *Gm = Gp + n;
  Status st;
  int rc = 0;
  for (int j = 0; !rc && j < n; j++) {
    double x0 = X[j], lo = x0 - step >= 0 ? x0 - step : x0;
    X[j] = x0 + step;
    rc = model_solve(md, X, &st) || grad_energy(md, Gp, &st);
    X[j] = lo;
    rc = rc || model_solve(md, X, &st) || grad_energy(md, Gm, &st);
    X[j] = x0;
    for (int i = 0; i < n; i++) H[(size_t) i * n + j] = (Gp[i] - Gm[i]) / (x0 + step - lo);
  }
  for (int i = 0; i < n; i++)
    for (int j = 0; j < i; j++)
      H[(size_t) i * n + j] = H[(size_t) j * n + i] =
        0.5 * (H[(size_t) i * n + j] + H[(size_t) j * n + i]);
  free(Gp);
  return rc;
}

static void curvature(void)
{
  Scene s;
  Status st;
  cholmod_common cm;
  Opt_report r;
  test_start(&cm);
  if (!check(scene_load(&s, "data/example-5.1.scene", 0, NULL, &st) == 0, "load 5.1")) return;
  int n = s.problem.N + 1, active = 0, near1 = 0, near0 = 0;
  Model *md = model_new(&s.problem, &s.solver, &cm, &st);
  Design_set B = design_set(&s.problem);
  double *X = malloc(n * sizeof *X), *H = malloc((size_t) n * n * sizeof *H),
         *S = malloc((size_t) n * n * sizeof *S), lo1 = HUGE_VAL, hi1 = 0, hi0 = 0;
  int ok = !design_project(&B, s.alpha0, X, NULL, &st)
           && !opt_minimize(md, &B, &s.optimizer, X, NULL, NULL, &r, &st)
           && !model_solve(md, X, &st) && !model_contact_stiffness(md, S, &st);
  for (int c = 0; ok && c < md->dofs->nc; c++)
    active += md->Q[md->dofs->contact[c]] <= md->lo[c] && md->T[c] > 0;
  ok = ok && !fd_hessian(md, X, n, 1e-7 * s.problem.C0, H);
  if (check(ok, "5.1: optimum, S and the difference Hessian of (4.8) (%d nodes in contact)", active)) {
    gsl_matrix_view Hv = gsl_matrix_view_array(H, n, n), Sv = gsl_matrix_view_array(S, n, n);
    gsl_vector *ev = gsl_vector_alloc(n);
    gsl_eigen_gensymm_workspace *w = gsl_eigen_gensymm_alloc(n);
    gsl_eigen_gensymm(&Hv.matrix, &Sv.matrix, ev, w);
    for (int i = 0; i < n; i++) {
      double l = gsl_vector_get(ev, i);
      if (fabs(l) < 1e-3) near0++, hi0 = fmax(hi0, fabs(l));
      else if (l > 0.8 && l < 1.1) near1++, lo1 = fmin(lo1, l), hi1 = fmax(hi1, l);
    }
    check(near1 == active && near0 == n - active, "5.1: %d generalised eigenvalues of "
          "(Hessian, S) in [%.2f, %.2f] (as many as nodes in contact), %d below %.1e",
          near1, lo1, hi1, near0, hi0);
    gsl_eigen_gensymm_free(w), gsl_vector_free(ev);
  }
  free(X), free(H), free(S);
  model_free(md);
  scene_free(&s);
  cholmod_finish(&cm);
}

/* The energy is evaluated accurately enough that two solvers' states,
   equal to rounding, give the same E to 1e-15: as 1/2 Q'AQ - b'Q in double
   the quadratic form loses about three digits to cancellation and the
   rounding of A (1.4e-14 apart here, 7e-14 at N = 256). */
static void energy_agreement(const char *path, int N)
{
  Scene s;
  Status st;
  cholmod_common cm;
  test_start(&cm);
  if (!check(load_refined(&s, path, N / 16, &st) == 0, "load %s at N = %d", path, N)) return;
  s.solver.tol = 1e-12;
  Model *a = solve_cold(&s, QP_PDAS, s.alpha0, &cm, &st);
  Model *b = a ? solve_cold(&s, QP_CGSSOR, s.alpha0, &cm, &st) : NULL;
  if (check(a && b, "%s N = %d: pdas and cgssor converge to kkt 1e-12%s%s", path,
            N, a && b ? "" : ": ", a && b ? "" : st.msg)) {
    double rel = fabs(a->energy - b->energy) / fabs(a->energy);
    check(rel <= 1e-15, "%s N = %d: E of pdas %.17g and of cgssor %.17g agree "
          "to %.1e <= 1e-15", path, N, a->energy, b->energy, rel);
  }
  model_free(a), model_free(b);
  scene_free(&s);
  cholmod_finish(&cm);
}

int main(void)
{
  energy_agreement("data/example-5.1.scene", 128);
  compare("data/example-5.1.scene", 16, QP_PDAS);
  compare("data/example-5.1.scene", 32, QP_PDAS);
  compare("data/example-5.1.scene", 32, QP_CGSSOR);
  compare("data/example-5.2.scene", 16, QP_PDAS);
  compare("tests/scenes/flat-punch.scene", 16, QP_PDAS);
  compare("tests/scenes/flat-punch.scene", 16, QP_PSOR);
  floating();
  curvature();
  return check_done();
}
