/* test_coulomb.c: the gradient of a Coulomb state's cost J_F through its
   fixed point (paper/coulomb.nw).  At F = 0 it is (4.8) of the
   frictionless scene to 1e-12; at F = 0.1, 0.2, 0.3 it meets central
   differences of J_F to 1e-6 of its largest component at every node
   whose differences keep the contact, stick and slip sets, and the
   fixed point's own term is at least 1e-3 of it; the other objectives of a
   Coulomb state likewise; the scene in other units of E (times 1e7) gives
   the gradient times 1e7. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "case.h"
#include "grad.h"
#include "objective.h"
#include "coulomb.h"

#define TRESCA "data/example-5.1-tresca.scene"

/* the Tresca scene as Coulomb at F, with more overrides, solved at alpha0
   with the fixed point to rounding */
static int open_coulomb(Case *c, const char *F, int n, char **more)
{
  char pf[48], *ov[8] = { "contact.model=coulomb", "contact.g=", pf };
  snprintf(pf, sizeof pf, "contact.friction=%s", F);
  for (int k = 0; k < n; k++) ov[3 + k] = more[k];
  if (case_load(c, TRESCA, 3 + n, ov) || case_model(c)) return c->rc;
  return c->rc = model_solve_to_rounding(c->md, c->s.alpha0, &c->st);
}

static void f_zero(void)
{
  Case a, b;
  int n = 17;
  double G[17], H[17];
  if (!check(open_case(&a, 0, NULL) == 0 && open_coulomb(&b, "0", 0, NULL) == 0,
             "F = 0: solved: %s%s", a.st.msg, b.st.msg)) return;
  Objective e = objective_default();
  int rc = grad_energy(a.md, G, &a.st) || objective_evaluate(b.md, &e, NULL, H, NULL, &b.st);
  check(!rc && max_diff(G, H, n) <= 1e-12 * max_abs(G, n), "F = 0: the gradient "
        "of J_F is (4.8) of the frictionless scene to %.1e <= 1e-12 of its "
        "largest component", max_diff(G, H, n) / max_abs(G, n));
  close_case(&a), close_case(&b);
}

/* the largest err of gc over the nodes whose differences kept the sets */
static double kept_error(const Grad_check *gc, int *kept)
{
  double e = 0;
  *kept = 0;
  for (int i = 0; i <= gc->N; i++)
    if (!gc->crossed[i]) e = fmax(e, gc->err[i]), ++*kept;
  return e;
}

/* central differences of J (o; NULL: J_F) at F, and the gradient at fixed
   slip bounds against them */
static void differences(const char *F, const Objective *o)
{
  Case c;
  const char *name = o ? objective_name(o->kind) : "J_F";
  if (!check(open_coulomb(&c, F, 0, NULL) == 0, "F = %s: solved: %s", F, c.st.msg)) return;
  int n = c.s.problem.N + 1, its = model_fixed_point_iterations(c.md), kept;
  double res = model_fixed_point_residual(c.md), Gs[64], fixed_err = 0;
  Objective e = objective_default();
  int rc = objective_gradient_fixed(c.md, o ? o : &e, NULL, NULL, NULL, Gs, NULL, &c.st);
  Grad_check *gc = grad_check_new(c.s.problem.N, &c.st);
  if (gc) gc->objective = o;
  if (!check(!rc && gc && grad_check(c.md, c.s.alpha0, gc, NULL, NULL, &c.st) == 0,
             "F = %s, %s: gradient check: %s", F, name, c.st.msg)) goto done;
  double err = kept_error(gc, &kept), Gmax = max_abs(gc->G, n);
  for (int i = 0; i <= gc->N; i++)
    if (!gc->crossed[i]) fixed_err = fmax(fixed_err, fabs(Gs[i] - gc->fd[i]) / Gmax);
  double term = max_diff(Gs, gc->G, n) / Gmax;
  check(err <= 1e-6 && kept >= n / 2, "F = %s, %s: the gradient through the "
        "fixed point meets central differences to %.1e <= 1e-6 at the %d of %d "
        "nodes that keep the sets (%d fixed-point iterations, change %.1e)",
        F, name, err, kept, n, its, res);
  check(term >= 1e-3, "F = %s, %s: the fixed point's term is %.1e >= 1e-3 of "
        "the largest component (the gradient at fixed slip bounds misses the "
        "differences by %.1e where the sets are kept)", F, name, term, fixed_err);
done:
  grad_check_free(gc);
  close_case(&c);
}

static void units(const char *F)
{
  char *big[] = { "material.E=2.15e18", "top.P2=-5.75e15" };
  Case a, b;
  double G[17], H[17];
  if (!check(open_coulomb(&a, F, 0, NULL) == 0 && open_coulomb(&b, F, 2, big) == 0,
             "F = %s, scaled: solved: %s%s", F, a.st.msg, b.st.msg)) return;
  Objective e = objective_default();
  int rc = objective_evaluate(a.md, &e, NULL, G, NULL, &a.st)
        || objective_evaluate(b.md, &e, NULL, H, NULL, &b.st);
  for (int i = 0; i < 17; i++) H[i] /= 1e7;
  check(!rc && max_diff(G, H, 17) <= 1e-10 * max_abs(G, 17), "F = %s: E and the "
        "load times 1e7 give the gradient times 1e7, to %.1e <= 1e-10", F,
        max_diff(G, H, 17) / max_abs(G, 17));
  close_case(&a), close_case(&b);
}

int main(void)
{
  Objective c = { OBJECTIVE_COMPLIANCE, 8 }, s = { OBJECTIVE_SPREAD, 8 },
            q = { OBJECTIVE_PEAK, 8 };
  f_zero();
  differences("0.1", NULL);
  differences("0.2", NULL);
  differences("0.3", NULL);
  differences("0.2", &c);
  differences("0.2", &s);
  differences("0.2", &q);
  units("0.1");
  units("0.3");
  return check_done();
}
