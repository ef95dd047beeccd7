/* test_grad.c: the gradient (paper/grad.nw).  Formula (4.8) at a weakly
   active node, one that touches
   the foundation with zero contact force.  Q is not differentiable there,
   E is: the analytic derivative must agree with the one-sided differences
   from both sides (the node leaves contact on one side, presses on the
   other).  The weakly active design is found by bisection on alpha_i
   between a design where node i is free and one where it presses.
   Then grad_check, the gradient check of the command gradcheck, called
   directly: its gradient, its progress calls, the one-sided difference
   at a node on the foundation, the model it leaves, its errors. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "case.h"
#include "grad.h"

static double energy(Model *md, double *X)
{
  Status st;
  if (model_solve(md, X, &st)) { printf("# %s\n", st.msg); return NAN; }
  return model_energy(md);
}

static void weakly_active(const char *path, Problem_plane_model model)
{
  Case cs;
  if (!check(case_load(&cs, path, 0, NULL) == 0, "load %s", path)) {
    close_case(&cs);
    return;
  }
  cs.s.problem.model = model;
  case_model(&cs);
  Model *md = cs.md;
  const Problem *P = &cs.s.problem;
  Status st;
  double *X = malloc((P->N + 1) * sizeof *X), *G = malloc((P->N + 1) * sizeof *G);
  memcpy(X, cs.s.alpha0, (P->N + 1) * sizeof *X);
  energy(md, X);
  int i = -1, c = -1;                 /* the last free node before the zone */
  for (int k = 0; k < model_dofs(md)->nc; k++) {
    int col = model_dofs(md)->contact_col[k];
    if (model_state(md)[model_dofs(md)->contact[k]] > -X[col] && k + 1 < model_dofs(md)->nc
        && model_state(md)[model_dofs(md)->contact[k + 1]] <= -X[col + 1]) { i = col; c = k; }
  }
  if (!check(i >= 0, "%s: a free node next to the contact zone", path)) return;
  double hi = X[i], lo = 0;             /* free at hi, pressing at lo = 0 */
  for (int it = 0; it < 200 && hi - lo > 1e-15 * P->C0; it++) {
    X[i] = 0.5 * (lo + hi);
    energy(md, X);
    if (model_state(md)[model_dofs(md)->contact[c]] > -X[i]) hi = X[i]; else lo = X[i];
  }
  X[i] = hi;
  energy(md, X);
  grad_energy(md, G, &st);
  double gap = model_state(md)[model_dofs(md)->contact[c]] + X[i], Tmax = 0, Gmax = 0;
  for (int k = 0; k < model_dofs(md)->nc; k++) Tmax = fmax(Tmax, model_forces(md)[k]);
  for (int k = 0; k <= P->N; k++) Gmax = fmax(Gmax, fabs(G[k]));
  check(gap <= 1e-12 * P->C0 && fabs(model_forces(md)[c]) <= 1e-6 * Tmax,
        "%s: node %d touches (gap %.1e m) with force %.1e max T (4.6): weakly active",
        path, i, gap, fabs(model_forces(md)[c]) / Tmax);
  double x0 = X[i], E0 = model_energy(md), h = 1e-5 * P->C0, Ep, Ep2, Em, Em2;
  X[i] = x0 + h; Ep = energy(md, X);
  X[i] = x0 + 2 * h; Ep2 = energy(md, X);
  X[i] = x0 - h; Em = energy(md, X);
  X[i] = x0 - 2 * h; Em2 = energy(md, X);
  X[i] = x0;
  double forward = (-3 * E0 + 4 * Ep - Ep2) / (2 * h);
  double backward = (3 * E0 - 4 * Em + Em2) / (2 * h);
  check(fabs(forward - G[i]) <= 1e-6 * Gmax,
        "%s: dE/dX_%d = %.9g by (4.8) agrees with the forward difference %.9g (%.1e)",
        path, i, G[i], forward, fabs(forward - G[i]) / Gmax);
  check(fabs(backward - G[i]) <= 1e-6 * Gmax,
        "%s: dE/dX_%d by (4.8) agrees with the backward difference %.9g (%.1e)",
        path, i, backward, fabs(backward - G[i]) / Gmax);
  free(X); free(G);
  close_case(&cs);
}

typedef struct { int calls, in_order; } Progress;

static void progress(int i, const Grad_check *gc, void *data)
{
  Progress *p = data;
  p->in_order &= i == p->calls && gc->err[i] < INFINITY;
  p->calls++;
}

static void check_grad_check(const char *path)
{
  Case cs, fr;
  Status st;
  if (!check(case_load(&cs, path, 0, NULL) == 0 && case_load(&fr, path, 0, NULL) == 0,
             "load %s", path)) {
    close_case(&cs), close_case(&fr);
    return;
  }
  int N = cs.s.problem.N;
  case_model(&cs);
  case_model(&fr);
  Model *md = cs.md, *fresh = fr.md;
  Grad_check *gc = grad_check_new(N, &st);
  double *G = malloc((N + 1) * sizeof *G), worst = 0;
  case_solve(&fr);
  grad_energy(fresh, G, &st);
  Progress p = { 0, 1 };
  int rc = grad_check(md, cs.s.alpha0, gc, progress, &p, &st);
  for (int i = 0; i <= N; i++) worst = fmax(worst, gc->err[i]);
  check(rc == 0 && !memcmp(G, gc->G, (N + 1) * sizeof *G),
        "%s: grad_check's G (4.8) is grad_energy's at alpha0, bit for bit", path);
  check(p.calls == N + 1 && p.in_order, "%s: progress called once per node, "
        "in order (%d calls for %d nodes)", path, p.calls, N + 1);
  check(worst < 1e-6 && gc->err[gc->worst] == worst,
        "%s: largest relative error of (4.8) %.2e < 1e-6, at node worst = %d", path,
        worst, gc->worst);
  if (cs.s.alpha0[0] == 0)
    check(gc->err[0] < 1e-6, "%s: node 0 on the foundation (alpha_0 = 0), "
          "one-sided difference of (4.8): error %.2e", path, gc->err[0]);
  check(fabs(model_energy(md) - model_energy(fresh)) <= 1e-12 * fabs(model_energy(fresh)),
        "%s: the model is left solved at alpha0 (E %.15g, fresh %.15g)", path,
        model_energy(md), model_energy(fresh));
  Grad_check *other = grad_check_new(N / 2, &st);
  check(grad_check(md, cs.s.alpha0, other, NULL, NULL, &st) == STATUS_INPUT,
        "%s: a check made for another N is refused: %s", path, st.msg);
  grad_check_free(other);
  free(G);
  grad_check_free(gc);
  close_case(&fr);
  cs.s.solver = qp_options_default(QP_CGSSOR);
  cs.s.solver.max_iter = 2;
  case_model(&cs);
  md = cs.md;
  gc = grad_check_new(N, &st);
  p = (Progress) { 0, 1 };
  rc = grad_check(md, cs.s.alpha0, gc, progress, &p, &st);
  check(rc == STATUS_NUMERIC && p.calls == 0, "%s: a state solve that fails "
        "stops the check with its status: %s", path, st.msg);
  grad_check_free(gc);
  close_case(&cs);
}

int main(void)
{
  weakly_active("data/example-5.1.scene", MODEL_PLANE_STRESS);
  weakly_active("data/example-5.1.scene", MODEL_PLANE_STRAIN);
  weakly_active("data/example-5.2.scene", MODEL_PLANE_STRESS);
  check_grad_check("data/example-5.1.scene");
  check_grad_check("data/example-5.2.scene");
  Status st;
  check(grad_check_new(0, &st) == NULL && st.code == STATUS_INPUT,
        "grad_check_new(0) is refused: %s", st.msg);
  return check_done();
}
