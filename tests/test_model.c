/* test_model.c: the model (paper/model.nw).  First the energy E of two
   solvers' states, equal to rounding, the same to 1e-15.  Then the
   measurement behind the Newton method's model (paper/newton.nw, "Where E
   is curved"): at the optimum of Example 5.1 the Hessian of E, by central
   differences of the gradient (4.8), against the contact stiffness S
   (model_contact_stiffness): their generalised eigenvalues lie near 1 on
   the nodes in contact and near 0 (|lambda| < 1e-3) on the others.  S
   itself, against the Schur complement formed densely: test_condense.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "case.h"
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_sort_vector.h>
#include "grad.h"
#include "design.h"
#include "opt.h"
#include "weakly_active.h"

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
  Case cs;
  Status st;
  Opt_report r;
  if (!check(case_load(&cs, EX51, 0, NULL) == 0, "load 5.1")) {
    close_case(&cs);
    return;
  }
  Scene *s = &cs.s;
  int n = s->problem.N + 1, active = 0, near1 = 0, near0 = 0;
  case_model(&cs);
  Model *md = cs.md;
  Design_set B = design_set(&s->problem);
  double *X = malloc(n * sizeof *X), *H = malloc((size_t) n * n * sizeof *H),
         *S = malloc((size_t) n * n * sizeof *S), lo1 = HUGE_VAL, hi1 = 0, hi0 = 0;
  int ok = !design_project(&B, s->alpha0, X, NULL, &st)
           && !opt_minimize(md, &B, &s->optimizer, X, NULL, NULL, &r, &st)
           && !model_solve(md, X, &st) && !model_contact_stiffness(md, S, &st);
  for (int c = 0; ok && c < model_dofs(md)->nc; c++)
    active += model_state(md)[model_dofs(md)->contact[c]] <= model_bounds(md)[c] && model_forces(md)[c] > 0;
  ok = ok && !fd_hessian(md, X, n, 1e-7 * s->problem.C0, H);
  if (check(ok, "5.1: optimum by Algorithm 4.1, S and the difference Hessian of (4.8) (%d nodes in contact)", active)) {
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
  close_case(&cs);
}

/* The energy is evaluated accurately enough that two solvers' states,
   equal to rounding, give the same E to 1e-15: as 1/2 Q'AQ - b'Q in double
   the quadratic form loses about three digits to cancellation and the
   rounding of A (1.4e-14 apart here, 7e-14 at N = 256). */
static void energy_agreement(const char *path, int N)
{
  Case cs;
  Status st;
  if (!check(case_load_refined(&cs, path, N / 16) == 0, "load %s at N = %d", path, N)) {
    close_case(&cs);
    return;
  }
  Scene *s = &cs.s;
  s->solver.tol = 1e-12;
  Model *a = solve_cold(s, QP_PDAS, s->alpha0, &cs.cm, &st);
  Model *b = a ? solve_cold(s, QP_CGSSOR, s->alpha0, &cs.cm, &st) : NULL;
  if (check(a && b, "%s N = %d: pdas and cgssor converge to kkt 1e-12%s%s", path,
            N, a && b ? "" : ": ", a && b ? "" : st.msg)) {
    double rel = fabs(model_energy(a) - model_energy(b)) / fabs(model_energy(a));
    check(rel <= 1e-15, "%s N = %d: E of pdas %.17g and of cgssor %.17g agree "
          "to %.1e <= 1e-15", path, N, model_energy(a), model_energy(b), rel);
  }
  model_free(a), model_free(b);
  close_case(&cs);
}

int main(void)
{
  energy_agreement("data/example-5.1.scene", 128);
  curvature();
  return check_done();
}
