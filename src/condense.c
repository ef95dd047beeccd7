#line 272 "paper/condense.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "qp_inline.h"
#include "condense.h"
#line 262 "paper/condense.nw"
static int cholmod_failed(const cholmod_common *cm, const char *what, Status *st);
static void fill_contact_matrix(Condense *cd, const double *d);
static int pattern_symmetric(Condense *cd);
static int permute_pattern(Condense *cd);
static void read_trailing_block(Condense *cd);
static void schur_complement(Condense *cd, const double *d);
static int condensed_load(Condense *cd, const double *b, Status *st);
#line 292 "paper/condense.nw"
/* the arrays and at; nonzero when out of memory or A's pattern is not
   symmetric */
static int alloc_arrays(Condense *cd, Status *st)
{
  size_t nc = (size_t) cd->nk + 1;
  cd->perm = malloc(((size_t) cd->n + 1) * sizeof *cd->perm);
  cd->at = malloc(((size_t) cd->n + 1) * sizeof *cd->at);
  cd->act = malloc(nc), cd->tc = malloc(nc * sizeof *cd->tc);
  cd->f = malloc(nc * sizeof *cd->f), cd->y = malloc(nc * sizeof *cd->y);
  cd->Lcc = malloc(nc * nc * sizeof *cd->Lcc);
  cd->S = malloc(nc * nc * sizeof *cd->S), cd->M = malloc(nc * nc * sizeof *cd->M);
  if (!cd->perm || !cd->at || !cd->act || !cd->tc || !cd->f || !cd->y
      || !cd->Lcc || !cd->S || !cd->M)
    return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (condensed onto the contact, "
                      "nc = %d)", cd->nk);
  int sym = pattern_symmetric(cd);
  if (sym < 0) return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (n = %d)", cd->n);
  if (!sym) return status_set(st, STATUS_INPUT, "qp_alloc: the pattern of A is not symmetric");
  for (int i = 0; i < cd->n; i++) cd->at[i] = -1;
  for (int k = 0; k < cd->nk; k++) cd->at[cd->ik[k]] = k;
  cd->first = cd->n - cd->nk;
  return STATUS_OK;
}
#line 323 "paper/condense.nw"
static int analyse_contact_last(Condense *cd, Status *st)
{
  cholmod_common *cm = cd->cm;
  size_t n = (size_t) cd->n;
  Sparse_index *last = calloc(n + 1, sizeof *last);
  if (!last) return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (n = %d)", cd->n);
  int nmethods = cm->nmethods, ordering = cm->method[0].ordering;
  int postorder = cm->postorder, ok;
  for (int c = 0; c < cd->nk; c++) last[cd->ik[c]] = 1;
  cholmod_sparse U = *cd->A;    /* CAMD reads the pattern of one triangle */
  U.stype = 1;
  cm->nmethods = 1, cm->method[0].ordering = CHOLMOD_NATURAL, cm->postorder = 0;
  ok = cholmod_l_camd(&U, NULL, 0, last, cd->perm, cm) && permute_pattern(cd)
       && (cd->Ls = cholmod_l_analyze(cd->K, cm));
  cm->nmethods = nmethods, cm->method[0].ordering = ordering;
  cm->postorder = postorder;
  free(last);
  if (!ok) return cholmod_failed(cm, "qp_alloc: CHOLMOD failed to analyse A", st);
  
#line 346 "paper/condense.nw"
if (!(cd->rhs = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, cm))
    || !(cd->sol = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, cm))
    || !(cd->Lb = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, cm)))
  return cholmod_failed(cm, "qp_alloc: CHOLMOD could not allocate the "
                        "vectors of the solves", st);
for (int t = 0; t < cd->nk; t++)
  if ((cd->tc[t] = cd->at[cd->perm[cd->first + t]]) < 0)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: CAMD did not order "
                      "the bounded unknowns last");
return STATUS_OK;
#line 342 "paper/condense.nw"
}
#line 359 "paper/condense.nw"
Condense *condense_alloc(const cholmod_sparse *A, int nk, const int *ik,
                         const Condense_contact *ct, cholmod_common *cm,
                         Status *st)
{
  Condense *cd = calloc(1, sizeof *cd);
  if (!cd) { status_set(st, STATUS_MEMORY, "qp_alloc: out of memory"); return NULL; }
  cd->A = A, cd->cm = cm, cd->n = (int) A->ncol, cd->nk = nk, cd->ik = ik;
  if (ct) cd->nc = ct->nc, cd->b = ct->b, cd->d = ct->d, cd->pos = ct->pos,
          cd->flo = ct->flo, cd->fhi = ct->fhi;
  if (alloc_arrays(cd, st) || analyse_contact_last(cd, st)) {
    condense_free(cd);
    return NULL;
  }
  return cd;
}

void condense_release(Condense *cd)
{
  if (!cd) return;
  cholmod_l_free_factor(&cd->L, cd->cm);     /* the next starts from Ls */
  cd->condensed = 0;
}

void condense_free(Condense *cd)
{
  if (!cd) return;
  if (cd->K) cholmod_l_free(cd->K->nzmax, sizeof *cd->src, cd->src, cd->cm);
  cholmod_l_free_sparse(&cd->K, cd->cm);
  free(cd->perm), free(cd->at), free(cd->act), free(cd->tc);
  free(cd->f), free(cd->y), free(cd->Lcc), free(cd->S), free(cd->M);
  cholmod_l_free_factor(&cd->Ls, cd->cm), cholmod_l_free_factor(&cd->L, cd->cm);
  cholmod_l_free_dense(&cd->rhs, cd->cm), cholmod_l_free_dense(&cd->sol, cd->cm);
  cholmod_l_free_dense(&cd->Lb, cd->cm);
  cholmod_l_free_dense(&cd->solve_Y, cd->cm), cholmod_l_free_dense(&cd->solve_E, cd->cm);
  free(cd);
}
#line 405 "paper/condense.nw"
/* the name of CHOLMOD's status s (cholmod_core.h) */
static const char *cholmod_status_name(int s)
{
  switch (s) {
  case CHOLMOD_OK: return "CHOLMOD_OK";
  case CHOLMOD_NOT_INSTALLED: return "CHOLMOD_NOT_INSTALLED";
  case CHOLMOD_OUT_OF_MEMORY: return "CHOLMOD_OUT_OF_MEMORY";
  case CHOLMOD_TOO_LARGE: return "CHOLMOD_TOO_LARGE";
  case CHOLMOD_INVALID: return "CHOLMOD_INVALID";
  case CHOLMOD_GPU_PROBLEM: return "CHOLMOD_GPU_PROBLEM";
  case CHOLMOD_NOT_POSDEF: return "CHOLMOD_NOT_POSDEF";
  case CHOLMOD_DSMALL: return "CHOLMOD_DSMALL";
  default: return "unknown";
  }
}

/* what failed, with CHOLMOD's status: STATUS_MEMORY when it ran out */
static int cholmod_failed(const cholmod_common *cm, const char *what,
                          Status *st)
{
  int s = cm->status;
  const char *name = cholmod_status_name(s);
  if (s == CHOLMOD_OUT_OF_MEMORY)
    return status_set(st, STATUS_MEMORY, "%s: out of memory (CHOLMOD status "
                      "%d, %s)", what, s, name);
  if (s == CHOLMOD_TOO_LARGE)
    return status_set(st, STATUS_MEMORY, "%s: the problem is too large for "
                      "CHOLMOD's integers (CHOLMOD status %d, %s)", what, s, name);
  return status_set(st, STATUS_SYSTEM, "%s (CHOLMOD status %d, %s)", what, s, name);
}
#line 457 "paper/condense.nw"
/* S, f and the factor of K = A + D_c at the current values of A and b,
   d the diagonal of A; CONDENSE_SINGULAR when K is */
int condense_factor(Condense *cd, Status *st)
{
  const double *b = cd->b, *d = cd->d;
  cholmod_common *cm = cd->cm;
  int print = cm->print, final_ll = cm->final_ll, ok;
  fill_contact_matrix(cd, d);
  cm->print = 0, cm->final_ll = 1;  /* a singular K is our message to give */
  if (!cd->L) cd->L = cholmod_l_copy_factor(cd->Ls, cm);
  ok = cd->L && cholmod_l_factorize(cd->K, cd->L, cm) && cm->status >= CHOLMOD_OK;
  cm->print = print, cm->final_ll = final_ll;
  if (!ok || cd->L->minor < cd->L->n) {
    cholmod_l_free_factor(&cd->L, cm);     /* the next starts from Ls */
    return ok ? CONDENSE_SINGULAR
              : cholmod_failed(cm, "condense: CHOLMOD failed to factorise K", st);
  }
  read_trailing_block(cd);
  schur_complement(cd, d);
  int code = condensed_load(cd, b, st);
  cd->condensed = !code;
  return code;
}
#line 508 "paper/condense.nw"
/* K = P (A + D_c) P' on the condensed unknowns, from the lower triangle
   of A; the values only */
static void fill_contact_matrix(Condense *cd, const double *d)
{
  const double *Ax = cd->A->x;
  const Sparse_index *Kp = cd->K->p, *src = cd->src;
  double *Kx = cd->K->x;
  for (Sparse_index q = 0; q < Kp[cd->n]; q++) Kx[q] = Ax[src[q]];
  for (int t = 0; t < cd->nk; t++)
    Kx[Kp[cd->first + t]] += d[cd->perm[cd->first + t]];
}

/* K = the pattern of the lower triangle of P A P', sorted, and src;
   0 (CHOLMOD's status set) when CHOLMOD fails */
static int permute_pattern(Condense *cd)
{
  cholmod_common *cm = cd->cm;
  size_t nz = (size_t) ((const Sparse_index *) cd->A->p)[cd->n];
  cholmod_sparse T = *cd->A, *U = NULL;    /* the lower triangle of A, */
  T.stype = -1, T.x = cholmod_l_malloc(nz, sizeof(double), cm);   /* its indices */
  if (!T.x) return 0;
  for (size_t k = 0; k < nz; k++) ((double *) T.x)[k] = (double) k;
  U = cholmod_l_ptranspose(&T, 2, cd->perm, NULL, 0, cm);    /* upper of PAP' */
  cholmod_l_free(nz, sizeof(double), T.x, cm);
  cd->K = U ? cholmod_l_ptranspose(U, 2, NULL, NULL, 0, cm) : NULL;   /* lower */
  cholmod_l_free_sparse(&U, cm);
  if (!cd->K || !(cd->src = cholmod_l_malloc(cd->K->nzmax, sizeof *cd->src, cm)))
    return 0;
  const double *Kx = cd->K->x;
  for (size_t q = 0; q < cd->K->nzmax; q++) cd->src[q] = (Sparse_index) Kx[q];
  return 1;
}

/* 1 if each lower entry (i, j) of A has its mirror (j, i) and each column
   its diagonal, the columns sorted; -1 when out of memory */
static int pattern_symmetric(Condense *cd)
{
  const Sparse_index *Ap = cd->A->p, *Ai = cd->A->i;
  Sparse_index *next = malloc(((size_t) cd->n + 1) * sizeof *next);
  int ok = 1;
  if (!next) return -1;
  for (int j = 0; j < cd->n; j++) next[j] = Ap[j];
  for (int j = 0; ok && j < cd->n; j++)
    for (Sparse_index k = Ap[j]; ok && k < Ap[j + 1]; k++) {
      Sparse_index i = Ai[k];
      if (i > j && (next[i] >= Ap[i + 1] || Ai[next[i]++] != j)) ok = 0;
    }
  for (int j = 0; ok && j < cd->n; j++)   /* the upper entries all met, then j */
    if (next[j] >= Ap[j + 1] || Ai[next[j]] != j) ok = 0;
  free(next);
  return ok;
}
#line 568 "paper/condense.nw"
/* Lcc = the rows and columns first..n-1 of L, row-major, lower */
static void read_trailing_block(Condense *cd)
{
  const cholmod_factor *L = cd->L;
  const double *Lx = L->x;
  int nc = cd->nk, first = cd->first;
  memset(cd->Lcc, 0, (size_t) nc * nc * sizeof *cd->Lcc);
  if (L->is_super) {
    
#line 587 "paper/condense.nw"
const Sparse_index *super = L->super, *pi = L->pi, *px = L->px, *Ls = L->s;
for (size_t s = 0; s < L->nsuper; s++) {
  Sparse_index k1 = super[s], k2 = super[s + 1], nrow = pi[s + 1] - pi[s];
  for (Sparse_index k = k1 > first ? k1 : first; k < k2; k++)
    for (Sparse_index q = k - k1; q < nrow; q++)
      cd->Lcc[(size_t) (Ls[pi[s] + q] - first) * nc + (k - first)] =
        Lx[px[s] + q + (size_t) (k - k1) * nrow];
}
#line 577 "paper/condense.nw"
  } else {
    const Sparse_index *Lp = L->p, *Li = L->i, *Lnz = L->nz;
    for (int k = first; k < cd->n; k++)
      for (Sparse_index q = Lp[k]; q < Lp[k] + Lnz[k]; q++)
        cd->Lcc[(size_t) (Li[q] - first) * nc + (k - first)] = Lx[q];
  }
}
#line 600 "paper/condense.nw"
static void schur_complement(Condense *cd, const double *d)
{
  int nc = cd->nk;
  if (nc == 0) return;
  gsl_matrix_view L = gsl_matrix_view_array(cd->Lcc, nc, nc),
                  LLt = gsl_matrix_view_array(cd->M, nc, nc);
  gsl_blas_dsyrk(CblasLower, CblasNoTrans, 1.0, &L.matrix, 0.0, &LLt.matrix);
  for (int t = 0; t < nc; t++)
    for (int u = 0; u <= t; u++) {
      int a = cd->tc[t], b = cd->tc[u];
      double v = cd->M[(size_t) t * nc + u] - (t == u ? d[cd->ik[a]] : 0);
      cd->S[(size_t) a * nc + b] = cd->S[(size_t) b * nc + a] = v;
    }
}
#line 619 "paper/condense.nw"
static int condensed_load(Condense *cd, const double *b, Status *st)
{
  memcpy(cd->rhs->x, b, (size_t) cd->n * sizeof *b);
  if (condense_solve(cd, 0, &cd->rhs, st)) return st->code;
  cholmod_dense *swap = cd->Lb;
  cd->Lb = cd->rhs, cd->rhs = swap;      /* keep z, reuse the old vector */
  const double *z = cd->Lb->x;
  cd->bu2 = 0;
  for (int i = 0; i < cd->n; i++)
    if (cd->at[i] < 0) cd->bu2 += b[i] * b[i];
  for (int t = 0; t < cd->nk; t++) {
    double s = 0;
    for (int u = 0; u <= t; u++) s += cd->Lcc[(size_t) t * cd->nk + u] * z[cd->first + u];
    cd->f[cd->tc[t]] = s;
  }
  return STATUS_OK;
}
#line 644 "paper/condense.nw"
int condense_solve(Condense *cd, int back, cholmod_dense **v, Status *st)
{
  cholmod_common *cm = cd->cm;
  const Sparse_index *P = cd->perm;
  double *s = cd->sol->x, *x = (*v)->x;
  int ok;
  if (!back) {
    for (int q = 0; q < cd->n; q++) s[q] = x[P[q]];
    ok = cholmod_l_solve2(CHOLMOD_L, cd->L, cd->sol, NULL, v, NULL, &cd->solve_Y, &cd->solve_E,
                          cm);
  } else if ((ok = cholmod_l_solve2(CHOLMOD_Lt, cd->L, *v, NULL, &cd->sol, NULL,
                                    &cd->solve_Y, &cd->solve_E, cm))) {
    s = cd->sol->x, x = (*v)->x;
    for (int q = 0; q < cd->n; q++) x[P[q]] = s[q];
  }
  return ok ? STATUS_OK
            : cholmod_failed(cm, "condense: CHOLMOD failed to solve with the factor of K", st);
}
#line 681 "paper/condense.nw"
void condense_forces(const Condense *cd, double *T)
{
  for (int c = 0; c < cd->nk; c++) {
    const double *Sc = cd->S + (size_t) c * cd->nk;
    double s = -cd->f[c];
    for (int e = 0; e < cd->nk; e++) s += Sc[e] * cd->y[e];
    T[c] = s;
  }
}
#line 694 "paper/condense.nw"
double condense_kkt(const Condense *cd, const double *T, double normA,
                    double gamma)
{
  double tn = 0, inf = 0, comp = 0, axax = cd->bu2, bb = cd->bu2, yy = 0, ll = 0;
  
#line 706 "paper/condense.nw"
for (int c = 0; c < cd->nk; c++) {
  double Tc = T[c], bc = cd->b[cd->ik[c]];
  if (c < cd->nc) {
    double gap = cd->y[c] - cd->pos[c];
    if (Tc < 0) tn += Tc * Tc;
    if (gap < 0) inf += gap * gap;
    comp += fabs(Tc) * fabs(gap);
    ll += cd->pos[c] * cd->pos[c];
  } else
    qp_slip_terms(cd->fhi[c], Tc, cd->y[c], &tn, &comp);
  bb += bc * bc, axax += (bc + Tc) * (bc + Tc);
  yy += cd->y[c] * cd->y[c];
}
#line 699 "paper/condense.nw"
  double sf = sqrt(bb) + sqrt(axax), su = sqrt(yy) + sqrt(ll);
  double rho = gamma * (normA * sqrt(yy) + sqrt(bb));
  return qp_kkt_combine(0, sqrt(tn), sqrt(inf), comp, sf, su, rho, gamma);
}
#line 726 "paper/condense.nw"
/* the state of c that y and T call for: with z = T_c + A_ii (pos_c - y_c),
   held where flo_c < z <= fhi_c, at the force flo_c or fhi_c beyond; an
   interval of width 0 (no friction) always gives its one force; after an
   active-set step, a slide that crossed its place sticks first */
static char predicted_state(const Condense *cd, const double *T, int c)
{
  if (cd->stepped && cd->act[c] != CONDENSE_HELD && cd->fhi[c] < INFINITY
      && cd->flo[c] != cd->fhi[c])
    return cd->act[c] == CONDENSE_LO
           ? (cd->y[c] < cd->pos[c] ? CONDENSE_HELD : CONDENSE_LO)
           : (cd->y[c] > cd->pos[c] ? CONDENSE_HELD : CONDENSE_HI);
  double z = T[c] + cd->d[cd->ik[c]] * (cd->pos[c] - cd->y[c]);
  if (z <= cd->flo[c] || cd->flo[c] == cd->fhi[c]) return CONDENSE_LO;
  return z > cd->fhi[c] ? CONDENSE_HI : CONDENSE_HELD;
}

/* act = the states that y and T call for; 1 if none changed */
int condense_predict(Condense *cd, const double *T)
{
  int same = 1;
  for (int c = 0; c < cd->nk; c++) {
    char a = predicted_state(cd, T, c);
    same &= a == cd->act[c];
    cd->act[c] = a;
  }
  return same;
}

/* y from x, T = S y - f, and the states they call for (no active-set
   step behind them): the guess of a warm start */
void condense_states_at(Condense *cd, const double *x, double *T)
{
  for (int c = 0; c < cd->nk; c++) cd->y[c] = x[cd->ik[c]];
  condense_forces(cd, T);
  cd->stepped = 0;
  condense_predict(cd, T);
  cd->stepped = 1;
}
#line 785 "paper/condense.nw"
int condense_expand(Condense *cd, double *x, Status *st)
{
  double *v = cd->rhs->x;
  memcpy(v, cd->Lb->x, (size_t) cd->n * sizeof *v);
  for (int t = 0; t < cd->nk; t++) {
    double s = 0;
    for (int u = t; u < cd->nk; u++)
      s += cd->Lcc[(size_t) u * cd->nk + t] * cd->y[cd->tc[u]];
    v[cd->first + t] = s;
  }
  if (condense_solve(cd, 1, &cd->rhs, st)) return st->code;
  memcpy(x, cd->rhs->x, (size_t) cd->n * sizeof *x);
  for (int c = 0; c < cd->nk; c++) x[cd->ik[c]] = cd->y[c];
  return STATUS_OK;
}
#line 808 "paper/condense.nw"
int condense_refine(Condense *cd, const double *grad, double *x, Status *st)
{
  double *v = cd->rhs->x;
  for (int i = 0; i < cd->n; i++) v[i] = cd->at[i] < 0 ? -grad[i] : 0;
  if (condense_solve(cd, 0, &cd->rhs, st)) return st->code;
  v = cd->rhs->x;
  memset(v + cd->first, 0, (size_t) cd->nk * sizeof *v);
  if (condense_solve(cd, 1, &cd->rhs, st)) return st->code;
  v = cd->rhs->x;
  for (int i = 0; i < cd->n; i++) if (cd->at[i] < 0) x[i] += v[i];
  return STATUS_OK;
}
#line 831 "paper/condense.nw"
/* S = the Schur complement of cd, its diagonal raised by shift d_i */
static void schur_copy(const Condense *cd, const double *d, double shift,
                       double *S)
{
  int nc = cd->nk;
  memcpy(S, cd->S, (size_t) nc * nc * sizeof *S);
  for (int k = 0; k < nc; k++) S[(size_t) k * nc + k] += shift * d[cd->ik[k]];
}
#line 851 "paper/condense.nw"
/* S = the Schur complement of S onto the bounded unknowns, the sticking
   tangential ones held and the sliding ones eliminated */
static int schur_friction(const Condense *cd, double shift, double *S,
                          Status *st)
{
  int nc = cd->nc, nk = cd->nk, m = 0, code = STATUS_OK;
  int *fr = malloc((size_t) (nk - nc + 1) * sizeof *fr);
  double *SFF = malloc((size_t) (nk - nc) * (nk - nc) * sizeof *SFF + 1);
  double *SFn = malloc((size_t) (nk - nc) * nc * sizeof *SFn + 1);
  if (!fr || !SFF || !SFn) code = status_set(st, STATUS_MEMORY, "qp_schur: out of memory");
  for (int k = nc; !code && k < nk; k++) if (cd->act[k] != CONDENSE_HELD) fr[m++] = k;
  
#line 870 "paper/condense.nw"
for (int a = 0; !code && a < m; a++) {
  for (int b = 0; b < m; b++) SFF[(size_t) a * m + b] = cd->S[(size_t) fr[a] * nk + fr[b]];
  for (int c = 0; c < nc; c++) SFn[(size_t) a * nc + c] = cd->S[(size_t) fr[a] * nk + c];
}
if (!code && m > 0) {
  gsl_matrix_view F = gsl_matrix_view_array(SFF, m, m), B = gsl_matrix_view_array(SFn, m, nc);
  if (gsl_linalg_cholesky_decomp1(&F.matrix))
    code = status_set(st, STATUS_NUMERIC, "qp_schur: the sliding nodes' "
                      "stiffness is singular: nothing holds them");
  else {
    gsl_blas_dtrsm(CblasLeft, CblasLower, CblasNoTrans, CblasNonUnit, 1.0, &F.matrix, &B.matrix);
    for (int c = 0; c < nc; c++)
      for (int e = 0; e < nc; e++) {
        double v = cd->S[(size_t) c * nk + e];
        for (int a = 0; a < m; a++) v -= SFn[(size_t) a * nc + c] * SFn[(size_t) a * nc + e];
        S[(size_t) c * nc + e] = v;
      }
  }
} else if (!code)
  for (int c = 0; c < nc; c++)
    memcpy(S + (size_t) c * nc, cd->S + (size_t) c * nk, (size_t) nc * sizeof *S);
for (int k = 0; !code && k < nc; k++) S[(size_t) k * nc + k] += shift * cd->d[cd->ik[k]];
#line 863 "paper/condense.nw"
  free(fr), free(SFF), free(SFn);
  return code;
}
#line 899 "paper/condense.nw"
int condense_schur(const Condense *cd, double shift, double *S,
                   Status *st)
{
  if (cd->nk > cd->nc) return schur_friction(cd, shift, S, st);
  schur_copy(cd, cd->d, shift, S);
  return STATUS_OK;
}
