#line 270 "paper/figures.nw"
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "plot_private.h"
#line 2049 "paper/figures.nw"
#define COLW 10.8     /* cm: the plot area of a column */
#define RMARGIN 0.5   /* cm: the page right of the right column */
#define GRAPHH 5.0    /* the height of a graph's row */
#define VHEAD 0.1029  /* the head of a displacement arrow (0.04 m in Fig. 5.2) */
#define MESHCELL 0.15 /* cm: the least cell of the mesh drawn */
#define ARROWCELL 0.3 /* cm: the least distance between two arrows */
#define CROSS 0.02    /* cm: a crossing of x2 = 0 that the title reports */
typedef struct {
  double ucm, vex;    /* cm per metre along x1; x2 exaggerated vex times */
  double pw;          /* cm: a body panel's plot area, centred in its column */
  int graphs;         /* rows of graphs under the three rows of bodies */
  int scol, srow;     /* lines of every scol-th column, every srow-th row */
  int acol, arow;     /* arrows at every acol-th node of every arow-th row */
  int marks;          /* a marker at every marks-th contact node */
  int sinks;          /* the body may move vertically: its sink is drawn unscaled */
  double S[2], t2[2]; /* each state: the scale of its displacements and its sink [m] */
  int below[2];       /* each state: its scaled contact surface crosses x2 = 0 */
  int tris;           /* a part: its triangles drawn (else only its outline) */
} Results_page;
#line 2071 "paper/figures.nw"
static int free_vertically(const Problem *p)
{
  Problem_bc_kind t = p->side[SIDE_TOP].kind;
  for (int s = 0; s < p->part.ncurve; s++)   /* a part's curves hold it as a top */
    if (p->part.curve[s].kind == BC_CLAMPED || p->part.curve[s].kind == BC_ROLLER) return 0;
  return p->side[SIDE_LEFT].kind != BC_CLAMPED && p->side[SIDE_RIGHT].kind != BC_CLAMPED
         && t != BC_CLAMPED && t != BC_ROLLER;
}
#line 2083 "paper/figures.nw"
static double largest(const Plot_state *s, double t2)
{
  double m = 0;
  for (int k = 0; k < s->n; k++)
    m = fmax(m, hypot(s->u[2 * k], s->u[2 * k + 1] - t2));
  return m;
}

static double sink(const Plot_state *s)
{
  double t = 0, touch = 1e-6 * largest(s, 0);
  for (int i = 0; i < s->ncol; i++)
    if (s->xy[2 * i + 1] + s->u[2 * i + 1] <= touch) t = fmin(t, s->u[2 * i + 1]);
  return t;
}
#line 2103 "paper/figures.nw"
static void state_scale(const Plot_state *s, int sinks, double umax, double *S, double *t2)
{
  double m;
  *t2 = sinks ? sink(s) : 0;
  m = largest(s, *t2);
  *S = m > 0 ? fmax(1, plot_nice_down(umax / m)) : 1;
}

/* the contact surface of s drawn with the factor S and the sink t2 lower than -tol */
static int crosses(const Plot_state *s, double S, double t2, double tol)
{
  for (int i = 0; i < s->ncol; i++)
    if (s->xy[2 * i + 1] + t2 + S * (s->u[2 * i + 1] - t2) < -tol) return 1;
  return 0;
}
#line 2123 "paper/figures.nw"
static void least_cell(const Plot_state *s, const Results_page *L, double *w, double *h)
{
  for (int j = 0; j < s->nrow; j++)
    for (int i = 0; i < s->ncol; i++) {
      const double *x = s->xy + 2 * (j * s->ncol + i);
      if (i + 1 < s->ncol) *w = fmin(*w, (x[2] - x[0]) * L->ucm);
      if (j + 1 < s->nrow) *h = fmin(*h, (x[2 * s->ncol + 1] - x[1]) * L->ucm * L->vex);
    }
}
#line 2135 "paper/figures.nw"
/* a part: the side of its mean own triangle on the page, cm */
static double part_cell(const Mesh *m, const Results_page *L)
{
  int first = 2 * m->N * m->M;
  double A = 0;
  for (int t = first; t < m->ntri; t++) A += fabs(mesh_area(m, t));
  return m->ntri > first ? sqrt(2 * A / (m->ntri - first)) * L->ucm * sqrt(L->vex) : 0;
}

static Results_page results_page(const Plot *pl)
{
  const Problem *p = &pl->s.problem;
  double w = HUGE_VAL, h = HUGE_VAL;
  Results_page L;
  L.ucm = fmin(COLW / (1.05 * (pl->right - pl->left)), 7.0 / (1.35 * pl->top));
  L.vex = pl->top * L.ucm >= 1.2 ? 1 : plot_nice_down(2.6 / (pl->top * L.ucm));
  plot_widen(&L.ucm, &L.vex, 1.05 * (pl->right - pl->left) * L.ucm, 1.2, 2.6);
  L.pw = 1.05 * (pl->right - pl->left) * L.ucm;
  L.graphs = pl->optimize ? (p->contact == CONTACT_FRICTIONLESS ? 1 : 2) : 0;
  L.sinks = free_vertically(p);
  for (int k = 0; k < 1 + pl->optimize; k++) {
    least_cell(&pl->mesh[k], &L, &w, &h);
    state_scale(&pl->mesh[k], L.sinks, 0.2 * pl->top, &L.S[k], &L.t2[k]);
    L.below[k] = crosses(&pl->mesh[k], L.S[k], L.t2[k], CROSS / (L.ucm * L.vex));
  }
  L.scol = (int) fmax(1, ceil(MESHCELL / w - SLACK));
  L.srow = (int) fmax(1, ceil(MESHCELL / h - SLACK));
  L.acol = (int) fmax(1, ceil(ARROWCELL / w - SLACK));
  L.arow = (int) fmax(1, ceil(ARROWCELL / h - SLACK));
  L.marks = (int) ceil((p->N + 1.0) / MARKS);
  L.tris = pl->part && part_cell(pl->part, &L) >= 2 * MESHCELL;
  return L;
}
#line 2172 "paper/figures.nw"
enum { MESH, DEFORMED, FIELD, ENERGY, PRESSURE, TANGENTIAL, SLIP };
typedef struct { int col, row; char letter; int kind, state; } Panel;
static const Panel optimize_panels[] = {
  { 0, 0, 'a', MESH, 0 }, { 0, 1, 'b', DEFORMED, 0 }, { 0, 2, 'c', FIELD, 0 },
  { 1, 0, 'e', MESH, 1 }, { 1, 1, 'f', DEFORMED, 1 }, { 1, 2, 'g', FIELD, 1 },
  { 0, 3, 'd', ENERGY, 0 }, { 1, 3, 'h', PRESSURE, 0 },
  { 0, 4, 'i', TANGENTIAL, 0 }, { 1, 4, 'j', SLIP, 0 } };
static const Panel solve_panels[] = {
  { 0, 0, 'a', MESH, 0 }, { 0, 1, 'b', DEFORMED, 0 }, { 0, 2, 'c', FIELD, 0 },
  { 1, 0, 'd', PRESSURE, 0 }, { 1, 1, 'e', TANGENTIAL, 0 }, { 1, 2, 'f', SLIP, 0 } };
#line 2189 "paper/figures.nw"
static void mesh_node(FILE *f, const Plot_state *s, int i, int j)
{
  const double *x = s->xy + 2 * (j * s->ncol + i), *u = s->u + 2 * (j * s->ncol + i);
  fprintf(f, "%.9g %.9g %.10g %.10g\n", x[0], x[1], u[0], u[1]);
}

/* row j (column: 0) or column i (1), every step nodes and the last */
static void mesh_straight(FILE *f, const Plot_state *s, int column, int at, int step)
{
  int n = column ? s->nrow : s->ncol;
  for (int k = 0; k < n; k += step) mesh_node(f, s, column ? at : k, column ? k : at);
  if ((n - 1) % step) mesh_node(f, s, column ? at : n - 1, column ? n - 1 : at);
  fputc('\n', f);
}

static void mesh_diagonal(FILE *f, const Plot_state *s, int i, int j, int step)
{
  for (; i < s->ncol && j < s->nrow; i += step, j += step) mesh_node(f, s, i, j);
  fputc('\n', f);
}
#line 2220 "paper/figures.nw"
static void part_lines(FILE *f, const Plot *pl, const Plot_state *s, int tris);
static void mesh_block(FILE *f, const Plot *pl, const Plot_state *s, int k, int sc, int sr,
                       int tris)
{
  int d = sc < sr ? sc : sr;
  fprintf(f, "$mesh%d << EOD\n", k);
  if (s->part) part_lines(f, pl, s, tris);
  mesh_straight(f, s, 0, 0, 1), mesh_straight(f, s, 0, s->nrow - 1, 1);
  mesh_straight(f, s, 1, 0, 1), mesh_straight(f, s, 1, s->ncol - 1, 1);
  for (int j = sr; j < s->nrow - 1; j += sr) mesh_straight(f, s, 0, j, sc);
  for (int i = sc; i < s->ncol - 1; i += sc) mesh_straight(f, s, 1, i, sr);
  for (int i = 0; i < s->ncol - 1; i += sc) mesh_diagonal(f, s, i, 0, d);
  for (int j = sc; j < s->nrow - 1; j += sc) mesh_diagonal(f, s, 0, j, d);
  fprintf(f, "EOD\n");
}
#line 2252 "paper/figures.nw"
static void part_lines(FILE *f, const Plot *pl, const Plot_state *s, int tris)
{
  const Mesh *m = s->part;
  if (!tris) {
    plot_chains_write(f, m, &pl->chains, s->xy, s->u, 0);
    return;
  }
  for (int t = 2 * m->N * m->M; t < m->ntri; t++) {
    for (int v = 0; v <= 3; v++) {
      int n = m->tri[3 * t + v % 3];
      fprintf(f, "%.9g %.9g %.10g %.10g\n", s->xy[2 * n], s->xy[2 * n + 1], s->u[2 * n],
              s->u[2 * n + 1]);
    }
    fputc('\n', f);
  }
}

/* the nodes that carry an arrow: every c-th of every r-th row, and the
   last row, where the top's load acts */
static void part_arrows(FILE *f, const Plot_state *s, const Results_page *L);
static void arrow_block(FILE *f, const Plot_state *s, const Results_page *L, int k)
{
  int c = L->acol, r = L->arow;
  fprintf(f, "$arrows%d << EOD\n", k);
  for (int j = 0; j < s->nrow; j = j + r < s->nrow || j == s->nrow - 1 ? j + r : s->nrow - 1)
    for (int i = 0; i < s->ncol; i += c) mesh_node(f, s, i, j);
  if (s->part) part_arrows(f, s, L);
  fprintf(f, "EOD\n");
}
#line 2285 "paper/figures.nw"
static void part_arrows(FILE *f, const Plot_state *s, const Results_page *L)
{
  double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
  double cell[2] = { ARROWCELL / L->ucm, ARROWCELL / (L->ucm * L->vex) };
  int first = s->ncol * s->nrow, w, h;
  char *taken;
  for (int k = first; k < s->n; k++)
    for (int i = 0; i < 2; i++)
      lo[i] = fmin(lo[i], s->xy[2 * k + i]), hi[i] = fmax(hi[i], s->xy[2 * k + i]);
  if (s->n <= first) return;
  w = (int) ((hi[0] - lo[0]) / cell[0]) + 1, h = (int) ((hi[1] - lo[1]) / cell[1]) + 1;
  if (!(taken = calloc((size_t) w * h, 1))) return;   /* no arrows in the part */
  for (int k = first; k < s->n; k++) {
    int i = (int) ((s->xy[2 * k] - lo[0]) / cell[0]);
    int j = (int) ((s->xy[2 * k + 1] - lo[1]) / cell[1]);
    if (taken[j * w + i]++) continue;
    fprintf(f, "%.9g %.9g %.10g %.10g\n", s->xy[2 * k], s->xy[2 * k + 1], s->u[2 * k],
            s->u[2 * k + 1]);
  }
  free(taken);
}
#line 2313 "paper/figures.nw"
static void results_scales(FILE *f, const Plot *pl);
static double results_width(const Plot *pl);
static void results_head(FILE *f, const Plot *pl, const Results_page *L, const char *out)
{
  double W = pl->right - pl->left;
  plot_script_head(f, pl, "The results", out);
  for (int k = 0; k < 1 + pl->optimize; k++) {
    fprintf(f, "s%d = ", k);
    plot_quote(f, pl->state[k], 0);
    fprintf(f, "                # the %s state\nS%d = %s; T%d = %s     # its displacements "
            "drawn as T + S*(u - T), T its sink\n", k ? "final" : "initial", k,
            plot_real(L->S[k], 0), k, plot_real(L->t2[k], 6));
  }
  if (pl->optimize) fprintf(f, "opt = "), plot_quote(f, pl->args->dir, 0), fprintf(f, "\n");
  if (pl->args->start) fprintf(f, "start = "), plot_quote(f, pl->args->start, 0), fprintf(f, "\n");
  fprintf(f, "bxlo = %s; bxhi = %s; bylo = %s; byhi = %s    # a body panel\n",
          plot_real(pl->left - 0.025 * W, 6), plot_real(pl->right + 0.025 * W, 6),
          plot_real(-0.25 * pl->top, 6), plot_real(1.1 * pl->top, 6));
  fprintf(f, "ucm = %s; vex = %s              # cm per metre along x1; x2 exaggerated\n"
          "left = 2.8; colw = %s; colgap = 2.4; pw = (bxhi - bxlo)*ucm    # cm\n"
          "top = 2.4; rowgap = 3.0; graphh = %s; bodyh = (byhi - bylo)*ucm*vex\n"
          "Wcm = %s\n"
          "graphgap = rowgap + 0.8          # between two rows of graphs, room for x labels\n"
          "Hcm = top + 3*bodyh + 2*rowgap + %d*(rowgap + graphh) + %d*0.8 + 2.0\n",
          plot_real(L->ucm, 6), plot_real(L->vex, 0), plot_real(COLW, 0), plot_real(GRAPHH, 0),
          plot_real(results_width(pl), 6), L->graphs, L->graphs > 1 ? L->graphs - 1 : 0);
  fputs(plot_page_lines, f);
  fprintf(f, "colx(c) = left + c*(colw + colgap)         # the left edge of column c\n"
          "bodyx(c) = colx(c) + (colw - pw)/2          # and of its body panels\n"
          "amax(x, y) = x > y ? x : y\n"
          "tens(m) = m > 0 ? floor(log10(m)) : 0       # the power of ten of m\n");
  for (int k = 0; k < 1 + pl->optimize; k++) {
    mesh_block(f, pl, &pl->mesh[k], k, L->scol, L->srow, L->tris);
    arrow_block(f, &pl->mesh[k], L, k);
  }
  if (!isnan(pl->start_value))
    fprintf(f, "$start << EOD      # %s at alpha0 as given, from start's summary.dat\n"
            "0 %.15g\nEOD\n", objective_name(pl->s.optimizer.objective.kind), pl->start_value);
  results_scales(f, pl);
}
#line 2356 "paper/figures.nw"
static double results_width(const Plot *pl)
{
  const char *t = pl->args->title ? pl->args->title : pl->args->dir;
  double w = plot_text_cm(t, 12) + plot_text_cm(": numerical results", 12) + 1;
  return fmax(2.8 + 2 * COLW + 2.4 + RMARGIN, w);
}
#line 2368 "paper/figures.nw"
static void results_power(FILE *f, const Plot *pl, const char *m, const char *e, int c);
/* the power of ten of the objective's values in history.dat, 0 for a
   dimensionless one between 0.01 and 1000, or with no history */
static int objective_power(const Plot *pl)
{
  double m = fmax(fabs(pl->jlo), fabs(pl->jhi));
  int e = m > 0 ? (int) floor(log10(m)) : 0;
  if (!*objective_unit(pl->s.optimizer.objective.kind) && e >= -2 && e < 3) e = 0;
  return e;
}

static void results_scales(FILE *f, const Plot *pl)
{
  fprintf(f, "round_down(x) = (p = 10**floor(log10(x)), m = x/p, "
          "(m >= 5 ? 5 : m >= 2 ? 2 : 1) * p)\n");
  if (pl->optimize)
    fprintf(f, "ee = %d      # the objective's power of ten (history.dat; a dimensionless "
            "one in [0.01, 1000) as it is)\n", objective_power(pl));
  results_power(f, pl, "pm", "pe", 6);
  fprintf(f, "plo = pm > 0 ? -0.06*pm/10.0**pe : -1\n");
  if (pl->s.problem.contact != CONTACT_FRICTIONLESS) {
    results_power(f, pl, "tm", "te", 8);
    results_power(f, pl, "um", "ue", 7);
  }
}

/* m = the largest |column c| of the states' contact.dat, e its power of ten,
   e_step the step of tick marks for a short graph of it */
static void results_power(FILE *f, const Plot *pl, const char *m, const char *e, int c)
{
  fprintf(f, "%s = 0\n", m);
  for (int k = 0; k < 1 + pl->optimize; k++)
    fprintf(f, "stats s%d.'/contact.dat' using %d nooutput; "
            "%s = amax(%s, amax(abs(STATS_min), abs(STATS_max)))\n", k, c, m, m);
  fprintf(f, "%s = tens(%s); %s_step = %s > 0 ? round_down(%s/10.0**%s/2) : 1\n",
          e, m, e, m, m, e);
}
#line 2413 "paper/figures.nw"
static const char *state_name[2] = { "Ω({/:Italic α}^0)", "Ω({/:Italic α}^*)" };

static void body_panel_place(FILE *f, const Plot *pl, const Results_page *L, const Panel *q)
{
  const Problem *p = &pl->s.problem;
  char x[32], y[64];
  snprintf(x, sizeof x, "bodyx(%d)", q->col);
  snprintf(y, sizeof y, "top + %d*(bodyh + rowgap)", q->row);
  plot_place(f, x, "pw", y, "bodyh");
  fprintf(f, "  set xrange [bxlo:bxhi]; set yrange [bylo:byhi]\n");
  plot_tics(f, "x", p->a, p->b, fmax(1, fmin(4, floor(L->pw / 2))), 0);
  plot_tics(f, "y", 0, pl->top, 2, 0);
  fprintf(f, "  set border 3\n  set xlabel '{/:Italic x}_1 [m]' offset 0, %s\n"
          "  set ylabel '{/:Italic x}_2 [m]' offset 0.6, 0\n",
          q->kind == DEFORMED && L->below[q->state] ? "-0.6" : "0.4");
}

/* the end of a body panel's title: the exaggeration of x2, if any */
static const char *exaggerated(const Results_page *L)
{
  static char buf[64];
  if (L->vex < 1) snprintf(buf, sizeof buf, ", {/:Italic x}_1 ×%g", 1 / L->vex);
  else snprintf(buf, sizeof buf, L->vex > 1 ? ", {/:Italic x}_2 ×%g" : "", L->vex);
  return buf;
}

/* "every 4th" for n = 4, "every" for n = 1, in buf */
static const char *nth(int n, char *buf, size_t size)
{
  int t = n % 100 >= 11 && n % 100 <= 13 ? 0 : n % 10;
  if (n <= 1) snprintf(buf, size, "every");
  else snprintf(buf, size, "every %d%s", n, t == 1 ? "st" : t == 2 ? "nd" : t == 3 ? "rd" : "th");
  return buf;
}

/* the lines of the mesh left out: ", every 4th line", ", every 6th
   column, every row", or "" for none */
static const char *every(const Results_page *L)
{
  static char buf[96];
  char c[32], r[32];
  nth(L->scol, c, sizeof c), nth(L->srow, r, sizeof r);
  if (L->scol == L->srow)
    snprintf(buf, sizeof buf, L->scol > 1 ? ", %s line" : "", c);
  else snprintf(buf, sizeof buf, ", %s column, %s row", c, r);
  return buf;
}

/* ", one arrow in 12" for the nodes left out, "" for none */
static const char *one_in(const Results_page *L)
{
  static char buf[64];
  snprintf(buf, sizeof buf, L->acol * L->arow > 1 ? ", one arrow in %d" : "", L->acol * L->arow);
  return buf;
}
#line 2475 "paper/figures.nw"
static const char foundation[] =
  "  set object 1 rect from bxlo, bylo to bxhi, 0 fs pattern 5 noborder fc 'gray50' back\n";
static void deformed_title(FILE *f, const Results_page *L, const Panel *q);
static void panel_title(FILE *f, const Results_page *L, int k, const char *fmt, ...);
static void body_panel(FILE *f, const Plot *pl, const Results_page *L, const Panel *q)
{
  int k = q->state;
  body_panel_place(f, pl, L, q);
  if (q->kind == MESH) {
    panel_title(f, L, k, "(%c) triangulation of %s%s%s%s", q->letter, state_name[k],
                exaggerated(L), every(L), pl->part && !L->tris ? ", the part by its outline" : "");
    fprintf(f, "%s  plot $mesh%d using 1:2 with lines lw 1 lc 'black' notitle\n"
            "  unset object 1\n", foundation, k);
  }
  if (q->kind == DEFORMED) {
    deformed_title(f, L, q);
    fprintf(f, "%s  plot $mesh%d using 1:2 with lines lw 0.5 lc 'gray75' notitle, \\\n"
            "       $mesh%d using ($1 + S%d*$3):($2 + T%d + S%d*($4 - T%d)) with lines lw 1 "
            "lc '#1f4e99' notitle\n  unset object 1; unset label 1; set format x\n",
            foundation, k, k, k, k, k, k);
  }
  if (q->kind == FIELD) {
    panel_title(f, L, k, "(%c) displacement field %s × %%g%s%s", q->letter, L->t2[k] < 0
                ? "less the sink" : "({/:Italic u}_1, {/:Italic u}_2)", exaggerated(L), one_in(L));
    fprintf(f, "  plot $mesh%d using 1:2 with lines lw 0.5 lc 'gray75' notitle, \\\n"
            "       $arrows%d using 1:2:(S%d*$3):(S%d*($4 - T%d)) with vectors head filled "
            "size cx(%g),20 \\\n           lw 1.2 lc '#b00000' notitle\n",
            k, k, k, k, k, VHEAD);
  }
}
#line 2518 "paper/figures.nw"
/* cm: the widest title over a body panel of column c */
#define TITLEW(c) (COLW + 2 * ((c) ? RMARGIN : 1.0))
static void panel_title(FILE *f, const Results_page *L, int k, const char *fmt, ...)
{
  char t[512], shown[600];
  va_list ap;
  double w;
  va_start(ap, fmt);
  vsnprintf(t, sizeof t, fmt, ap);
  va_end(ap);
  snprintf(shown, sizeof shown, t, L->S[k]);
  w = plot_text_cm(shown, 12);
  fprintf(f, "  set title sprintf('%s', S%d) font sprintf(',%%g', %s*fsz)\n", t, k,
          plot_real(fmin(1, TITLEW(k) / w), 3));
}
#line 2539 "paper/figures.nw"
static void deformed_title(FILE *f, const Results_page *L, const Panel *q)
{
  int k = q->state;
  char t[64];
  plot_enhanced_number(L->t2[k], t, sizeof t);
  if (L->t2[k] < 0)
    panel_title(f, L, k, "(%c) %s deformed: sink %s m, the rest × %%g%s", q->letter,
                state_name[k], t, exaggerated(L));
  else
    panel_title(f, L, k, "(%c) %s after deformation, displacements × %%g%s", q->letter,
                state_name[k], exaggerated(L));
  if (L->below[k])
    fprintf(f, "  set format x ''; set label 1 'so magnified, Γ_C falls below "
            "{/:Italic x}_2 = 0' at graph 0.5, graph 0 center offset 0, -1\n");
}
#line 2560 "paper/figures.nw"
static void graph_place(FILE *f, const Panel *q, double indent)
{
  char x[64], y[96], w[64];
  snprintf(x, sizeof x, "colx(%d)%s%s", q->col, indent > 0 ? " + " : "",
           indent > 0 ? plot_real(indent, 3) : "");
  snprintf(w, sizeof w, "colw%s%s", indent > 0 ? " - " : "",
           indent > 0 ? plot_real(indent, 3) : "");
  if (q->row < 3) snprintf(y, sizeof y, "top + %d*(bodyh + rowgap)", q->row);
  else snprintf(y, sizeof y, "top + 3*(bodyh + rowgap) + %d*(graphh + graphgap)", q->row - 3);
  plot_place(f, x, w, y, q->row < 3 ? "bodyh" : "graphh");
}
#line 2596 "paper/figures.nw"
#define KEYBAND "0.5"  /* of the objective's range: the band of (d)'s key */
#define KEYFONT "1.0"  /* of the text: the keys of the graphs */
/* the objective in a title, its symbol on an axis */
static void objective_words(const Objective *o, char *title, char *symbol, size_t size)
{
  static const char *const name[] = { "", "compliance ", "pressure spread ", "pressure peak " };
  static const char *const sym[] = { "{/:Italic E_h}", "{/:Italic J_c}", "{/:Italic J_s}",
                                     "{/:Italic J_q}" };
  snprintf(symbol, size, "%s", sym[o->kind]);
  snprintf(title, size, "%s%s", name[o->kind], sym[o->kind]);
  if (objective_has_exponent(o->kind))
    snprintf(title, size, "%s%s, {/:Italic q} = %s", name[o->kind], sym[o->kind], plot_num(o->q));
}

static int objective_format(FILE *f, const Plot *pl);
static void objective_graph(FILE *f, const Plot *pl)
{
  const Objective *o = &pl->s.optimizer.objective;
  const char *unit = objective_unit(o->kind);
  double step = plot_nice_up(fmax(1, pl->iterations / 6.0));
  char title[128], sym[64];
  int formatted = objective_format(f, pl);
  objective_words(o, title, sym, sizeof title);
  fprintf(f, "  set title '(d) %s against iteration'\n"
          "  set xlabel 'iteration' offset 0, 0.4\n", title);
  if (*unit) fprintf(f, "  set ylabel sprintf('%s [10^{%%d}%s]', ee) offset -0.4, 0\n", sym, unit);
  else fprintf(f, "  set ylabel (ee == 0 ? '%s' : sprintf('%s [10^{%%d}]', ee)) offset -0.4, 0\n",
               sym, sym);
  fprintf(f, "  set xrange [*:*]; set autoscale xfix; set yrange [*:*]; set autoscale yfix\n"
          "  set offsets 0.5, 0.5, graph %s, graph 0.05   # a band for the key above the points\n"
          "  set xtics 0, %s out nomirror; set ytics autofreq out nomirror\n"
          "  keyfont = sprintf(',%%g', %s*fsz); "
          "set key top right spacing 1.2 samplen 2 font keyfont\n"
          "  plot opt.'/history.dat' using 1:($2/10.0**ee) with linespoints pt 7 ps 0.6 "
          "lw 1.5 \\\n           pi %d lc '#1f4e99' title '%s'", KEYBAND, plot_num(step),
          KEYFONT,
          (int) ceil((pl->iterations + 1.0) / MARKS), pl->projected ?
          "iterates from {/:Italic P_B}({/:Italic α}^0)" : "iterates");
  if (!isnan(pl->start_value))
    fprintf(f, ", \\\n       $start using 1:($2/10.0**ee) with points pt 6 ps 1.2 lc 'black' "
            "title '%s'", pl->projected ? "{/:Italic α}^0 (outside {/:Italic B})"
                                        : "{/:Italic α}^0 as given");
  fprintf(f, "\n  set offsets 0, 0, 0, 0\n%s", formatted ? "  set format y\n" : "");
}
#line 2658 "paper/figures.nw"
/* gnuplot's step of tick marks for a range r (quantize_normal_tics, guide 20) */
static double gnuplot_step(double r)
{
  double power = pow(10, floor(log10(r))), xnorm = r / power, posns = 20 / xnorm;
  double t = posns > 40 ? 0.05 : posns > 20 ? 0.1 : posns > 10 ? 0.2 : posns > 4 ? 0.5
           : posns > 2 ? 1 : posns > 0.5 ? 2 : ceil(xnorm);
  return t * power;
}

/* the characters of (d)'s widest tick label, 0 without a history; *step:
   gnuplot's step between them, in units of 10^ee */
static int objective_ticks(const Plot *pl, double *step)
{
  double lo = pl->jlo, hi = pl->jhi;
  if (isnan(lo)) return 0;
  int e = objective_power(pl);
  if (!isnan(pl->start_value)) lo = fmin(lo, pl->start_value), hi = fmax(hi, pl->start_value);
  lo /= pow(10, e), hi /= pow(10, e);
  if (hi == lo) lo -= lo ? 0.01 * fabs(lo) : 1, hi += hi ? 0.01 * fabs(hi) : 1;
  double d = hi - lo;
  lo -= 0.05 * d, hi += atof(KEYBAND) * d;
  *step = gnuplot_step(hi - lo);
  return plot_tick_chars(lo, *step, hi);
}

/* cm: how far (d) starts right of its column, for its widest tick label */
static double objective_indent(const Plot *pl)
{
  double step;
  int chars = objective_ticks(pl, &step);
  return chars ? fmax(0, plot_tick_room(PLOT_GRAPH_BASE, chars, results_width(pl)) - 2.8) : 0;
}

/* (d)'s tick labels with the decimals of their step, where they are
   long; 1 if so */
static int objective_format(FILE *f, const Plot *pl)
{
  double step;
  if (objective_ticks(pl, &step) <= 4) return 0;
  fprintf(f, "  set format y '%%.%df'\n", plot_decimals(step));
  return 1;
}
#line 2722 "paper/figures.nw"
/* the largest pressure (column 6) of the states' contact.dat at x1 in
   [lo, hi], 0 where none; the largest of all in *top */
static double pressure_in(const Plot *pl, double lo, double hi, double *top)
{
  double in = 0;
  *top = 0;
  for (int k = 0; k < 1 + pl->optimize; k++) {
    char path[1200], line[1024];
    double v[6];
    snprintf(path, sizeof path, "%s/contact.dat", pl->state[k]);
    FILE *f = fopen(path, "r");
    while (f && fgets(line, sizeof line, f))
      if (line[0] != '#' && sscanf(line, "%lf %lf %lf %lf %lf %lf", v, v + 1, v + 2, v + 3,
                                   v + 4, v + 5) == 6) {
        *top = fmax(*top, v[5]);
        if (v[0] >= lo && v[0] <= hi) in = fmax(in, v[5]);
      }
    if (f) fclose(f);
  }
  return in;
}

/* the key of the pressure graph: a free corner, or a band above the points */
static void pressure_key(FILE *f, const Plot *pl)
{
  const Problem *p = &pl->s.problem;
  double w = 0.4 * (p->b - p->a), top;
  const char *corner = "left";
  if (pressure_in(pl, p->a, p->a + w, &top) > 0.6 * top) {
    corner = "right";
    if (pressure_in(pl, p->b - w, p->b, &top) > 0.6 * top) {
      corner = "left";
      fprintf(f, "  set offsets 0, 0, graph %s, 0   # a band for the key above the points\n",
              KEYBAND);
    }
  }
  fprintf(f, "  keyfont = sprintf(',%%g', %s*fsz); set key top %s font keyfont\n", KEYFONT,
          corner);
}

static void contact_graph(FILE *f, const Plot *pl, const Results_page *L, const Panel *q)
{
  const Problem *p = &pl->s.problem;
  int c = q->kind == PRESSURE ? 6 : q->kind == TANGENTIAL ? 8 : 7;
  const char *e = q->kind == PRESSURE ? "pe" : q->kind == TANGENTIAL ? "te" : "ue";
  fprintf(f, "  set title '(%c) %s along Γ_C'\n", q->letter, q->kind == PRESSURE ?
          "contact pressure" : q->kind == TANGENTIAL ? "tangential force"
          : "tangential displacement (slip)");
  if (q->row >= 3) fprintf(f, "  set xlabel '{/:Italic x}_1 [m]' offset 0, 0.4\n");
  fprintf(f, "  set ylabel sprintf('%s [10^{%%d} %s]', %s)\n", q->kind == PRESSURE ?
          "−{/:Italic T}_2" : q->kind == TANGENTIAL ? "{/:Italic T}_t" : "{/:Italic u}_1",
          q->kind == PRESSURE ? "N/m^2" : q->kind == TANGENTIAL ? "N/m" : "m", e);
  fprintf(f, "  set xrange [%s:%s]; ", plot_num(p->a), plot_num(p->b));
  if (q->kind == PRESSURE) fprintf(f, "set yrange [plo:*]\n");
  else fprintf(f, "set yrange [*:*]; if (%cm == 0) { set yrange [-1:1] }\n", e[0]);
  plot_tics(f, "x", p->a, p->b, 4, 0);
  if (q->row < 3) fprintf(f, "  set ytics %s_step out nomirror\n", e);
  if (q->kind == PRESSURE && pl->optimize) pressure_key(f, pl);
  else if (q->kind == PRESSURE)
    fprintf(f, "  keyfont = sprintf(',%%g', %s*fsz); set key top left font keyfont\n", KEYFONT);
  else fprintf(f, "  unset key\n");
  fprintf(f, "  plot s0.'/contact.dat' using 1:($%d/10.0**%s) with "
          "linespoints pt '▷' ps 1.3 lw 1.2 pi %d \\\n           lc '#b00000' %s", c, e,
          L->marks, pl->optimize ? "title 'initial {/:Italic α}^0'" : "notitle");
  if (pl->optimize)
    fprintf(f, ", \\\n       s1.'/contact.dat' using 1:($%d/10.0**%s) with linespoints "
            "pt '◁' ps 1.3 lw 1.2 pi %d \\\n           lc '#1f4e99' title 'final {/:Italic α}^*'",
            c, e, L->marks);
  fprintf(f, "\n  set offsets 0, 0, 0, 0\n");
}
#line 2797 "paper/figures.nw"
void plot_results_figure(FILE *f, const Plot *pl, const char *out)
{
  Results_page L = results_page(pl);
  const Panel *q = pl->optimize ? optimize_panels : solve_panels;
  int n = pl->optimize ? 8 : 4;
  if (pl->s.problem.contact != CONTACT_FRICTIONLESS) n += 2;
  results_head(f, pl, &L, out);
  fprintf(f, "do for [fmt in 'pdf png'] {\n%s", plot_terminal_lines);
  fprintf(f, "  set multiplot title sprintf('%%s: numerical results', title)\n");
  for (int k = 0; k < n; k++) {
    if (q[k].kind <= FIELD) { body_panel(f, pl, &L, &q[k]); continue; }
    if (k > 0 && q[k - 1].kind <= FIELD)
      fprintf(f, "  unset title; set title font sprintf(',%%g', fsz)\n"
              "  set border 3; set ytics autofreq; set xtics autofreq\n");
    graph_place(f, &q[k], q[k].kind == ENERGY ? objective_indent(pl) : 0);
    if (q[k].kind == ENERGY) objective_graph(f, pl);
    else contact_graph(f, pl, &L, &q[k]);
  }
  fprintf(f, "  unset multiplot\n  set output\n}\n");
}
