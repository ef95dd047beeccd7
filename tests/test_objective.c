/* test_objective.c: the objectives and their adjoint gradient
   (paper/objective.nw).  The energy through the adjoint is (4.8) to
   1e-12 of its largest component, frictionless and with given friction;
   a uniform load on a flat body resting on its whole bottom gives the
   closed forms J_s = 0 and J_q = 1; the compliance is -2E where every
   gap bound is zero (the flat design, frictionless). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "case.h"
#include "grad.h"
#include "objective.h"

/* the case of the scene at path with the overrides, its model solved at
   alpha0; NULL, the case closed, if not */
static Model *solved(Case *cs, const char *path, int nov, char **ov)
{
  if (!check(case_load(cs, path, nov, ov) == 0, "load %s", path)) {
    close_case(cs);
    return NULL;
  }
  if (case_model(cs) || case_solve(cs)) {
    check(0, "%s: solve: %s", path, cs->st.msg);
    close_case(cs);
    return NULL;
  }
  return cs->md;
}

static void energy_is_48(const char *path)
{
  Case cs;
  Status st;
  Model *md = solved(&cs, path, 0, NULL);
  if (!md) return;
  int n = cs.s.problem.N + 1;
  double *G = malloc(2 * n * sizeof *G), *H = G + n, Gmax = 0, d = 0;
  Objective o = objective_default();
  int rc = grad_energy(md, G, &st)
        || objective_gradient_fixed(md, &o, NULL, NULL, NULL, H, NULL, &st);
  for (int i = 0; i < n; i++)
    Gmax = fmax(Gmax, fabs(G[i])), d = fmax(d, fabs(G[i] - H[i]));
  check(!rc && d <= 1e-12 * Gmax, "%s: the energy through the adjoint is "
        "(4.8) to %.1e <= 1e-12 of its largest component", path, d / Gmax);
  free(G);
  close_case(&cs);
}

static void uniform_pressure(void)
{
  char *ov[] = { "design.initial=constant", "design.constant=0", "design.C2=4",
                 "left.bc=roller", "top.from=0", "top.to=4" };
  Case cs;
  Status st;
  Model *md = solved(&cs, "data/example-5.1.scene", 6, ov);
  if (!md) return;
  double Js, Jq;
  Objective spread = { OBJECTIVE_SPREAD, 8 }, peak = { OBJECTIVE_PEAK, 8 };
  int rc = objective_value(md, &spread, &Js, &st) || objective_value(md, &peak, &Jq, &st);
  check(!rc && fabs(Js) <= 1e-12 && fabs(Jq - 1) <= 1e-12, "a uniform load on "
        "a flat body in full contact: J_s = %.1e = 0, J_q - 1 = %.1e = 0",
        Js, Jq - 1);
  close_case(&cs);
}

static void compliance_is_minus_2E(const char *path)
{
  char *ov[] = { "design.initial=constant", "design.constant=0" };
  Case cs;
  Status st;
  Model *md = solved(&cs, path, 2, ov);
  if (!md) return;
  double J;
  Objective c = { OBJECTIVE_COMPLIANCE, 8 };
  int rc = objective_value(md, &c, &J, &st);
  check(!rc && fabs(J + 2 * model_energy(md)) <= 1e-12 * fabs(J), "%s at alpha = 0: "
        "compliance %.10g = -2E (relative %.1e)", path, J,
        fabs(J + 2 * model_energy(md)) / fabs(J));
  close_case(&cs);
}

static void lift_off(void)
{
  char *ov[] = { "top.P2=5.75e8", "left.bc=clamped" };
  Case cs;
  Status st;
  Model *md = solved(&cs, "data/example-5.1.scene", 2, ov);
  if (!md) return;
  double J;
  Objective o = { OBJECTIVE_SPREAD, 8 };
  int rc = objective_value(md, &o, &J, &st);
  check(rc == STATUS_NUMERIC && strstr(st.msg, "lifts off"), "a load that lifts "
        "the body off leaves the pressure spread undefined: %s", st.msg);
  close_case(&cs);
}

int main(void)
{
  energy_is_48("data/example-5.1.scene");
  energy_is_48("data/example-5.2.scene");
  energy_is_48("data/example-5.1-tresca.scene");
  uniform_pressure();
  compliance_is_minus_2E("data/example-5.1.scene");
  compliance_is_minus_2E("data/example-5.2.scene");
  lift_off();
  return check_done();
}
