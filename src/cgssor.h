#line 87 "paper/cgssor.nw"
#ifndef CONTACTOPT_MPRGP_H
#define CONTACTOPT_MPRGP_H
/* CG-SSOR with projection (solver.state = cgssor), by the algorithm
   MPRGP: what cgssor.c gives qp.c, the state solver's hub, which alone includes this header. */
#include "qp_private.h"

int cgssor_alloc(Qp_workspace *w, Status *st);
void cgssor_set(Qp_workspace *w);
int cgssor_iterate(Qp_workspace *w, Status *st);
void cgssor_free(Qp_workspace *w);
/* with friction, S, f and the states at x, if no step condensed them */
int cgssor_end(Qp_workspace *w, Status *st);
#endif
