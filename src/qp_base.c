#line 415 "paper/qp.nw"
#include <math.h>
#include "qp_private.h"
#line 403 "paper/qp.nw"
static double qp_norm_bound(const cholmod_sparse *A);
#line 607 "paper/qp.nw"
/* the relative KKT residual of x; normA = max_j sum_i |A_ij|; grad = Ax - b
   if known, else NULL; T (nc, may be NULL) receives the contact forces */
double qp_kkt_eval(const Qp *qp, double normA, const double *x,
                   const double *grad, double *T)
{
  const double *b = qp->b;
  const Sparse_index *Ap = qp->A->p;
  double rf = 0, tn = 0, inf = 0, comp = 0, bb = 0, axax = 0, xx = 0, ll = 0;
  int m = 0;                               /* the longest column of A */
  for (int j = 0, c = 0, k = 0; j < (int) qp->A->ncol; j++) {
    double r = grad ? grad[j] : qp_row_dot(qp->A, j, x) - b[j], axj = r + b[j];
    if (Ap[j + 1] - Ap[j] > m) m = (int) (Ap[j + 1] - Ap[j]);
    bb += b[j] * b[j];
    axax += axj * axj;
    xx += x[j] * x[j];
    if (c < qp->nc && qp->ic[c] == j) {
      
#line 636 "paper/qp.nw"
double gap = x[j] - qp->lo[c];
if (r < 0) tn += r * r;          /* a pulling contact force */
if (gap < 0) inf += gap * gap;   /* a penetration */
comp += fabs(r) * fabs(gap);     /* a force without contact */
ll += qp->lo[c] * qp->lo[c];
if (T) T[c] = r;
#line 624 "paper/qp.nw"
      c++;
    } else if (k < qp->nt && qp->it[k] == j) {
      
#line 649 "paper/qp.nw"
qp_slip_terms(qp->slip[k], r, x[j], &tn, &comp);
if (T) T[qp->nc + k] = r;
#line 627 "paper/qp.nw"
      k++;
    } else
      rf += r * r;
  }
  
#line 657 "paper/qp.nw"
double sf = sqrt(bb) + sqrt(axax), su = sqrt(xx) + sqrt(ll);
double gm = qp_gamma(m + 2);             /* m + 1 terms, and x rounded */
double rho = gm * (normA * sqrt(xx) + sqrt(bb));
return qp_kkt_combine(sqrt(rf), sqrt(tn), sqrt(inf), comp, sf, su, rho, gm);
#line 632 "paper/qp.nw"
}
#line 664 "paper/qp.nw"
double qp_kkt(const Qp *qp, const double *x, double *T)
{
  return qp_kkt_eval(qp, qp_norm_bound(qp->A), x, NULL, T);
}
#line 672 "paper/qp.nw"
/* max_j sum_i |A_ij|: an upper bound of ||A||_2 and of || |A| ||_2 */
static double qp_norm_bound(const cholmod_sparse *A)
{
  const Sparse_index *Ap = A->p;
  const double *Ax = A->x;
  double m = 0;
  for (int j = 0; j < (int) A->ncol; j++) {
    double sum = 0;
    for (Sparse_index k = Ap[j]; k < Ap[j + 1]; k++) sum += fabs(Ax[k]);
    m = fmax(m, sum);
  }
  return m;
}
#line 733 "paper/qp.nw"
/* y = A x */
void qp_matvec(const cholmod_sparse *A, const double *x, double *y)
{
  for (int j = 0; j < (int) A->ncol; j++) y[j] = qp_row_dot(A, j, x);
}

/* grad = A x - b, then kkt and T at x */
void qp_refresh(Qp_workspace *w)
{
  qp_matvec(w->qp->A, w->x, w->grad);
  for (int i = 0; i < w->n; i++) w->grad[i] -= w->qp->b[i];
  w->kkt = qp_kkt_eval(w->qp, w->normA, w->x, w->grad, w->T);
}
#line 1047 "paper/qp.nw"
const char *qp_method_name(Qp_method m)
{
  return m == QP_PDAS ? "pdas" : m == QP_PSOR ? "psor"
       : m == QP_CGSSOR ? "cgssor" : "?";
}
#line 1110 "paper/qp.nw"
/* bounded unknowns at their bound */
int qp_count_active(const Qp_workspace *w)
{
  int m = 0;
  for (int c = 0; c < w->nc; c++) m += !qp_is_free(w, w->qp->ic[c]);
  return m;
}
#line 1125 "paper/qp.nw"
/* (4.3) has no solution: why, with how many bounds active */
int qp_not_held(const Qp_workspace *w, Status *st, const char *why,
                int active)
{
  return status_set(st, STATUS_NUMERIC, "%s: the body is not held with %d "
    "of %d bounds active: %s, at iteration %d",
    qp_method_name(w->opt.method), active, w->nc, why, w->iter + 1);
}
#line 1144 "paper/qp.nw"
int qp_condense(Qp_workspace *w, Status *st)
{
  int code = condense_factor(w->cond, st);
  return code != CONDENSE_SINGULAR ? code : qp_not_held(w, st,
    "A is singular even with every bound held", w->nc);
}

int qp_expand(Qp_workspace *w, Status *st)
{
  int code = condense_expand(w->cond, w->x, st);
  if (!code) qp_refresh(w);
  return code;
}

int qp_refine(Qp_workspace *w, Status *st)
{
  int code = condense_refine(w->cond, w->grad, w->x, st);
  if (!code) qp_refresh(w);
  return code;
}
