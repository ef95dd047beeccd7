#line 204 "paper/main.nw"
#ifndef CONTACTOPT_ARGS_H
#define CONTACTOPT_ARGS_H
#include "status.h"
#define MAX_OVERRIDES 64
typedef struct {
  const char *scene;                   /* the scene file */
  const char *outdir;                  /* -o, or NULL for out/NAME */
  const char *matrix_market;           /* --matrix-market FILE, or NULL */
  const char *components;              /* --components LIST, or NULL: all */
  int plot_files;                      /* --plot-files */
  int replace;                         /* --replace: another command's run */
  int noverride;
  char *override[MAX_OVERRIDES];       /* -s section.key=value */
} Args;

/* the options and the scene of argv[2..], for the command argv[1] */
int args_read(int argc, char **argv, Args *a, Status *st);
#endif
