#line 326 "paper/output.nw"
#ifndef CONTACTOPT_OUTPUT_PRIVATE_H
#define CONTACTOPT_OUTPUT_PRIVATE_H
/* The output module's own header: the files output*.c include it, no
   other module does. */
#include <signal.h>
#include <stdio.h>
#include "output.h"

#line 440 "paper/output.nw"
#define ITERATE_PREFIX "iterate-"     /* the VTU of an iterate, in iterates/ */
#define ITERATE_VTU ITERATE_PREFIX "%04d.vtu"
#line 537 "paper/output.nw"
/* status_set with the code of errno e: STATUS_MEMORY for ENOMEM */
int output_errno(Status *st, int e, const char *path, const char *what);
#line 367 "paper/output.nw"
/* *mark = v, after every write before it, as a signal handler sees them */
void output_publish(volatile sig_atomic_t *mark, int v);
/* close f, the file dir/name: STATUS_SYSTEM if a write failed */
int output_finish(FILE *f, const char *dir, const char *name, Status *st);
/* stage the folder name whole, its files not remembered one by one */
int output_folder(Output *o, const char *name, Status *st);
/* open the file name of the state in the sub-folder sub ("" for none) */
FILE *output_open_in(Output *o, const char *sub, const char *name,
                     Status *st);
/* open the file name in the folder staged whole */
FILE *output_open_in_folder(Output *o, const char *folder,
                            const char *name, Status *st);
#line 1136 "paper/output.nw"
/* the displacement u_c of a node, 0 where it is held */
double output_u(const Model *md, int node, int c);
/* write the state of md at the design X as a VTU file into f */
int output_vtu_write(FILE *f, const Model *md, const double *X, Status *st);
/* solution.vtu in the sub-folder sub: the state of md at X */
int output_vtu(Output *o, const char *sub, const Model *md, const double *X,
               Status *st);
#line 1446 "paper/output.nw"
/* the lines of a summary that the friction law adds (none without) */
void output_friction(FILE *f, const Model *md);
/* the lines of a summary of the model's state: the reactions of its held
   sides, the peak contact pressure, the contact length, the largest von
   Mises stress (model_summary's ms) */
void output_reactions(FILE *f, const Model *md, const Model_summary *ms);
/* J = every objective at the model's state, the peak's exponent q, NaN
   where undefined (a body that lifts off has no pressure); the status
   of an objective that failed otherwise (out of memory) */
int output_objectives(const Model *md, double q, Objective_values *J, Status *st);
#line 339 "paper/output.nw"
#endif
