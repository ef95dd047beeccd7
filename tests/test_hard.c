/* test_hard: the state solvers at a weakly active node, one that touches
   the foundation with zero contact force.  There the complementarity
   conditions are degenerate (gap = 0 and T = 0 at once), the case in which
   an active set method may cycle and a projected iteration may stall.  The
   design is found as in test_gradient.c, by bisection on alpha_i between a
   design where node i is free and one where it presses; then every solver
   must converge there, and just above and just below it, to the same
   state as the active set method started cold. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "setup.h"
#include "scene.h"
#include "model.h"

static const char *name[] = { "pdas", "psor", "cgssor" };

/* a model of scene s solved at X by method m from a cold start; NULL on failure */
static Model *solve_cold(Scene *s, Qp_method m, const double *X,
                         cholmod_common *cm, Status *st)
{
  double tol = s->solver.tol;            /* the test's own, kept */
  s->solver = qp_options_default(m);
  s->solver.tol = tol;
  Model *md = model_new(&s->problem, &s->solver, cm, st);
  if (md && model_solve(md, X, st)) { model_free(md); md = NULL; }
  return md;
}

/* node i next to the contact zone, made weakly active by bisection on X[i];
   c is its contact DOF; 0 if there is none */
static int weakly_active(Model *md, const Scene *s, double *X, int *i, int *c)
{
  Status st;
  *i = *c = -1;
  for (int k = 0; k + 1 < md->dofs->nc; k++) {
    int col = md->dofs->contact_col[k];
    if (md->Q[md->dofs->contact[k]] > -X[col]
        && md->Q[md->dofs->contact[k + 1]] <= -X[col + 1]) *i = col, *c = k;
  }
  if (*i < 0) return 0;
  double hi = X[*i], lo = 0;          /* free at hi, pressing at lo = 0 */
  for (int it = 0; it < 200 && hi - lo > 1e-15 * s->problem.C0; it++) {
    X[*i] = 0.5 * (lo + hi);
    if (model_solve(md, X, &st)) return 0;
    if (md->Q[md->dofs->contact[*c]] > -X[*i]) hi = X[*i]; else lo = X[*i];
  }
  X[*i] = hi;
  return !model_solve(md, X, &st);
}

/* every solver at X agrees with pdas from a cold start */
static void agree(Scene *s, const char *tag, const double *X, cholmod_common *cm)
{
  Status st;
  Model *ref = solve_cold(s, QP_PDAS, X, cm, &st);
  if (!check(ref != NULL, "%s: pdas converges%s%s", tag, ref ? "" : ": ",
             ref ? "" : st.msg)) return;
  int n = ref->dofs->n;
  double umax = 0;
  for (int j = 0; j < n; j++) umax = fmax(umax, fabs(ref->Q[j]));
  check(ref->report.kkt <= s->solver.tol, "%s: pdas KKT residual %.1e <= %.0e after %d "
        "iterations", tag, ref->report.kkt, s->solver.tol, ref->report.iterations);
  for (int m = QP_PSOR; m <= QP_CGSSOR; m++) {
    Model *md = solve_cold(s, (Qp_method) m, X, cm, &st);
    if (!check(md != NULL, "%s: %s converges%s%s", tag, name[m], md ? "" : ": ",
               md ? "" : st.msg)) continue;
    double du = 0;
    for (int j = 0; j < n; j++) du = fmax(du, fabs(md->Q[j] - ref->Q[j]));
    check(fabs(md->energy - ref->energy) <= 1e-9 * fabs(ref->energy)
          && du <= 1e-6 * umax, "%s: %s agrees with pdas (E %.1e, Q %.1e "
          "relative) after %d iterations", tag, name[m],
          fabs(md->energy - ref->energy) / fabs(ref->energy), du / umax,
          md->report.iterations);
    model_free(md);
  }
  model_free(ref);
}

static void weakly_active_node(const char *path, Plane_model model)
{
  Scene s;
  Status st;
  cholmod_common cm;
  test_start(&cm);
  if (!check(scene_load(&s, path, 0, NULL, &st) == 0, "load %s", path)) return;
  s.problem.model = model;
  s.solver.tol = 1e-11;
  const char *mname = problem_model_name(model);
  double *X = malloc((s.problem.N + 1) * sizeof *X);
  memcpy(X, s.alpha0, (s.problem.N + 1) * sizeof *X);
  Model *md = solve_cold(&s, QP_PDAS, X, &cm, &st);
  int i = -1, c = -1;
  if (check(md && weakly_active(md, &s, X, &i, &c), "%s %s: a weakly active "
            "design found by bisection (pdas warm starts throughout)", path, mname)) {
    double gap = md->Q[md->dofs->contact[c]] + X[i], Tmax = 0;
    for (int k = 0; k < md->dofs->nc; k++) Tmax = fmax(Tmax, md->T[k]);
    check(fabs(gap) <= 1e-12 * s.problem.C0 && fabs(md->T[c]) <= 1e-6 * Tmax,
          "%s %s: node %d touches (gap %.1e m) with force %.1e max T", path,
          mname, i, gap, fabs(md->T[c]) / Tmax);
    char tag[600];
    double x0 = X[i];
    for (int side = -1; side <= 1; side++) {
      X[i] = x0 + side * 1e-9 * s.problem.C0;
      snprintf(tag, sizeof tag, "%s %s, node %d %s", path, mname, i,
               side < 0 ? "pressed by 1e-9 C0" : side > 0 ? "lifted by 1e-9 C0"
               : "weakly active");
      agree(&s, tag, X, &cm);
    }
  }
  model_free(md);
  free(X);
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
  weakly_active_node("data/example-5.1.scene", MODEL_PLANE_STRESS);
  weakly_active_node("data/example-5.1.scene", MODEL_PLANE_STRAIN);
  weakly_active_node("data/example-5.2.scene", MODEL_PLANE_STRESS);
  return check_done();
}
