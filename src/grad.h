#line 71 "paper/grad.nw"
#ifndef CONTACTOPT_GRAD_H
#define CONTACTOPT_GRAD_H
#include "status.h"
#include "model.h"

/* G (N+1 values) = grad E(X) by (4.8), at the design and state that the
   model solved last.  It is a checked error to call it before a solve. */
int grad_energy(const Model *md, double *G, Status *st);
#endif
