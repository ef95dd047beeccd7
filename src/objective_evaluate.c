#line 644 "paper/objective.nw"
#include <float.h>
#include <math.h>
#include "objective.h"
#include "grad.h"
#include "coulomb.h"
#line 653 "paper/objective.nw"
/* eps m(J): the rounding of J's evaluation; delta E for the energy */
static double evaluation_rounding(const Model *md, Objective_kind kind, double J)
{
  if (kind == OBJECTIVE_ENERGY) return model_energy_rounding(md);
  if (kind == OBJECTIVE_SPREAD) return 4 * DBL_EPSILON * (fabs(J) + 1);
  if (kind == OBJECTIVE_PEAK) return 4 * DBL_EPSILON * fabs(J);
  const double *b = model_load(md), *Q = model_state(md);
  long double m = 0;
  for (int i = 0; i < model_dofs(md)->n; i++) m += fabsl((long double) b[i] * Q[i]);
  return DBL_EPSILON * (double) m;
}

/* G and *dJ (each may be NULL; dJ's state term comes with G) at the last
   state, whose J is known */
static int evaluate_gradient(const Model *md, const Objective *o, double J,
                             double *G, double *dJ, Status *st)
{
  int rc = STATUS_OK;
  double state = 0;
  if (model_problem(md)->contact == CONTACT_COULOMB) {        /* no state term */
    if (G) rc = coulomb_gradient(md, o, G, st);
  } else if (objective_is_energy(o->kind)) {            /* (4.8) */
    if (G) rc = grad_energy(md, G, st);
  } else if (G)
    rc = objective_gradient_fixed(md, o, NULL, NULL, NULL, G, dJ ? &state : NULL, st);
  if (!rc && dJ) *dJ = evaluation_rounding(md, o->kind, J) + state;
  return rc;
}

int objective_evaluate(const Model *md, const Objective *o, double *J,
                       double *G, double *dJ, Status *st)
{
  double v;
  if (G && !model_solved(md))
    return status_set(st, STATUS_INPUT, "gradient: no state has been solved");
  int rc = objective_value(md, o, &v, st);
  if (J) *J = rc ? NAN : v;
  return rc ? rc : evaluate_gradient(md, o, v, G, dJ, st);
}
