#line 104 "paper/figures.nw"
#ifndef CONTACTOPT_PLOT_H
#define CONTACTOPT_PLOT_H
#include <stdio.h>
#include "status.h"

enum { PLOT_BODY = 1, PLOT_RESULTS = 2 };   /* the figures, as bits */
typedef struct {
  const char *dir;     /* the run: an output folder of solve or optimize */
  const char *start;   /* --start: a solve folder, the initial state, or NULL */
  const char *name;    /* -o: the figures' name without extension, or NULL */
  const char *title;   /* --title: the head of every title, or NULL (dir) */
  int figures;         /* PLOT_BODY, PLOT_RESULTS or both */
  int print;           /* --gnuplot: print the scripts, draw nothing */
} Plot_args;

typedef struct {
  char name[2][1200];  /* the names of the body and the results figure */
  int n, drawn[2];     /* the figures drawn: n of them, their indices */
} Plot_drawn;

/* the options of contactopt plot, argv[2..]; STATUS_INPUT if bad */
int plot_args_read(int argc, char **argv, Plot_args *a, Status *st);
/* draw the figures of a->dir with gnuplot (d: their names), or print
   their scripts on out; STATUS_INPUT for a folder that is not a finished
   run's, STATUS_SYSTEM for a figure not written (gnuplot missing or
   failing included), STATUS_INTERRUPTED after SIGINT or SIGTERM */
int plot_run(const Plot_args *a, FILE *out, Plot_drawn *d, Status *st);
#endif
