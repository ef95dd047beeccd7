#line 137 "paper/state.nw"
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "state.h"
#line 808 "paper/state.nw"
#define SINGULAR (-1)    /* newton_solve: K is singular (not a Status_code) */
#line 947 "paper/state.nw"
#define PDAS_RCOND_MIN (100 * DBL_EPSILON) /* smaller: K taken to be singular */
#line 1125 "paper/state.nw"
#define MPRGP_GAMMA 1.0  /* proportioning: ||beta||^2 <= Gamma^2 phi~'phi */
#define MPRGP_ABAR 1.9   /* expansion step length abar = 1.9 / ||A|| */
#line 1345 "paper/state.nw"
#define TIE (4 * DBL_EPSILON)  /* blocking steps this close are equal */
#line 254 "paper/state.nw"
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
  
#line 717 "paper/state.nw"
cholmod_sparse K;      /* the Newton matrix: A's pattern (borrowed),
                          own values, stype -1 */
cholmod_factor *Ls;    /* the symbolic analysis of K, from qp_alloc */
cholmod_factor *L;     /* the factor of the Newton matrix of fac (LDL') */
int *iperm;            /* n: the position of each unknown in L's order */
cholmod_sparse *R;     /* n x 1: a column of K to add to L */
cholmod_dense *rhs;    /* n x 1: the Newton right-hand side */
cholmod_dense *sol, *Y, *E; /* the solution and cholmod_solve2's workspace */
char *act;             /* nc: the active set of the next Newton step */
char *fac;             /* nc: the active set that L factorises */
int fresh;             /* 1: the next step factorises from the analysis */
int refactored;        /* 1: the last step did */
int warm;              /* the first active set was guessed from x0 */
#line 269 "paper/state.nw"
  
#line 1130 "paper/state.nw"
double *p;             /* n: the conjugate direction */
double *q;             /* n: A p, or A beta in a proportioning step */
double *z;             /* n: the preconditioned free gradient, or beta */
double abar;           /* the expansion step length 1.9 / normA */
int restart;           /* 1: p must restart from z (the face changed) */
#line 270 "paper/state.nw"
};
#line 334 "paper/state.nw"
static int check_problem(const Qp *qp, const Qp_options *opt,
                         cholmod_common *cm, Status *st);
static int check_options(const Qp_options *opt, Status *st);
static int alloc_common(Qp_workspace *w, Status *st);
static int check_pattern(Qp_workspace *w, Status *st);
static int pdas_alloc(Qp_workspace *w, Status *st);
static int mprgp_alloc(Qp_workspace *w, Status *st);
#line 515 "paper/state.nw"
static void pdas_set(Qp_workspace *w, int warm);
static void mprgp_set(Qp_workspace *w);
static int pdas_step(Qp_workspace *w, Status *st);
static int psor_sweep(Qp_workspace *w, Status *st);
static int mprgp_iterate(Qp_workspace *w, Status *st);
#line 578 "paper/state.nw"
static int not_converged(const Qp_workspace *w, Status *st);
static int count_active(const Qp_workspace *w);
#line 796 "paper/state.nw"
static int newton_solve(Qp_workspace *w, Status *st);
static int factorise(Qp_workspace *w, Status *st);
static int modify_factor(Qp_workspace *w, Status *st);
static int factor_is_regular(const Qp_workspace *w);
static void fill_newton_rhs(Qp_workspace *w);
static int predict_active_set(Qp_workspace *w);
static int update_active_set(Qp_workspace *w, Status *st);
#line 865 "paper/state.nw"
static void fill_newton_matrix(Qp_workspace *w);
#line 914 "paper/state.nw"
static void fill_added_column(Qp_workspace *w, int j);
#line 991 "paper/state.nw"
static int not_held(const Qp_workspace *w, Status *st, const char *why,
                    int active);
#line 1214 "paper/state.nw"
static int proportional(const Qp_workspace *w);
static int cg_or_expansion_step(Qp_workspace *w, Status *st);
static int proportioning_step(Qp_workspace *w, Status *st);
#line 1296 "paper/state.nw"
static double feasible_step(const Qp_workspace *w);
static void cg_step(Qp_workspace *w, double acg, double pap);
static void expansion_step(Qp_workspace *w, double af);
#line 178 "paper/state.nw"
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
#line 197 "paper/state.nw"
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
      
#line 220 "paper/state.nw"
double gap = x[j] - qp->lo[c];
if (r < 0) tn += r * r;          /* a pulling contact force */
if (gap < 0) inf += gap * gap;   /* a penetration */
comp += fabs(r) * fabs(gap);     /* a force without contact */
ll += qp->lo[c] * qp->lo[c];
if (T) T[c] = r;
#line 211 "paper/state.nw"
      c++;
    } else
      rf += r * r;
  }
  
#line 231 "paper/state.nw"
double sf = sqrt(bb) + sqrt(axax), su = sqrt(xx) + sqrt(ll);
double k = fmax(fmax(ratio(sqrt(rf), sf), ratio(sqrt(tn), sf)),
                fmax(ratio(sqrt(inf), su), ratio(ratio(comp, sf), su)));
return isfinite(rf + tn + inf + comp + sf + su) ? k : NAN;
#line 216 "paper/state.nw"
}
#line 238 "paper/state.nw"
double qp_kkt(const Qp *qp, const double *x, double *T)
{
  return kkt_eval(qp, x, NULL, T);
}
#line 277 "paper/state.nw"
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
#line 302 "paper/state.nw"
/* g = A x - b, then kkt and T at x */
static void refresh(Qp_workspace *w)
{
  matvec(w->qp->A, w->x, w->g);
  for (int i = 0; i < w->n; i++) w->g[i] -= w->qp->b[i];
  w->kkt = kkt_eval(w->qp, w->x, w->g, w->T);
}
#line 316 "paper/state.nw"
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
  if (!code && opt->method == STATE_PDAS) code = pdas_alloc(w, st);
  if (!code && opt->method == STATE_CGSSOR) code = mprgp_alloc(w, st);
  if (code) { qp_free(w); return NULL; }
  return w;
}
#line 345 "paper/state.nw"
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
#line 371 "paper/state.nw"
static int check_options(const Qp_options *opt, Status *st)
{
  if (opt->method != STATE_PDAS && opt->method != STATE_PSOR
      && opt->method != STATE_CGSSOR)
    return status_set(st, STATUS_INPUT, "qp_alloc: unknown method %d",
                      (int) opt->method);
  if (!(opt->tol > 0) || opt->max_iter < 1)
    return status_set(st, STATUS_INPUT, "qp_alloc: tol = %g must be positive "
                      "and max_iter = %d at least 1", opt->tol, opt->max_iter);
  if (opt->method != STATE_PDAS && !(opt->omega > 0 && opt->omega < 2))
    return status_set(st, STATUS_INPUT, "qp_alloc: omega = %g is not in (0, 2)",
                      opt->omega);
  return STATUS_OK;
}
#line 390 "paper/state.nw"
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
#line 412 "paper/state.nw"
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
#line 433 "paper/state.nw"
void qp_free(Qp_workspace *w)
{
  if (!w) return;
  
#line 767 "paper/state.nw"
free(w->K.x), free(w->act), free(w->fac), free(w->iperm);
cholmod_free_factor(&w->Ls, w->cm), cholmod_free_factor(&w->L, w->cm);
cholmod_free_sparse(&w->R, w->cm);
cholmod_free_dense(&w->rhs, w->cm), cholmod_free_dense(&w->sol, w->cm);
cholmod_free_dense(&w->Y, w->cm), cholmod_free_dense(&w->E, w->cm);
#line 437 "paper/state.nw"
  
#line 1156 "paper/state.nw"
free(w->p), free(w->q), free(w->z);
#line 438 "paper/state.nw"
  free(w->bnd), free(w->lo), free(w->d);
  free(w->x), free(w->g), free(w->T);
  free(w);
}
#line 453 "paper/state.nw"
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
#line 479 "paper/state.nw"
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
#line 498 "paper/state.nw"
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
  if (w->opt.method == STATE_PDAS) pdas_set(w, x0 != NULL);
  if (w->opt.method == STATE_CGSSOR) mprgp_set(w);
  return STATUS_OK;
}
#line 528 "paper/state.nw"
static const char *method_name(State_method m)
{
  return m == STATE_PDAS ? "pdas" : m == STATE_PSOR ? "psor" : "cgssor";
}

int qp_iterate(Qp_workspace *w, Status *st)
{
  State_method m = w->opt.method;
  int code = m == STATE_PDAS ? pdas_step(w, st)
           : m == STATE_PSOR ? psor_sweep(w, st) : mprgp_iterate(w, st);
  w->iter++;
  if (!code && !isfinite(w->kkt))
    code = status_set(st, STATUS_NUMERIC, "%s: NaN or infinity after %d "
                      "iterations", method_name(m), w->iter);
  return code;
}

int qp_test(const Qp_workspace *w) { return w->kkt <= w->opt.tol; }

const double *qp_x(const Qp_workspace *w) { return w->x; }
#line 559 "paper/state.nw"
int qp_solve(Qp_workspace *w, const double *x0, double *x, double *T,
             Qp_report *rep, Status *st)
{
  int code = qp_set(w, x0, st);
  if (code) return code;
  while (!code && (!qp_test(w) || (w->iter == 0 && w->opt.method == STATE_PDAS)))
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
#line 586 "paper/state.nw"
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
    "iteration%s (kkt = %.3g > tol = %.3g)%s", method_name(w->opt.method),
    w->iter, w->iter == 1 ? "" : "s", w->kkt, w->opt.tol, hint(w));
}
#line 662 "paper/state.nw"
/* the first active set: all of I (cold), or the Newton rule's at x0 (warm) */
static void pdas_set(Qp_workspace *w, int warm)
{
  w->warm = warm, w->fresh = 1;
  for (int c = 0; c < w->nc; c++) w->act[c] = 1;
  if (warm) predict_active_set(w);
}

/* unknown i is bounded and active in the factorised Newton matrix */
static int is_held(const Qp_workspace *w, int i)
{
  return w->bnd[i] >= 0 && w->fac[w->bnd[i]];
}

/* the size of the active set */
static int count_act(const Qp_workspace *w)
{
  int m = 0;
  for (int c = 0; c < w->nc; c++) m += w->act[c];
  return m;
}
#line 733 "paper/state.nw"
static int pdas_alloc(Qp_workspace *w, Status *st)
{
  const cholmod_sparse *A = w->qp->A;
  const int *Ap = A->p;
  size_t nz = (size_t) Ap[w->n], n = (size_t) w->n, maxcol = 1;
  for (int j = 0; j < w->n; j++)
    if ((size_t) (Ap[j + 1] - Ap[j]) > maxcol) maxcol = (size_t) (Ap[j + 1] - Ap[j]);
  w->K = *A;                 /* the header: p and i are shared with A */
  w->K.x = malloc((nz + 1) * sizeof(double));
  w->K.nzmax = nz, w->K.stype = -1;
  w->act = malloc((size_t) w->nc + 1), w->fac = malloc((size_t) w->nc + 1);
  w->iperm = malloc((n + 1) * sizeof *w->iperm);
  if (!w->K.x || !w->act || !w->fac || !w->iperm)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: out of memory (pdas)");
  memcpy(w->K.x, A->x, nz * sizeof(double));
  
#line 755 "paper/state.nw"
cholmod_common *cm = w->cm;
w->Ls = cholmod_analyze(&w->K, cm);
w->rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, cm);
w->R = cholmod_allocate_sparse(n, 1, maxcol, 0, 1, 0, CHOLMOD_REAL, cm);
if (!w->Ls || !w->rhs || !w->R)
  return status_set(st, STATUS_SYSTEM, "qp_alloc: CHOLMOD failed to "
                    "analyse A (CHOLMOD status %d)", cm->status);
const int *perm = w->Ls->Perm;
for (int k = 0; k < w->n; k++) w->iperm[perm[k]] = k;
#line 749 "paper/state.nw"
  return STATUS_OK;
}
#line 780 "paper/state.nw"
static int pdas_step(Qp_workspace *w, Status *st)
{
  int code = newton_solve(w, st);
  if (code == SINGULAR && w->iter == 0 && w->warm) {
    pdas_set(w, 0);              /* the warm guess holds nothing: go cold */
    code = newton_solve(w, st);
  }
  if (code == SINGULAR)
    return not_held(w, st, "the Newton matrix is singular", count_act(w));
  if (code) return code;
  refresh(w);
  return update_active_set(w, st);
}
#line 812 "paper/state.nw"
/* x = K \ rhs for the active set act, x_i = lo_i exactly on it */
static int newton_solve(Qp_workspace *w, Status *st)
{
  int code = w->fresh ? factorise(w, st) : modify_factor(w, st);
  if (code) return code;
  if (!factor_is_regular(w)) {
    if (w->refactored) return SINGULAR;
    w->fresh = 1;
    return newton_solve(w, st);
  }
  fill_newton_rhs(w);
  if (!cholmod_solve2(CHOLMOD_A, w->L, w->rhs, NULL, &w->sol, NULL,
                      &w->Y, &w->E, w->cm))
    return status_set(st, STATUS_SYSTEM, "pdas: CHOLMOD failed to solve "
                      "(CHOLMOD status %d)", w->cm->status);
  const double *s = w->sol->x;
  for (int i = 0; i < w->n; i++) w->x[i] = is_held(w, i) ? w->lo[i] : s[i];
  return STATUS_OK;
}
#line 843 "paper/state.nw"
static int factorise(Qp_workspace *w, Status *st)
{
  cholmod_common *cm = w->cm;
  int print = cm->print, ok;
  memcpy(w->fac, w->act, (size_t) w->nc);
  fill_newton_matrix(w);
  cholmod_free_factor(&w->L, cm);
  cm->print = 0;                  /* a singular K is our message to give */
  w->L = cholmod_copy_factor(w->Ls, cm);
  ok = w->L && cholmod_factorize(&w->K, w->L, cm) && cm->status >= CHOLMOD_OK;
  if (ok && w->L->minor == w->L->n)
    ok = cholmod_change_factor(CHOLMOD_REAL, 0, 0, 0, 0, w->L, cm);
  cm->print = print;
  if (!ok)
    return status_set(st, STATUS_SYSTEM, "pdas: CHOLMOD failed to factorise "
                      "(CHOLMOD status %d)", cm->status);
  w->fresh = 0, w->refactored = 1;
  return STATUS_OK;
}
#line 869 "paper/state.nw"
/* K = A, with the row and column of each active unknown reduced to A_ii */
static void fill_newton_matrix(Qp_workspace *w)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  const double *Ax = w->qp->A->x;
  double *Kx = w->K.x;
  for (int j = 0; j < w->n; j++)
    for (int k = Ap[j]; k < Ap[j + 1]; k++) {
      int i = Ai[k];
      Kx[k] = i != j && (is_held(w, i) || is_held(w, j)) ? 0 : Ax[k];
    }
}
#line 891 "paper/state.nw"
/* L: from the Newton matrix of fac to that of act, row by row */
static int modify_factor(Qp_workspace *w, Status *st)
{
  int ok = 1, print = w->cm->print;
  w->cm->print = 0;               /* as in factorise */
  for (int c = 0; ok && c < w->nc; c++)
    if (w->act[c] && !w->fac[c]) {
      ok = cholmod_rowdel((size_t) w->iperm[w->qp->ic[c]], NULL, w->L, w->cm);
      w->fac[c] = 1;
    }
  for (int c = 0; ok && c < w->nc; c++)
    if (!w->act[c] && w->fac[c]) {
      w->fac[c] = 0;
      fill_added_column(w, w->qp->ic[c]);
      ok = cholmod_rowadd((size_t) w->iperm[w->qp->ic[c]], w->R, w->L, w->cm);
    }
  w->cm->print = print, w->refactored = 0;
  return ok ? STATUS_OK : status_set(st, STATUS_SYSTEM, "pdas: CHOLMOD "
    "failed to modify the factor (CHOLMOD status %d)", w->cm->status);
}
#line 918 "paper/state.nw"
/* R = column j of A in the rows not held, in the factor's order */
static void fill_added_column(Qp_workspace *w, int j)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  const double *Ax = w->qp->A->x;
  int *Rp = w->R->p, *Ri = w->R->i, m = 0;
  double *Rx = w->R->x;
  for (int k = Ap[j]; k < Ap[j + 1]; k++)
    if (!is_held(w, Ai[k])) Ri[m] = w->iperm[Ai[k]], Rx[m++] = Ax[k];
  Rp[0] = 0, Rp[1] = m;
}
#line 951 "paper/state.nw"
/* the pivots of the unknowns not held are positive and within 1/RCOND_MIN */
static int factor_is_regular(const Qp_workspace *w)
{
  const cholmod_factor *L = w->L;
  const int *Lp = L->p, *perm = L->Perm;
  const double *Lx = L->x;
  double dmin = INFINITY, dmax = 0;
  if (L->minor < L->n) return 0;
  for (int k = 0; k < w->n; k++)
    if (!is_held(w, perm[k]))
      dmin = fmin(dmin, Lx[Lp[k]]), dmax = fmax(dmax, Lx[Lp[k]]);
  return dmax == 0 || (dmin > 0 && dmin >= PDAS_RCOND_MIN * dmax);
}
#line 973 "paper/state.nw"
/* rhs = b - A(:,act) lo(act) off the active set, A_ii lo_i on it */
static void fill_newton_rhs(Qp_workspace *w)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  const double *Ax = w->qp->A->x;
  double *r = w->rhs->x;
  memcpy(r, w->qp->b, (size_t) w->n * sizeof *r);
  for (int c = 0; c < w->nc; c++) {
    int j = w->qp->ic[c];
    if (!w->fac[c]) continue;
    for (int k = Ap[j]; k < Ap[j + 1]; k++)
      if (!is_held(w, Ai[k])) r[Ai[k]] -= Ax[k] * w->qp->lo[c];
    r[j] = w->d[j] * w->qp->lo[c];
  }
}
#line 996 "paper/state.nw"
/* (4.3) has no solution: why, with how many bounds active */
static int not_held(const Qp_workspace *w, Status *st, const char *why,
                    int active)
{
  return status_set(st, STATUS_NUMERIC, "%s: the body is not held (a load "
    "that lifts it off, with nothing else holding it): %s, with %d of %d "
    "bounds active, at iteration %d", method_name(w->opt.method), why,
    active, w->nc, w->iter + 1);
}
#line 1020 "paper/state.nw"
/* act = { c : T_c + A_ii (lo_c - x_i) > 0 }; 1 if it did not change */
static int predict_active_set(Qp_workspace *w)
{
  int same = 1;
  for (int c = 0; c < w->nc; c++) {
    int i = w->qp->ic[c];
    char a = w->T[c] + w->d[i] * (w->qp->lo[c] - w->x[i]) > 0;
    same &= a == w->act[c];
    w->act[c] = a;
  }
  return same;
}

/* the next active set; a repeated set that does not meet tol is a failure */
static int update_active_set(Qp_workspace *w, Status *st)
{
  int same = predict_active_set(w);
  if (!same || w->kkt <= w->opt.tol) return STATUS_OK;
  if (!w->refactored) { w->fresh = 1; return STATUS_OK; }
  return status_set(st, STATUS_NUMERIC, "pdas: the active set repeated at "
    "Newton step %d but kkt = %.3g > tol = %.3g: A is too ill-conditioned "
    "for this tolerance%s", w->iter + 1, w->kkt, w->opt.tol, hint(w));
}
#line 1063 "paper/state.nw"
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
#line 1138 "paper/state.nw"
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
#line 1173 "paper/state.nw"
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
#line 1202 "paper/state.nw"
static int mprgp_iterate(Qp_workspace *w, Status *st)
{
  int code = proportional(w) ? cg_or_expansion_step(w, st)
                             : proportioning_step(w, st);
  if (code) return code;
  w->kkt = kkt_eval(w->qp, w->x, w->g, w->T);
  if (w->kkt <= w->opt.tol) refresh(w);   /* confirm from scratch */
  return STATUS_OK;
}
#line 1220 "paper/state.nw"
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
#line 1241 "paper/state.nw"
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
#line 1272 "paper/state.nw"
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
#line 1302 "paper/state.nw"
/* the largest alpha with x - alpha p >= lo */
static double feasible_step(const Qp_workspace *w)
{
  double af = INFINITY;
  for (int i = 0; i < w->n; i++)
    if (w->p[i] > 0 && w->bnd[i] >= 0)
      af = fmin(af, (w->x[i] - w->lo[i]) / w->p[i]);
  return af;
}
#line 1319 "paper/state.nw"
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
#line 1349 "paper/state.nw"
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
