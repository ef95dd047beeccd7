#line 208 "paper/figures.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "plot_private.h"
#line 1109 "paper/figures.nw"
#define COLW 10.8     /* cm: the plot area of a column */
#define GRAPHH 5.0    /* the height of a graph's row */
#define VHEAD 0.1029  /* the head of a displacement arrow (0.04 m in Fig. 5.2) */
typedef struct {
  double ucm, vex;  /* cm per metre along x1; x2 exaggerated vex times */
  int graphs;       /* rows of graphs under the three rows of bodies */
} Results_page;

static Results_page results_page(const Plot *pl)
{
  const Problem *p = &pl->s.problem;
  Results_page L;
  L.ucm = fmin(COLW / (1.05 * (p->b - p->a)), 7.0 / (1.35 * p->gamma));
  L.vex = p->gamma * L.ucm >= 1.2 ? 1 : plot_nice_down(2.6 / (p->gamma * L.ucm));
  L.graphs = pl->optimize ? (p->contact == CONTACT_FRICTIONLESS ? 1 : 2) : 0;
  return L;
}
#line 1130 "paper/figures.nw"
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
#line 1146 "paper/figures.nw"
static void results_scales(FILE *f, const Plot *pl);
static void results_head(FILE *f, const Plot *pl, const Results_page *L, const char *out)
{
  const Problem *p = &pl->s.problem;
  double W = p->b - p->a;
  plot_script_head(f, pl, "The results", out);
  for (int k = 0; k < 1 + pl->optimize; k++) {
    fprintf(f, "s%d = ", k);
    plot_quote(f, pl->state[k], 0);
    fprintf(f, "                # the %s state\n", k ? "final" : "initial");
  }
  if (pl->optimize) fprintf(f, "opt = "), plot_quote(f, pl->args->dir, 0), fprintf(f, "\n");
  if (pl->args->start) fprintf(f, "start = "), plot_quote(f, pl->args->start, 0), fprintf(f, "\n");
  fprintf(f, "bxlo = %s; bxhi = %s; bylo = %s; byhi = %s    # a body panel\n",
          plot_real(p->a - 0.025 * W, 6), plot_real(p->b + 0.025 * W, 6), plot_real(-0.25 * p->gamma, 6),
          plot_real(1.1 * p->gamma, 6));
  fprintf(f, "ucm = %s; vex = %s              # cm per metre along x1; x2 exaggerated\n"
          "left = 2.8; colw = %s; colgap = 2.4; pw = (bxhi - bxlo)*ucm    # cm\n"
          "top = 2.4; rowgap = 2.3; graphh = %s; bodyh = (byhi - bylo)*ucm*vex\n"
          "Wcm = left + 2*colw + colgap + 0.5\n"
          "graphgap = rowgap + 0.8          # between two rows of graphs, room for x labels\n"
          "Hcm = top + 3*bodyh + 2*rowgap + %d*(rowgap + graphh) + %d*0.8 + 1.6\n",
          plot_real(L->ucm, 6), plot_real(L->vex, 0), plot_real(COLW, 0), plot_real(GRAPHH, 0), L->graphs,
          L->graphs > 1 ? L->graphs - 1 : 0);
  fputs(plot_page_lines, f);
  fprintf(f, "colx(c) = left + c*(colw + colgap)         # the left edge of column c\n"
          "amax(x, y) = x > y ? x : y\n"
          "tens(m) = m > 0 ? floor(log10(m)) : 0       # the power of ten of m\n");
  results_scales(f, pl);
}
#line 1182 "paper/figures.nw"
static void results_power(FILE *f, const Plot *pl, const char *m, const char *e, int c);
static void results_scales(FILE *f, const Plot *pl)
{
  fprintf(f, "umax = 0.2*gamma      # the largest scaled displacement\n"
          "round_down(x) = (p = 10**floor(log10(x)), m = x/p, "
          "(m >= 5 ? 5 : m >= 2 ? 2 : 1) * p)\n");
  for (int k = 0; k < 1 + pl->optimize; k++)
    fprintf(f, "stats s%d.'/nodes.dat' using (sqrt($6**2 + $7**2)) nooutput\n"
            "S%d = STATS_max > 0 ? round_down(umax / STATS_max) : 1\n", k, k);
  if (pl->optimize)
    fprintf(f, "stats opt.'/history.dat' using 2 nooutput\n"
            "ee = tens(amax(abs(STATS_min), abs(STATS_max)))\n");
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
#line 1218 "paper/figures.nw"
static const char *state_name[2] = { "Ω({/:Italic α}^0)", "Ω({/:Italic α}^*)" };

static void body_panel_place(FILE *f, const Plot *pl, const Panel *q)
{
  const Problem *p = &pl->s.problem;
  char x[32], y[64];
  snprintf(x, sizeof x, "colx(%d)", q->col);
  snprintf(y, sizeof y, "top + %d*(bodyh + rowgap)", q->row);
  plot_place(f, x, "pw", y, "bodyh");
  fprintf(f, "  set xrange [bxlo:bxhi]; set yrange [bylo:byhi]\n");
  plot_tics(f, "x", p->a, p->b, 4, 0);
  plot_tics(f, "y", 0, p->gamma, 2, 0);
  fprintf(f, "  set border 3\n");
}

/* the end of a body panel's title: the exaggeration of x2, if any */
static const char *exaggerated(const Results_page *L)
{
  static char buf[64];
  snprintf(buf, sizeof buf, L->vex > 1 ? ", {/:Italic x}_2 ×%g" : "", L->vex);
  return buf;
}
#line 1247 "paper/figures.nw"
static void body_panel(FILE *f, const Plot *pl, const Results_page *L, const Panel *q)
{
  int k = q->state;
  body_panel_place(f, pl, q);
  if (q->kind == MESH)
    fprintf(f, "  set title '(%c) triangulation of %s%s'\n"
            "  set object 1 rect from bxlo, bylo to bxhi, 0 fs pattern 5 noborder fc 'gray50' back\n"
            "  plot s%d.'/triangles.dat' using 1:2 with lines lw 1 lc 'black' notitle\n"
            "  unset object 1\n", q->letter, state_name[k], exaggerated(L), k);
  if (q->kind == DEFORMED)
    fprintf(f, "  set title sprintf('(%c) %s after deformation, displacements × %%g%s', S%d)\n"
            "  plot s%d.'/triangles.dat' using 1:2 with lines lw 0.5 lc 'gray75' notitle, \\\n"
            "       s%d.'/triangles.dat' using ($1 + S%d*$3):($2 + S%d*$4) with lines lw 1 "
            "lc '#1f4e99' notitle\n", q->letter, state_name[k], exaggerated(L), k, k, k, k, k);
  if (q->kind == FIELD)
    fprintf(f, "  set title sprintf('(%c) displacement field ({/:Italic u}_1, {/:Italic u}_2) "
            "× %%g%s', S%d)\n"
            "  plot s%d.'/triangles.dat' using 1:2 with lines lw 0.5 lc 'gray75' notitle, \\\n"
            "       s%d.'/nodes.dat' using 4:5:(S%d*$6):(S%d*$7) with vectors head filled "
            "size cx(%g),20 \\\n           lw 1.2 lc '#b00000' notitle\n",
            q->letter, exaggerated(L), k, k, k, k, k, VHEAD);
}
#line 1275 "paper/figures.nw"
static void graph_place(FILE *f, const Panel *q)
{
  char x[32], y[96];
  snprintf(x, sizeof x, "colx(%d)", q->col);
  if (q->row < 3) snprintf(y, sizeof y, "top + %d*(bodyh + rowgap)", q->row);
  else snprintf(y, sizeof y, "top + 3*(bodyh + rowgap) + %d*(graphh + graphgap)", q->row - 3);
  plot_place(f, x, "colw", y, q->row < 3 ? "bodyh" : "graphh");
}
#line 1291 "paper/figures.nw"
static void energy_graph(FILE *f, const Plot *pl)
{
  double step = plot_nice_up(fmax(1, pl->iterations / 2.0));
  fprintf(f, "  set title '(d) {/:Italic E_h} against iteration'\n"
          "  set xlabel 'iteration' offset 0, 0.4\n"
          "  set ylabel sprintf('{/:Italic E_h} [10^{%%d} J/m]', ee)\n"
          "  set xrange [*:*]; set autoscale xfix; set yrange [*:*]; set offsets 0.5, 0.5, 0, 0\n"
          "  set xtics 0, %s out nomirror; set ytics autofreq out nomirror\n"
          "  set key top right spacing 1.2\n"
          "  plot opt.'/history.dat' using 1:($2/10.0**ee) with linespoints pt 7 ps 0.6 lw 1.5 \\\n"
          "           lc '#1f4e99' title '%s'", plot_num(step), pl->projected ?
          "iterates, from {/:Italic α}^0 projected onto {/:Italic B}" : "iterates");
  if (pl->args->start)
    fprintf(f, ", \\\n       start.'/summary.dat' using (0):(strcol(1) eq 'energy' ? "
            "$2/10.0**ee : NaN) \\\n           with points pt 6 ps 1.2 lc 'black' title '%s'",
            pl->projected ? "{/:Italic α}^0 as given, outside {/:Italic B}"
                          : "{/:Italic α}^0 as given");
  fprintf(f, "\n  set offsets 0, 0, 0, 0\n");
}
#line 1323 "paper/figures.nw"
static void contact_graph(FILE *f, const Plot *pl, const Panel *q)
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
  fprintf(f, q->kind == PRESSURE ? "  set key top left\n" : "  unset key\n");
  fprintf(f, "  plot s0.'/contact.dat' using 1:($%d/10.0**%s) with "
          "linespoints pt '▷' ps 1.3 lw 1.2 \\\n           lc '#b00000' %s", c, e,
          pl->optimize ? "title 'initial {/:Italic α}^0'" : "notitle");
  if (pl->optimize)
    fprintf(f, ", \\\n       s1.'/contact.dat' using 1:($%d/10.0**%s) with linespoints "
            "pt '◁' ps 1.3 lw 1.2 \\\n           lc '#1f4e99' title 'final {/:Italic α}^*'", c, e);
  fprintf(f, "\n");
}
#line 1354 "paper/figures.nw"
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
      fprintf(f, "  unset title; set border 3; set ytics autofreq; set xtics autofreq\n");
    graph_place(f, &q[k]);
    if (q[k].kind == ENERGY) energy_graph(f, pl);
    else contact_graph(f, pl, &q[k]);
  }
  fprintf(f, "  unset multiplot\n  set output\n}\n");
}
