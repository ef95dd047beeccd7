#line 147 "paper/output.nw"
#ifndef CONTACTOPT_OUTPUT_H
#define CONTACTOPT_OUTPUT_H
#include <signal.h>
#include <stdio.h>
#include "status.h"
#include "model.h"
#include "grad.h"
#include "opt.h"
#include "objective.h"

#define OUTPUT_MAX_FILES 64
#define OUTPUT_PATH 1024              /* room for a path the program writes */
typedef struct {
  char dir[OUTPUT_PATH];              /* the output folder */
  char command[16];                   /* solve, optimize, gradcheck */
  int plot_files;                     /* also nodes.dat, triangles.dat */
  char stage[1100];                   /* the staging folder beside it */
  char file[OUTPUT_MAX_FILES][128];   /* the files' names relative to dir */
  /* what a signal handler may read (output_abort_now): */
  volatile sig_atomic_t staged;       /* stage is named, and may exist */
  volatile sig_atomic_t nfiles;       /* files (and folders) staged so far */
  volatile sig_atomic_t opening;      /* 1 while file[nfiles] is created */
  volatile sig_atomic_t iterates;     /* iterates/ holds iterate 0 .. this - 1 */
} Output;

/* dir = the folder name given, its trailing slashes dropped; STATUS_INPUT
   if it is empty, too long, or . or .. (a folder that cannot be replaced) */
int output_dir_name(const char *given, char *dir, size_t size, Status *st);
/* STATUS_INPUT if dir is there and not a run's folder (nor empty), or
   the run of another command than command and not replace; STATUS_SYSTEM
   if it cannot be created or replaced where it is */
int output_check(const char *dir, const char *command, int replace, Status *st);
/* for a file written after the commit into dir (the matrix): STATUS_INPUT
   if its name is empty or too long, STATUS_SYSTEM if it cannot be created
   (its folder is neither there and writable nor dir itself) */
int output_check_file(const char *path, const char *dir, Status *st);
/* stage the run of command into dir, checked by output_check */
int output_begin(Output *o, const char *dir, const char *command, int replace,
                 Status *st);
FILE *output_open(Output *o, const char *name, Status *st);
int output_close(Output *o, FILE *f, Status *st);
int output_commit(Output *o, Status *st);
void output_abort(Output *o);
/* output_abort from a signal handler (o an Output *): async-signal-safe,
   by the names staged, for a handler that interrupts the program anywhere */
void output_abort_now(void *o);
/* commit when rc is STATUS_OK, else abort; returns rc or the commit's */
int output_end(Output *o, int rc, Status *st);
/* the files of the state at the model's last design, in folder sub/ */
int output_state(Output *o, const char *sub, const Model *md,
                 const double *X, Status *st);
/* out/NAME + suffix for the scene file path/NAME.scene */
void output_default_dir(const char *scene, const char *suffix, char *dir,
                        size_t size);
#line 211 "paper/output.nw"
typedef struct {
  const char *scene;        /* the scene file, as given */
  const char *state_solver; /* the name of the state solver */
  const char *optimizer;    /* the name of the optimiser */
  const char *metric;       /* the name of its metric */
  const Objective *objective; /* what the optimiser minimises */
} Output_run;

/* solve: the state files at X and summary.dat */
int output_solve(Output *o, const Output_run *run, const Model *md,
                 const double *X, Status *st);
/* A(X) of the model's last design, Dirichlet DOFs removed, into path */
int output_matrix_market(const char *path, const Model *md, Status *st);
/* gradcheck: summary.dat and gradient.dat, the model solved at X */
int output_gradcheck(Output *o, const Output_run *run, const Model *md,
                     const Grad_check *gc, Status *st);
#line 235 "paper/output.nw"
typedef struct {
  int n, size;              /* iterations recorded, room */
  int ndesign;              /* N+1 */
  Opt_progress *p;          /* n: the progress of each iteration */
  double *X;                /* n x ndesign: the iterates */
  int failed;               /* out of memory while recording */
  Output *o;                /* with VTUs: the output receiving iterates/ */
  const Model *md;          /* with VTUs: the model, at each iterate */
  Status vtu;               /* the first VTU not written; code 0: none */
  Objective_kind objective; /* the objective of the progress' values */
} Output_history;

Output_history *output_history_new(int ndesign, Status *st);
/* from now on output_history_add also writes the state of md, which must
   be at the iterate, as iterates/iterate-NNNN.vtu (NNNN the iteration)
   into o, and output_history the collection iterates.pvd */
int output_history_vtu(Output_history *h, Output *o, const Model *md,
                       Status *st);
void output_history_add(Output_history *h, const Opt_progress *p,
                        const double *X);
void output_history_free(Output_history *h);
/* history.dat and iterates.dat of the design problem p */
int output_history(Output *o, const Problem *p, const Output_history *h,
                   Status *st);
/* multipliers.dat: X, G = grad E(X) and the multipliers m of min_B E */
int output_multipliers(Output *o, const Problem *p, const double *X,
                       const double *G, const Design_multipliers *m,
                       Status *st);
#line 268 "paper/output.nw"
typedef struct {
  double energy;            /* E at the start, in B */
  double cv;                /* the contact-pressure CV there */
  double moved;             /* ||start - alpha0||_2, 0: alpha0 was in B */
  Objective_values J;       /* every objective there (NaN: undefined) */
} Output_start;

/* initial/: the state files at the start X, solved by the model; start
   receives what the summary will say of it, the pressure peak at q */
int output_start(Output *o, const Model *md, const double *X, double moved,
                 double q, Output_start *start, Status *st);
int output_opt_summary(Output *o, const Output_run *run, const Model *md,
                       const Output_start *start, const Opt_report *r,
                       double mu, Status *st);
#line 204 "paper/output.nw"
#endif
