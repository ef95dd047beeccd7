/* weakly_active.h: the state solvers at a weakly active node, one that
   touches the foundation with zero contact force.  There the
   complementarity conditions are degenerate (gap = 0 and T = 0 at once),
   the case in which an active set method may cycle and a projected
   iteration may stall.  The design is found as in test_grad.c, by
   bisection on alpha_i between a design where node i is free and one
   where it presses; then every solver must converge there, and just above
   and just below it, to the same state as the active set method started
   cold.  weakly_active_nodes(m) makes the checks of method m: for pdas
   (test_pdas.c) the design found and pdas's convergence, for psor and
   cgssor (test_psor.c, test_cgssor.c) their agreement with pdas. */
#ifndef CONTACTOPT_TEST_WEAKLY_ACTIVE_H
#define CONTACTOPT_TEST_WEAKLY_ACTIVE_H
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "case.h"

static const char *weakly_name[] = { "pdas", "psor", "cgssor" };

/* a model of scene s solved at X by method m from a cold start; NULL on failure */
static inline Model *solve_cold(Scene *s, Qp_method m, const double *X,
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
static inline int weakly_active(Model *md, const Scene *s, double *X, int *i, int *c)
{
  Status st;
  *i = *c = -1;
  for (int k = 0; k + 1 < model_dofs(md)->nc; k++) {
    int col = model_dofs(md)->contact_col[k];
    if (model_state(md)[model_dofs(md)->contact[k]] > -X[col]
        && model_state(md)[model_dofs(md)->contact[k + 1]] <= -X[col + 1]) *i = col, *c = k;
  }
  if (*i < 0) return 0;
  double hi = X[*i], lo = 0;          /* free at hi, pressing at lo = 0 */
  for (int it = 0; it < 200 && hi - lo > 1e-15 * s->problem.C0; it++) {
    X[*i] = 0.5 * (lo + hi);
    if (model_solve(md, X, &st)) return 0;
    if (model_state(md)[model_dofs(md)->contact[*c]] > -X[*i]) hi = X[*i]; else lo = X[*i];
  }
  X[*i] = hi;
  return !model_solve(md, X, &st);
}

/* pdas at X from a cold start converges (m = pdas); method m at X agrees
   with it (m = psor, cgssor) */
static inline void agree(Scene *s, const char *tag, const double *X,
                         cholmod_common *cm, Qp_method m)
{
  Status st;
  Model *ref = solve_cold(s, QP_PDAS, X, cm, &st);
  if (m == QP_PDAS) {
    if (!check(ref != NULL, "%s: pdas converges%s%s", tag, ref ? "" : ": ",
               ref ? "" : st.msg)) return;
  } else if (!ref) return;                 /* test_pdas.c says so */
  int n = model_dofs(ref)->n;
  double umax = 0;
  for (int j = 0; j < n; j++) umax = fmax(umax, fabs(model_state(ref)[j]));
  if (m == QP_PDAS)
    check(model_report(ref)->kkt <= s->solver.tol, "%s: pdas KKT residual of (4.3) "
          "%.1e <= %.0e after %d iterations", tag, model_report(ref)->kkt,
          s->solver.tol, model_report(ref)->iterations);
  else {
    Model *md = solve_cold(s, m, X, cm, &st);
    if (check(md != NULL, "%s: %s converges%s%s", tag, weakly_name[m],
              md ? "" : ": ", md ? "" : st.msg)) {
      double du = 0;
      for (int j = 0; j < n; j++) du = fmax(du, fabs(model_state(md)[j] - model_state(ref)[j]));
      check(fabs(model_energy(md) - model_energy(ref)) <= 1e-9 * fabs(model_energy(ref))
            && du <= 1e-6 * umax, "%s: %s agrees with pdas on the state (4.3) "
            "(E %.1e, Q %.1e relative) after %d iterations", tag, weakly_name[m],
            fabs(model_energy(md) - model_energy(ref)) / fabs(model_energy(ref)), du / umax,
            model_report(md)->iterations);
      model_free(md);
    }
  }
  model_free(ref);
}

/* the checks of method m at the weakly active node of scene path, and 1e-9
   C0 on either side of it */
static inline void weakly_active_node(const char *path, Problem_plane_model model,
                                      Qp_method m)
{
  Case cs;
  Status st;
  int pdas = m == QP_PDAS;
  int loaded = case_load(&cs, path, 0, NULL) == 0;
  if (!(pdas ? check(loaded, "load %s", path) : loaded)) {
    close_case(&cs);
    return;
  }
  Scene *s = &cs.s;
  s->problem.model = model;
  s->solver.tol = 1e-11;
  const char *mname = problem_model_name(model);
  double *X = malloc((s->problem.N + 1) * sizeof *X);
  memcpy(X, s->alpha0, (s->problem.N + 1) * sizeof *X);
  Model *md = solve_cold(s, QP_PDAS, X, &cs.cm, &st);
  int i = -1, c = -1, found = md && weakly_active(md, s, X, &i, &c);
  if (pdas ? check(found, "%s %s: a weakly active design found by bisection "
                   "(pdas warm starts throughout)", path, mname) : found) {
    double gap = model_state(md)[model_dofs(md)->contact[c]] + X[i], Tmax = 0;
    for (int k = 0; k < model_dofs(md)->nc; k++) Tmax = fmax(Tmax, model_forces(md)[k]);
    if (pdas)
      check(fabs(gap) <= 1e-12 * s->problem.C0 && fabs(model_forces(md)[c]) <= 1e-6 * Tmax,
            "%s %s: node %d touches (gap %.1e m) with force %.1e max T (4.6)",
            path, mname, i, gap, fabs(model_forces(md)[c]) / Tmax);
    char tag[600];
    double x0 = X[i];
    for (int side = -1; side <= 1; side++) {
      X[i] = x0 + side * 1e-9 * s->problem.C0;
      snprintf(tag, sizeof tag, "%s %s, node %d %s", path, mname, i,
               side < 0 ? "pressed by 1e-9 C0" : side > 0 ? "lifted by 1e-9 C0"
               : "weakly active");
      agree(s, tag, X, &cs.cm, m);
    }
  }
  model_free(md);
  free(X);
  close_case(&cs);
}

/* Examples 5.1 (plane stress and plane strain) and 5.2 */
static inline void weakly_active_nodes(Qp_method m)
{
  weakly_active_node("data/example-5.1.scene", MODEL_PLANE_STRESS, m);
  weakly_active_node("data/example-5.1.scene", MODEL_PLANE_STRAIN, m);
  weakly_active_node("data/example-5.2.scene", MODEL_PLANE_STRESS, m);
}
#endif
