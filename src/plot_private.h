#line 161 "paper/figures.nw"
#ifndef CONTACTOPT_PLOT_PRIVATE_H
#define CONTACTOPT_PLOT_PRIVATE_H
#include <stdio.h>
#include "plot.h"
#include "scene.h"
#include "objective.h"
#include "mesh.h"
#line 457 "paper/figures.nw"
typedef struct {
  int ncol, nrow;   /* N+1 columns and M+R+1 rows: node (i,j) is j*ncol + i */
  int n;            /* all nodes: ncol*nrow, then a part's own */
  const Mesh *part; /* a part: its triangles and boundary edges; NULL for
                       the rectangle */
  double *xy;       /* 2 per node: x1, x2 [m] */
  double *u;        /* 2 per node: u1, u2 [m] */
} Plot_state;
/* the state in dir/solution.vtu, of the mesh of p (of part, a part's
   mesh, when not NULL); STATUS_INPUT for a file that is not such a
   state, STATUS_MEMORY */
int plot_state_read(const char *dir, const Problem *p, const Mesh *part, Plot_state *s,
                    Status *st);
void plot_state_free(Plot_state *s);
#line 611 "paper/figures.nw"
typedef struct {
  int nchain;   /* chains of boundary edges */
  int *order;   /* nedge: the edges chain by chain, each one's end the next one's start */
  int *start;   /* nchain + 1: chain k is order[start[k] .. start[k+1] - 1] */
  int *closed;  /* nchain: it ends at its first node */
} Plot_chains;
/* m's boundary edges in chains; nonzero when out of memory */
int plot_chains(const Mesh *m, Plot_chains *c);
void plot_chains_free(Plot_chains *c);
/* the signed area that chain k closed by a straight line encloses, m^2 */
double plot_chain_area(const Mesh *m, const Plot_chains *c, int k, const double *xy);
/* the chains as polylines, a line a node ("x1 x2", or "x1 x2 u1 u2" if
   u), a blank line after each: the holes (which < 0), the rest (which >
   0), or all (which == 0) */
void plot_chains_write(FILE *f, const Mesh *m, const Plot_chains *c, const double *xy,
                       const double *u, int which);
#line 284 "paper/figures.nw"
typedef struct {
  const Plot_args *args;
  Scene s;                 /* DIR/effective.scene, alpha0 its first design */
  int optimize;            /* DIR is optimize's (history.dat, initial/, final/) */
  int projected;           /* its start was projected onto B */
  int iterations;          /* its iterations */
  char state[2][1100];     /* the folders of its states: initial, final */
  Plot_state mesh[2];      /* their meshes and displacements (results only) */
  Mesh *part;              /* a part of the user's own: its mesh, rebuilt
                              from the scene; NULL for the rectangle */
  double top;              /* the body's top: gamma, or the part's */
  double left, right;      /* its extent in x1: a and b, or the part's */
  Plot_chains chains;      /* a part: its boundary edges in chains */
  double start_value;      /* --start: the objective at alpha0 as given, or NaN */
  double jlo, jhi;         /* the least and the greatest objective of
                              history.dat (NaN: none) */
} Plot;
#line 171 "paper/figures.nw"
#define SLACK 1e-9    /* relative: what a round number may be off by */
#define MARKS 33      /* the most markers along a curve of the contact surface */
#line 1369 "paper/figures.nw"
#define WALL 0.528    /* cm: the wall of a clamp (0.12 m in Fig. 5.1) */
#define ROLLER 0.154  /* a roller's radius (0.035 m) */
#define RWALL 0.352   /* the wall behind the rollers (0.08 m) */
#define LGAP 0.22     /* between a decoration and the side's name */
#line 1546 "paper/figures.nw"
#define ARROW 1.232   /* cm: a load arrow (0.28 m in Fig. 5.1) */
#define AGAP 0.088    /* between the side and the arrow (0.02 m) */
#define ASTEP 1.1     /* between two arrows (0.25 m) */
#define AHEAD 0.264   /* the arrow's head (0.06 m) */
#line 174 "paper/figures.nw"
/* a part's named curves on the body figure: the decorations of their
   conditions and their names, at ucm cm a metre, x2 exaggerated vex times */
void plot_part_curves(FILE *f, const Plot *pl, double ucm, double vex);
/* how far those whose names stand beside them (sideways) or above or
   below them (!sideways) reach out of the body, their names included, cm */
double plot_part_reach(const Plot *pl, double ucm, double vex, int sideways);
/* a part's materials on the body figure: the data block $interfaces of
   the edges between triangles of two materials (the strip's among them),
   and a label naming each region of a material of its own */
void plot_part_interfaces(FILE *f, const Plot *pl);
void plot_part_region_labels(FILE *f, const Plot *pl);
/* the lines that set up the page and the terminal of every script */
extern const char plot_page_lines[], plot_terminal_lines[];
/* v as gnuplot reads it back exactly; in a static buffer of 8 */
const char *plot_num(double v);
/* v with at most digits significant digits (all of them at 0) */
const char *plot_real(double v, int digits);
/* v as enhanced text in buf: -5.75e8 as −5.75·10^{8} */
void plot_enhanced_number(double v, char *buf, size_t size);
/* s in gnuplot's quotes; enhanced: its markup escaped */
void plot_quote(FILE *f, const char *s, int enhanced);
/* round numbers (1, 2 or 5 times a power of ten) below, above and near x */
double plot_nice_down(double x);
double plot_nice_up(double x);
double plot_nice(double x);
/* tick marks of axis from first by step to last, and some n tick marks
   on [lo, hi] at a round step; format: with a fixed number of decimals */
void plot_tics_at(FILE *f, const char *axis, double first, double step,
                  double last, int format);
void plot_tics(FILE *f, const char *axis, double lo, double hi, double n, int format);
/* the head of a script: the figure, the run, and the variables of both */
void plot_script_head(FILE *f, const Plot *pl, const char *what, const char *out);
/* a panel's plot area, in centimetres on the page */
void plot_place(FILE *f, const char *x, const char *w, const char *y, const char *h);
/* the width on the page of enhanced text s at pt points, in cm (an
   estimate: DejaVu Sans averages 0.6 of its size a character) */
double plot_text_cm(const char *s, double pt);
/* the characters of the widest label of tick marks from first to last
   (first <= last) printed with the decimals of step ('%.*f') */
int plot_tick_chars(double first, double step, double last);
/* the decimals that tick marks a step apart need */
int plot_decimals(double step);
/* cm: the room left of an axis that its name and tick labels of chars
   characters take on a page Wcm wide, with base ems for the name, the
   tick marks and the gaps (PLOT_BODY_BASE, PLOT_GRAPH_BASE) */
double plot_tick_room(double base, int chars, double Wcm);
#define PLOT_BODY_BASE 2.67    /* ems: the body figure's x2 axes */
#define PLOT_GRAPH_BASE 3.0    /* ems: a graph's axis, its name offset -0.4 */
/* a body w cm wide on the page, under least cm: x1 exaggerated a round
   number of times, to about want cm (*ucm times it, *vex divided by it) */
void plot_widen(double *ucm, double *vex, double w, double least, double want);
/* the scripts of the two figures */
void plot_body_figure(FILE *f, const Plot *pl, const char *out);
void plot_results_figure(FILE *f, const Plot *pl, const char *out);
#endif
