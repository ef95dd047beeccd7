#line 197 "paper/design.nw"
#ifndef CONTACTOPT_DESIGN_PRIVATE_H
#define CONTACTOPT_DESIGN_PRIVATE_H
#include "design.h"
/* the weight of node i in the trapezoid rule of the area */
double design_weight(const Design_set *B, int i);
/* STATUS_INPUT unless B is a design set that is not empty */
int design_check_set(const Design_set *B, Status *st);
/* STATUS_NUMERIC unless every component of Y, named what, is finite */
int design_check_point(const Design_set *B, const double *Y,
                       const char *what, Status *st);
#endif
