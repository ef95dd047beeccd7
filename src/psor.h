#line 30 "paper/psor.nw"
#ifndef CONTACTOPT_PSOR_H
#define CONTACTOPT_PSOR_H
/* Projected SOR (solver.state = psor): what psor.c gives qp.c, the state
   solver's hub, which alone includes this header. */
#include "qp_private.h"

int psor_iterate(Qp_workspace *w, Status *st);
#endif
