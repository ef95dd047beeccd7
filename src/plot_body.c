#line 242 "paper/figures.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "plot_private.h"
#line 1376 "paper/figures.nw"
#define LROOM 1.4     /* room for the name */
#define BELOW 0.88    /* the foundation, drawn under x2 = 0 */
#define ABOVE 0.88    /* room above the top's decoration */

typedef struct {
  double ucm, vex;            /* cm per metre along x1; x2 exaggerated vex times */
  double ext[SIDE_COUNT];     /* each side's decoration outside the body, cm */
  double xlo, xhi, ylo, yhi;  /* the upper panel, m */
  double top;                 /* cm above the upper panel */
  double slo, shi, exag;      /* the strip: slo < x2 < shi, exaggerated exag times */
  double width;               /* cm: the page */
  double left;                /* cm: the page left of the panels */
} Body_page;
#line 1393 "paper/figures.nw"
/* the rollers along a side of n cm */
static int rollers(double n) { return (int) fmax(1, floor(n / 0.88 + 0.5) - 1); }
#line 1401 "paper/figures.nw"
static const char hatch[] = "fs pattern 4 noborder fc 'gray40' back";

/* a clamp or rollers on the left (s = -1) or the right (s = 1) side at x,
   from end up to top */
static void side_support(FILE *f, Problem_bc_kind kind, const char *x, const char *end,
                         int s, int n, const char *top)
{
  if (kind == BC_CLAMPED && s < 0)
    fprintf(f, "  set object rect from %s - cx(%g), %s to %s, %s %s\n",
            x, WALL, end, x, top, hatch);
  if (kind == BC_CLAMPED && s > 0)
    fprintf(f, "  set object rect from %s, %s to %s + cx(%g), %s %s\n",
            x, end, x, WALL, top, hatch);
  if (kind != BC_ROLLER) return;
  fprintf(f, "  do for [k=1:%d] {\n"
          "    set object circle at %s %c cx(%g), %s + k*(%s - %s)/%d size cx(%g) \\\n"
          "        fs empty border lc 'black' lw 1.5 front\n  }\n", n, x,
          s > 0 ? '+' : '-', ROLLER, end, top, end, n + 1, ROLLER);
  fprintf(f, "  set object rect from %s %c cx(%g), %s to %s %c cx(%g), %s %s\n",
          x, s > 0 ? '+' : '-', 2 * ROLLER, end, x, s > 0 ? '+' : '-',
          2 * ROLLER + RWALL, top, hatch);
  fprintf(f, "  set arrow from %s %c cx(%g), %s to %s %c cx(%g), %s "
          "nohead lw 1.5 lc 'black' back\n", x, s > 0 ? '+' : '-', 2 * ROLLER,
          end, x, s > 0 ? '+' : '-', 2 * ROLLER, top);
}
#line 1429 "paper/figures.nw"
static void top_support(FILE *f, Problem_bc_kind kind, int n)
{
  if (kind == BC_CLAMPED)
    fprintf(f, "  set object rect from a, gamma to b, gamma + cy(%g) %s\n", WALL, hatch);
  if (kind != BC_ROLLER) return;
  fprintf(f, "  do for [k=1:%d] {\n"
          "    set object circle at a + k*(b - a)/%d, gamma + cy(%g) size cx(%g) \\\n"
          "        fs empty border lc 'black' lw 1.5 front\n  }\n", n, n + 1,
          ROLLER, ROLLER);
  fprintf(f, "  set object rect from a, gamma + cy(%g) to b, gamma + cy(%g) %s\n",
          2 * ROLLER, 2 * ROLLER + RWALL, hatch);
  fprintf(f, "  set arrow from a, gamma + cy(%g) to b, gamma + cy(%g) "
          "nohead lw 1.5 lc 'black' back\n", 2 * ROLLER, 2 * ROLLER);
}
#line 1448 "paper/figures.nw"
static double load_reach(const Problem_side *sd, int k);
#define ALABEL 0.484  /* a load's value beyond its arrows (0.11 m) */
static double side_reach(const Problem_side *sd, int k)
{
  switch (sd->kind) {
  case BC_CLAMPED: return WALL;
  case BC_ROLLER: return 2 * ROLLER + RWALL;
  case BC_TRACTION: return load_reach(sd, k) + (k == SIDE_TOP ? 0 : ALABEL + 0.5);
  default: return 0;
  }
}
#line 1464 "paper/figures.nw"
static void body_fit(const Plot *pl, Body_page *L);
static Body_page body_page(const Plot *pl)
{
  const Problem *p = &pl->s.problem;
  double W = pl->right - pl->left, amax = 0;
  Body_page L;
  for (int i = 0; i <= p->N; i++) amax = fmax(amax, pl->s.alpha0[i]);
  L.ucm = fmin(17.6 / W, 8.8 / pl->top);
  L.vex = pl->top * L.ucm >= 1.76 ? 1 : plot_nice_down(3.52 / (pl->top * L.ucm));
  plot_widen(&L.ucm, &L.vex, W * L.ucm, 1.76, 3.52);
  for (int k = 0; k < SIDE_COUNT; k++) L.ext[k] = side_reach(&p->side[k], k);
  if (pl->part) {
    double r = plot_part_reach(pl, L.ucm, L.vex, 1);
    L.ext[SIDE_TOP] = plot_part_reach(pl, L.ucm, L.vex, 0);
    L.ext[SIDE_LEFT] = fmax(L.ext[SIDE_LEFT], r), L.ext[SIDE_RIGHT] = fmax(L.ext[SIDE_RIGHT], r);
  }
  L.xlo = pl->left - (L.ext[SIDE_LEFT] + LGAP + LROOM) / L.ucm;
  L.xhi = pl->right + (L.ext[SIDE_RIGHT] + LGAP + LROOM) / L.ucm;
  L.ylo = -BELOW / (L.ucm * L.vex);
  L.yhi = pl->top + (L.ext[SIDE_TOP] + ABOVE) / (L.ucm * L.vex);
  L.top = L.vex != 1 ? 2.2 : 1.4;
  L.slo = -0.2 * fmax(p->C0, amax);
  L.shi = 1.4 * fmax(p->C0, amax);
  L.exag = fmax(L.vex, plot_nice(3.52 / ((L.shi - L.slo) * L.ucm)));
  body_fit(pl, &L);
  return L;
}
#line 1498 "paper/figures.nw"
static void foundation_text(const Problem *p, char *buf, size_t size);
static void load_text(const Problem_side *sd, char *buf, size_t size);
static void body_fit(const Plot *pl, Body_page *L)
{
  const Problem *p = &pl->s.problem;
  char t[256];
  double w, grow;
  snprintf(t, sizeof t, "the bottom strip −%g ≤ x_2 ≤ %g, vertical scale exaggerated ×%g%s",
           -L->slo, L->shi, L->exag, pl->optimize ? "; dashed: the final α^*" : "");
  w = plot_text_cm(t, 12);
  foundation_text(p, t, sizeof t);
  w = fmax(w, plot_text_cm(t, 12));
  if (p->side[SIDE_TOP].kind == BC_TRACTION) {
    load_text(&p->side[SIDE_TOP], t, sizeof t);
    w = fmax(w, plot_text_cm(t, 12));
  }
  grow = fmax(0, (w + 1) / L->ucm - (L->xhi - L->xlo)) / 2;
  L->xlo -= grow, L->xhi += grow;
  snprintf(t, sizeof t, "%s: Ω(α^0) and the parts of its boundary",
           pl->args->title ? pl->args->title : pl->args->dir);
  L->width = fmax(2.6 + (L->xhi - L->xlo) * L->ucm + 0.6, plot_text_cm(t, 12) + 1);
  double step = plot_nice(pl->top / 2), sstep = plot_nice(0.4 * L->shi / 1.4);
  int chars = plot_tick_chars(0, step, floor(pl->top / step + SLACK) * step);
  chars = (int) fmax(chars, plot_tick_chars(0, sstep, floor(L->shi / sstep + SLACK) * sstep));
  L->left = 2.6;
  for (int k = 0; k < 3; k++) {      /* the font grows with the page: settle */
    double left = fmax(2.6, plot_tick_room(PLOT_BODY_BASE, chars, L->width));
    L->width += left - L->left, L->left = left;
  }
}
#line 1553 "paper/figures.nw"
static const double normal[SIDE_COUNT][2] = { { -1, 0 }, { 1, 0 }, { 0, 1 } };

/* the tail and head of the arrows of side k, cm from the side */
static void load_arrow(const Problem_side *sd, int k, double tail[2], double head[2])
{
  double P = hypot(sd->P[0], sd->P[1]), t[2] = { sd->P[0] / P, sd->P[1] / P };
  const double *n = normal[k];
  double c = t[0] * n[0] + t[1] * n[1];
  double o = c <= -0.3 ? -ARROW : c >= 0.3 ? 0 : -0.5 * ARROW;  /* tail on t */
  double h = c < 0.3 && c > -0.3 ? 0.4 * ARROW : 0;              /* off the side */
  for (int i = 0; i < 2; i++) {
    tail[i] = (AGAP + h) * n[i] + o * t[i];
    head[i] = tail[i] + ARROW * t[i];
  }
}

/* how far the arrows of side k reach out of the body, cm */
static double load_reach(const Problem_side *sd, int k)
{
  double tail[2], head[2];
  const double *n = normal[k];
  load_arrow(sd, k, tail, head);
  return fmax(tail[0] * n[0] + tail[1] * n[1], head[0] * n[0] + head[1] * n[1]);
}
#line 1580 "paper/figures.nw"
static void load_text(const Problem_side *sd, char *buf, size_t size)
{
  char p1[64], p2[64];
  plot_enhanced_number(sd->P[0], p1, sizeof p1);
  plot_enhanced_number(sd->P[1], p2, sizeof p2);
  if (sd->P[0] == 0) snprintf(buf, size, "{/:Italic P}_2 = %s N/m^2", p2);
  else if (sd->P[1] == 0) snprintf(buf, size, "{/:Italic P}_1 = %s N/m^2", p1);
  else snprintf(buf, size, "({/:Italic P}_1, {/:Italic P}_2) = (%s, %s) N/m^2", p1, p2);
}
#line 1594 "paper/figures.nw"
static void side_point(FILE *f, int k, const char *s, double dx, double dy)
{
  fprintf(f, "%s + cx(%.4g), %s + cy(%.4g)", k == SIDE_TOP ? s : k == SIDE_LEFT ? "a" : "b",
          dx, k == SIDE_TOP ? "gamma" : s, dy);
}
#line 1604 "paper/figures.nw"
static void side_load(FILE *f, const Problem_side *sd, int k, double ucm)
{
  double tail[2], head[2], reach = load_reach(sd, k);
  double len = (sd->to - sd->from) * ucm, step;
  const double *n = normal[k];
  int m = (int) fmax(2, floor(len / ASTEP + 0.5) + 1);
  char text[256], mid[64];
  load_arrow(sd, k, tail, head);
  step = (sd->to - sd->from) / (m - 1);
  fprintf(f, "  # %s: the traction (P1, P2) = (%s, %s) N/m^2 on %s < s < %s\n",
          k == SIDE_TOP ? "top" : k == SIDE_LEFT ? "left" : "right", plot_num(sd->P[0]),
          plot_num(sd->P[1]), plot_num(sd->from), plot_num(sd->to));
  fprintf(f, "  do for [k=0:%d] {\n    s = %s + k*%s\n    set arrow from ", m - 1,
          plot_num(sd->from), plot_num(step));
  side_point(f, k, "s", tail[0], tail[1]);
  fprintf(f, " to ");
  side_point(f, k, "s", head[0], head[1]);
  fprintf(f, " \\\n        head filled size cx(%g),25 lw 1.5 lc '#b00000'\n  }\n", AHEAD);
  if (tail[0] * n[0] + tail[1] * n[1] > AGAP) {    /* it pushes: join the tails */
    fprintf(f, "  set arrow from ");
    side_point(f, k, plot_num(sd->from), tail[0], tail[1]);
    fprintf(f, " to ");
    side_point(f, k, plot_num(sd->to), tail[0], tail[1]);
    fprintf(f, " nohead lw 1.5 lc '#b00000'\n");
  }
  load_text(sd, text, sizeof text);
  snprintf(mid, sizeof mid, "%s", plot_num(0.5 * (sd->from + sd->to)));
  fprintf(f, "  set label ");
  plot_quote(f, text, 0);
  fprintf(f, " at ");
  side_point(f, k, mid, (reach + ALABEL) * n[0], (reach + ALABEL) * n[1]);
  fprintf(f, " center%s tc '#b00000'\n", k == SIDE_TOP ? "" : " rotate by 90");
}
#line 1653 "paper/figures.nw"
/* the sides' names at 1.2 times the text, so that they print at 9.8 pt
   (the text's 8.2 pt, fontpt); the stacked scripts of Gamma_P^k at 0.85 of
   gnuplot's scripts (0.8), 6.7 pt, where the two clear each other */
#define NAMEFONT " font sprintf(',%g', 1.2*fsz)"
/* the name of side k: Gamma_D, or Gamma_P with its number among the others */
static void side_name(const Problem *p, int k, char *buf, size_t size)
{
  int m = 0;
  for (int j = 0; j <= k; j++) m += p->side[j].kind != BC_CLAMPED;
  if (p->side[k].kind == BC_CLAMPED) snprintf(buf, size, "Γ_D");
  else snprintf(buf, size, "Γ@^{/*0.85 %d}_{/*0.85 P}", m);
}

/* x1 of the top's name, and its height above the top in cm */
static void top_name_place(const Problem *p, const Body_page *L, double *x, double *up)
{
  const Problem_side *t = &p->side[SIDE_TOP];
  double W = p->b - p->a, left = 0, right = 0;
  *x = p->a + 0.25 * W;
  *up = L->ext[SIDE_TOP] + 0.396;
  if (t->kind != BC_TRACTION) return;
  left = t->from - p->a;
  right = p->b - t->to;
  if (fmax(left, right) >= 0.2 * W) {
    *x = left >= right ? p->a + 0.5 * left : t->to + 0.5 * right;
    *up = 0.396;
  } else {                 /* beside the arrows, clear of their value */
    *x = p->a - 0.6 / L->ucm;
    *up = 0.5 * L->ext[SIDE_TOP];
  }
}
#line 1693 "paper/figures.nw"
static void body_force_label(FILE *f, const Problem *p, int low, int narrow);
static void body_labels(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  char name[64], g[160];
  double x, up;
  int low = pl->top * L->ucm * L->vex < 3, narrow = !low && (p->b - p->a) * L->ucm < 4;
  fprintf(f, "  set label 'Ω({/:Italic α}^0)' at a + %s*(b - a), %s*gamma "
          "center front font sprintf(',%%g', 1.4*fsz)\n", narrow ? "0.5" : low ? "0.3"
          : "0.275", low ? "0.5" : "0.6");
  /* beside its own supports, not past a part's labels */
  side_name(p, SIDE_LEFT, name, sizeof name);
  fprintf(f, "  set label '%s' at a - cx(%.4g), %s right%s\n", name,
          side_reach(&p->side[SIDE_LEFT], SIDE_LEFT) + LGAP,
          pl->part ? "0.5*cprime" : "0.6*gamma", NAMEFONT);
  side_name(p, SIDE_RIGHT, name, sizeof name);
  fprintf(f, "  set label '%s' at b + cx(%.4g), %s left%s\n", name,
          side_reach(&p->side[SIDE_RIGHT], SIDE_RIGHT) + LGAP,
          pl->part ? "0.5*cprime" : "0.6*gamma", NAMEFONT);
  side_name(p, SIDE_TOP, name, sizeof name);
  top_name_place(p, L, &x, &up);
  if (!pl->part)
    fprintf(f, "  set label '%s' at %s, gamma + cy(%.4g) center%s\n", name,
            plot_num(x), up, NAMEFONT);
  fprintf(f, "  set label 'Γ_C({/:Italic α}^0)' at a + %s*(b - a), cy(0.616) center front\n",
          narrow ? "0.5" : low ? "0.1" : "0.1875");
  foundation_text(p, g, sizeof g);
  fprintf(f, "  set label '%s' at (a + b)/2, -cy(0.44) center boxed\n", g);
  fprintf(f, "  set style textbox opaque noborder\n");
  if (p->has_body_force) body_force_label(f, p, low, narrow);
}
#line 1727 "paper/figures.nw"
static void foundation_text(const Problem *p, char *buf, size_t size)
{
  char g[64] = "";
  if (p->contact == CONTACT_TRESCA) plot_enhanced_number(p->slip_bound, g, sizeof g);
  if (p->contact == CONTACT_COULOMB) plot_enhanced_number(p->friction, g, sizeof g);
  snprintf(buf, size, "rigid foundation  {/:Italic x}_2 ≤ 0%s%s%s",
           p->contact == CONTACT_TRESCA ? ", given friction {/:Italic g} = "
           : p->contact == CONTACT_COULOMB ? ", Coulomb friction {/:Italic F} = " : "",
           g, p->contact == CONTACT_TRESCA ? " N/m^2" : "");
}
#line 1742 "paper/figures.nw"
static void body_force_label(FILE *f, const Problem *p, int low, int narrow)
{
  char f1[64], f2[64];
  plot_enhanced_number(p->body_force[0], f1, sizeof f1);
  plot_enhanced_number(p->body_force[1], f2, sizeof f2);
  fprintf(f, "  set label 'body force ({/:Italic F}_1, {/:Italic F}_2) = (%s, %s) N/m^3' "
          "at a + %s*(b - a), %s*gamma center front%s\n", f1, f2, narrow ? "0.5" : low
          ? "0.7" : "0.65", narrow ? "0.45" : low ? "0.5" : "0.6", narrow ? " boxed" : "");
}
#line 1759 "paper/figures.nw"
static void body_part(FILE *f, const Plot *pl, const Body_page *L);
static void body_upper(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  plot_place(f, "left", "(xhi - xlo)*ucm", "top", "(yhi - ylo)*ucm*vex");
  fprintf(f, "  set xrange [xlo:xhi]; set yrange [ylo:yhi]\n");
  plot_tics(f, "x", p->a, p->b, fmax(1, fmin(4, floor((p->b - p->a) * L->ucm / 2))), 0);
  plot_tics(f, "y", 0, pl->top, 2, 1);
  fprintf(f, "  set ylabel '{/:Italic x}_2 [m]'\n  set border 3\n");
  if (L->vex != 1)
    fprintf(f, "  set title '%s scale exaggerated ×%g' offset 0, -0.3\n", L->vex > 1
            ? "vertical" : "horizontal", L->vex > 1 ? L->vex : 1 / L->vex);
  fprintf(f, "  set object rect from xlo, ylo to xhi, 0 fs pattern 5 noborder fc 'gray40' back\n"
          "  set arrow from xlo, 0 to xhi, 0 nohead lw 2 lc 'gray30' back\n");
  if (pl->part) {
    body_part(f, pl, L);
    return;
  }
  int n = rollers(p->gamma * L->ucm * L->vex);
  side_support(f, p->side[SIDE_LEFT].kind, "a", "a_left", -1, n, "gamma");
  side_support(f, p->side[SIDE_RIGHT].kind, "b", "a_right", 1, n, "gamma");
  top_support(f, p->side[SIDE_TOP].kind, rollers((p->b - p->a) * L->ucm));
  for (int k = 0; k < SIDE_COUNT; k++)
    if (p->side[k].kind == BC_TRACTION)
      side_load(f, &p->side[k], k, L->ucm * (k == SIDE_TOP ? 1 : L->vex));
  body_labels(f, pl, L);
  fprintf(f, "  set arrow from a, a_left to a, gamma nohead lw 2 lc 'black' front\n"
          "  set arrow from a, gamma to b, gamma nohead lw 2 lc 'black' front\n"
          "  set arrow from b, gamma to b, a_right nohead lw 2 lc 'black' front\n"
          "  plot shape using 1:2 with filledcurves y=gamma fc '#dce6f2' notitle, \\\n"
          "       shape using 1:2 with lines lw 2 lc 'black' notitle\n"
          "  unset object; unset arrow; unset label; unset title\n");
}
#line 1808 "paper/figures.nw"
static void body_part(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  int n = rollers(p->C0prime * L->ucm * L->vex);
  side_support(f, p->side[SIDE_LEFT].kind, "a", "a_left", -1, n, "cprime");
  side_support(f, p->side[SIDE_RIGHT].kind, "b", "a_right", 1, n, "cprime");
  plot_part_curves(f, pl, L->ucm, L->vex);
  plot_part_region_labels(f, pl);
  body_labels(f, pl, L);
  fprintf(f, "  set arrow from a, a_left to a, cprime nohead lw 2 lc 'black' front\n"
          "  set arrow from b, cprime to b, a_right nohead lw 2 lc 'black' front\n"
          "  plot shape using 1:2 with filledcurves y=cprime fc '#dce6f2' notitle, \\\n"
          "       $part using 1:2 with filledcurves closed fc '#dce6f2' notitle, \\\n"
          "       $holes using 1:2 with filledcurves closed fc 'white' notitle, \\\n"
          "       $interfaces using 1:2 with lines lw 1 dt 2 lc 'gray30' notitle, \\\n"
          "       $outline using 1:2 with lines lw 2 lc 'black' notitle, \\\n"
          "       shape using 1:2 with lines lw 2 lc 'black' notitle\n"
          "  unset object; unset arrow; unset label; unset title\n");
}
#line 1839 "paper/figures.nw"
static void body_strip_plot(FILE *f, const Plot *pl);
static void body_strip(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  double step = plot_nice(0.4 * L->shi / 1.4);
  fprintf(f, "  stop = top + (yhi - ylo)*ucm*vex + gap\n");
  plot_place(f, "left", "(xhi - xlo)*ucm", "stop", "(shi - slo)*exag*ucm");
  fprintf(f, "  set yrange [slo:shi]\n");
  plot_tics_at(f, "y", 0, step, floor(L->shi / step + SLACK) * step, 1);
  fprintf(f, "  set xlabel '{/:Italic x}_1 [m]' offset 0, 0.5\n"
          "  set title sprintf('the bottom strip −%%g ≤ {/:Italic x}_2 ≤ %%g, vertical "
          "scale exaggerated ×%%g%s', -slo, shi, exag) offset 0, -0.3\n"
          "  set object rect from xlo, slo to xhi, 0 fs pattern 5 noborder fc 'gray40' back\n"
          "  set arrow from xlo, 0 to xhi, 0 nohead lw 2 lc 'gray30' back\n",
          pl->optimize ? "; dashed: the final {/:Italic α}^*" : "");
  if (p->side[SIDE_LEFT].kind == BC_CLAMPED)
    fprintf(f, "  set object rect from a - cx(%g), a_left to a, shi %s\n", WALL, hatch);
  if (p->side[SIDE_RIGHT].kind == BC_CLAMPED)
    fprintf(f, "  set object rect from b, a_right to b + cx(%g), shi %s\n", WALL, hatch);
  fprintf(f, "  set arrow from a, a_left to a, shi nohead lw 2 lc 'black' front\n"
          "  set arrow from b, a_right to b, shi nohead lw 2 lc 'black' front\n"
          "  set label 'Γ_C({/:Italic α}^0)' at a + %s*(b - a), 0.9*shi/1.4 center front\n"
          "  if (a_max > 0) {\n"
          "    set label 'gap' at (x_gap < (a + b)/2 ? x_gap + 0.075*(b - a) : "
          "x_gap - 0.075*(b - a)), 0.4*a_max \\\n"
          "        center front font sprintf(',%%g', 0.9*fsz)\n  }\n",
          (p->b - p->a) * L->ucm < 4 ? "0.5" : "0.25");
  body_strip_plot(f, pl);
  fprintf(f, "  unset object; unset arrow; unset label; unset title; unset xlabel\n");
}
#line 1874 "paper/figures.nw"
static void body_strip_plot(FILE *f, const Plot *pl)
{
  fprintf(f, "  plot shape using 1:2 with filledcurves y=shi fc '#dce6f2' notitle, \\\n"
          "       shape using 1:2 with linespoints lw 2 pt 7 ps 0.5 pi %d lc 'black' notitle",
          (int) ceil((pl->s.problem.N + 1.0) / MARKS));
  if (pl->optimize)
    fprintf(f, ", \\\n       final using 1:2 with lines dt 2 lw 2 lc '#1f4e99' notitle");
  fprintf(f, "\n");
}
#line 1892 "paper/figures.nw"
/* a part's outline: its chains, those filled, its holes */
static void body_part_blocks(FILE *f, const Plot *pl)
{
  static const char *const name[3] = { "$holes", "$outline", "$part" };
  for (int w = -1; w <= 1; w++) {
    fprintf(f, "%s << EOD\n", name[w + 1]);
    plot_chains_write(f, pl->part, &pl->chains, pl->part->xy, NULL, w);
    fprintf(f, "EOD\n");
  }
  plot_part_interfaces(f, pl);
}

void plot_body_figure(FILE *f, const Plot *pl, const char *out)
{
  const Problem *p = &pl->s.problem;
  const double *al = pl->s.alpha0;
  Body_page L = body_page(pl);
  char path[1200];
  int g = 0;
  for (int i = 1; i <= p->N; i++) if (al[i] > al[g]) g = i;
  plot_script_head(f, pl, "The body", out);
  snprintf(path, sizeof path, "%s/%sshape.dat", pl->args->dir, pl->optimize ? "initial/" : "");
  fprintf(f, "shape = ");
  plot_quote(f, path, 0);
  snprintf(path, sizeof path, "%s/final/shape.dat", pl->args->dir);
  if (pl->optimize) fprintf(f, "; final = "), plot_quote(f, path, 0);
  fprintf(f, "\na_left = %s; a_right = %s          # alpha0 at a and at b\n"
          "x_gap = %s; a_max = %s           # the widest gap, and where\n",
          plot_real(al[0], 0), plot_real(al[p->N], 0), plot_real(problem_node_x(p, g), 0),
          plot_real(al[g], 0));
  fprintf(f, "ucm = %s; vex = %s                # cm per metre along x1; x2 exaggerated\n",
          plot_real(L.ucm, 6), plot_real(L.vex, 0));
  fprintf(f, "xlo = %s; xhi = %s; ylo = %s; yhi = %s    # the upper panel\n",
          plot_real(L.xlo, 6), plot_real(L.xhi, 6), plot_real(L.ylo, 6), plot_real(L.yhi, 6));
  fprintf(f, "slo = %s; shi = %s; exag = %s     # the bottom strip, x2 times exag\n"
          "left = %s; top = %s; gap = 2.2                  # margins (cm)\n"
          "Wcm = %s       # left + (xhi - xlo)*ucm + 0.6, or the title's width\n"
          "Hcm = top + (yhi - ylo)*ucm*vex + gap + (shi - slo)*exag*ucm + %s\n",
          plot_real(L.slo, 6), plot_real(L.shi, 6), plot_real(L.exag, 0), plot_real(L.left, 6),
          plot_real(L.top, 0), plot_real(L.width, 6), pl->part ? "2.0" : "1.8");
  fputs(plot_page_lines, f);
  if (pl->part) body_part_blocks(f, pl);
  fprintf(f, "do for [fmt in 'pdf png'] {\n%s", plot_terminal_lines);
  fprintf(f, "  set multiplot title sprintf('%%s: Ω({/:Italic α}^0) and the parts of its "
          "boundary', title)\n");
  body_upper(f, pl, &L);
  body_strip(f, pl, &L);
  fprintf(f, "  unset multiplot\n  set output\n}\n");
}
