#line 27 "paper/output.nw"
#ifndef CONTACTOPT_OUTPUT_H
#define CONTACTOPT_OUTPUT_H
#include <stdio.h>
#include "status.h"
#include "model.h"

#define OUTPUT_MAX_FILES 64
typedef struct {
  char dir[1024];                     /* the output folder */
  char stage[1100];                   /* the staging folder beside it */
  int nfiles;                         /* files written so far */
  char file[OUTPUT_MAX_FILES][128];   /* their names relative to dir */
} Output;

int output_begin(Output *o, const char *dir, Status *st);
FILE *output_open(Output *o, const char *name, Status *st);
int output_close(Output *o, FILE *f, Status *st);
int output_commit(Output *o, Status *st);
void output_abort(Output *o);
/* the files of the state at the model's last design, in folder sub/ */
int output_state(Output *o, const char *sub, const Model *md,
                 const double *X, Status *st);
#endif
