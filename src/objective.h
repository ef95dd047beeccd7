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
/* G (N+1) = grad J by the adjoint of the last state; for energy the same
   path gives (4.8); under Coulomb friction the gradient through the fixed
   point (coulomb_gradient).  A checked error before a solve. */
int objective_gradient(Model *md, const Objective *o, double *G, Status *st);
/* G as objective_gradient, and dJ (may be NULL) the rounding of J at the
   last state: its evaluation's and its state's (below) */
int objective_gradient_rounding(Model *md, const Objective *o, double *G,
                                double *dJ, Status *st);
/* G (N+1) = the gradient at fixed slip bounds of J (o; NULL: none) plus
   t'T (t, nc, may be NULL, zero off the held contact unknowns); lam (n)
   and held_out (nc + nt), each may be NULL, receive the adjoint and the
   held sets.  A checked error before a solve. */
int objective_gradient_fixed(const Model *md, const Objective *o,
                             const double *t, double *lam, char *held_out,
                             double *G, Status *st);
#endif
