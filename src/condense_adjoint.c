#line 935 "paper/condense.nw"
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "qp_inline.h"
#include "condense.h"
#line 945 "paper/condense.nw"
/* held[k] = 1 where condensed unknown k is held: a bound touched, or
   (friction) sticking */
static void adjoint_held(const Condense *cd, const double *x, char *held)
{
  for (int k = 0; k < cd->nk; k++)
    held[k] = k < cd->nc ? !(x[cd->ik[k]] > cd->pos[k])
                         : cd->act[k] == CONDENSE_HELD;
}
#line 958 "paper/condense.nw"
/* z = L \ P grad in cd->rhs; r (nk, ik order) = L_cc z_c */
static int adjoint_forward(Condense *cd, const double *grad, double *r, Status *st)
{
  memcpy(cd->rhs->x, grad, (size_t) cd->n * sizeof *grad);
  if (condense_solve(cd, 0, &cd->rhs, st)) return st->code;
  const double *z = cd->rhs->x;
  for (int t = 0; t < cd->nk; t++) {
    double s = 0;
    for (int u = 0; u <= t; u++) s += cd->Lcc[(size_t) t * cd->nk + u] * z[cd->first + u];
    r[cd->tc[t]] = s;
  }
  return STATUS_OK;
}
#line 976 "paper/condense.nw"
/* y (nk) = 0 on the held, S_FF \ r_F on the others */
static int adjoint_condensed(const Condense *cd, const char *held,
                             const double *r, double *y, Status *st)
{
  int nk = cd->nk, m = 0, code = STATUS_OK;
  int *fr = malloc(((size_t) nk + 1) * sizeof *fr);
  double *SFF = malloc(((size_t) nk * nk + 1) * sizeof *SFF);
  if (!fr || !SFF) code = status_set(st, STATUS_MEMORY, "adjoint: out of memory");
  for (int k = 0; !code && k < nk; k++) { y[k] = 0; if (!held[k]) fr[m++] = k; }
  for (int a = 0; !code && a < m; a++)
    for (int b = 0; b < m; b++) SFF[(size_t) a * m + b] = cd->S[(size_t) fr[a] * nk + fr[b]];
  if (!code && m > 0) {
    gsl_matrix_view F = gsl_matrix_view_array(SFF, m, m);
    double *rf = malloc((size_t) m * sizeof *rf);
    if (!rf) code = status_set(st, STATUS_MEMORY, "adjoint: out of memory");
    else if (gsl_linalg_cholesky_decomp1(&F.matrix) || !qp_factor_regular(SFF, m))
      code = status_set(st, STATUS_NUMERIC, "adjoint: the free contact nodes' "
                        "stiffness is singular: nothing holds them");
    else {
      for (int a = 0; a < m; a++) rf[a] = r[fr[a]];
      gsl_vector_view x = gsl_vector_view_array(rf, m);
      gsl_linalg_cholesky_svx(&F.matrix, &x.vector);
      for (int a = 0; a < m; a++) y[fr[a]] = rf[a];
    }
    free(rf);
  }
  free(fr), free(SFF);
  return code;
}
#line 1018 "paper/condense.nw"
int condense_adjoint(Condense *cd, const double *x, const double *grad,
                     double *lam, char *held, Status *st)
{
  int nk = cd->nk, code = STATUS_OK;
  char *h = malloc((size_t) nk + 1);
  double *r = malloc(2 * ((size_t) nk + 1) * sizeof *r), *y = r + nk + 1;
  if (!h || !r) code = status_set(st, STATUS_MEMORY, "adjoint: out of memory");
  if (!code) adjoint_held(cd, x, h);
  if (!code) code = adjoint_forward(cd, grad, r, st);
  if (!code) code = adjoint_condensed(cd, h, r, y, st);
  if (!code) {
    double *v = cd->rhs->x;
    for (int t = 0; t < nk; t++) {
      double s = 0;
      for (int u = t; u < nk; u++) s += cd->Lcc[(size_t) u * nk + t] * y[cd->tc[u]];
      v[cd->first + t] = s;
    }
    code = condense_solve(cd, 1, &cd->rhs, st);
  }
  if (!code) {
    memcpy(lam, cd->rhs->x, (size_t) cd->n * sizeof *lam);
    for (int k = 0; k < nk; k++) lam[cd->ik[k]] = y[k];
    if (held) memcpy(held, h, (size_t) nk);
  }
  free(h), free(r);
  return code;
}
