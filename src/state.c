#line 151 "paper/state.nw"
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "state.h"
#line 859 "paper/state.nw"
#define SINGULAR (-1)    /* K or a Newton matrix is singular (not a Status_code) */
#line 1063 "paper/state.nw"
#define PDAS_RCOND_MIN (100 * DBL_EPSILON) /* smaller: K taken to be singular */
#line 1331 "paper/state.nw"
#define MPRGP_GAMMA 1.0  /* proportioning: ||beta||^2 <= Gamma^2 phi~'phi */
#define MPRGP_ABAR 1.9   /* expansion step length abar = 1.9 / ||A|| */
#line 1551 "paper/state.nw"
#define TIE (4 * DBL_EPSILON)  /* blocking steps this close are equal */
#line 270 "paper/state.nw"
struct Qp_workspace {
  const Qp *qp;          /* the problem: its pattern fixed, values may change */
  Qp_options opt;        /* a copy of the caller's options */
  cholmod_common *cm;    /* the caller's CHOLMOD environment */
  int n, nc;             /* unknowns; bounded unknowns |I| */
  int *bnd;              /* n: c when unknown i = ic[c], -1 when unbounded */
  double *lo;            /* n: the lower bound of each unknown, -INFINITY if none */
  double *d;             /* n: the diagonal A_ii > 0 */
  double normA;          /* max row sum of |A|: an upper bound of ||A||_2 */
  double *x;             /* n: the iterate */
  double *g;             /* n: the gradient A x - b at x */
  double *T;             /* nc: the contact forces g[ic[c]] */
  double kkt;            /* qp_kkt at x */
  int iter;              /* iterations since qp_set */
  
#line 732 "paper/state.nw"
cholmod_sparse K;      /* A + D_c: A's pattern (borrowed), own values,
                          stype -1 */
cholmod_factor *Ls;    /* the symbolic analysis of K, bounded unknowns last */
cholmod_factor *L;     /* the factor LL' of K at the current values */
int first;             /* n - nc: where the bounded unknowns start in L */
int *tc;               /* nc: the bounded unknown at position first + t */
double *Lcc;           /* nc x nc, row-major: the trailing block of L */
double *S;             /* nc x nc, row-major: the Schur complement of A */
double *f;             /* nc: the condensed load */
double *y;             /* nc: the condensed iterate x[ic] */
double *M;             /* nc x nc: S on the free set, then its factor
                          (L_cc L_cc' while condensing) */
double *r;             /* nc: a right-hand side on the free set */
int *fr;               /* nc: the free set, listed */
double bu2;            /* ||b_u||^2, for the residual */
cholmod_dense *rhs, *sol, *Y, *E; /* n x 1: cholmod_solve2's vectors */
cholmod_dense *Lb;     /* n x 1: z = L \ P b */
char *act;             /* nc: the active set of the next Newton step */
int condensed;         /* S, f belong to the current values of A and b */
int warm;              /* the first active set is to be guessed from x0 */
#line 285 "paper/state.nw"
  
#line 1336 "paper/state.nw"
double *p;             /* n: the conjugate direction */
double *q;             /* n: A p, or A beta in a proportioning step */
double *z;             /* n: the preconditioned free gradient, or beta */
double abar;           /* the expansion step length 1.9 / normA */
int restart;           /* 1: p must restart from z (the face changed) */
#line 286 "paper/state.nw"
};
#line 350 "paper/state.nw"
static int check_problem(const Qp *qp, const Qp_options *opt,
                         cholmod_common *cm, Status *st);
static int check_options(const Qp_options *opt, Status *st);
static int alloc_common(Qp_workspace *w, Status *st);
static int check_pattern(Qp_workspace *w, Status *st);
static int pdas_alloc(Qp_workspace *w, Status *st);
static int mprgp_alloc(Qp_workspace *w, Status *st);
#line 540 "paper/state.nw"
static void pdas_set(Qp_workspace *w, int warm);
static void mprgp_set(Qp_workspace *w);
static int pdas_step(Qp_workspace *w, Status *st);
static int psor_sweep(Qp_workspace *w, Status *st);
static int mprgp_iterate(Qp_workspace *w, Status *st);
#line 604 "paper/state.nw"
static int not_converged(const Qp_workspace *w, Status *st);
static int count_active(const Qp_workspace *w);
#line 807 "paper/state.nw"
static int analyse_contact_last(Qp_workspace *w, Status *st);
#line 863 "paper/state.nw"
static int condense(Qp_workspace *w, Status *st);
static int newton_solve(Qp_workspace *w);
static void condensed_forces(Qp_workspace *w);
static double condensed_kkt(const Qp_workspace *w);
static int predict_active_set(Qp_workspace *w);
static int expand(Qp_workspace *w, Status *st);
static int refine(Qp_workspace *w, Status *st);
static int solve_pair(Qp_workspace *w, int sys1, int sys2, cholmod_dense **v,
                      Status *st);
static int not_held(const Qp_workspace *w, Status *st, const char *why,
                    int active);
#line 931 "paper/state.nw"
static void fill_contact_matrix(Qp_workspace *w);
static void read_trailing_block(Qp_workspace *w);
static int condensed_load(Qp_workspace *w, Status *st);
static void schur_complement(Qp_workspace *w);
#line 1420 "paper/state.nw"
static int proportional(const Qp_workspace *w);
static int cg_or_expansion_step(Qp_workspace *w, Status *st);
static int proportioning_step(Qp_workspace *w, Status *st);
#line 1502 "paper/state.nw"
static double feasible_step(const Qp_workspace *w);
static void cg_step(Qp_workspace *w, double acg, double pap);
static void expansion_step(Qp_workspace *w, double af);
#line 194 "paper/state.nw"
/* num/den, and 0 whenever num is 0 (den may then be 0 too) */
static double ratio(double num, double den) { return num == 0 ? 0 : num / den; }

/* (Ax)_j: column j of A, which is also its row j */
static double row_dot(const cholmod_sparse *A, int j, const double *x)
{
  const int *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x;
  double s = 0;
  for (int k = Ap[j]; k < Ap[j + 1]; k++) s += Ax[k] * x[Ai[k]];
  return s;
}
#line 213 "paper/state.nw"
/* the relative KKT residual of x; g = Ax - b if known, else NULL;
   T (nc, may be NULL) receives the contact forces */
static double kkt_eval(const Qp *qp, const double *x, const double *g,
                       double *T)
{
  const double *b = qp->b;
  double rf = 0, tn = 0, inf = 0, comp = 0, bb = 0, axax = 0, xx = 0, ll = 0;
  for (int j = 0, c = 0; j < (int) qp->A->ncol; j++) {
    double r = g ? g[j] : row_dot(qp->A, j, x) - b[j], axj = r + b[j];
    bb += b[j] * b[j];
    axax += axj * axj;
    xx += x[j] * x[j];
    if (c < qp->nc && qp->ic[c] == j) {
      
#line 236 "paper/state.nw"
double gap = x[j] - qp->lo[c];
if (r < 0) tn += r * r;          /* a pulling contact force */
if (gap < 0) inf += gap * gap;   /* a penetration */
comp += fabs(r) * fabs(gap);     /* a force without contact */
ll += qp->lo[c] * qp->lo[c];
if (T) T[c] = r;
#line 227 "paper/state.nw"
      c++;
    } else
      rf += r * r;
  }
  
#line 247 "paper/state.nw"
double sf = sqrt(bb) + sqrt(axax), su = sqrt(xx) + sqrt(ll);
double k = fmax(fmax(ratio(sqrt(rf), sf), ratio(sqrt(tn), sf)),
                fmax(ratio(sqrt(inf), su), ratio(ratio(comp, sf), su)));
return isfinite(rf + tn + inf + comp + sf + su) ? k : NAN;
#line 232 "paper/state.nw"
}
#line 254 "paper/state.nw"
double qp_kkt(const Qp *qp, const double *x, double *T)
{
  return kkt_eval(qp, x, NULL, T);
}
#line 293 "paper/state.nw"
/* unknown i is off its bound */
static int is_free(const Qp_workspace *w, int i) { return w->x[i] > w->lo[i]; }

/* the projection of value y of unknown i onto x_i >= lo_i */
static double proj(const Qp_workspace *w, int i, double y)
{
  return y < w->lo[i] ? w->lo[i] : y;
}

static double dot(int n, const double *u, const double *v)
{
  double s = 0;
  for (int i = 0; i < n; i++) s += u[i] * v[i];
  return s;
}

/* y = A x */
static void matvec(const cholmod_sparse *A, const double *x, double *y)
{
  for (int j = 0; j < (int) A->ncol; j++) y[j] = row_dot(A, j, x);
}
#line 318 "paper/state.nw"
/* g = A x - b, then kkt and T at x */
static void refresh(Qp_workspace *w)
{
  matvec(w->qp->A, w->x, w->g);
  for (int i = 0; i < w->n; i++) w->g[i] -= w->qp->b[i];
  w->kkt = kkt_eval(w->qp, w->x, w->g, w->T);
}
#line 332 "paper/state.nw"
Qp_workspace *qp_alloc(const Qp *qp, const Qp_options *opt,
                       cholmod_common *cm, Status *st)
{
  if (check_problem(qp, opt, cm, st)) return NULL;
  Qp_workspace *w = calloc(1, sizeof *w);
  if (!w) { status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory"); return NULL; }
  w->qp = qp, w->opt = *opt, w->cm = cm;
  w->n = (int) qp->A->ncol, w->nc = qp->nc;
  int code = alloc_common(w, st);
  if (!code) code = check_pattern(w, st);
  if (!code && opt->method == QP_PDAS) code = pdas_alloc(w, st);
  if (!code && opt->method == QP_CGSSOR) code = mprgp_alloc(w, st);
  if (code) { qp_free(w); return NULL; }
  return w;
}
#line 361 "paper/state.nw"
static int check_problem(const Qp *qp, const Qp_options *opt,
                         cholmod_common *cm, Status *st)
{
  if (!qp || !qp->A || !qp->b || !opt || !cm
      || (qp->nc > 0 && (!qp->ic || !qp->lo)))
    return status_set(st, STATUS_INPUT, "qp_alloc: a NULL argument");
  const cholmod_sparse *A = qp->A;
  if (A->nrow != A->ncol || A->ncol > INT_MAX || A->stype != 0
      || A->itype != CHOLMOD_INT || A->xtype != CHOLMOD_REAL
      || A->dtype != CHOLMOD_DOUBLE || !A->packed || !A->sorted)
    return status_set(st, STATUS_INPUT, "qp_alloc: A must be square, real "
                      "double with int indices, both triangles stored "
                      "(stype 0), sorted and packed");
  if (qp->nc < 0 || qp->nc > (int) A->ncol)
    return status_set(st, STATUS_INPUT, "qp_alloc: nc = %d is not in [0, %d]",
                      qp->nc, (int) A->ncol);
  for (int c = 0; c < qp->nc; c++)
    if (qp->ic[c] < (c ? qp->ic[c - 1] + 1 : 0) || qp->ic[c] >= (int) A->ncol)
      return status_set(st, STATUS_INPUT, "qp_alloc: ic[%d] = %d: the bounded "
                        "unknowns must increase within [0, %d)", c, qp->ic[c],
                        (int) A->ncol);
  return check_options(opt, st);
}
#line 387 "paper/state.nw"
Qp_options qp_options_default(Qp_method method)
{
  return (Qp_options) { method, 1e-10, method == QP_PDAS ? 100 : 100000, 1.5 };
}
#line 396 "paper/state.nw"
static int check_options(const Qp_options *opt, Status *st)
{
  if (opt->method != QP_PDAS && opt->method != QP_PSOR
      && opt->method != QP_CGSSOR)
    return status_set(st, STATUS_INPUT, "qp_alloc: unknown method %d",
                      (int) opt->method);
  if (!(opt->tol > 0) || opt->max_iter < 1)
    return status_set(st, STATUS_INPUT, "qp_alloc: tol = %g must be positive "
                      "and max_iter = %d at least 1", opt->tol, opt->max_iter);
  if (opt->method != QP_PDAS && !(opt->omega > 0 && opt->omega < 2))
    return status_set(st, STATUS_INPUT, "qp_alloc: omega = %g is not in (0, 2)",
                      opt->omega);
  return STATUS_OK;
}
#line 415 "paper/state.nw"
static int alloc_common(Qp_workspace *w, Status *st)
{
  size_t n = (size_t) w->n + 1, nc = (size_t) w->nc + 1;
  w->bnd = malloc(n * sizeof *w->bnd);
  w->lo = malloc(n * sizeof *w->lo), w->d = malloc(n * sizeof *w->d);
  w->x = malloc(n * sizeof *w->x), w->g = malloc(n * sizeof *w->g);
  w->T = malloc(nc * sizeof *w->T);
  if (!w->bnd || !w->lo || !w->d || !w->x || !w->g || !w->T)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory (n = %d)",
                      w->n);
  for (int i = 0; i < w->n; i++) w->bnd[i] = -1;
  for (int c = 0; c < w->nc; c++) w->bnd[w->qp->ic[c]] = c;
  return STATUS_OK;
}
#line 437 "paper/state.nw"
/* the pattern of A is symmetric: (i,j) is stored iff (j,i) is */
static int check_pattern(Qp_workspace *w, Status *st)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  int *next = malloc(((size_t) w->n + 1) * sizeof *next);
  int oom = !next, bad = oom;
  for (int i = 0; !bad && i < w->n; i++) next[i] = Ap[i];
  for (int j = 0; !bad && j < w->n; j++)
    for (int k = Ap[j]; !bad && k < Ap[j + 1]; k++) {
      int i = Ai[k];
      bad = next[i] >= Ap[i + 1] || Ai[next[i]++] != j;
    }
  for (int i = 0; !bad && i < w->n; i++) bad = next[i] != Ap[i + 1];
  free(next);
  if (oom) return status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory");
  return !bad ? STATUS_OK : status_set(st, STATUS_INPUT, "qp_alloc: the "
    "pattern of A is not symmetric (both triangles must be stored)");
}
#line 458 "paper/state.nw"
void qp_free(Qp_workspace *w)
{
  if (!w) return;
  
#line 840 "paper/state.nw"
free(w->K.x), free(w->act), free(w->tc), free(w->fr);
free(w->f), free(w->y), free(w->r), free(w->Lcc), free(w->S), free(w->M);
cholmod_free_factor(&w->Ls, w->cm), cholmod_free_factor(&w->L, w->cm);
cholmod_free_dense(&w->rhs, w->cm), cholmod_free_dense(&w->sol, w->cm);
cholmod_free_dense(&w->Lb, w->cm);
cholmod_free_dense(&w->Y, w->cm), cholmod_free_dense(&w->E, w->cm);
#line 462 "paper/state.nw"
  
#line 1362 "paper/state.nw"
free(w->p), free(w->q), free(w->z);
#line 463 "paper/state.nw"
  free(w->bnd), free(w->lo), free(w->d);
  free(w->x), free(w->g), free(w->T);
  free(w);
}
#line 478 "paper/state.nw"
/* the diagonal of A, max_j sum_i |A_ij|, and finite values throughout */
static int read_matrix(Qp_workspace *w, Status *st)
{
  const cholmod_sparse *A = w->qp->A;
  const int *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x;
  w->normA = 0;
  for (int j = 0; j < w->n; j++) {
    double sum = 0;
    w->d[j] = 0;
    for (int k = Ap[j]; k < Ap[j + 1]; k++) {
      if (!isfinite(Ax[k])) return status_set(st, STATUS_NUMERIC,
        "qp_set: A(%d,%d) = %g is not finite", Ai[k], j, Ax[k]);
      sum += fabs(Ax[k]);
      if (Ai[k] == j) w->d[j] = Ax[k];
    }
    if (!(w->d[j] > 0)) return status_set(st, STATUS_INPUT, "qp_set: A(%d,%d) = "
      "%g: a diagonal entry must be positive (an unknown without stiffness?)",
      j, j, w->d[j]);
    w->normA = fmax(w->normA, sum);
  }
  return STATUS_OK;
}
#line 504 "paper/state.nw"
/* b and lo finite; lo expanded to all unknowns */
static int read_vectors(Qp_workspace *w, Status *st)
{
  for (int i = 0; i < w->n; i++)
    if (!isfinite(w->qp->b[i])) return status_set(st, STATUS_NUMERIC,
      "qp_set: b[%d] = %g is not finite", i, w->qp->b[i]);
  for (int i = 0; i < w->n; i++) {
    int c = w->bnd[i];
    w->lo[i] = c < 0 ? -INFINITY : w->qp->lo[c];
    if (c >= 0 && !isfinite(w->lo[i])) return status_set(st, STATUS_NUMERIC,
      "qp_set: lo[%d] = %g is not finite", c, w->lo[i]);
  }
  return STATUS_OK;
}
#line 523 "paper/state.nw"
int qp_set(Qp_workspace *w, const double *x0, Status *st)
{
  int code = read_matrix(w, st);
  if (!code) code = read_vectors(w, st);
  if (code) return code;
  for (int i = 0; i < w->n; i++) w->x[i] = proj(w, i, x0 ? x0[i] : 0);
  w->iter = 0;
  refresh(w);
  if (!isfinite(w->kkt))
    return status_set(st, STATUS_NUMERIC, "qp_set: the starting point is not finite");
  if (w->opt.method == QP_PDAS) pdas_set(w, x0 != NULL);
  if (w->opt.method == QP_CGSSOR) mprgp_set(w);
  return STATUS_OK;
}
#line 553 "paper/state.nw"
const char *qp_method_name(Qp_method m)
{
  return m == QP_PDAS ? "pdas" : m == QP_PSOR ? "psor"
       : m == QP_CGSSOR ? "cgssor" : "?";
}

int qp_iterate(Qp_workspace *w, Status *st)
{
  Qp_method m = w->opt.method;
  int code = m == QP_PDAS ? pdas_step(w, st)
           : m == QP_PSOR ? psor_sweep(w, st) : mprgp_iterate(w, st);
  w->iter++;
  if (!code && !isfinite(w->kkt))
    code = status_set(st, STATUS_NUMERIC, "%s: NaN or infinity after %d "
                      "iterations", qp_method_name(m), w->iter);
  return code;
}

int qp_test(const Qp_workspace *w) { return w->kkt <= w->opt.tol; }

const double *qp_x(const Qp_workspace *w) { return w->x; }
#line 585 "paper/state.nw"
int qp_solve(Qp_workspace *w, const double *x0, double *x, double *T,
             Qp_report *rep, Status *st)
{
  int code = qp_set(w, x0, st);
  if (code) return code;
  while (!code && (!qp_test(w) || (w->iter == 0 && w->opt.method == QP_PDAS)))
    code = w->iter >= w->opt.max_iter ? not_converged(w, st)
                                      : qp_iterate(w, st);
  memcpy(x, w->x, (size_t) w->n * sizeof *x);
  if (T) memcpy(T, w->T, (size_t) w->nc * sizeof *T);
  if (rep) {
    rep->iterations = w->iter, rep->kkt = w->kkt;
    rep->active = count_active(w), rep->converged = qp_test(w);
  }
  return code;
}
#line 612 "paper/state.nw"
/* bounded unknowns at their bound */
static int count_active(const Qp_workspace *w)
{
  int m = 0;
  for (int c = 0; c < w->nc; c++) m += !is_free(w, w->qp->ic[c]);
  return m;
}

static const char *hint(const Qp_workspace *w)
{
  return count_active(w) ? "" : "; no bounded unknown touches its bound: "
    "if only the contact holds the body, the load lifts it off";
}

static int not_converged(const Qp_workspace *w, Status *st)
{
  return status_set(st, STATUS_NUMERIC, "%s: not converged after %d "
    "iteration%s (kkt = %.3g > tol = %.3g)%s", qp_method_name(w->opt.method),
    w->iter, w->iter == 1 ? "" : "s", w->kkt, w->opt.tol, hint(w));
}
#line 755 "paper/state.nw"
/* the first active set: all of I; a warm start guesses after condensing */
static void pdas_set(Qp_workspace *w, int warm)
{
  w->warm = warm, w->condensed = 0;
  for (int c = 0; c < w->nc; c++) w->act[c] = 1;
}

/* the size of the active set */
static int count_act(const Qp_workspace *w)
{
  int m = 0;
  for (int c = 0; c < w->nc; c++) m += w->act[c];
  return m;
}
#line 779 "paper/state.nw"
static int pdas_alloc(Qp_workspace *w, Status *st)
{
  const cholmod_sparse *A = w->qp->A;
  size_t nz = (size_t) ((const int *) A->p)[w->n], nc = (size_t) w->nc + 1;
  w->K = *A;                 /* the header: p and i are shared with A */
  w->K.x = malloc((nz + 1) * sizeof(double));
  w->K.nzmax = nz, w->K.stype = -1;
  w->act = malloc(nc), w->tc = malloc(nc * sizeof *w->tc);
  w->fr = malloc(nc * sizeof *w->fr);
  w->f = malloc(nc * sizeof *w->f), w->y = malloc(nc * sizeof *w->y);
  w->r = malloc(nc * sizeof *w->r);
  w->Lcc = malloc(nc * nc * sizeof *w->Lcc);
  w->S = malloc(nc * nc * sizeof *w->S), w->M = malloc(nc * nc * sizeof *w->M);
  if (!w->K.x || !w->act || !w->tc || !w->fr || !w->f || !w->y || !w->r
      || !w->Lcc || !w->S || !w->M)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory (pdas, "
                      "nc = %d)", w->nc);
  memcpy(w->K.x, A->x, nz * sizeof(double));
  w->first = w->n - w->nc;
  return analyse_contact_last(w, st);
}
#line 811 "paper/state.nw"
static int analyse_contact_last(Qp_workspace *w, Status *st)
{
  cholmod_common *cm = w->cm;
  size_t n = (size_t) w->n;
  int *last = calloc(n + 1, sizeof *last), *perm = malloc((n + 1) * sizeof *perm);
  int nmethods = cm->nmethods, ordering = cm->method[0].ordering;
  int postorder = cm->postorder, ok = last && perm;
  for (int c = 0; ok && c < w->nc; c++) last[w->qp->ic[c]] = 1;
  cm->nmethods = 1, cm->method[0].ordering = CHOLMOD_GIVEN, cm->postorder = 0;
  ok = ok && cholmod_camd(&w->K, NULL, 0, last, perm, cm)
          && (w->Ls = cholmod_analyze_p(&w->K, perm, NULL, 0, cm));
  cm->nmethods = nmethods, cm->method[0].ordering = ordering;
  cm->postorder = postorder;
  free(last), free(perm);
  w->rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, cm);
  w->Lb = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, cm);
  if (!ok || !w->rhs || !w->Lb)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: CHOLMOD failed to "
                      "analyse A (CHOLMOD status %d)", cm->status);
  const int *P = w->Ls->Perm;
  for (int t = 0; t < w->nc; t++)
    if ((w->tc[t] = w->bnd[P[w->first + t]]) < 0)
      return status_set(st, STATUS_SYSTEM, "qp_alloc: CAMD did not order "
                        "the bounded unknowns last");
  return STATUS_OK;
}
#line 877 "paper/state.nw"
static int pdas_step(Qp_workspace *w, Status *st)
{
  int code;
  if (!w->condensed) {
    if ((code = condense(w, st)) == SINGULAR)
      return not_held(w, st, "A is singular even with every bound held", w->nc);
    if (code) return code;
    if (w->warm) {
      for (int c = 0; c < w->nc; c++) w->y[c] = w->x[w->qp->ic[c]];
      condensed_forces(w);
      predict_active_set(w);
    }
  }
  if ((code = newton_solve(w)) == SINGULAR && w->iter == 0 && w->warm) {
    pdas_set(w, 0), w->condensed = 1;   /* the guess holds nothing: go cold */
    code = newton_solve(w);
  }
  if (code == SINGULAR)
    return not_held(w, st, "the Newton matrix is singular", count_act(w));
  condensed_forces(w);
  w->kkt = condensed_kkt(w);
  
#line 911 "paper/state.nw"
int same = predict_active_set(w), solved = w->kkt <= w->opt.tol;
if (!same && !solved && w->iter + 1 < w->opt.max_iter) return STATUS_OK;
if ((code = expand(w, st))) return code;
if (w->kkt > w->opt.tol && (same || solved) && (code = refine(w, st))) return code;
if (!same || w->kkt <= w->opt.tol) return STATUS_OK;
return status_set(st, STATUS_NUMERIC, "pdas: the active set repeated at "
  "Newton step %d but kkt = %.3g > tol = %.3g: A is too ill-conditioned "
  "for this tolerance%s", w->iter + 1, w->kkt, w->opt.tol, hint(w));
#line 899 "paper/state.nw"
}
#line 938 "paper/state.nw"
static int condense(Qp_workspace *w, Status *st)
{
  cholmod_common *cm = w->cm;
  int print = cm->print, final_ll = cm->final_ll, ok;
  fill_contact_matrix(w);
  cholmod_free_factor(&w->L, cm);
  cm->print = 0, cm->final_ll = 1;  /* a singular K is our message to give */
  w->L = cholmod_copy_factor(w->Ls, cm);
  ok = w->L && cholmod_factorize(&w->K, w->L, cm) && cm->status >= CHOLMOD_OK;
  cm->print = print, cm->final_ll = final_ll;
  if (!ok)
    return status_set(st, STATUS_SYSTEM, "pdas: CHOLMOD failed to factorise "
                      "(CHOLMOD status %d)", cm->status);
  if (w->L->minor < w->L->n) return SINGULAR;
  read_trailing_block(w);
  schur_complement(w);
  int code = condensed_load(w, st);
  w->condensed = !code;
  return code;
}

/* K = A + diag(A_ii) on the bounded unknowns; the values only */
static void fill_contact_matrix(Qp_workspace *w)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  double *Kx = w->K.x;
  memcpy(Kx, w->qp->A->x, (size_t) Ap[w->n] * sizeof *Kx);
  for (int c = 0; c < w->nc; c++) {
    int j = w->qp->ic[c];
    for (int k = Ap[j]; k < Ap[j + 1]; k++)
      if (Ai[k] == j) Kx[k] += w->d[j];
  }
}
#line 979 "paper/state.nw"
/* Lcc = the rows and columns first..n-1 of L, row-major, lower */
static void read_trailing_block(Qp_workspace *w)
{
  const cholmod_factor *L = w->L;
  const double *Lx = L->x;
  int nc = w->nc, first = w->first;
  memset(w->Lcc, 0, (size_t) nc * nc * sizeof *w->Lcc);
  if (L->is_super) {
    const int *super = L->super, *pi = L->pi, *px = L->px, *Ls = L->s;
    for (size_t s = 0; s < L->nsuper; s++) {
      int k1 = super[s], k2 = super[s + 1], nrow = pi[s + 1] - pi[s];
      for (int k = k1 > first ? k1 : first; k < k2; k++)
        for (int q = k - k1; q < nrow; q++)
          w->Lcc[(size_t) (Ls[pi[s] + q] - first) * nc + (k - first)] =
            Lx[px[s] + q + (size_t) (k - k1) * nrow];
    }
  } else {
    const int *Lp = L->p, *Li = L->i, *Lnz = L->nz;
    for (int k = first; k < w->n; k++)
      for (int q = Lp[k]; q < Lp[k] + Lnz[k]; q++)
        w->Lcc[(size_t) (Li[q] - first) * nc + (k - first)] = Lx[q];
  }
}
#line 1007 "paper/state.nw"
static void schur_complement(Qp_workspace *w)
{
  int nc = w->nc;
  if (nc == 0) return;
  gsl_matrix_view L = gsl_matrix_view_array(w->Lcc, nc, nc),
                  LLt = gsl_matrix_view_array(w->M, nc, nc);
  gsl_blas_dsyrk(CblasLower, CblasNoTrans, 1.0, &L.matrix, 0.0, &LLt.matrix);
  for (int t = 0; t < nc; t++)
    for (int u = 0; u <= t; u++) {
      int a = w->tc[t], b = w->tc[u];
      double v = w->M[(size_t) t * nc + u] - (t == u ? w->d[w->qp->ic[a]] : 0);
      w->S[(size_t) a * nc + b] = w->S[(size_t) b * nc + a] = v;
    }
}
#line 1026 "paper/state.nw"
static int condensed_load(Qp_workspace *w, Status *st)
{
  const double *b = w->qp->b;
  memcpy(w->rhs->x, b, (size_t) w->n * sizeof *b);
  if (solve_pair(w, CHOLMOD_P, CHOLMOD_L, &w->rhs, st)) return st->code;
  cholmod_dense *swap = w->Lb;
  w->Lb = w->rhs, w->rhs = swap;         /* keep z, reuse the old vector */
  const double *z = w->Lb->x;
  w->bu2 = 0;
  for (int i = 0; i < w->n; i++)
    if (w->bnd[i] < 0) w->bu2 += b[i] * b[i];
  for (int t = 0; t < w->nc; t++) {
    double s = 0;
    for (int u = 0; u <= t; u++) s += w->Lcc[(size_t) t * w->nc + u] * z[w->first + u];
    w->f[w->tc[t]] = s;
  }
  return STATUS_OK;
}
#line 1067 "paper/state.nw"
/* y = lo on the active set, the solution of the Newton system off it */
static int newton_solve(Qp_workspace *w)
{
  int nc = w->nc, m = 0;
  const double *lo = w->qp->lo;
  for (int c = 0; c < nc; c++)
    if (w->act[c]) w->y[c] = lo[c];
    else w->fr[m++] = c;
  for (int a = 0; a < m; a++) {
    const double *Sa = w->S + (size_t) w->fr[a] * nc;
    double s = w->f[w->fr[a]];
    for (int c = 0; c < nc; c++) if (w->act[c]) s -= Sa[c] * lo[c];
    w->r[a] = s;
    for (int b = 0; b < m; b++) w->M[(size_t) a * m + b] = Sa[w->fr[b]];
  }
  if (m == 0) return STATUS_OK;
  gsl_matrix_view M = gsl_matrix_view_array(w->M, m, m);
  gsl_vector_view r = gsl_vector_view_array(w->r, m);
  double dmin = INFINITY, dmax = 0;
  if (gsl_linalg_cholesky_decomp1(&M.matrix)) return SINGULAR;
  for (int a = 0; a < m; a++) {
    double p = w->M[(size_t) a * m + a] * w->M[(size_t) a * m + a];
    dmin = fmin(dmin, p), dmax = fmax(dmax, p);
  }
  if (!(dmin >= PDAS_RCOND_MIN * dmax)) return SINGULAR;
  gsl_linalg_cholesky_svx(&M.matrix, &r.vector);
  for (int a = 0; a < m; a++) w->y[w->fr[a]] = w->r[a];
  return STATUS_OK;
}
#line 1103 "paper/state.nw"
static void condensed_forces(Qp_workspace *w)
{
  for (int c = 0; c < w->nc; c++) {
    const double *Sc = w->S + (size_t) c * w->nc;
    double s = -w->f[c];
    for (int e = 0; e < w->nc; e++) s += Sc[e] * w->y[e];
    w->T[c] = s;
  }
}

static double condensed_kkt(const Qp_workspace *w)
{
  double tn = 0, inf = 0, comp = 0, axax = w->bu2, bb = w->bu2, yy = 0, ll = 0;
  for (int c = 0; c < w->nc; c++) {
    double T = w->T[c], gap = w->y[c] - w->qp->lo[c], bc = w->qp->b[w->qp->ic[c]];
    if (T < 0) tn += T * T;
    if (gap < 0) inf += gap * gap;
    comp += fabs(T) * fabs(gap);
    bb += bc * bc, axax += (bc + T) * (bc + T);
    yy += w->y[c] * w->y[c], ll += w->qp->lo[c] * w->qp->lo[c];
  }
  double sf = sqrt(bb) + sqrt(axax), su = sqrt(yy) + sqrt(ll);
  double k = fmax(ratio(sqrt(tn), sf),
                  fmax(ratio(sqrt(inf), su), ratio(ratio(comp, sf), su)));
  return isfinite(tn + inf + comp + sf + su) ? k : NAN;
}
#line 1138 "paper/state.nw"
/* act = { c : T_c + A_ii (lo_c - y_c) > 0 }; 1 if it did not change */
static int predict_active_set(Qp_workspace *w)
{
  int same = 1;
  for (int c = 0; c < w->nc; c++) {
    char a = w->T[c] + w->d[w->qp->ic[c]] * (w->qp->lo[c] - w->y[c]) > 0;
    same &= a == w->act[c];
    w->act[c] = a;
  }
  return same;
}
#line 1157 "paper/state.nw"
static int expand(Qp_workspace *w, Status *st)
{
  double *v = w->rhs->x;
  memcpy(v, w->Lb->x, (size_t) w->n * sizeof *v);
  for (int t = 0; t < w->nc; t++) {
    double s = 0;
    for (int u = t; u < w->nc; u++)
      s += w->Lcc[(size_t) u * w->nc + t] * w->y[w->tc[u]];
    v[w->first + t] = s;
  }
  if (solve_pair(w, CHOLMOD_Lt, CHOLMOD_Pt, &w->rhs, st)) return st->code;
  memcpy(w->x, w->rhs->x, (size_t) w->n * sizeof *w->x);
  for (int c = 0; c < w->nc; c++) w->x[w->qp->ic[c]] = w->y[c];
  refresh(w);
  return STATUS_OK;
}
#line 1181 "paper/state.nw"
static int refine(Qp_workspace *w, Status *st)
{
  double *v = w->rhs->x;
  for (int i = 0; i < w->n; i++) v[i] = w->bnd[i] < 0 ? -w->g[i] : 0;
  if (solve_pair(w, CHOLMOD_P, CHOLMOD_L, &w->rhs, st)) return st->code;
  v = w->rhs->x;
  memset(v + w->first, 0, (size_t) w->nc * sizeof *v);
  if (solve_pair(w, CHOLMOD_Lt, CHOLMOD_Pt, &w->rhs, st)) return st->code;
  v = w->rhs->x;
  for (int i = 0; i < w->n; i++) if (w->bnd[i] < 0) w->x[i] += v[i];
  refresh(w);
  return STATUS_OK;
}

/* *v = the solves sys2(sys1(*v)) with L, through w->sol */
static int solve_pair(Qp_workspace *w, int sys1, int sys2, cholmod_dense **v,
                      Status *st)
{
  cholmod_common *cm = w->cm;
  if (!cholmod_solve2(sys1, w->L, *v, NULL, &w->sol, NULL, &w->Y, &w->E, cm)
      || !cholmod_solve2(sys2, w->L, w->sol, NULL, v, NULL, &w->Y, &w->E, cm))
    return status_set(st, STATUS_SYSTEM, "pdas: CHOLMOD failed to solve "
                      "(CHOLMOD status %d)", cm->status);
  return STATUS_OK;
}
#line 1216 "paper/state.nw"
int qp_schur(const Qp_workspace *w, double shift, double *S, Status *st)
{
  int nc = w->nc, code = STATUS_OK;
  Qp_workspace *c = NULL;
  if (w->opt.method != QP_PDAS || !w->condensed) {
    Qp_options opt = { QP_PDAS, 1, 1, 1 };
    if (!(c = qp_alloc(w->qp, &opt, w->cm, st))) return st->code;
    code = read_matrix(c, st);
    if (!code) code = read_vectors(c, st);
    if (!code && (code = condense(c, st)) == SINGULAR)
      code = status_set(st, STATUS_NUMERIC, "qp_schur: A is singular even "
                        "with every bounded unknown held");
  }
  const Qp_workspace *from = c ? c : w;
  if (!code) {
    memcpy(S, from->S, (size_t) nc * nc * sizeof *S);
    for (int k = 0; k < nc; k++) S[(size_t) k * nc + k] += shift * from->d[w->qp->ic[k]];
  }
  qp_free(c);
  return code;
}
#line 1240 "paper/state.nw"
/* (4.3) has no solution: why, with how many bounds active */
static int not_held(const Qp_workspace *w, Status *st, const char *why,
                    int active)
{
  return status_set(st, STATUS_NUMERIC, "%s: the body is not held (a load "
    "that lifts it off, with nothing else holding it): %s, with %d of %d "
    "bounds active, at iteration %d", qp_method_name(w->opt.method), why,
    active, w->nc, w->iter + 1);
}
#line 1269 "paper/state.nw"
/* one projected SOR sweep over all unknowns, then the residual */
static int psor_sweep(Qp_workspace *w, Status *st)
{
  const cholmod_sparse *A = w->qp->A;
  double *x = w->x, om = w->opt.omega;
  for (int i = 0; i < w->n; i++)
    x[i] = proj(w, i, x[i] - om * (row_dot(A, i, x) - w->qp->b[i]) / w->d[i]);
  refresh(w);
  (void) st;      /* a sweep cannot fail; NaN is caught by qp_iterate */
  return STATUS_OK;
}
#line 1344 "paper/state.nw"
static int mprgp_alloc(Qp_workspace *w, Status *st)
{
  size_t n = (size_t) w->n + 1;
  w->p = malloc(n * sizeof *w->p), w->q = malloc(n * sizeof *w->q);
  w->z = malloc(n * sizeof *w->z);
  if (!w->p || !w->q || !w->z)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory (cgssor)");
  return STATUS_OK;
}

static void mprgp_set(Qp_workspace *w)
{
  w->abar = MPRGP_ABAR / w->normA;
  w->restart = 1;
}
#line 1379 "paper/state.nw"
/* z = SSOR(omega) of A restricted to the free set, applied to phi */
static void ssor_free(Qp_workspace *w)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  const double *Ax = w->qp->A->x;
  double *z = w->z, om = w->opt.omega;
  for (int i = 0; i < w->n; i++) {          /* (D + omega L) y = phi */
    double s = w->g[i];
    for (int k = Ap[i]; k < Ap[i + 1] && Ai[k] < i; k++) s -= om * Ax[k] * z[Ai[k]];
    z[i] = is_free(w, i) ? s / w->d[i] : 0;
  }
  for (int i = w->n - 1; i >= 0; i--) {     /* (D + omega U) z = D y */
    double s = 0;
    if (!is_free(w, i)) continue;
    for (int k = Ap[i + 1] - 1; k >= Ap[i] && Ai[k] > i; k--) s += Ax[k] * z[Ai[k]];
    z[i] -= om * s / w->d[i];
  }
}
#line 1408 "paper/state.nw"
static int mprgp_iterate(Qp_workspace *w, Status *st)
{
  int code = proportional(w) ? cg_or_expansion_step(w, st)
                             : proportioning_step(w, st);
  if (code) return code;
  w->kkt = kkt_eval(w->qp, w->x, w->g, w->T);
  if (w->kkt <= w->opt.tol) refresh(w);   /* confirm from scratch */
  return STATUS_OK;
}
#line 1426 "paper/state.nw"
/* ||beta||^2 <= Gamma^2 phi~' phi */
static int proportional(const Qp_workspace *w)
{
  double bb = 0, fp = 0;
  for (int i = 0; i < w->n; i++) {
    double gi = w->g[i];
    if (is_free(w, i))
      fp += fmin((w->x[i] - w->lo[i]) / w->abar, gi) * gi;
    else if (gi < 0)
      bb += gi * gi;
  }
  return bb <= MPRGP_GAMMA * MPRGP_GAMMA * fp;
}
#line 1447 "paper/state.nw"
/* x <- x - alpha beta, the exact minimiser along the chopped gradient */
static int proportioning_step(Qp_workspace *w, Status *st)
{
  for (int i = 0; i < w->n; i++)
    w->z[i] = !is_free(w, i) && w->g[i] < 0 ? w->g[i] : 0;
  matvec(w->qp->A, w->z, w->q);
  double bb = dot(w->n, w->z, w->z), bab = dot(w->n, w->z, w->q);
  if (!(bab > DBL_EPSILON * w->normA * bb))
    return not_held(w, st, "A does not resist the chopped gradient",
                    count_active(w));
  double alpha = bb / bab;
  for (int i = 0; i < w->n; i++)
    w->x[i] -= alpha * w->z[i], w->g[i] -= alpha * w->q[i];
  w->restart = 1;
  return STATUS_OK;
}
#line 1478 "paper/state.nw"
static int cg_or_expansion_step(Qp_workspace *w, Status *st)
{
  int n = w->n;
  if (w->restart || !(dot(n, w->g, w->p) > 0)) {
    ssor_free(w);
    memcpy(w->p, w->z, (size_t) n * sizeof *w->p);
    w->restart = 0;
  }
  double pp = dot(n, w->p, w->p);
  if (pp == 0) { refresh(w); return STATUS_OK; }
  matvec(w->qp->A, w->p, w->q);
  double pap = dot(n, w->p, w->q), af = feasible_step(w);
  double acg = pap > DBL_EPSILON * w->normA * pp ? dot(n, w->g, w->p) / pap
                                                 : INFINITY;
  if (acg == INFINITY && af == INFINITY)
    return not_held(w, st, "neither A nor a bound resists the CG direction",
                    count_active(w));
  if (acg <= af) cg_step(w, acg, pap);
  else expansion_step(w, af);
  return STATUS_OK;
}
#line 1508 "paper/state.nw"
/* the largest alpha with x - alpha p >= lo */
static double feasible_step(const Qp_workspace *w)
{
  double af = INFINITY;
  for (int i = 0; i < w->n; i++)
    if (w->p[i] > 0 && w->bnd[i] >= 0)
      af = fmin(af, (w->x[i] - w->lo[i]) / w->p[i]);
  return af;
}
#line 1525 "paper/state.nw"
/* x <- x - acg p; p <- z - gamma p, A-conjugate to the old p */
static void cg_step(Qp_workspace *w, double acg, double pap)
{
  for (int i = 0; i < w->n; i++) {
    w->x[i] = proj(w, i, w->x[i] - acg * w->p[i]);
    w->g[i] -= acg * w->q[i];
  }
  ssor_free(w);
  double gamma = dot(w->n, w->z, w->q) / pap;
  for (int i = 0; i < w->n; i++) w->p[i] = w->z[i] - gamma * w->p[i];
}
#line 1555 "paper/state.nw"
/* x <- P(x_half - abar phi(x_half)), x_half = x - af p */
static void expansion_step(Qp_workspace *w, double af)
{
  for (int i = 0; i < w->n; i++) {
    int tie = w->p[i] > 0 && w->x[i] - w->lo[i] <= af * w->p[i] * (1 + TIE);
    w->x[i] = tie ? w->lo[i] : proj(w, i, w->x[i] - af * w->p[i]);
    w->g[i] -= af * w->q[i];
  }
  for (int i = 0; i < w->n; i++)
    if (is_free(w, i)) w->x[i] = proj(w, i, w->x[i] - w->abar * w->g[i]);
  refresh(w);
  w->restart = 1;
}
