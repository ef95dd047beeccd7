#line 133 "paper/coulomb.nw"
#ifndef CONTACTOPT_COULOMB_H
#define CONTACTOPT_COULOMB_H
#include "status.h"
#include "model.h"
#include "objective.h"

/* the course of a fixed point: tol in, the rest out */
typedef struct {
  double tol;        /* the relative change of T to reach (solver.tol) */
  int iterations;    /* Tresca solves after the first */
  double residual;   /* the last relative change of T */
  int steps;         /* the state solver's iterations over the solves
                        before the last */
} Coulomb_fixed_point;

/* the state of a Coulomb problem at the model's design, by successive
   approximations: state (the model's one state solve) under the bounds
   slip (nt, the model's, written here) = friction T of the last normal forces,
   to fp->tol; rounding 1: on past it to the rounding of the forces (for
   a gradient).  STATUS_NUMERIC when it stops short, or state's status. */
int coulomb_fixed_point(Model *md, int (*state)(Model *, Status *),
                        double *slip, int rounding, Coulomb_fixed_point *fp,
                        Status *st);
/* G (N+1) = dJ/dX of the objective o at the Coulomb state the model
   solved last, through its fixed point s = friction T on the state's
   contact, stick and slip sets */
int coulomb_gradient(const Model *md, const Objective *o, double *G,
                     Status *st);
#endif
