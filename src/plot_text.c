#line 232 "paper/figures.nw"
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "plot_private.h"
#line 992 "paper/figures.nw"
/* v in the fewest digits that read back as v; an integer as one (10, not 1e+01) */
const char *plot_num(double v)
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
#line 1014 "paper/figures.nw"
const char *plot_real(double v, int digits)
{
  static char buf[8][40];
  static int k;
  char *s = buf[k++ % 8];
  if (digits) snprintf(s, 32, "%.*g", digits, v);
  else snprintf(s, 32, "%s", plot_num(v));
  if (!strpbrk(s, ".en")) strcat(s, ".0");
  return s;
}
#line 1029 "paper/figures.nw"
/* |v| of power of ten x, -2 <= x <= 3, after the sign: three significant
   digits, or all of its integer part (1000, not 1e+03) */
static void plain_number(double v, int x, const char *minus, char *buf, size_t size)
{
  char *e;
  snprintf(buf, size, "%s%.*f", minus, x < 2 ? 2 - x : 0, fabs(v));
  if (!strchr(buf, '.')) return;
  for (e = buf + strlen(buf) - 1; *e == '0'; e--) *e = 0;
  if (*e == '.') *e = 0;
}

/* v as enhanced text: -5.75e8 as −5.75·10^{8} */
void plot_enhanced_number(double v, char *buf, size_t size)
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
  else if (x >= -2 && x <= 3) plain_number(v, x, minus, buf, size);
  else snprintf(buf, size, "%s%s%s10^{%s%d}", minus, strcmp(m, "1") ? m : "",
                strcmp(m, "1") ? "·" : "", x < 0 ? "−" : "", abs(x));
}
#line 1064 "paper/figures.nw"
/* s between single quotes for gnuplot; enhanced: its marks escaped */
void plot_quote(FILE *f, const char *s, int enhanced)
{
  fputc('\'', f);
  for (; *s; s++) {
    if (*s == '\'') fputc('\'', f);
    else if (enhanced && strchr("_^@&~{}\\", *s)) fputc('\\', f);
    fputc(*s, f);
  }
  fputc('\'', f);
}
#line 1082 "paper/figures.nw"
double plot_text_cm(const char *s, double pt)
{
  int n = 0;
  for (; *s; s++) {
    if (*s == '/' && (s[1] == ':' || s[1] == '*')) {      /* a font switch: to its blank */
      while (*s && *s != ' ') s++;
      if (!*s) break;
      continue;
    }
    if (!strchr("{}_^@", *s) && ((unsigned char) *s & 0xC0) != 0x80) n++;
  }
  return n * 0.6 * pt * 2.54 / 72;
}
#line 1108 "paper/figures.nw"
int plot_decimals(double step)
{
  return (int) fmax(0, ceil(-log10(step) - SLACK));
}

int plot_tick_chars(double first, double step, double last)
{
  int chars = 0, d = plot_decimals(step);
  double end[2] = { first, last };
  for (int k = 0; k < 2; k++) {
    double m = fabs(end[k]);
    int digits = m >= 1 ? (int) floor(log10(m) + SLACK) + 1 : 1;
    chars = (int) fmax(chars, (end[k] < 0) + digits + (d ? d + 1 : 0));
  }
  return chars;
}

double plot_tick_room(double base, int chars, double Wcm)
{
  double em = 8.2 * Wcm / 16.4 * 2.54 / 72;       /* cm: fontpt */
  return (base + 0.64 * chars) * em + 0.12;
}
#line 1136 "paper/figures.nw"
double plot_nice_down(double x)
{
  double p = pow(10, floor(log10(x) + SLACK)), m = x / p * (1 + SLACK);
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}
double plot_nice_up(double x)
{
  double d = plot_nice_down(x), m = d / pow(10, floor(log10(d) + SLACK));
  if (d >= x * (1 - SLACK)) return d;
  return d * (fabs(m - 2) < 0.5 ? 2.5 : 2);         /* 1 -> 2, 2 -> 5, 5 -> 10 */
}
double plot_nice(double x)
{
  double d = plot_nice_down(x), u = plot_nice_up(x);
  return x / d <= u / x ? d : u;
}
#line 1161 "paper/figures.nw"
void plot_tics_at(FILE *f, const char *axis, double first, double step,
                    double last, int format)
{
  int decimals = plot_decimals(step);
  if (fabs(first) < step * SLACK) first = 0;
  fprintf(f, "  set %stics %s, %s, %s out nomirror\n", axis, plot_num(first), plot_num(step),
          plot_num(last));
  if (format) fprintf(f, "  set format %s '%%.%df'\n", axis, decimals);
}
void plot_tics(FILE *f, const char *axis, double lo, double hi, double n, int format)
{
  double step = plot_nice((hi - lo) / n);
  plot_tics_at(f, axis, ceil(lo / step - SLACK) * step, step, hi, format);
}
#line 1259 "paper/figures.nw"
const char plot_page_lines[] =
  "dpcm = 1600.0 / Wcm; fontpt = 8.2*Wcm/16.4   # 8.2 pt printed 16.4 cm wide\n"
  "sx(cm) = cm / Wcm\n"
  "sy(cm) = 1.0 - cm / Hcm\n"
  "cx(cm) = cm / ucm             # a length on the page along x1, in m\n"
  "cy(cm) = cm / (ucm*vex)       # and along x2\n";
const char plot_terminal_lines[] =
  "  set encoding utf8; set minussign\n"
  "  dpi = dpcm * 2.54\n"
  "  kfont = fmt eq 'pdf' ? 1.5 : dpi/96.0     # nominal font size per point\n"
  "  klw = fmt eq 'pdf' ? 1.0 : 0.5*dpi/72.0   # nominal line width per half point\n"
  "  fsz = kfont * fontpt\n"
  "  if (fmt eq 'pdf') {\n"
  "    set terminal pdfcairo enhanced color size Wcm/2.54, Hcm/2.54 \\\n"
  "        font sprintf('DejaVu Sans,%.2f', fsz) linewidth klw\n"
  "  } else {\n"
  "    set terminal pngcairo enhanced color size int(Wcm*dpcm + 0.5), int(Hcm*dpcm) \\\n"
  "        font sprintf('DejaVu Sans,%.2f', fsz) linewidth klw background 'white'\n"
  "  }\n"
  "  set output out.'.'.fmt\n"
  "  unset xlabel; unset ylabel; unset title; unset key\n";
#line 1290 "paper/figures.nw"
void plot_widen(double *ucm, double *vex, double w, double least, double want)
{
  double hex;
  if (w >= least) return;
  hex = plot_nice_down(want / w);
  *ucm *= hex;
  *vex /= hex;
}
#line 1307 "paper/figures.nw"
/* the head of a script: the figure, the run, and the variables of both */
void plot_script_head(FILE *f, const Plot *pl, const char *what, const char *out)
{
  const Problem *p = &pl->s.problem;
  fprintf(f, "# %s of the run in %s, from its effective.scene: written by\n"
          "# contactopt plot (the woven paper, appendix \"Figures of a run\").\n"
          "# gnuplot draws it: gnuplot FILE writes out.pdf and out.png.\n"
          "reset\nout = ", what, pl->args->dir);
  plot_quote(f, out, 0);
  fprintf(f, "\ntitle = ");
  plot_quote(f, pl->args->title ? pl->args->title : pl->args->dir, 1);
  fprintf(f, "\na = %s; b = %s; gamma = %s      # the body: a < x1 < b, x2 < gamma\n",
          plot_real(p->a, 0), plot_real(p->b, 0), plot_real(pl->top, 0));
  if (pl->part)
    fprintf(f, "cprime = %s      # the part stands on the strip x2 < cprime\n",
            plot_real(p->C0prime, 0));
}
#line 1328 "paper/figures.nw"
void plot_place(FILE *f, const char *x, const char *w, const char *y, const char *h)
{
  fprintf(f, "  set lmargin at screen sx(%s); set rmargin at screen sx(%s + %s)\n"
          "  set tmargin at screen sy(%s); set bmargin at screen sy(%s + %s)\n",
          x, x, w, y, y, h);
}
