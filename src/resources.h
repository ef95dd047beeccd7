#line 11 "paper/resources.nw"
#ifndef CONTACTOPT_RESOURCES_H
#define CONTACTOPT_RESOURCES_H
#include "status.h"
#include "problem.h"
/* seconds on a monotonic clock: the one clock of the package's timings */
double resources_clock(void);
/* bytes a model of p and its state solve need, estimated before any is
   allocated (see below) */
double resources_memory(const Problem *p);
/* STATUS_MEMORY, naming origin, if the model of p and extra bytes exceed
   the memory this process may use */
int resources_fits(const Problem *p, double extra, const char *origin, Status *st);
#endif
