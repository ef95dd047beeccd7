#line 211 "paper/design.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design_private.h"
#line 545 "paper/design.nw"
typedef struct {              /* points of a piecewise linear derivative */
  double *x, *d;              /* cap: stored (xi, eta) of each point */
  int bot, top, cap;          /* live: bot..top-1, top-1 nearest the zero */
  double s, c, e;             /* (xi, eta) is x = xi + s, d = eta + c xi + e */
} Breakpoints;
#line 553 "paper/design.nw"
typedef struct {
  const Design_set *B;
  int n;                      /* N+1 */
  double delta;               /* min(delta, C0): the slope bound of the pass */
  double *Y;                  /* n: the point, copied (X may alias Y) */
  double *Z;                  /* n: Y - mu w, projected onto C */
  double *xstar;              /* n: the minimiser of V_i over [0, C0] */
  double *X;                  /* n: P_C(Z) */
  double *lo, *hi;            /* n: intervals of the slope multipliers */
  signed char *edge, *box;    /* n: active at X: step i +1 up, -1 down,
                                 2 both (delta = 0); X_i -1 at 0, +1 at C0 */
  signed char *edge0, *box0;  /* n: those of the previous evaluation */
  Breakpoints L, R;                 /* the derivative left and right of its zero */
  double M;                   /* the largest term of a value read in the pass */
  double mu, g, slope;        /* the multiplier, g(mu), g' on its piece */
} Projection;
#line 355 "paper/design.nw"
static void evaluate_g(Projection *w, double mu);

static double area_rounding(const Projection *w)
{
  return w->n * DBL_EPSILON * w->B->C0 * w->B->N * w->B->h;
}

static int newton_on_pieces(Projection *w, double lo, double hi, Status *st);

static int find_multiplier(Projection *w, Status *st)
{
  const Design_set *B = w->B;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 0; i < w->n; i++) {
    lo = fmin(lo, (w->Y[i] - B->C0) / design_weight(B, i));
    hi = fmax(hi, w->Y[i] / design_weight(B, i));
  }
  double top = B->C0 * B->N * B->h;
  if (B->area >= top - area_rounding(w)) { evaluate_g(w, lo); return STATUS_OK; }
  if (B->area <= area_rounding(w)) { evaluate_g(w, hi); return STATUS_OK; }
  return newton_on_pieces(w, lo, hi, st);
}
#line 381 "paper/design.nw"
static void chain_project(Projection *w);
static double piece_slope(const Projection *w);

static void evaluate_g(Projection *w, double mu)
{
  w->mu = mu;
  for (int i = 0; i < w->n; i++) w->Z[i] = w->Y[i] - mu * design_weight(w->B, i);
  chain_project(w);
  w->g = design_area(w->B, w->X) - w->B->area;
  w->slope = piece_slope(w);
}
#line 397 "paper/design.nw"
static double piece_slope(const Projection *w)
{
  double slope = 0;
  for (int first = 0, last; first < w->n; first = last + 1) {
    double sum = 0;
    int fixed = 0;
    for (last = first; ; last++) {
      sum += design_weight(w->B, last);
      fixed |= w->box[last] != 0;
      if (last == w->n - 1 || !w->edge[last]) break;
    }
    if (!fixed) slope -= sum * sum / (last - first + 1);
  }
  return slope;
}
#line 435 "paper/design.nw"
static int same_piece(const Projection *w);
static void keep_piece(Projection *w);

static int newton_on_pieces(Projection *w, double lo, double hi, Status *st)
{
  const int limit = 3 * (DBL_MAX_EXP - DBL_MIN_EXP + 2 * DBL_MANT_DIG);
  double mu = lo < 0 && 0 < hi ? 0 : lo + 0.5 * (hi - lo);
  double g1 = HUGE_VAL, g2 = HUGE_VAL;     /* |g| one and two evaluations ago */
  int newton = 0;
  for (int it = 0; it < limit; it++) {
    evaluate_g(w, mu);
    
#line 456 "paper/design.nw"
if (fabs(w->g) <= area_rounding(w) || (newton && same_piece(w)))
  return STATUS_OK;
#line 447 "paper/design.nw"
    
#line 461 "paper/design.nw"
if (w->g > 0) lo = mu; else hi = mu;
int stalled = fabs(w->g) > 0.5 * g2;
g2 = g1;
g1 = fabs(w->g);
keep_piece(w);
#line 448 "paper/design.nw"
    
#line 470 "paper/design.nw"
double mid = lo + 0.5 * (hi - lo);
if (!(lo < mid && mid < hi)) return STATUS_OK;
double step = w->slope < 0 ? mu - w->g / w->slope : mid;
newton = w->slope < 0 && !stalled && lo < step && step < hi;
mu = newton ? step : mid;
#line 449 "paper/design.nw"
  }
  return status_set(st, STATUS_NUMERIC, "design: the multiplier of the area "
                    "was not found in %d evaluations", limit);
}
#line 479 "paper/design.nw"
static int same_piece(const Projection *w)
{
  return !memcmp(w->edge, w->edge0, w->n) && !memcmp(w->box, w->box0, w->n);
}

static void keep_piece(Projection *w)
{
  memcpy(w->edge0, w->edge, w->n);
  memcpy(w->box0, w->box, w->n);
}
#line 572 "paper/design.nw"
static double point_x(const Breakpoints *G, int k) { return G->x[k] + G->s; }
static double point_d(const Breakpoints *G, int k)
{
  return G->d[k] + G->c * G->x[k] + G->e;
}

static void point_set(Breakpoints *G, int k, double x, double d)
{
  G->x[k] = x - G->s;
  G->d[k] = d - G->c * G->x[k] - G->e;
}
#line 587 "paper/design.nw"
static void push(Breakpoints *G, double x, double d)
{
  if (G->top == G->cap) {
    int live = G->top - G->bot;
    memmove(G->x, G->x + G->bot, live * sizeof *G->x);
    memmove(G->d, G->d + G->bot, live * sizeof *G->d);
    G->bot = 0;
    G->top = live;
  }
  point_set(G, G->top++, x, d);
}

static void move_top(Breakpoints *from, Breakpoints *to)
{
  int k = --from->top;
  push(to, point_x(from, k), point_d(from, k));
}
#line 608 "paper/design.nw"
static void rebase(Breakpoints *G);

static void add_linear(Breakpoints *G, double z, double C0)
{
  G->c += 1;
  G->e += G->s - z;
  if (G->c > G->top - G->bot + 16 || fabs(G->s) > C0) rebase(G);
}
#line 622 "paper/design.nw"
static double argmin_V(Projection *w);
static void step_V(Projection *w, double xstar, double z);
static void backtrack(Projection *w);
static void mark_active(Projection *w);
static void polish(Projection *w);

static void chain_project(Projection *w)
{
  Breakpoints *L = &w->L, *R = &w->R;
  L->bot = L->top = R->bot = R->top = 0;
  L->s = L->c = L->e = R->s = R->c = R->e = 0;
  push(R, w->B->C0, 0);
  push(R, 0, 0);
  w->M = 0;
  add_linear(L, w->Z[0], w->B->C0);
  add_linear(R, w->Z[0], w->B->C0);
  w->xstar[0] = argmin_V(w);
  for (int i = 1; i < w->n; i++) {
    step_V(w, w->xstar[i - 1], w->Z[i]);
    w->xstar[i] = argmin_V(w);
  }
  backtrack(w);
  mark_active(w);
  polish(w);
}
#line 656 "paper/design.nw"
static void rebase(Breakpoints *G)
{
  for (int k = G->bot; k < G->top; k++) {
    double x = point_x(G, k), d = point_d(G, k);
    G->x[k] = x;
    G->d[k] = d;
  }
  G->s = G->c = G->e = 0;
}
#line 670 "paper/design.nw"
static void cut(Breakpoints *G, const Breakpoints *other, double bound, double side);

static void step_V(Projection *w, double xstar, double z)
{
  Breakpoints *L = &w->L, *R = &w->R;
  push(L, xstar, 0);
  push(R, xstar, 0);
  L->s -= w->delta;
  R->s += w->delta;
  add_linear(L, z, w->B->C0);
  add_linear(R, z, w->B->C0);
  cut(L, R, 0, -1);
  cut(R, L, w->B->C0, +1);
}
#line 693 "paper/design.nw"
static void cut(Breakpoints *G, const Breakpoints *other, double bound, double side)
{
  while (G->top > G->bot && side * (point_x(G, G->bot) - bound) > 0) {
    const Breakpoints *H = G;
    int k = G->bot + 1;
    if (k == G->top) { H = other; k = other->top - 1; }
    double xp = point_x(G, G->bot), dp = point_d(G, G->bot);
    if (k < H->bot) { point_set(G, G->bot, bound, dp); return; }
    double xq = point_x(H, k), dq = point_d(H, k);
    if (side * (xq - bound) >= 0) { G->bot++; continue; }
    point_set(G, G->bot, bound, dp + (dq - dp) * (bound - xp) / (xq - xp));
    return;
  }
}
#line 718 "paper/design.nw"
static double point_terms(const Breakpoints *G, int k)
{
  return fabs(G->d[k]) + fabs(G->c * G->x[k]) + fabs(G->e)
       + fabs(G->x[k]) + fabs(G->s);
}

static double argmin_V(Projection *w)
{
  Breakpoints *L = &w->L, *R = &w->R;
  while (L->top > L->bot && point_d(L, L->top - 1) >= 0) move_top(L, R);
  while (R->top > R->bot && point_d(R, R->top - 1) < 0) move_top(R, L);
  if (L->top == L->bot) return 0;
  if (R->top == R->bot) return w->B->C0;
  double xl = point_x(L, L->top - 1), dl = point_d(L, L->top - 1);
  double xr = point_x(R, R->top - 1), dr = point_d(R, R->top - 1);
  double x = !(xr > xl) ? xr
           : dl >= 0 ? xl : xl + (xr - xl) * (-dl / (dr - dl));
  w->M = fmax(w->M, point_terms(L, L->top - 1) + point_terms(R, R->top - 1));
  return fmin(fmax(x, 0), w->B->C0);
}
#line 742 "paper/design.nw"
static void backtrack(Projection *w)
{
  double *X = w->X, delta = w->delta;
  X[w->n - 1] = w->xstar[w->n - 1];
  for (int i = w->n - 1; i > 0; i--)
    X[i - 1] = fmin(fmax(w->xstar[i - 1], X[i] - delta), X[i] + delta);
}
#line 776 "paper/design.nw"
static void mark_active(Projection *w)
{
  double C0 = w->B->C0, delta = w->B->delta, *X = w->X;
  double tau = 8 * DBL_EPSILON * (w->n * C0 + w->M);
  for (int i = 0; i + 1 < w->n; i++) {
    int up = X[i + 1] - X[i] >= delta - tau;
    int down = X[i] - X[i + 1] >= delta - tau;
    w->edge[i] = up && down ? 2 : up ? 1 : down ? -1 : 0;
  }
  w->edge[w->n - 1] = 0;
  for (int i = 0; i < w->n; i++)
    w->box[i] = X[i] <= tau ? -1 : X[i] >= C0 - tau ? 1 : 0;
}
#line 800 "paper/design.nw"
static void polish_block(Projection *w, int first, int last);

static void polish(Projection *w)
{
  for (int first = 0, last; first < w->n; first = last + 1) {
    for (last = first; last < w->n - 1 && w->edge[last]; last++) ;
    polish_block(w, first, last);
  }
}
#line 817 "paper/design.nw"
static double block_mean(const Projection *w, int first, int last);

static void polish_block(Projection *w, int first, int last)
{
  double *X = w->X, C0 = w->B->C0, o = 0, t;
  int anchor = -1;
  for (int j = first; j <= last; j++) {
    if (j > first) o += w->edge[j - 1] == 1 ? w->B->delta
                      : w->edge[j - 1] == -1 ? -w->B->delta : 0;
    X[j] = o;
    if (anchor < 0 && w->box[j]) anchor = j;
  }
  t = anchor >= 0 ? (w->box[anchor] > 0 ? C0 : 0) - X[anchor]
                  : block_mean(w, first, last);
  for (int j = first; j <= last; j++)
    X[j] = w->box[j] ? (w->box[j] > 0 ? C0 : 0) : fmin(fmax(t + X[j], 0), C0);
}

/* the mean of Z_j - X_j over the block, X holding the offsets */
static double block_mean(const Projection *w, int first, int last)
{
  double t = 0, r = 0;
  int m = last - first + 1;
  for (int j = first; j <= last; j++) t += w->Z[j] - w->X[j];
  t /= m;
  for (int j = first; j <= last; j++) r += w->Z[j] - w->X[j] - t;
  return t + r / m;
}
#line 875 "paper/design.nw"
static void range_of_beta(const Projection *w, int j, double *lo, double *hi)
{
  *lo = w->box[j] < 0 ? -HUGE_VAL : 0;
  *hi = w->box[j] > 0 ? HUGE_VAL : 0;
}

static void range_of_nu(const Projection *w, int j, double *lo, double *hi)
{
  int e = j < w->n - 1 ? w->edge[j] : 0;
  *lo = e == -1 || e == 2 ? -HUGE_VAL : 0;
  *hi = e == 1 || e == 2 ? HUGE_VAL : 0;
}
#line 891 "paper/design.nw"
static void sweep_forward(Projection *w)
{
  double lo = 0, hi = 0, blo, bhi, nlo, nhi;
  for (int j = 0; j < w->n; j++) {
    double r = w->Z[j] - w->X[j];
    range_of_beta(w, j, &blo, &bhi);
    range_of_nu(w, j, &nlo, &nhi);
    lo = fmax(lo - r + blo, nlo);
    hi = fmin(hi - r + bhi, nhi);
    if (lo > hi) lo = hi = hi < nlo ? nlo : nhi;   /* empty by rounding */
    w->lo[j] = lo;
    w->hi[j] = hi;
  }
}
#line 910 "paper/design.nw"
static void sweep_backward(const Projection *w, Design_multipliers *m)
{
  double nu = 0, blo, bhi;
  for (int j = w->n - 1; j >= 0; j--) {
    double target = nu + w->Z[j] - w->X[j];
    double prev = j > 0 ? fmin(fmax(target, w->lo[j - 1]), w->hi[j - 1]) : 0;
    range_of_beta(w, j, &blo, &bhi);
    double beta = fmin(fmax(target - prev, blo), bhi);
    m->upper[j] = fmax(beta, 0);
    m->lower[j] = fmax(-beta, 0);
    if (j > 0) {
      m->up[j - 1] = fmax(prev, 0);
      m->down[j - 1] = fmax(-prev, 0);
    }
    nu = prev;
  }
  m->mu = w->mu;
}
#line 937 "paper/design.nw"
static Projection *projection_new(const Design_set *B, Status *st);
static void projection_free(Projection *w);

int design_project(const Design_set *B, const double *Y, double *X,
                   Design_multipliers *mult, Status *st)
{
  int rc;
  if ((rc = design_check_set(B, st))
      || (rc = design_check_point(B, Y, "the point to project", st))) return rc;
  if (mult && mult->N != B->N)
    return status_set(st, STATUS_INPUT, "design: multipliers made for N = %d "
                      "passed with a design set of N = %d", mult->N, B->N);
  Projection *w = projection_new(B, st);
  if (!w) return STATUS_MEMORY;
  memcpy(w->Y, Y, w->n * sizeof *Y);
  if (!(rc = find_multiplier(w, st))) {
    memcpy(X, w->X, w->n * sizeof *X);
    if (mult) { sweep_forward(w); sweep_backward(w, mult); }
  }
  projection_free(w);
  return rc;
}
#line 963 "paper/design.nw"
static Projection *projection_new(const Design_set *B, Status *st)
{
  Projection *w = calloc(1, sizeof *w);
  if (!w) {
    status_set(st, STATUS_MEMORY, "design: out of memory");
    return NULL;
  }
  w->B = B;
  w->n = B->N + 1;
  w->L.cap = w->R.cap = 2 * w->n + 2;
  w->delta = fmin(B->delta, B->C0);
  w->Y = malloc((6 * (size_t) w->n + 4 * (size_t) w->L.cap) * sizeof *w->Y);
  w->edge = malloc(4 * (size_t) w->n);
  if (!w->Y || !w->edge) {
    projection_free(w);
    status_set(st, STATUS_MEMORY, "design: out of memory for N = %d", B->N);
    return NULL;
  }
  
#line 995 "paper/design.nw"
w->Z = w->Y + w->n;
w->xstar = w->Z + w->n;
w->X = w->xstar + w->n;
w->lo = w->X + w->n;
w->hi = w->lo + w->n;
w->L.x = w->hi + w->n;
w->L.d = w->L.x + w->L.cap;
w->R.x = w->L.d + w->L.cap;
w->R.d = w->R.x + w->R.cap;
w->box = w->edge + w->n;
w->edge0 = w->box + w->n;
w->box0 = w->edge0 + w->n;
#line 982 "paper/design.nw"
  return w;
}

static void projection_free(Projection *w)
{
  if (!w) return;
  free(w->Y);
  free(w->edge);
  free(w);
}
