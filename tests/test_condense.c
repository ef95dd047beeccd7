/* test_condense.c: the condensation onto the contact unknowns
   (paper/condense.nw).  The stiffness of the body seen from its contact
   nodes, S = A_cc - A_ci A_ii^-1 A_ic of the matrix A of (4.3), as
   qp_schur hands it over through model_contact_stiffness (the trailing
   block of a CAMD-ordered Cholesky factor), against the same Schur
   complement formed independently: A as a dense matrix, A_ii factorised
   by GSL, n_c dense solves.  Both paths of qp_schur: after a solve by
   pdas, which hands over the workspace's own S, and after one by cgssor
   or psor, which have it condensed apart.  The contact diagonals carry
   the documented shift of 1e-6 of themselves in both.  Also: S is
   positive definite, and for a body that only the foundation holds (the
   flat punch) S without the shift annihilates the vertical rigid motion,
   which the shift makes invertible.  And a failure of CHOLMOD's analysis
   (its allocations made to fail) is reported with CHOLMOD's own status,
   as out of memory (exit status 5). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "case.h"
#include "condense.h"

/* the dense Schur complement of A onto the contact unknowns, ordered by
   contact number c, the contact diagonals multiplied by 1 + shift */
static gsl_matrix *dense_schur(const Model *md, double shift)
{
  const Fem_dofs *d = model_dofs(md);
  int n = d->n, nc = d->nc, ni = n - nc, *is_c = calloc(n, sizeof *is_c), *pos = malloc(n * sizeof *pos);
  gsl_matrix *A = gsl_matrix_calloc(n, n);
  const Sparse_index *Ap = model_stiffness(md)->p, *Ai = model_stiffness(md)->i;
  const double *Ax = model_stiffness(md)->x;
  for (int j = 0; j < n; j++)
    for (Sparse_index k = Ap[j]; k < Ap[j + 1]; k++) gsl_matrix_set(A, Ai[k], j, Ax[k]);
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
  Case cs;
  if (!check(case_load_refined(&cs, path, N / 16) == 0, "load %s", path)) {
    close_case(&cs);
    return;
  }
  cs.s.solver = qp_options_default(state);
  case_model(&cs);
  Model *md = cs.md;
  int n1 = N + 1, nc = model_dofs(md)->nc;
  double *S = malloc((size_t) n1 * n1 * sizeof *S), err = 0, scale = 0;
  const char *sn = qp_method_name(state);
  check(case_solve(&cs) == 0, "%s N = %d %s: solve", path, N, sn);
  int rc = model_contact_stiffness(md, S, &cs.st);
  check(rc == 0, "%s N = %d %s: model_contact_stiffness (%s)", path, N, sn, rc ? cs.st.msg : "ok");
  gsl_matrix *ref = dense_schur(md, 1e-6);
  for (int c = 0; c < nc; c++)
    for (int e = 0; e < nc; e++) {
      const int *col = model_dofs(md)->contact_col;
      double v = S[(size_t) col[c] * n1 + col[e]];
      err = fmax(err, fabs(v - gsl_matrix_get(ref, c, e)));
      scale = fmax(scale, fabs(gsl_matrix_get(ref, c, e)));
    }
  check(err <= 1e-13 * scale, "%s N = %d %s: S agrees with the dense Schur complement of A (4.3) "
        "(%d contact unknowns; largest difference %.1e of max |S|)", path, N, sn, nc, err / scale);
  gsl_matrix_view Sv = gsl_matrix_view_array(S, n1, n1);
  check(gsl_linalg_cholesky_decomp1(&Sv.matrix) == 0, "%s N = %d %s: S is positive definite", path, N, sn);
  gsl_matrix_free(ref);
  free(S);
  close_case(&cs);
}

/* the flat punch: no shift, S times the vertical rigid motion is zero */
static void floating(void)
{
  Case cs;
  if (!check(case_load(&cs, "tests/scenes/flat-punch.scene", 0, NULL) == 0, "load flat punch")) {
    close_case(&cs);
    return;
  }
  case_model(&cs);
  case_solve(&cs);
  Model *md = cs.md;
  gsl_matrix *S = dense_schur(md, 0);
  int nc = model_dofs(md)->nc;
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
  close_case(&cs);
}

/* CHOLMOD's allocator, made to fail */
static void *no_malloc(size_t n) { (void) n; return NULL; }
static void *no_calloc(size_t n, size_t m) { (void) n, (void) m; return NULL; }

/* the analysis of K fails when CHOLMOD cannot allocate: STATUS_MEMORY,
   a message that gives CHOLMOD's status by number and name */
static void analysis_fails(void)
{
  Case cs;
  if (!check(case_load(&cs, EX51, 0, NULL) == 0, "load example 5.1")) {
    close_case(&cs);
    return;
  }
  case_model(&cs);
  Model *md = cs.md;
  Status st;
  void *(*m)(size_t) = SuiteSparse_config.malloc_func;
  void *(*c)(size_t, size_t) = SuiteSparse_config.calloc_func;
  SuiteSparse_config.malloc_func = no_malloc, SuiteSparse_config.calloc_func = no_calloc;
  st.code = STATUS_OK, st.msg[0] = 0;
  const Fem_dofs *d = model_dofs(md);
  Condense *cd = condense_alloc(model_stiffness(md), d->nc, d->contact, NULL, &cs.cm, &st);
  SuiteSparse_config.malloc_func = m, SuiteSparse_config.calloc_func = c;
  check(!cd && st.code == STATUS_MEMORY && strstr(st.msg, "CHOLMOD failed to analyse A: out of memory "
        "(CHOLMOD status -2, CHOLMOD_OUT_OF_MEMORY)"),
        "CHOLMOD's allocations fail in the analysis: exit status 5, CHOLMOD's status in the message (%d: %s)",
        st.code, st.msg);
  condense_free(cd);
  close_case(&cs);
}

int main(void)
{
  compare("data/example-5.1.scene", 16, QP_PDAS);
  compare("data/example-5.1.scene", 32, QP_PDAS);
  compare("data/example-5.1.scene", 32, QP_CGSSOR);
  compare("data/example-5.2.scene", 16, QP_PDAS);
  compare("tests/scenes/flat-punch.scene", 16, QP_PDAS);
  compare("tests/scenes/flat-punch.scene", 16, QP_PSOR);
  floating();
  analysis_fails();
  return check_done();
}
