#line 130 "paper/figures.nw"
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "plot.h"
#include "scene.h"
#include "interrupt.h"
#line 162 "paper/figures.nw"
typedef struct {
  const Plot_args *args;
  Scene s;                 /* DIR/effective.scene, alpha0 its first design */
  int optimize;            /* DIR is optimize's (history.dat, initial/, final/) */
  int projected;           /* its start was projected onto B */
  int iterations;          /* its iterations */
  char state[2][1100];     /* the folders of its states: initial, final */
} Plot;
#line 180 "paper/figures.nw"
int plot_args_read(int argc, char **argv, Plot_args *a, Status *st)
{
  memset(a, 0, sizeof *a);
  for (int k = 2; k < argc; k++) {
    const char *s = argv[k];
    int more = k + 1 < argc;
    if (!strcmp(s, "-o") && more) a->name = argv[++k];
    else if (!strcmp(s, "--start") && more) a->start = argv[++k];
    else if (!strcmp(s, "--title") && more) a->title = argv[++k];
    else if (!strcmp(s, "--body")) a->figures |= PLOT_BODY;
    else if (!strcmp(s, "--results")) a->figures |= PLOT_RESULTS;
    else if (!strcmp(s, "--gnuplot")) a->print = 1;
    else if (s[0] != '-' && !a->dir) a->dir = s;
    else return status_set(st, STATUS_INPUT, "command line: %s: %s", s,
                           s[0] == '-' ? "unknown option or missing value"
                                       : "more than one folder");
  }
  if (!a->figures) a->figures = PLOT_BODY | PLOT_RESULTS;
  if (!a->dir || !a->dir[0])
    return status_set(st, STATUS_INPUT, "command line: plot: no DIR given");
  if (a->name && !a->name[0])
    return status_set(st, STATUS_INPUT, "command line: -o: an empty name");
  if (a->start && !(a->figures & PLOT_RESULTS))
    return status_set(st, STATUS_INPUT, "command line: --start: only the "
                      "results figure draws it");
  return STATUS_OK;
}
#line 220 "paper/figures.nw"
/* dir/name is there, a plain file */
static int has(const char *dir, const char *name)
{
  char path[2200];
  struct stat sb;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return !stat(path, &sb) && S_ISREG(sb.st_mode);
}

/* dir's last component contains ".partial-": a staging folder */
static int staging(const char *dir)
{
  char last[1024];
  size_t n = strlen(dir), k;
  while (n > 1 && dir[n - 1] == '/') n--;
  for (k = n; k > 0 && dir[k - 1] != '/'; k--) ;
  snprintf(last, sizeof last, "%.*s", (int) (n - k), dir + k);
  return strstr(last, ".partial-") != NULL;
}
#line 243 "paper/figures.nw"
static const char *const state_files[] = {
  "shape.dat", "contact.dat", "nodes.dat", "triangles.dat" };

/* dir: a finished run of solve or optimize (*optimize says which) whose
   states have their mesh files */
static int plot_folder(const char *dir, int *optimize, Status *st)
{
  struct stat sb;
  if (staging(dir))
    return status_set(st, STATUS_INPUT, "plot: %s: the staging folder of a run "
                      "that did not finish, not an output folder", dir);
  if (stat(dir, &sb))
    return status_set(st, STATUS_INPUT, "plot: %s: %s", dir,
                      errno == ENOENT ? "no such folder" : strerror(errno));
  if (!S_ISDIR(sb.st_mode))
    return status_set(st, STATUS_INPUT, "plot: %s: not a folder", dir);
  if (has(dir, "gradient.dat"))
    return status_set(st, STATUS_INPUT, "plot: %s: an output folder of gradcheck; "
                      "plot draws those of solve and optimize", dir);
  if (!has(dir, "summary.dat") || !has(dir, "effective.scene"))
    return status_set(st, STATUS_INPUT, "plot: %s: not an output folder of solve "
                      "or optimize (no summary.dat and effective.scene)", dir);
  *optimize = has(dir, "history.dat");
  for (int k = 0; k < (*optimize ? 2 : 1); k++)
    for (int j = 0; j < 4; j++) {
      char name[64];
      snprintf(name, sizeof name, "%s%s", *optimize ? (k ? "final/" : "initial/")
               : "", state_files[j]);
      if (has(dir, name)) continue;
      if (j < 2)
        return status_set(st, STATUS_INPUT, "plot: %s: not an output folder of "
                          "solve or optimize (no %s)", dir, name);
      return status_set(st, STATUS_INPUT, "plot: %s: no %s: the mesh files are "
                        "written only with --plot-files; rerun the command with it",
                        dir, name);
    }
  return STATUS_OK;
}
#line 286 "paper/figures.nw"
/* the value of the line "name value" of dir/summary.dat, or fallback */
static double summary_value(const char *dir, const char *name, double fallback)
{
  char path[2200], line[1024], key[128];
  double v, found = fallback;
  FILE *f;
  snprintf(path, sizeof path, "%s/summary.dat", dir);
  if (!(f = fopen(path, "r"))) return fallback;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "%127s %lf", key, &v) == 2 && !strcmp(key, name)) found = v;
  fclose(f);
  return found;
}
#line 310 "paper/figures.nw"
/* v in the fewest digits that read back as v; an integer as one (10, not 1e+01) */
static const char *num(double v)
{
  static char buf[8][32];
  static int k;
  char *s = buf[k++ % 8];
  if (v == floor(v) && fabs(v) < 1e15) {
    snprintf(s, 32, "%.0f", v);
    return s;
  }
  for (int d = 1; d <= 17; d++) {
    snprintf(s, 32, "%.*g", d, v);
    if (strtod(s, NULL) == v) break;
  }
  return s;
}
#line 332 "paper/figures.nw"
static const char *real(double v, int digits)
{
  static char buf[8][40];
  static int k;
  char *s = buf[k++ % 8];
  if (digits) snprintf(s, 32, "%.*g", digits, v);
  else snprintf(s, 32, "%s", num(v));
  if (!strpbrk(s, ".en")) strcat(s, ".0");
  return s;
}
#line 346 "paper/figures.nw"
/* v as enhanced text: -5.75e8 as −5.75·10^{8} */
static void enhanced_number(double v, char *buf, size_t size)
{
  char m[32], *e;
  const char *minus = v < 0 ? "−" : "";
  int x;
  snprintf(m, sizeof m, "%.2e", fabs(v));
  e = strchr(m, 'e');
  x = atoi(e + 1);
  *e = 0;
  for (e--; *e == '0'; e--) *e = 0;          /* 5.00 -> 5. -> 5 */
  if (*e == '.') *e = 0;
  if (v == 0) snprintf(buf, size, "0");
  else if (x >= -2 && x <= 3) snprintf(buf, size, "%s%.3g", minus, fabs(v));
  else snprintf(buf, size, "%s%s%s10^{%s%d}", minus, strcmp(m, "1") ? m : "",
                strcmp(m, "1") ? "·" : "", x < 0 ? "−" : "", abs(x));
}
#line 370 "paper/figures.nw"
/* s between single quotes for gnuplot; enhanced: its marks escaped */
static void quote(FILE *f, const char *s, int enhanced)
{
  fputc('\'', f);
  for (; *s; s++) {
    if (*s == '\'') fputc('\'', f);
    else if (enhanced && strchr("_^@&~{}\\", *s)) fputc('\\', f);
    fputc(*s, f);
  }
  fputc('\'', f);
}
#line 387 "paper/figures.nw"
#define SLACK 1e-9
static double nice_down(double x)
{
  double p = pow(10, floor(log10(x) + SLACK)), m = x / p * (1 + SLACK);
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}
static double nice_up(double x)
{
  double d = nice_down(x), m = d / pow(10, floor(log10(d) + SLACK));
  if (d >= x * (1 - SLACK)) return d;
  return d * (fabs(m - 2) < 0.5 ? 2.5 : 2);         /* 1 -> 2, 2 -> 5, 5 -> 10 */
}
static double nice(double x)
{
  double d = nice_down(x), u = nice_up(x);
  return x / d <= u / x ? d : u;
}
#line 413 "paper/figures.nw"
static void tics_at(FILE *f, const char *axis, double first, double step,
                    double last, int format)
{
  int decimals = (int) fmax(0, ceil(-log10(step) - SLACK));
  if (fabs(first) < step * SLACK) first = 0;
  fprintf(f, "  set %stics %s, %s, %s out nomirror\n", axis, num(first), num(step),
          num(last));
  if (format) fprintf(f, "  set format %s '%%.%df'\n", axis, decimals);
}
static void tics(FILE *f, const char *axis, double lo, double hi, double n, int format)
{
  double step = nice((hi - lo) / n);
  tics_at(f, axis, ceil(lo / step - SLACK) * step, step, hi, format);
}
#line 478 "paper/figures.nw"
static const char page_lines[] =
  "dpcm = 1600.0 / Wcm; fontpt = 12\n"
  "sx(cm) = cm / Wcm\n"
  "sy(cm) = 1.0 - cm / Hcm\n"
  "cx(cm) = cm / ucm             # a length on the page along x1, in m\n"
  "cy(cm) = cm / (ucm*vex)       # and along x2\n";
static const char terminal_lines[] =
  "  set encoding utf8; set minussign\n"
  "  dpi = dpcm * 2.54\n"
  "  kfont = fmt eq 'pdf' ? 1.5 : dpi/96.0     # nominal font size per point\n"
  "  klw = fmt eq 'pdf' ? 1.0 : 0.5*dpi/72.0   # nominal line width per half point\n"
  "  fsz = kfont * fontpt\n"
  "  if (fmt eq 'pdf') {\n"
  "    set terminal pdfcairo enhanced color size Wcm/2.54, Hcm/2.54 \\\n"
  "        font sprintf('DejaVu Sans,%.2f', fsz) linewidth klw\n"
  "  } else {\n"
  "    set terminal pngcairo enhanced color size int(Wcm*dpcm), int(Hcm*dpcm) \\\n"
  "        font sprintf('DejaVu Sans,%.2f', fsz) linewidth klw background 'white'\n"
  "  }\n"
  "  set output out.'.'.fmt\n"
  "  unset xlabel; unset ylabel; unset title; unset key\n";
#line 508 "paper/figures.nw"
/* the head of a script: the figure, the run, and the variables of both */
static void script_head(FILE *f, const Plot *pl, const char *what, const char *out)
{
  const Problem *p = &pl->s.problem;
  fprintf(f, "# %s of the run in %s, from its effective.scene: written by\n"
          "# contactopt plot (the woven paper, appendix \"Figures of a run\").\n"
          "# gnuplot draws it: gnuplot FILE writes out.pdf and out.png.\n"
          "reset\nout = ", what, pl->args->dir);
  quote(f, out, 0);
  fprintf(f, "\ntitle = ");
  quote(f, pl->args->title ? pl->args->title : pl->args->dir, 1);
  fprintf(f, "\na = %s; b = %s; gamma = %s      # the body: a < x1 < b, x2 < gamma\n",
          real(p->a, 0), real(p->b, 0), real(p->gamma, 0));
}
#line 526 "paper/figures.nw"
static void place(FILE *f, const char *x, const char *w, const char *y, const char *h)
{
  fprintf(f, "  set lmargin at screen sx(%s); set rmargin at screen sx(%s + %s)\n"
          "  set tmargin at screen sy(%s); set bmargin at screen sy(%s + %s)\n",
          x, x, w, y, y, h);
}
#line 565 "paper/figures.nw"
#define WALL 0.528    /* cm: the wall of a clamp (0.12 m in Fig. 5.1) */
#define ROLLER 0.154  /* a roller's radius (0.035 m) */
#define RWALL 0.352   /* the wall behind the rollers (0.08 m) */
#define LGAP 0.22     /* between a decoration and the side's name */
#define LROOM 1.4     /* room for the name */
#define BELOW 0.88    /* the foundation, drawn under x2 = 0 */
#define ABOVE 0.88    /* room above the top's decoration */

typedef struct {
  double ucm, vex;            /* cm per metre along x1; x2 exaggerated vex times */
  double ext[SIDE_COUNT];     /* each side's decoration outside the body, cm */
  double xlo, xhi, ylo, yhi;  /* the upper panel, m */
  double top;                 /* cm above the upper panel */
  double slo, shi, exag;      /* the strip: slo < x2 < shi, exaggerated exag times */
} Body_page;
#line 584 "paper/figures.nw"
/* the rollers along a side of n cm */
static int rollers(double n) { return (int) fmax(1, floor(n / 0.88 + 0.5) - 1); }
#line 592 "paper/figures.nw"
static const char hatch[] = "fs pattern 4 noborder fc 'gray40' back";

/* a clamp or rollers on the left (s = -1) or the right (s = 1) side at x */
static void side_support(FILE *f, Bc_kind kind, const char *x, const char *end,
                         int s, int n)
{
  if (kind == BC_CLAMPED && s < 0)
    fprintf(f, "  set object rect from %s - cx(%g), %s to %s, gamma %s\n",
            x, WALL, end, x, hatch);
  if (kind == BC_CLAMPED && s > 0)
    fprintf(f, "  set object rect from %s, %s to %s + cx(%g), gamma %s\n",
            x, end, x, WALL, hatch);
  if (kind != BC_ROLLER) return;
  fprintf(f, "  do for [k=1:%d] {\n"
          "    set object circle at %s %c cx(%g), %s + k*(gamma - %s)/%d size cx(%g) \\\n"
          "        fs empty border lc 'black' lw 1.5 front\n  }\n", n, x,
          s > 0 ? '+' : '-', ROLLER, end, end, n + 1, ROLLER);
  fprintf(f, "  set object rect from %s %c cx(%g), %s to %s %c cx(%g), gamma %s\n",
          x, s > 0 ? '+' : '-', 2 * ROLLER, end, x, s > 0 ? '+' : '-',
          2 * ROLLER + RWALL, hatch);
  fprintf(f, "  set arrow from %s %c cx(%g), %s to %s %c cx(%g), gamma "
          "nohead lw 1.5 lc 'black' back\n", x, s > 0 ? '+' : '-', 2 * ROLLER,
          end, x, s > 0 ? '+' : '-', 2 * ROLLER);
}
#line 619 "paper/figures.nw"
static void top_support(FILE *f, Bc_kind kind, int n)
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
#line 638 "paper/figures.nw"
static double load_reach(const Side *sd, int k);
#define ALABEL 0.484  /* a load's value beyond its arrows (0.11 m) */
static double side_reach(const Side *sd, int k)
{
  switch (sd->kind) {
  case BC_CLAMPED: return WALL;
  case BC_ROLLER: return 2 * ROLLER + RWALL;
  case BC_TRACTION: return load_reach(sd, k) + (k == SIDE_TOP ? 0 : ALABEL + 0.5);
  default: return 0;
  }
}
#line 654 "paper/figures.nw"
static Body_page body_page(const Plot *pl)
{
  const Problem *p = &pl->s.problem;
  double W = p->b - p->a, amax = 0;
  Body_page L;
  for (int i = 0; i <= p->N; i++) amax = fmax(amax, pl->s.alpha0[i]);
  L.ucm = fmin(17.6 / W, 8.8 / p->gamma);
  L.vex = p->gamma * L.ucm >= 1.76 ? 1 : nice_down(3.52 / (p->gamma * L.ucm));
  for (int k = 0; k < SIDE_COUNT; k++) L.ext[k] = side_reach(&p->side[k], k);
  L.xlo = p->a - (L.ext[SIDE_LEFT] + LGAP + LROOM) / L.ucm;
  L.xhi = p->b + (L.ext[SIDE_RIGHT] + LGAP + LROOM) / L.ucm;
  L.ylo = -BELOW / (L.ucm * L.vex);
  L.yhi = p->gamma + (L.ext[SIDE_TOP] + ABOVE) / (L.ucm * L.vex);
  L.top = L.vex > 1 ? 2.2 : 1.4;
  L.slo = -0.2 * fmax(p->C0, amax);
  L.shi = 1.4 * fmax(p->C0, amax);
  L.exag = fmax(L.vex, nice(3.52 / ((L.shi - L.slo) * L.ucm)));
  return L;
}
#line 686 "paper/figures.nw"
#define ARROW 1.232   /* cm: a load arrow (0.28 m in Fig. 5.1) */
#define AGAP 0.088    /* between the side and the arrow (0.02 m) */
#define ASTEP 1.1     /* between two arrows (0.25 m) */
#define AHEAD 0.264   /* the arrow's head (0.06 m) */
static const double normal[SIDE_COUNT][2] = { { -1, 0 }, { 1, 0 }, { 0, 1 } };

/* the tail and head of the arrows of side k, cm from the side */
static void load_arrow(const Side *sd, int k, double tail[2], double head[2])
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
static double load_reach(const Side *sd, int k)
{
  double tail[2], head[2];
  const double *n = normal[k];
  load_arrow(sd, k, tail, head);
  return fmax(tail[0] * n[0] + tail[1] * n[1], head[0] * n[0] + head[1] * n[1]);
}
#line 717 "paper/figures.nw"
static void load_text(const Side *sd, char *buf, size_t size)
{
  char p1[64], p2[64];
  enhanced_number(sd->P[0], p1, sizeof p1);
  enhanced_number(sd->P[1], p2, sizeof p2);
  if (sd->P[0] == 0) snprintf(buf, size, "{/:Italic P}_2 = %s N/m^2", p2);
  else if (sd->P[1] == 0) snprintf(buf, size, "{/:Italic P}_1 = %s N/m^2", p1);
  else snprintf(buf, size, "({/:Italic P}_1, {/:Italic P}_2) = (%s, %s) N/m^2", p1, p2);
}
#line 731 "paper/figures.nw"
static void side_point(FILE *f, int k, const char *s, double dx, double dy)
{
  fprintf(f, "%s + cx(%.4g), %s + cy(%.4g)", k == SIDE_TOP ? s : k == SIDE_LEFT ? "a" : "b",
          dx, k == SIDE_TOP ? "gamma" : s, dy);
}
#line 741 "paper/figures.nw"
static void side_load(FILE *f, const Side *sd, int k, double ucm)
{
  double tail[2], head[2], reach = load_reach(sd, k);
  double len = (sd->to - sd->from) * ucm, step;
  const double *n = normal[k];
  int m = (int) fmax(2, floor(len / ASTEP + 0.5) + 1);
  char text[256], mid[64];
  load_arrow(sd, k, tail, head);
  step = (sd->to - sd->from) / (m - 1);
  fprintf(f, "  # %s: the traction (P1, P2) = (%s, %s) N/m^2 on %s < s < %s\n",
          k == SIDE_TOP ? "top" : k == SIDE_LEFT ? "left" : "right", num(sd->P[0]),
          num(sd->P[1]), num(sd->from), num(sd->to));
  fprintf(f, "  do for [k=0:%d] {\n    s = %s + k*%s\n    set arrow from ", m - 1,
          num(sd->from), num(step));
  side_point(f, k, "s", tail[0], tail[1]);
  fprintf(f, " to ");
  side_point(f, k, "s", head[0], head[1]);
  fprintf(f, " \\\n        head filled size cx(%g),25 lw 1.5 lc '#b00000'\n  }\n", AHEAD);
  if (tail[0] * n[0] + tail[1] * n[1] > AGAP) {    /* it pushes: join the tails */
    fprintf(f, "  set arrow from ");
    side_point(f, k, num(sd->from), tail[0], tail[1]);
    fprintf(f, " to ");
    side_point(f, k, num(sd->to), tail[0], tail[1]);
    fprintf(f, " nohead lw 1.5 lc '#b00000'\n");
  }
  load_text(sd, text, sizeof text);
  snprintf(mid, sizeof mid, "%s", num(0.5 * (sd->from + sd->to)));
  fprintf(f, "  set label ");
  quote(f, text, 0);
  fprintf(f, " at ");
  side_point(f, k, mid, (reach + ALABEL) * n[0], (reach + ALABEL) * n[1]);
  fprintf(f, " center%s tc '#b00000'\n", k == SIDE_TOP ? "" : " rotate by 90");
}
#line 785 "paper/figures.nw"
/* the name of side k: Gamma_D, or Gamma_P with its number among the others */
static void side_name(const Problem *p, int k, char *buf, size_t size)
{
  int m = 0;
  for (int j = 0; j <= k; j++) m += p->side[j].kind != BC_CLAMPED;
  if (p->side[k].kind == BC_CLAMPED) snprintf(buf, size, "Γ_D");
  else snprintf(buf, size, "Γ@^{/*0.7 %d}_{/*0.7 P}", m);
}

/* x1 of the top's name, and its height above the top in cm */
static void top_name_place(const Problem *p, const Body_page *L, double *x, double *up)
{
  const Side *t = &p->side[SIDE_TOP];
  double W = p->b - p->a, left = 0, right = 0;
  *x = p->a + 0.25 * W;
  *up = L->ext[SIDE_TOP] + 0.396;
  if (t->kind != BC_TRACTION) return;
  left = t->from - p->a;
  right = p->b - t->to;
  if (fmax(left, right) >= 0.2 * W) {
    *x = left >= right ? p->a + 0.5 * left : t->to + 0.5 * right;
    *up = 0.396;
  } else {
    *x = p->a + 0.08 * W;
    *up = L->ext[SIDE_TOP] + ALABEL + 0.396;
  }
}
#line 819 "paper/figures.nw"
static void body_force_label(FILE *f, const Problem *p, int low);
static void body_labels(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  char name[64], g[64];
  double x, up;
  int low = p->gamma * L->ucm * L->vex < 3;
  fprintf(f, "  set label 'Ω({/:Italic α}^0)' at a + %s*(b - a), %s*gamma "
          "center front font sprintf(',%%g', 1.4*fsz)\n", low ? "0.3" : "0.275",
          low ? "0.5" : "0.6");
  side_name(p, SIDE_LEFT, name, sizeof name);
  fprintf(f, "  set label '%s' at a - cx(%.4g), 0.6*gamma right\n", name, L->ext[0] + LGAP);
  side_name(p, SIDE_RIGHT, name, sizeof name);
  fprintf(f, "  set label '%s' at b + cx(%.4g), 0.6*gamma left\n", name, L->ext[1] + LGAP);
  side_name(p, SIDE_TOP, name, sizeof name);
  top_name_place(p, L, &x, &up);
  fprintf(f, "  set label '%s' at %s, gamma + cy(%.4g) center\n", name, num(x), up);
  fprintf(f, "  set label 'Γ_C({/:Italic α}^0)' at a + %s*(b - a), cy(0.616) center front\n",
          low ? "0.1" : "0.1875");
  if (p->contact == CONTACT_TRESCA) enhanced_number(p->slip_bound, g, sizeof g);
  if (p->contact == CONTACT_COULOMB) enhanced_number(p->friction, g, sizeof g);
  fprintf(f, "  set label 'rigid foundation  {/:Italic x}_2 ≤ 0%s%s%s' at (a + b)/2, "
          "-cy(0.44) center boxed\n", p->contact == CONTACT_TRESCA ? ", given friction "
          "{/:Italic g} = " : p->contact == CONTACT_COULOMB ? ", Coulomb friction "
          "{/:Italic F} = " : "", p->contact == CONTACT_FRICTIONLESS ? "" : g,
          p->contact == CONTACT_TRESCA ? " N/m^2" : "");
  fprintf(f, "  set style textbox opaque noborder\n");
  if (p->has_body_force) body_force_label(f, p, low);
}
#line 852 "paper/figures.nw"
static void body_force_label(FILE *f, const Problem *p, int low)
{
  char f1[64], f2[64];
  enhanced_number(p->F[0], f1, sizeof f1);
  enhanced_number(p->F[1], f2, sizeof f2);
  fprintf(f, "  set label 'body force ({/:Italic F}_1, {/:Italic F}_2) = (%s, %s) N/m^3' "
          "at a + %s*(b - a), %s*gamma center front\n", f1, f2, low ? "0.7" : "0.65",
          low ? "0.5" : "0.6");
}
#line 867 "paper/figures.nw"
static void body_upper(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  place(f, "left", "(xhi - xlo)*ucm", "top", "(yhi - ylo)*ucm*vex");
  fprintf(f, "  set xrange [xlo:xhi]; set yrange [ylo:yhi]\n");
  tics(f, "x", p->a, p->b, 4, 0);
  tics(f, "y", 0, p->gamma, 2, 1);
  fprintf(f, "  set ylabel '{/:Italic x}_2 [m]'\n  set border 3\n");
  if (L->vex > 1)
    fprintf(f, "  set title 'vertical scale exaggerated ×%g' offset 0, -0.3\n", L->vex);
  fprintf(f, "  set object rect from xlo, ylo to xhi, 0 fs pattern 5 noborder fc 'gray40' back\n"
          "  set arrow from xlo, 0 to xhi, 0 nohead lw 2 lc 'gray30' back\n");
  int n = rollers(p->gamma * L->ucm * L->vex);
  side_support(f, p->side[SIDE_LEFT].kind, "a", "a_left", -1, n);
  side_support(f, p->side[SIDE_RIGHT].kind, "b", "a_right", 1, n);
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
#line 907 "paper/figures.nw"
static void body_strip_plot(FILE *f, const Plot *pl);
static void body_strip(FILE *f, const Plot *pl, const Body_page *L)
{
  const Problem *p = &pl->s.problem;
  double step = nice(0.4 * L->shi / 1.4);
  fprintf(f, "  stop = top + (yhi - ylo)*ucm*vex + gap\n");
  place(f, "left", "(xhi - xlo)*ucm", "stop", "(shi - slo)*exag*ucm");
  fprintf(f, "  set yrange [slo:shi]\n");
  tics_at(f, "y", 0, step, floor(L->shi / step + SLACK) * step, 1);
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
          "  set label 'Γ_C({/:Italic α}^0)' at a + 0.25*(b - a), 0.9*shi/1.4 center front\n"
          "  if (a_max > 0) {\n"
          "    set label 'gap' at (x_gap < (a + b)/2 ? x_gap + 0.075*(b - a) : "
          "x_gap - 0.075*(b - a)), 0.4*a_max \\\n"
          "        center front font sprintf(',%%g', 0.9*fsz)\n  }\n");
  body_strip_plot(f, pl);
  fprintf(f, "  unset object; unset arrow; unset label; unset title; unset xlabel\n");
}
#line 940 "paper/figures.nw"
static void body_strip_plot(FILE *f, const Plot *pl)
{
  fprintf(f, "  plot shape using 1:2 with filledcurves y=shi fc '#dce6f2' notitle, \\\n"
          "       shape using 1:2 with linespoints lw 2 pt 7 ps 0.5 lc 'black' notitle");
  if (pl->optimize)
    fprintf(f, ", \\\n       final using 1:2 with lines dt 2 lw 2 lc '#1f4e99' notitle");
  fprintf(f, "\n");
}
#line 957 "paper/figures.nw"
static void body_figure(FILE *f, const Plot *pl, const char *out)
{
  const Problem *p = &pl->s.problem;
  const double *al = pl->s.alpha0;
  Body_page L = body_page(pl);
  char path[1200];
  int g = 0;
  for (int i = 1; i <= p->N; i++) if (al[i] > al[g]) g = i;
  script_head(f, pl, "The body", out);
  snprintf(path, sizeof path, "%s/%sshape.dat", pl->args->dir, pl->optimize ? "initial/" : "");
  fprintf(f, "shape = ");
  quote(f, path, 0);
  snprintf(path, sizeof path, "%s/final/shape.dat", pl->args->dir);
  if (pl->optimize) fprintf(f, "; final = "), quote(f, path, 0);
  fprintf(f, "\na_left = %s; a_right = %s          # alpha0 at a and at b\n"
          "x_gap = %s; a_max = %s           # the widest gap, and where\n",
          real(al[0], 0), real(al[p->N], 0), real(problem_node_x(p, g), 0), real(al[g], 0));
  fprintf(f, "ucm = %s; vex = %s                # cm per metre along x1; x2 exaggerated\n",
          real(L.ucm, 6), real(L.vex, 0));
  fprintf(f, "xlo = %s; xhi = %s; ylo = %s; yhi = %s    # the upper panel\n",
          real(L.xlo, 6), real(L.xhi, 6), real(L.ylo, 6), real(L.yhi, 6));
  fprintf(f, "slo = %s; shi = %s; exag = %s     # the bottom strip, x2 times exag\n"
          "left = 2.6; top = %s; gap = 2.2                  # margins (cm)\n"
          "Wcm = left + (xhi - xlo)*ucm + 0.6\n"
          "Hcm = top + (yhi - ylo)*ucm*vex + gap + (shi - slo)*exag*ucm + 1.6\n",
          real(L.slo, 6), real(L.shi, 6), real(L.exag, 0), real(L.top, 0));
  fputs(page_lines, f);
  fprintf(f, "do for [fmt in 'pdf png'] {\n%s", terminal_lines);
  fprintf(f, "  set multiplot title sprintf('%%s: Ω({/:Italic α}^0) and the parts of its "
          "boundary', title)\n");
  body_upper(f, pl, &L);
  body_strip(f, pl, &L);
  fprintf(f, "  unset multiplot\n  set output\n}\n");
}
#line 1051 "paper/figures.nw"
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
  L.vex = p->gamma * L.ucm >= 1.2 ? 1 : nice_down(2.6 / (p->gamma * L.ucm));
  L.graphs = pl->optimize ? (p->contact == CONTACT_FRICTIONLESS ? 1 : 2) : 0;
  return L;
}
#line 1072 "paper/figures.nw"
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
#line 1088 "paper/figures.nw"
static void results_scales(FILE *f, const Plot *pl);
static void results_head(FILE *f, const Plot *pl, const Results_page *L, const char *out)
{
  const Problem *p = &pl->s.problem;
  double W = p->b - p->a;
  script_head(f, pl, "The results", out);
  for (int k = 0; k < 1 + pl->optimize; k++) {
    fprintf(f, "s%d = ", k);
    quote(f, pl->state[k], 0);
    fprintf(f, "                # the %s state\n", k ? "final" : "initial");
  }
  if (pl->optimize) fprintf(f, "opt = "), quote(f, pl->args->dir, 0), fprintf(f, "\n");
  if (pl->args->start) fprintf(f, "start = "), quote(f, pl->args->start, 0), fprintf(f, "\n");
  fprintf(f, "bxlo = %s; bxhi = %s; bylo = %s; byhi = %s    # a body panel\n",
          real(p->a - 0.025 * W, 6), real(p->b + 0.025 * W, 6), real(-0.25 * p->gamma, 6),
          real(1.1 * p->gamma, 6));
  fprintf(f, "ucm = %s; vex = %s              # cm per metre along x1; x2 exaggerated\n"
          "left = 2.8; colw = %s; colgap = 2.4; pw = (bxhi - bxlo)*ucm    # cm\n"
          "top = 2.4; rowgap = 2.3; graphh = %s; bodyh = (byhi - bylo)*ucm*vex\n"
          "Wcm = left + 2*colw + colgap + 0.5\n"
          "graphgap = rowgap + 0.8          # between two rows of graphs, room for x labels\n"
          "Hcm = top + 3*bodyh + 2*rowgap + %d*(rowgap + graphh) + %d*0.8 + 1.6\n",
          real(L->ucm, 6), real(L->vex, 0), real(COLW, 0), real(GRAPHH, 0), L->graphs,
          L->graphs > 1 ? L->graphs - 1 : 0);
  fputs(page_lines, f);
  fprintf(f, "colx(c) = left + c*(colw + colgap)         # the left edge of column c\n"
          "amax(x, y) = x > y ? x : y\n"
          "tens(m) = m > 0 ? floor(log10(m)) : 0       # the power of ten of m\n");
  results_scales(f, pl);
}
#line 1124 "paper/figures.nw"
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
#line 1160 "paper/figures.nw"
static const char *state_name[2] = { "Ω({/:Italic α}^0)", "Ω({/:Italic α}^*)" };

static void body_panel_place(FILE *f, const Plot *pl, const Panel *q)
{
  const Problem *p = &pl->s.problem;
  char x[32], y[64];
  snprintf(x, sizeof x, "colx(%d)", q->col);
  snprintf(y, sizeof y, "top + %d*(bodyh + rowgap)", q->row);
  place(f, x, "pw", y, "bodyh");
  fprintf(f, "  set xrange [bxlo:bxhi]; set yrange [bylo:byhi]\n");
  tics(f, "x", p->a, p->b, 4, 0);
  tics(f, "y", 0, p->gamma, 2, 0);
  fprintf(f, "  set border 3\n");
}

/* the end of a body panel's title: the exaggeration of x2, if any */
static const char *exaggerated(const Results_page *L)
{
  static char buf[64];
  snprintf(buf, sizeof buf, L->vex > 1 ? ", {/:Italic x}_2 ×%g" : "", L->vex);
  return buf;
}
#line 1189 "paper/figures.nw"
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
#line 1217 "paper/figures.nw"
static void graph_place(FILE *f, const Panel *q)
{
  char x[32], y[96];
  snprintf(x, sizeof x, "colx(%d)", q->col);
  if (q->row < 3) snprintf(y, sizeof y, "top + %d*(bodyh + rowgap)", q->row);
  else snprintf(y, sizeof y, "top + 3*(bodyh + rowgap) + %d*(graphh + graphgap)", q->row - 3);
  place(f, x, "colw", y, q->row < 3 ? "bodyh" : "graphh");
}
#line 1233 "paper/figures.nw"
static void energy_graph(FILE *f, const Plot *pl)
{
  double step = nice_up(fmax(1, pl->iterations / 2.0));
  fprintf(f, "  set title '(d) {/:Italic E_h} against iteration'\n"
          "  set xlabel 'iteration' offset 0, 0.4\n"
          "  set ylabel sprintf('{/:Italic E_h} [10^{%%d} J/m]', ee)\n"
          "  set xrange [*:*]; set autoscale xfix; set yrange [*:*]; set offsets 0.5, 0.5, 0, 0\n"
          "  set xtics 0, %s out nomirror; set ytics autofreq out nomirror\n"
          "  set key top right spacing 1.2\n"
          "  plot opt.'/history.dat' using 1:($2/10.0**ee) with linespoints pt 7 ps 0.6 lw 1.5 \\\n"
          "           lc '#1f4e99' title '%s'", num(step), pl->projected ?
          "iterates, from {/:Italic α}^0 projected onto {/:Italic B}" : "iterates");
  if (pl->args->start)
    fprintf(f, ", \\\n       start.'/summary.dat' using (0):(strcol(1) eq 'energy' ? "
            "$2/10.0**ee : NaN) \\\n           with points pt 6 ps 1.2 lc 'black' title '%s'",
            pl->projected ? "{/:Italic α}^0 as given, outside {/:Italic B}"
                          : "{/:Italic α}^0 as given");
  fprintf(f, "\n  set offsets 0, 0, 0, 0\n");
}
#line 1265 "paper/figures.nw"
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
  fprintf(f, "  set xrange [%s:%s]; ", num(p->a), num(p->b));
  if (q->kind == PRESSURE) fprintf(f, "set yrange [plo:*]\n");
  else fprintf(f, "set yrange [*:*]; if (%cm == 0) { set yrange [-1:1] }\n", e[0]);
  tics(f, "x", p->a, p->b, 4, 0);
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
#line 1296 "paper/figures.nw"
static void results_figure(FILE *f, const Plot *pl, const char *out)
{
  Results_page L = results_page(pl);
  const Panel *q = pl->optimize ? optimize_panels : solve_panels;
  int n = pl->optimize ? 8 : 4;
  if (pl->s.problem.contact != CONTACT_FRICTIONLESS) n += 2;
  results_head(f, pl, &L, out);
  fprintf(f, "do for [fmt in 'pdf png'] {\n%s", terminal_lines);
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
#line 1330 "paper/figures.nw"
extern char **environ;

/* gnuplot started, reading its script from *f, its errors going to err */
static int gnuplot_start(pid_t *pid, FILE **f, int err, Status *st)
{
  int fd[2], rc;
  char *argv[] = { (char *) "gnuplot", NULL };
  posix_spawn_file_actions_t fa;
  if (pipe(fd))
    return status_set(st, STATUS_SYSTEM, "plot: cannot run gnuplot: %s", strerror(errno));
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fd[0], 0);
  posix_spawn_file_actions_adddup2(&fa, err, 2);
  posix_spawn_file_actions_addclose(&fa, fd[0]);
  posix_spawn_file_actions_addclose(&fa, fd[1]);
  rc = posix_spawnp(pid, "gnuplot", &fa, NULL, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  close(fd[0]);
  if (rc) {
    close(fd[1]);
    return status_set(st, STATUS_SYSTEM, "plot: cannot run gnuplot (%s); it draws "
                      "the figures: install it (Debian: apt-get install gnuplot-nox)",
                      strerror(rc));
  }
  if (!(*f = fdopen(fd[1], "w"))) {
    close(fd[1]);
    waitpid(*pid, NULL, 0);
    return status_set(st, STATUS_SYSTEM, "plot: cannot write to gnuplot: %s", strerror(errno));
  }
  return STATUS_OK;
}
#line 1365 "paper/figures.nw"
static void last_line(FILE *f, char *buf, size_t size)
{
  char line[1024];
  buf[0] = 0;
  rewind(f);
  while (fgets(line, sizeof line, f)) {
    char *s = line, *e = line + strlen(line);
    while (*s == ' ' || *s == '\t') s++;
    while (e > s && (e[-1] == '\n' || e[-1] == ' ' || e[-1] == '\t')) *--e = 0;
    if (*s) snprintf(buf, size, "%s", s);
  }
}
#line 1382 "paper/figures.nw"
static int gnuplot_end(pid_t pid, FILE *err, const char *name, Status *st)
{
  int ws = 0, done;
  char why[1024];
  while ((done = waitpid(pid, &ws, 0)) < 0 && errno == EINTR) ;
  if (done >= 0 && WIFEXITED(ws) && WEXITSTATUS(ws) == 0) return STATUS_OK;
  if (interrupt_signal())
    return status_set(st, STATUS_INTERRUPTED, "plot: interrupted by signal %d: "
                      "%s not drawn", interrupt_signal(), name);
  if (done >= 0 && WIFSIGNALED(ws))
    return status_set(st, STATUS_SYSTEM, "plot: gnuplot was killed by signal %d "
                      "drawing %s", WTERMSIG(ws), name);
  last_line(err, why, sizeof why);
  return status_set(st, STATUS_SYSTEM, "plot: gnuplot failed (exit status %d) "
                    "drawing %s%s%s", done < 0 ? -1 : WEXITSTATUS(ws), name,
                    why[0] ? ": " : "", why);
}
#line 1406 "paper/figures.nw"
static void write_script(FILE *f, const Plot *pl, int fig, const char *out)
{
  if (fig == PLOT_BODY) body_figure(f, pl, out);
  else results_figure(f, pl, out);
}

/* remove the staged files of a figure */
static void unstage(const char *stage)
{
  char path[1300];
  snprintf(path, sizeof path, "%s.pdf", stage);
  remove(path);
  snprintf(path, sizeof path, "%s.png", stage);
  remove(path);
}

/* the staged files of a figure moved into place */
static int commit(const char *stage, const char *name, Status *st)
{
  static const char *const ext[] = { "pdf", "png" };
  char from[1300], to[1300];
  for (int k = 0; k < 2; k++) {
    snprintf(from, sizeof from, "%s.%s", stage, ext[k]);
    snprintf(to, sizeof to, "%s.%s", name, ext[k]);
    if (rename(from, to)) {
      int e = errno;
      unstage(stage);
      return status_set(st, STATUS_SYSTEM, "plot: cannot move %s into place: %s", to,
                        strerror(e));
    }
  }
  return STATUS_OK;
}
#line 1448 "paper/figures.nw"
static int draw(const Plot *pl, int fig, const char *name, Status *st)
{
  char stage[1200];
  struct sigaction ignore, before;
  FILE *f, *err = tmpfile();
  pid_t pid;
  int rc;
  if (!err)
    return status_set(st, STATUS_SYSTEM, "plot: cannot make a temporary file: %s",
                      strerror(errno));
  snprintf(stage, sizeof stage, "%s.partial-%ld", name, (long) getpid());
  if ((rc = gnuplot_start(&pid, &f, fileno(err), st))) {
    fclose(err);
    return rc;
  }
  memset(&ignore, 0, sizeof ignore);
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &before);
  write_script(f, pl, fig, stage);
  fclose(f);               /* an error here is gnuplot's, and its status says it */
  rc = gnuplot_end(pid, err, name, st);
  sigaction(SIGPIPE, &before, NULL);
  fclose(err);
  if (rc) unstage(stage);
  return rc ? rc : commit(stage, name, st);
}
#line 1485 "paper/figures.nw"
static void figure_name(const Plot_args *a, int fig, char *buf, size_t size)
{
  const char *suffix = fig == PLOT_BODY ? "body" : "results";
  if (a->name && a->figures != (PLOT_BODY | PLOT_RESULTS)) snprintf(buf, size, "%s", a->name);
  else if (a->name) snprintf(buf, size, "%s-%s", a->name, suffix);
  else snprintf(buf, size, "%s/plot-%s", a->dir, suffix);
}

static int writable(const char *name, Status *st)
{
  char dir[1200];
  const char *slash = strrchr(name, '/');
  if (!slash) snprintf(dir, sizeof dir, ".");
  else if (slash == name) snprintf(dir, sizeof dir, "/");
  else snprintf(dir, sizeof dir, "%.*s", (int) (slash - name), name);
  if (access(dir, W_OK))
    return status_set(st, STATUS_SYSTEM, "plot: cannot write %s.pdf: %s: %s", name,
                      dir, strerror(errno));
  return STATUS_OK;
}
#line 1511 "paper/figures.nw"
static int plot_open(Plot *pl, const Plot_args *a, Status *st)
{
  char scene[1100], file[64];
  char *override[2] = { (char *) "design.initial=file", file };
  int start_optimize = 0, rc;
  memset(pl, 0, sizeof *pl);
  pl->args = a;
  if ((rc = plot_folder(a->dir, &pl->optimize, st))) return rc;
  if (a->start && !pl->optimize)
    return status_set(st, STATUS_INPUT, "plot: --start: %s is a run of solve; --start "
                      "gives a run of optimize its initial state", a->dir);
  if (a->start && (rc = plot_folder(a->start, &start_optimize, st))) return rc;
  if (start_optimize)
    return status_set(st, STATUS_INPUT, "plot: --start %s: a run of optimize, not of "
                      "solve", a->start);
  snprintf(pl->state[0], sizeof pl->state[0], "%s%s", a->start ? a->start : a->dir,
           pl->optimize && !a->start ? "/initial" : "");
  snprintf(pl->state[1], sizeof pl->state[1], "%s/final", a->dir);
  snprintf(file, sizeof file, "design.file=%sshape.dat", pl->optimize ? "initial/" : "");
  snprintf(scene, sizeof scene, "%s/effective.scene", a->dir);
  if ((rc = scene_load(&pl->s, scene, 2, override, st))) return rc;
  pl->projected = summary_value(a->dir, "initial_projected", 0) != 0;
  pl->iterations = (int) summary_value(a->dir, "iterations", 0);
  return STATUS_OK;
}
#line 1541 "paper/figures.nw"
int plot_run(const Plot_args *a, FILE *out, Plot_drawn *d, Status *st)
{
  static const int fig[2] = { PLOT_BODY, PLOT_RESULTS };
  Plot pl;
  int rc = plot_open(&pl, a, st);
  d->n = 0;
  for (int k = 0; k < 2 && !rc; k++) {
    figure_name(a, fig[k], d->name[k], sizeof d->name[k]);
    if ((a->figures & fig[k]) && !a->print) rc = writable(d->name[k], st);
  }
  if (!rc && !a->print)
    interrupt_catch(1, "contactopt: plot: interrupted: the figures finished are "
                    "kept, the one being drawn is not\n", NULL, NULL);
  for (int k = 0; k < 2 && !rc; k++) {
    if (!(a->figures & fig[k])) continue;
    if (a->print) write_script(out, &pl, fig[k], d->name[k]);
    else if (!(rc = draw(&pl, fig[k], d->name[k], st))) d->drawn[d->n++] = k;
    if (!rc && !a->print && interrupt_signal())
      rc = status_set(st, STATUS_INTERRUPTED, "plot: interrupted by signal %d after "
                      "%s", interrupt_signal(), d->name[k]);
  }
  if (!a->print) interrupt_catch(0, NULL, NULL, NULL);
  if (!rc && a->print && fflush(out))
    rc = status_set(st, STATUS_SYSTEM, "plot: cannot print the script: %s", strerror(errno));
  scene_free(&pl.s);
  return rc;
}
