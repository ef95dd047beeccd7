#line 130 "paper/coulomb.nw"
#ifndef CONTACTOPT_COULOMB_H
#define CONTACTOPT_COULOMB_H
#include "status.h"
#include "model.h"
#include "objective.h"

/* G (N+1) = dJ/dX of the objective o at the Coulomb state the model
   solved last, through its fixed point s = F T on the state's contact,
   stick and slip sets */
int coulomb_gradient(const Model *md, const Objective *o, double *G,
                     Status *st);
#endif
