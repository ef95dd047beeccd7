#line 420 "paper/qp.nw"
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qp_private.h"
#include "pdas.h"
#include "cgssor.h"
#include "psor.h"
#line 407 "paper/qp.nw"
static int check_options(const Qp_options *opt, Status *st);
static int check_problem(const Qp *qp, const Qp_options *opt, cholmod_common *cm, Status *st);
static int alloc_common(Qp_workspace *w, Status *st);
static int check_pattern(Qp_workspace *w, Status *st);
static int not_converged(const Qp_workspace *w, Status *st);
#line 753 "paper/qp.nw"
Qp_workspace *qp_alloc(const Qp *qp, const Qp_options *opt,
                       cholmod_common *cm, Status *st)
{
  if (check_problem(qp, opt, cm, st)) return NULL;
  Qp_workspace *w = calloc(1, sizeof *w);
  if (!w) { status_set(st, STATUS_MEMORY, "qp_alloc: out of memory"); return NULL; }
  w->qp = qp, w->opt = *opt, w->cm = cm;
  w->n = (int) qp->A->ncol, w->nc = qp->nc, w->nk = qp->nc + qp->nt;
  int code = alloc_common(w, st);
  if (!code) code = check_pattern(w, st);
  Condense_contact ct = { w->nc, qp->b, w->d, w->pos, w->flo, w->fhi };
  if (!code && (opt->method == QP_PDAS || (opt->method == QP_CGSSOR && qp->nt))
      && !(w->cond = condense_alloc(qp->A, w->nk, w->ik, &ct, cm, st)))
    code = st->code;               /* CG--SSOR with friction condenses too */
  if (!code && opt->method == QP_PDAS) code = pdas_alloc(w, st);
  if (!code && opt->method == QP_CGSSOR) code = cgssor_alloc(w, st);
  if (code) { qp_free(w); return NULL; }
  return w;
}
#line 776 "paper/qp.nw"
static int check_problem(const Qp *qp, const Qp_options *opt,
                         cholmod_common *cm, Status *st)
{
  if (!qp || !qp->A || !qp->b || !opt || !cm
      || (qp->nc > 0 && (!qp->ic || !qp->lo)))
    return status_set(st, STATUS_INPUT, "qp_alloc: a NULL argument");
  const cholmod_sparse *A = qp->A;
  if (A->nrow != A->ncol || A->ncol > INT_MAX || A->stype != 0
      || A->itype != CHOLMOD_LONG || A->xtype != CHOLMOD_REAL
      || A->dtype != CHOLMOD_DOUBLE || !A->packed || !A->sorted)
    return status_set(st, STATUS_INPUT, "qp_alloc: A must be square, real "
                      "double with long indices (cholmod_l_), both triangles stored "
                      "(stype 0), sorted and packed");
  if (qp->nc < 0 || qp->nc > (int) A->ncol)
    return status_set(st, STATUS_INPUT, "qp_alloc: nc = %d is not in [0, %d]",
                      qp->nc, (int) A->ncol);
  for (int c = 0; c < qp->nc; c++)
    if (qp->ic[c] < (c ? qp->ic[c - 1] + 1 : 0) || qp->ic[c] >= (int) A->ncol)
      return status_set(st, STATUS_INPUT, "qp_alloc: ic[%d] = %d: the bounded "
                        "unknowns must increase within [0, %d)", c, qp->ic[c],
                        (int) A->ncol);
  
#line 919 "paper/qp.nw"
if (qp->nt < 0 || qp->nt > (int) A->ncol || (qp->nt > 0 && (!qp->it || !qp->slip)))
  return status_set(st, STATUS_INPUT, "qp_alloc: nt = %d is not in [0, %d] "
                    "or it, slip is NULL", qp->nt, (int) A->ncol);
for (int k = 0; k < qp->nt; k++)
  if (qp->it[k] < (k ? qp->it[k - 1] + 1 : 0) || qp->it[k] >= (int) A->ncol)
    return status_set(st, STATUS_INPUT, "qp_alloc: it[%d] = %d: the slipping "
                      "unknowns must increase within [0, %d)", k, qp->it[k],
                      (int) A->ncol);
if (qp->nt > 0 && opt->method == QP_PSOR)
  return status_set(st, STATUS_INPUT, "psor cannot solve contact with "
                    "friction: use solver.state = pdas or cgssor");
#line 798 "paper/qp.nw"
  return check_options(opt, st);
}
#line 803 "paper/qp.nw"
Qp_options qp_options_default(Qp_method method)
{
  return (Qp_options) { method, 1e-10, method == QP_PDAS ? 100 : 100000, 1.5 };
}
#line 812 "paper/qp.nw"
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
#line 833 "paper/qp.nw"
static int alloc_common(Qp_workspace *w, Status *st)
{
  size_t n = (size_t) w->n + 1, nk = (size_t) w->nk + 1;
  w->bnd = malloc(n * sizeof *w->bnd);
  w->lo = malloc(n * sizeof *w->lo), w->d = malloc(n * sizeof *w->d);
  w->x = malloc(n * sizeof *w->x), w->grad = malloc(n * sizeof *w->grad);
  w->T = malloc(nk * sizeof *w->T), w->ik = malloc(nk * sizeof *w->ik);
  w->pos = malloc(nk * sizeof *w->pos);
  w->flo = malloc(nk * sizeof *w->flo), w->fhi = malloc(nk * sizeof *w->fhi);
  if (!w->bnd || !w->lo || !w->d || !w->x || !w->grad || !w->T || !w->ik
      || !w->pos || !w->flo || !w->fhi)
    return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (n = %d)",
                      w->n);
  int m = 0;
  for (int i = 0; i < w->n; i++) {
    const Sparse_index *Ap = w->qp->A->p;
    w->bnd[i] = -1;
    if (Ap[i + 1] - Ap[i] > m) m = (int) (Ap[i + 1] - Ap[i]);
  }
  w->gamma = qp_gamma(m + 2);    /* as qp_kkt_eval finds it */
  for (int k = 0; k < w->nk; k++) {
    int i = w->ik[k] = k < w->nc ? w->qp->ic[k] : w->qp->it[k - w->nc];
    if (w->bnd[i] >= 0)
      return status_set(st, STATUS_INPUT, "qp_alloc: unknown %d is both "
                        "bounded and slipping", i);
    w->bnd[i] = k;
  }
  return STATUS_OK;
}
#line 870 "paper/qp.nw"
/* the pattern of A is symmetric: (i,j) is stored iff (j,i) is */
static int check_pattern(Qp_workspace *w, Status *st)
{
  const Sparse_index *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  Sparse_index *next = malloc(((size_t) w->n + 1) * sizeof *next);
  int oom = !next, bad = oom;
  for (int i = 0; !bad && i < w->n; i++) next[i] = Ap[i];
  for (int j = 0; !bad && j < w->n; j++)
    for (Sparse_index k = Ap[j]; !bad && k < Ap[j + 1]; k++) {
      Sparse_index i = Ai[k];
      bad = next[i] >= Ap[i + 1] || Ai[next[i]++] != j;
    }
  for (int i = 0; !bad && i < w->n; i++) bad = next[i] != Ap[i + 1];
  free(next);
  if (oom) return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory");
  return !bad ? STATUS_OK : status_set(st, STATUS_INPUT, "qp_alloc: the "
    "pattern of A is not symmetric (both triangles must be stored)");
}
#line 892 "paper/qp.nw"
void qp_release(Qp_workspace *w)
{
  if (w) condense_release(w->cond);
}

void qp_free(Qp_workspace *w)
{
  if (!w) return;
  condense_free(w->cond);
  pdas_free(w);
  cgssor_free(w);
  free(w->bnd), free(w->lo), free(w->d);
  free(w->x), free(w->grad), free(w->T);
  free(w->ik), free(w->pos), free(w->flo), free(w->fhi);
  free(w);
}
#line 941 "paper/qp.nw"
/* the diagonal of A, max_j sum_i |A_ij|, and finite values throughout */
static int read_matrix(Qp_workspace *w, Status *st)
{
  const cholmod_sparse *A = w->qp->A;
  const Sparse_index *Ap = A->p, *Ai = A->i;
  const double *Ax = A->x;
  w->normA = 0;
  for (int j = 0; j < w->n; j++) {
    double sum = 0;
    w->d[j] = 0;
    for (Sparse_index k = Ap[j]; k < Ap[j + 1]; k++) {
      if (!isfinite(Ax[k])) return status_set(st, STATUS_NUMERIC,
        "qp_set: A(%d,%d) = %g is not finite", (int) Ai[k], j, Ax[k]);
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
#line 971 "paper/qp.nw"
/* b, lo and slip finite; lo expanded to all unknowns; pos, flo, fhi */
static int read_vectors(Qp_workspace *w, Status *st)
{
  for (int i = 0; i < w->n; i++)
    if (!isfinite(w->qp->b[i])) return status_set(st, STATUS_NUMERIC,
      "qp_set: b[%d] = %g is not finite", i, w->qp->b[i]);
  for (int i = 0; i < w->n; i++) {
    int c = w->bnd[i] < w->nc ? w->bnd[i] : -1;
    w->lo[i] = c < 0 ? -INFINITY : w->qp->lo[c];
    if (c >= 0 && !isfinite(w->lo[i])) return status_set(st, STATUS_NUMERIC,
      "qp_set: lo[%d] = %g is not finite", c, w->lo[i]);
  }
  for (int c = 0; c < w->nc; c++)
    w->pos[c] = w->qp->lo[c], w->flo[c] = 0, w->fhi[c] = INFINITY;
  for (int k = 0; k < w->qp->nt; k++) {
    double s = w->qp->slip[k];
    if (!(s >= 0 && isfinite(s))) return status_set(st, STATUS_NUMERIC,
      "qp_set: slip[%d] = %g is not a finite bound >= 0", k, s);
    w->pos[w->nc + k] = 0, w->flo[w->nc + k] = -s, w->fhi[w->nc + k] = s;
  }
  return STATUS_OK;
}
#line 996 "paper/qp.nw"
/* the current values of A, b and lo, read and checked */
static int qp_read_values(Qp_workspace *w, Status *st)
{
  int code = read_matrix(w, st);
  if (!code) code = read_vectors(w, st);
  return code;
}
#line 1008 "paper/qp.nw"
int qp_set(Qp_workspace *w, const double *x0, Status *st)
{
  int code = qp_read_values(w, st);
  if (code) return code;
  for (int i = 0; i < w->n; i++) w->x[i] = qp_proj(w, i, x0 ? x0[i] : 0);
  w->iter = 0;
  qp_refresh(w);
  if (!isfinite(w->kkt))
    return status_set(st, STATUS_NUMERIC, "qp_set: the starting point is not finite");
  if (w->opt.method == QP_PDAS) pdas_set(w, x0 != NULL);
  if (w->opt.method == QP_CGSSOR) cgssor_set(w);
  return STATUS_OK;
}
#line 1029 "paper/qp.nw"
int qp_iterate(Qp_workspace *w, Status *st)
{
  Qp_method m = w->opt.method;
  int code = m == QP_PDAS ? pdas_iterate(w, st)
           : m == QP_PSOR ? psor_iterate(w, st) : cgssor_iterate(w, st);
  w->iter++;
  if (!code && !isfinite(w->kkt))
    code = status_set(st, STATUS_NUMERIC, "%s: NaN or infinity after %d "
                      "iterations", qp_method_name(m), w->iter);
  return code;
}

int qp_test(const Qp_workspace *w) { return w->kkt <= w->opt.tol; }

const double *qp_x(const Qp_workspace *w) { return w->x; }
#line 1069 "paper/qp.nw"
int qp_solve(Qp_workspace *w, const double *x0, double *x, double *T,
             Qp_report *rep, Status *st)
{
  int code = qp_set(w, x0, st);
  if (code) return code;
  while (!code && (!qp_test(w) || (w->iter == 0 && w->opt.method == QP_PDAS)))
    code = w->iter >= w->opt.max_iter ? not_converged(w, st)
                                      : qp_iterate(w, st);
  memcpy(x, w->x, (size_t) w->n * sizeof *x);
  if (T) memcpy(T, w->T, (size_t) w->nk * sizeof *T);
  if (rep) {
    rep->iterations = w->iter, rep->kkt = w->kkt;
    rep->active = qp_count_active(w), rep->converged = qp_test(w);
  }
  if (!code && w->opt.method == QP_CGSSOR)
    code = cgssor_end(w, st);        /* for qp_schur; after the copies */
  return code;
}
#line 1100 "paper/qp.nw"
static int not_converged(const Qp_workspace *w, Status *st)
{
  return status_set(st, STATUS_NUMERIC, "%s: not converged after %d "
    "iteration%s (kkt = %.3g > tol = %.3g), %d of %d bounds active",
    qp_method_name(w->opt.method), w->iter, w->iter == 1 ? "" : "s",
    w->kkt, w->opt.tol, qp_count_active(w), w->nc);
}
#line 1193 "paper/qp.nw"
/* w's problem without friction condensed onto its bounded unknowns at
   the values of the last qp_set; who names the caller in a message */
static Condense *condense_apart(const Qp_workspace *w, const char *who,
                                Status *st)
{
  Condense_contact ct = { w->nc, w->qp->b, w->d, w->pos, w->flo, w->fhi };
  Condense *cd = condense_alloc(w->qp->A, w->nc, w->ik, &ct, w->cm, st);
  if (!cd) return NULL;
  int code = condense_factor(cd, st);
  if (code == CONDENSE_SINGULAR)
    status_set(st, STATUS_NUMERIC, "%s: A is singular even with every "
               "bounded unknown held", who);
  if (code) { condense_free(cd); return NULL; }
  return cd;
}

/* the workspace's own condensation when it belongs to the values of the
   last qp_set, else NULL */
static Condense *condensed(const Qp_workspace *w)
{
  return w->cond && w->cond->condensed ? w->cond : NULL;
}
#line 1218 "paper/qp.nw"
int qp_schur(const Qp_workspace *w, double shift, double *S, Status *st)
{
  Condense *cd = condensed(w);
  if (cd) return condense_schur(cd, shift, S, st);
  if (!(cd = condense_apart(w, "qp_schur", st))) return st->code;
  int code = condense_schur(cd, shift, S, st);
  condense_free(cd);
  return code;
}
#line 1232 "paper/qp.nw"
int qp_adjoint(const Qp_workspace *w, const double *grad, double *lam,
               char *held, Status *st)
{
  Condense *cd = condensed(w), *own = NULL;
  if (!cd && w->nk > w->nc)
    return status_set(st, STATUS_INPUT, "adjoint: no condensation of the "
                      "friction state to solve with");
  if (!cd && !(cd = own = condense_apart(w, "adjoint", st))) return st->code;
  int code = condense_adjoint(cd, w->x, grad, lam, held, st);
  condense_free(own);
  return code;
}
