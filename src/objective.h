#line 92 "paper/objective.nw"
#ifndef CONTACTOPT_OBJECTIVE_H
#define CONTACTOPT_OBJECTIVE_H
#include "status.h"
#include "model.h"

typedef enum { OBJECTIVE_ENERGY, OBJECTIVE_COMPLIANCE, OBJECTIVE_SPREAD,
               OBJECTIVE_PEAK, OBJECTIVE_COUNT } Objective_kind;
/* energy, compliance, pressure_spread, pressure_peak, NULL */
extern const char *const objective_names[];

typedef struct {
  Objective_kind kind;  /* what the design minimises */
  double q;             /* pressure_peak: the exponent, >= 1 */
} Objective;

/* energy, q = 8 */
Objective objective_default(void);
const char *objective_name(Objective_kind k);  /* or "?" */
/* the symbol the messages give J (E for the energy, else the name), and
   its unit: " J/m", or "" for a dimensionless one */
const char *objective_symbol(Objective_kind k);
const char *objective_unit(Objective_kind k);
/* 1 if the contact stiffness is the curvature of o where the body
   presses (energy, compliance): the schur metric fits it; 0 if not */
int objective_fits_schur(const Objective *o);
/* J at the model's last state (E itself for energy); STATUS_NUMERIC for
   a pressure objective of a body that no contact node presses */
int objective_value(const Model *md, const Objective *o, double *J,
                    Status *st);
/* J, and dT, dw (nc, may be NULL) its partial derivatives in T (0 at a
   node off its bound, whose T vanishes on the state's sets) and omega,
   the explicit terms of E and b'Q left out (for the gradient) */
int objective_partials(const Model *md, const Objective *o, double *J,
                       double *dT, double *dw, Status *st);
/* 1 if the last state's held set (contact nodes on their bound, and with
   friction the sticking ones) is that of held[] (nc + nt), 0 if not;
   held NULL: write it */
int objective_same_sets(const Model *md, char *held, int write);
/* the properties of a kind that its callers ask for: 1 if it is the
   energy E (the Newton method's model, (4.8), a line of its own in a
   summary); 1 if it takes the exponent q (J_q) */
int objective_is_energy(Objective_kind k);
int objective_has_exponent(Objective_kind k);
/* 1 if J at the model's problem has a kink where the held sets change:
   another objective than E, or any under Coulomb friction (J_F) */
int objective_has_kinks(const Model *md, const Objective *o);
/* every kind's J at a state, in the order of objective_names (NaN:
   undefined there) */
typedef struct { double value[OBJECTIVE_COUNT]; } Objective_values;
/* G (N+1) = the gradient by the adjoint of the last state of J (o;
   NULL: none) plus t'T (t, nc, may be NULL, zero off the held contact
   unknowns), at fixed slip bounds under Coulomb friction; lam (n)
   and held_out (nc + nt), each may be NULL, receive the adjoint and the
   held sets, and *state (may be NULL) the rounding of J through its
   state (below).  A checked error before a solve. */
int objective_gradient_fixed(const Model *md, const Objective *o,
                             const double *t, double *lam, char *held_out,
                             double *G, double *state, Status *st);
/* the front door, for every kind and contact law: *J (may be NULL) the
   objective o at the model's last state, G (N+1, may be NULL) its
   gradient and *dJ (may be NULL) the rounding of J; the energy's
   gradient by (4.8) (grad_energy), another's by the adjoint
   (objective_gradient_fixed), and either under Coulomb friction through
   the fixed point (coulomb_gradient).  STATUS_NUMERIC with *J = NaN where
   J is undefined; a checked error before a solve. */
int objective_evaluate(const Model *md, const Objective *o, double *J,
                       double *G, double *dJ, Status *st);
#endif
