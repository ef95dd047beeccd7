#line 195 "paper/pdas.nw"
#ifndef CONTACTOPT_PDAS_H
#define CONTACTOPT_PDAS_H
/* The primal-dual active set method (solver.state = pdas): what pdas.c
   gives qp.c, the state solver's hub, which alone includes this header. */
#include "qp_private.h"

int pdas_alloc(Qp_workspace *w, Status *st);
void pdas_set(Qp_workspace *w, int warm);
int pdas_iterate(Qp_workspace *w, Status *st);
void pdas_free(Qp_workspace *w);
#endif
