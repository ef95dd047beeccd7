#line 261 "paper/figures.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "plot_private.h"
#line 632 "paper/figures.nw"
static void chain_walk(const Mesh *m, Plot_chains *c, const int *out, char *seen, int e, int *n)
{
  int first = m->edge[2 * e];
  c->start[c->nchain] = *n;
  for (int k = e; k >= 0 && !seen[k]; k = out[m->edge[2 * k + 1]])
    seen[k] = 1, c->order[(*n)++] = k;
  c->closed[c->nchain++] = m->edge[2 * c->order[*n - 1] + 1] == first;
}

int plot_chains(const Mesh *m, Plot_chains *c)
{
  int ne = m->nedge, n = 0, *out = malloc((size_t) m->nnodes * sizeof *out);
  char *into = calloc((size_t) m->nnodes, 1), *seen = calloc((size_t) ne + 1, 1);
  c->nchain = 0;
  c->order = malloc(((size_t) ne + 1) * sizeof *c->order);
  c->start = malloc(((size_t) ne + 2) * sizeof *c->start);
  c->closed = malloc(((size_t) ne + 1) * sizeof *c->closed);
  if (out && into && seen && c->order && c->start && c->closed) {
    for (int k = 0; k < m->nnodes; k++) out[k] = -1;
    for (int e = 0; e < ne; e++) out[m->edge[2 * e]] = e, into[m->edge[2 * e + 1]] = 1;
    for (int pass = 0; pass < 2; pass++)
      for (int e = 0; e < ne; e++)
        if (!seen[e] && (pass || !into[m->edge[2 * e]])) chain_walk(m, c, out, seen, e, &n);
    c->start[c->nchain] = n;
  }
  free(out), free(into), free(seen);
  return !(c->order && c->start && c->closed);
}

void plot_chains_free(Plot_chains *c)
{
  free(c->order), free(c->start), free(c->closed);
  memset(c, 0, sizeof *c);
}
#line 670 "paper/figures.nw"
double plot_chain_area(const Mesh *m, const Plot_chains *c, int k, const double *xy)
{
  double A = 0;
  int first = m->edge[2 * c->order[c->start[k]]];
  int last = m->edge[2 * c->order[c->start[k + 1] - 1] + 1];
  for (int j = c->start[k]; j < c->start[k + 1]; j++) {
    const double *p = xy + 2 * m->edge[2 * c->order[j]];
    const double *q = xy + 2 * m->edge[2 * c->order[j] + 1];
    A += p[0] * q[1] - q[0] * p[1];
  }
  A += xy[2 * last] * xy[2 * first + 1] - xy[2 * first] * xy[2 * last + 1];
  return 0.5 * A;
}

static void chain_node(FILE *f, const double *xy, const double *u, int k)
{
  if (u) fprintf(f, "%.9g %.9g %.10g %.10g\n", xy[2 * k], xy[2 * k + 1], u[2 * k], u[2 * k + 1]);
  else fprintf(f, "%.9g %.9g\n", xy[2 * k], xy[2 * k + 1]);
}

void plot_chains_write(FILE *f, const Mesh *m, const Plot_chains *c, const double *xy,
                       const double *u, int which)
{
  for (int k = 0; k < c->nchain; k++) {
    int hole = c->closed[k] && plot_chain_area(m, c, k, xy) < 0;
    if ((which < 0 && !hole) || (which > 0 && hole)) continue;
    chain_node(f, xy, u, m->edge[2 * c->order[c->start[k]]]);
    for (int j = c->start[k]; j < c->start[k + 1]; j++)
      chain_node(f, xy, u, m->edge[2 * c->order[j] + 1]);
    fputc('\n', f);
  }
}
#line 715 "paper/figures.nw"
typedef struct {
  double x[2];       /* a point of the curve, m */
  double n[2], t[2]; /* the outward normal and the tangent there, on the page */
} Curve_mark;

/* the page's vector of edge e, cm */
static void edge_cm(const Mesh *m, int e, double ucm, double vex, double d[2])
{
  const double *p = m->xy + 2 * m->edge[2 * e], *q = m->xy + 2 * m->edge[2 * e + 1];
  d[0] = (q[0] - p[0]) * ucm, d[1] = (q[1] - p[1]) * ucm * vex;
}

/* the length of curve s in chain k on the page, cm */
static double curve_cm(const Plot *pl, int k, int s, double ucm, double vex)
{
  const Plot_chains *c = &pl->chains;
  double d[2], len = 0;
  for (int j = c->start[k]; j < c->start[k + 1]; j++)
    if (pl->part->edge_curve[c->order[j]] == s)
      edge_cm(pl->part, c->order[j], ucm, vex, d), len += hypot(d[0], d[1]);
  return len;
}
#line 740 "paper/figures.nw"
static int curve_mark(const Plot *pl, int k, int s, double at, double ucm, double vex,
                      Curve_mark *q)
{
  const Plot_chains *c = &pl->chains;
  const Mesh *m = pl->part;
  double d[2], l;
  for (int j = c->start[k]; j < c->start[k + 1]; j++) {
    int e = c->order[j];
    if (m->edge_curve[e] != s) continue;
    edge_cm(m, e, ucm, vex, d);
    l = hypot(d[0], d[1]);
    if (at > l && j + 1 < c->start[k + 1]) { at -= l; continue; }
    const double *p = m->xy + 2 * m->edge[2 * e], *r = m->xy + 2 * m->edge[2 * e + 1];
    double w = l > 0 ? fmin(1, at / l) : 0;
    q->x[0] = p[0] + w * (r[0] - p[0]), q->x[1] = p[1] + w * (r[1] - p[1]);
    q->t[0] = d[0] / l, q->t[1] = d[1] / l;
    q->n[0] = q->t[1], q->n[1] = -q->t[0];       /* the body on the left */
    return 1;
  }
  return 0;
}

/* the smaller side of chain k's box on the page, cm */
static double chain_box(const Plot *pl, int k, double ucm, double vex)
{
  const Plot_chains *c = &pl->chains;
  double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
  for (int j = c->start[k]; j < c->start[k + 1]; j++) {
    const double *p = pl->part->xy + 2 * pl->part->edge[2 * c->order[j]];
    for (int i = 0; i < 2; i++) lo[i] = fmin(lo[i], p[i]), hi[i] = fmax(hi[i], p[i]);
  }
  return fmin((hi[0] - lo[0]) * ucm, (hi[1] - lo[1]) * ucm * vex);
}
#line 777 "paper/figures.nw"
static void mark_arrow(const Problem_curve *cv, const Curve_mark *q, double len,
                       double tail[2], double head[2])
{
  double P[2] = { cv->P[0], cv->P[1] }, a, t[2], c, o, h;
  if (cv->kind == BC_PRESSURE) P[0] = -cv->pressure * q->n[0], P[1] = -cv->pressure * q->n[1];
  a = hypot(P[0], P[1]);
  t[0] = a > 0 ? P[0] / a : 0, t[1] = a > 0 ? P[1] / a : 0;
  c = t[0] * q->n[0] + t[1] * q->n[1];
  o = c <= -0.3 ? -len : c >= 0.3 ? 0 : -0.5 * len;
  h = c < 0.3 && c > -0.3 ? 0.4 * len : 0;
  for (int i = 0; i < 2; i++) {
    tail[i] = (AGAP + h) * q->n[i] + o * t[i];
    head[i] = tail[i] + len * t[i];
  }
}

/* the decoration of curve cv at q, cm out of the body; f NULL: its reach */
static double mark_draw(FILE *f, const Problem_curve *cv, const Curve_mark *q, double len)
{
  double tail[2], head[2], x = q->x[0], y = q->x[1];
  const double *n = q->n, *t = q->t;
  if (cv->kind == BC_CLAMPED && f)
    fprintf(f, "  set arrow from %.9g, %.9g to %.9g + cx(%.4g), %.9g + cy(%.4g) nohead "
            "lw 1 lc 'gray40' back\n", x, y, x, 0.8 * WALL * n[0] - 0.3 * WALL * t[0],
            y, 0.8 * WALL * n[1] - 0.3 * WALL * t[1]);
  if (cv->kind == BC_CLAMPED) return WALL;
  if (cv->kind == BC_ROLLER && f)
    fprintf(f, "  set object circle at %.9g + cx(%.4g), %.9g + cy(%.4g) size cx(%g) "
            "fs empty border lc 'black' lw 1.5 front\n", x, ROLLER * n[0], y,
            ROLLER * n[1], ROLLER);
  if (cv->kind == BC_ROLLER) return 2 * ROLLER;
  if (cv->kind != BC_TRACTION && cv->kind != BC_PRESSURE) return 0;
  mark_arrow(cv, q, len, tail, head);
  if (f)
    fprintf(f, "  set arrow from %.9g + cx(%.4g), %.9g + cy(%.4g) to %.9g + cx(%.4g), "
            "%.9g + cy(%.4g) head filled size cx(%g),25 lw 1.5 lc '#b00000'\n", x, tail[0],
            y, tail[1], x, head[0], y, head[1], AHEAD);
  return fmax(tail[0] * n[0] + tail[1] * n[1], head[0] * n[0] + head[1] * n[1]);
}
#line 820 "paper/figures.nw"
static void curve_text(FILE *f, const Problem_curve *cv)
{
  char v[2][64];
  plot_quote(f, cv->name, 1);
  plot_enhanced_number(cv->P[0], v[0], sizeof v[0]);
  plot_enhanced_number(cv->P[1], v[1], sizeof v[1]);
  if (cv->kind == BC_PRESSURE) plot_enhanced_number(cv->pressure, v[0], sizeof v[0]);
  if (cv->kind == BC_CLAMPED || cv->kind == BC_ROLLER)
    fprintf(f, ".' (%s)'", problem_bc_name(cv->kind));
  if (cv->kind == BC_PRESSURE) fprintf(f, ".': {/:Italic p} = %s N/m^2'", v[0]);
  if (cv->kind == BC_TRACTION)
    fprintf(f, ".': ({/:Italic P}_1, {/:Italic P}_2) = (%s, %s) N/m^2'", v[0], v[1]);
}

/* an estimate of its width on the page, cm */
static double curve_text_cm(const Problem_curve *cv)
{
  return plot_text_cm(cv->name, 9.8) + (cv->kind == BC_FREE ? 0 : plot_text_cm(
         cv->kind == BC_TRACTION ? ": (P_1, P_2) = (−5.75·10^8, −5.75·10^8) N/m^2"
         : ": p = −5.75·10^8 N/m^2 (clamped)", 9.8));
}
#line 847 "paper/figures.nw"
static double curve_draw(FILE *f, const Plot *pl, int k, int s, double ucm, double vex,
                         int sideways)
{
  const Problem_curve *cv = &pl->s.problem.part.curve[s];
  double len = curve_cm(pl, k, s, ucm, vex), reach = 0, step, arrow, out;
  int hole = pl->chains.closed[k] && plot_chain_area(pl->part, &pl->chains, k,
                                                      pl->part->xy) < 0, n;
  Curve_mark q;
  if (len <= 0) return 0;
  step = cv->kind == BC_CLAMPED ? 0.25 * ASTEP : cv->kind == BC_ROLLER ? 0.88 : ASTEP;
  n = (int) fmax(1, floor(len / step + 0.5));
  arrow = fmin(ARROW, 0.45 * chain_box(pl, k, ucm, vex));
  for (int j = 0; j < n; j++)
    if (curve_mark(pl, k, s, (j + 0.5) * len / n, ucm, vex, &q))
      reach = fmax(reach, mark_draw(f, cv, &q, arrow));
  if (!curve_mark(pl, k, s, 0.5 * len, ucm, vex, &q)) return reach;
  if (f) {
    out = hole ? -0.5 : reach + LGAP + 0.2;
    fprintf(f, "  set label ");
    curve_text(f, cv);
    fprintf(f, " at %.9g + cx(%.4g), %.9g + cy(%.4g) %s front tc '%s' font "
            "sprintf(',%%g', fsz)\n", q.x[0], out * q.n[0], q.x[1], out * q.n[1],
            hole || fabs(q.n[0]) < 0.5 ? "center" : q.n[0] > 0 ? "left" : "right",
            cv->kind == BC_TRACTION || cv->kind == BC_PRESSURE ? "#b00000" : "black");
  }
  if (hole || (fabs(q.n[0]) >= 0.5) != sideways) return 0;
  return reach + LGAP + 0.6 + (sideways ? curve_text_cm(cv) : 0);
}

void plot_part_curves(FILE *f, const Plot *pl, double ucm, double vex)
{
  for (int k = 0; k < pl->chains.nchain; k++)
    for (int s = 0; s < pl->s.problem.part.ncurve; s++) curve_draw(f, pl, k, s, ucm, vex, 0);
}

double plot_part_reach(const Plot *pl, double ucm, double vex, int sideways)
{
  double r = 0;
  for (int k = 0; k < pl->chains.nchain; k++)
    for (int s = 0; s < pl->s.problem.part.ncurve; s++)
      r = fmax(r, curve_draw(NULL, pl, k, s, ucm, vex, sideways));
  return r;
}
#line 904 "paper/figures.nw"
typedef struct { int lo, hi, material; } Region_edge;

static int region_edge_cmp(const void *x, const void *y)
{
  const Region_edge *a = x, *b = y;
  if (a->lo != b->lo) return (a->lo > b->lo) - (a->lo < b->lo);
  return (a->hi > b->hi) - (a->hi < b->hi);
}

/* the material of index k of mesh_material: 0 the problem's, 1 + s region s's */
static const Problem_material *material_of(const Plot *pl, int k)
{
  return k ? &pl->s.problem.part.region[k - 1].material : &pl->s.problem.material;
}

/* 1 if the materials of indices j and k have the same kind and values */
static int same_material(const Plot *pl, int j, int k)
{
  const Problem_material *a = material_of(pl, j), *b = material_of(pl, k);
  return a->kind == b->kind && a->young == b->young && a->nu == b->nu && a->E1 == b->E1
         && a->E2 == b->E2 && a->nu12 == b->nu12 && a->G12 == b->G12 && a->E3 == b->E3
         && a->nu13 == b->nu13 && a->nu23 == b->nu23 && a->angle == b->angle;
}

void plot_part_interfaces(FILE *f, const Plot *pl)
{
  const Mesh *m = pl->part;
  size_t n = 3 * (size_t) m->ntri;
  Region_edge *e = malloc(n * sizeof *e + 1);
  fprintf(f, "$interfaces << EOD\n");
  for (int t = 0; e && t < m->ntri; t++)
    for (int k = 0; k < 3; k++) {
      int u = m->tri[3 * t + k], v = m->tri[3 * t + (k + 1) % 3];
      e[3 * t + k] = (Region_edge){ u < v ? u : v, u < v ? v : u, mesh_material(m, t) };
    }
  if (e) qsort(e, n, sizeof *e, region_edge_cmp);
  for (size_t k = 0; e && k + 1 < n; k++)
    if (e[k].lo == e[k + 1].lo && e[k].hi == e[k + 1].hi
        && !same_material(pl, e[k].material, e[k + 1].material))
      fprintf(f, "%.9g %.9g\n%.9g %.9g\n\n", m->xy[2 * e[k].lo], m->xy[2 * e[k].lo + 1],
              m->xy[2 * e[k].hi], m->xy[2 * e[k].hi + 1]);
  fprintf(f, "0 0\n0 0\nEOD\n");    /* never empty: gnuplot refuses an empty block */
  free(e);
}

static void triangle_centroid(const Mesh *m, int t, double c[2])
{
  for (int d = 0; d < 2; d++)
    c[d] = (m->xy[2 * m->tri[3 * t] + d] + m->xy[2 * m->tri[3 * t + 1] + d]
            + m->xy[2 * m->tri[3 * t + 2] + d]) / 3;
}

void plot_part_region_labels(FILE *f, const Plot *pl)
{
  const Mesh *m = pl->part;
  for (int s = 1; s <= pl->s.problem.part.nregion; s++) {
    double area = 0, at[2] = { 0, 0 }, c[2], best = INFINITY, label[2] = { 0, 0 };
    for (int t = 0; t < m->ntri; t++)
      if (mesh_material(m, t) == s) {
        double a = mesh_area(m, t);
        triangle_centroid(m, t, c);
        area += a, at[0] += a * c[0], at[1] += a * c[1];
      }
    if (!(area > 0)) continue;
    at[0] /= area, at[1] /= area;
    for (int t = 0; t < m->ntri; t++)
      if (mesh_material(m, t) == s) {
        triangle_centroid(m, t, c);
        double d = hypot(c[0] - at[0], c[1] - at[1]);
        if (d < best) best = d, label[0] = c[0], label[1] = c[1];
      }
    fprintf(f, "  set label ");
    plot_quote(f, pl->s.problem.part.region[s - 1].name, 1);
    fprintf(f, " at %.9g, %.9g center front font sprintf(',%%g', 0.9*fsz)\n",
            label[0], label[1]);
  }
}
