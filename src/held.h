#line 819 "paper/model.nw"
#ifndef CONTACTOPT_HELD_H
#define CONTACTOPT_HELD_H
#include "status.h"
#include "problem.h"
#include "mesh.h"
#include "fem.h"

/* 1 if no side holds the vertical translation e2 */
int held_lift_free(const Problem *p);
/* 0 if the sides and the foundation hold the body against the loads b
   (n, the unknowns of d) at the mesh's design, by the test (H) with the
   slip bounds slip (nt; NULL: none, or Coulomb's); else code, with the
   motion that nothing resists named in st */
int held_check(const Problem *p, const Mesh *m, const Fem_dofs *d,
               const double *b, const double *slip, Status_code code,
               Status *st);
#endif
