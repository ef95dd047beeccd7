#line 300 "paper/pdas.nw"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "qp_private.h"

#line 465 "paper/pdas.nw"
#define SINGULAR (-1)    /* K or a Newton matrix is singular (not a Status_code) */
#line 448 "paper/pdas.nw"
/* what failed, with CHOLMOD's status: STATUS_MEMORY when it ran out */
static int pdas_cholmod_failed(const cholmod_common *cm, const char *what,
                               Status *st)
{
  if (cm->status == CHOLMOD_OUT_OF_MEMORY)
    return status_set(st, STATUS_MEMORY, "%s: out of memory", what);
  if (cm->status == CHOLMOD_TOO_LARGE)
    return status_set(st, STATUS_MEMORY, "%s: the problem is too large for "
                      "CHOLMOD's 32-bit integers", what);
  return status_set(st, STATUS_SYSTEM, "%s (CHOLMOD status %d)", what, cm->status);
}
#line 473 "paper/pdas.nw"
enum { FORCE_LO = 0, HELD = 1, FORCE_HI = 2 };
#line 478 "paper/pdas.nw"
enum { GUIDE_OFF = 0, GUIDE_ON = 1, GUIDE_STOPPED = 2 };

#line 1011 "paper/pdas.nw"
/* *v = the solves sys2(sys1(*v)) with L, through w->pdas.sol */
static int solve_pair(Qp_workspace *w, int sys1, int sys2, cholmod_dense **v,
                      Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  cholmod_common *cm = w->cm;
  if (!cholmod_solve2(sys1, pd->L, *v, NULL, &pd->sol, NULL, &pd->Y, &pd->E, cm)
      || !cholmod_solve2(sys2, pd->L, pd->sol, NULL, v, NULL, &pd->Y, &pd->E, cm))
    return pdas_cholmod_failed(cm, "pdas: CHOLMOD failed to solve", st);
  return STATUS_OK;
}

#line 384 "paper/pdas.nw"
static int analyse_contact_last(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  cholmod_common *cm = w->cm;
  size_t n = (size_t) w->n;
  int *last = calloc(n + 1, sizeof *last), *perm = malloc((n + 1) * sizeof *perm);
  int nmethods = cm->nmethods, ordering = cm->method[0].ordering;
  int postorder = cm->postorder, ok = last && perm;
  if (!ok) {
    free(last), free(perm);
    return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (n = %d)", w->n);
  }
  for (int c = 0; c < w->nk; c++) last[w->ik[c]] = 1;
  cm->nmethods = 1, cm->method[0].ordering = CHOLMOD_GIVEN, cm->postorder = 0;
  ok = ok && cholmod_camd(&pd->K, NULL, 0, last, perm, cm)
          && (pd->Ls = cholmod_analyze_p(&pd->K, perm, NULL, 0, cm));
  cm->nmethods = nmethods, cm->method[0].ordering = ordering;
  cm->postorder = postorder;
  free(last), free(perm);
  if (!ok) return pdas_cholmod_failed(cm, "qp_alloc: CHOLMOD failed to analyse A", st);
  
#line 409 "paper/pdas.nw"
if (!(pd->rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, cm))
    || !(pd->Lb = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, cm)))
  return pdas_cholmod_failed(cm, "qp_alloc: CHOLMOD could not allocate the "
                             "vectors of the solves", st);
const int *P = pd->Ls->Perm;
for (int t = 0; t < w->nk; t++)
  if ((pd->tc[t] = w->bnd[P[pd->first + t]]) < 0)
    return status_set(st, STATUS_SYSTEM, "qp_alloc: CAMD did not order "
                      "the bounded unknowns last");
return STATUS_OK;
#line 405 "paper/pdas.nw"
}

#line 341 "paper/pdas.nw"
/* the guide's vectors, nc each; nonzero when out of memory */
static int alloc_guide(Pdas_guide *ip, size_t nc)
{
  ip->s = malloc(nc * sizeof *ip->s), ip->t = malloc(nc * sizeof *ip->t);
  ip->ds = malloc(nc * sizeof *ip->ds), ip->dt = malloc(nc * sizeof *ip->dt);
  ip->as = malloc(nc * sizeof *ip->as), ip->at = malloc(nc * sizeof *ip->at);
  ip->b = malloc(nc * sizeof *ip->b), ip->db = malloc(nc * sizeof *ip->db);
  ip->ab = malloc(nc * sizeof *ip->ab);
  ip->h = malloc(nc * sizeof *ip->h);
  ip->pred = malloc(nc), ip->own = malloc(nc);
  return !ip->s || !ip->t || !ip->ds || !ip->dt || !ip->as || !ip->at
         || !ip->b || !ip->db || !ip->ab || !ip->h || !ip->pred || !ip->own;
}

int pdas_alloc(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  const cholmod_sparse *A = w->qp->A;
  size_t nz = (size_t) ((const int *) A->p)[w->n], nc = (size_t) w->nk + 1;
  pd->K = *A;                /* the header: p and i are shared with A */
  pd->K.x = malloc((nz + 1) * sizeof(double));
  pd->K.nzmax = nz, pd->K.stype = -1;
  pd->act = malloc(nc), pd->tc = malloc(nc * sizeof *pd->tc);
  pd->fr = malloc(nc * sizeof *pd->fr);
  pd->f = malloc(nc * sizeof *pd->f), pd->y = malloc(nc * sizeof *pd->y);
  pd->r = malloc(nc * sizeof *pd->r);
  pd->Lcc = malloc(nc * nc * sizeof *pd->Lcc);
  pd->S = malloc(nc * nc * sizeof *pd->S), pd->M = malloc(nc * nc * sizeof *pd->M);
  if (!pd->K.x || !pd->act || !pd->tc || !pd->fr || !pd->f || !pd->y || !pd->r
      || !pd->Lcc || !pd->S || !pd->M || alloc_guide(&pd->ip, nc))
    return status_set(st, STATUS_MEMORY, "qp_alloc: out of memory (pdas, "
                      "nc = %d)", w->nk);
  memcpy(pd->K.x, A->x, nz * sizeof(double));
  pd->first = w->n - w->nk;
  return analyse_contact_last(w, st);
}

#line 422 "paper/pdas.nw"
void pdas_free(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  free(pd->K.x), free(pd->act), free(pd->tc), free(pd->fr);
  free(pd->f), free(pd->y), free(pd->r), free(pd->Lcc), free(pd->S), free(pd->M);
  free(pd->ip.s), free(pd->ip.t), free(pd->ip.ds), free(pd->ip.dt);
  free(pd->ip.as), free(pd->ip.at), free(pd->ip.h), free(pd->ip.pred), free(pd->ip.own);
  free(pd->ip.b), free(pd->ip.db), free(pd->ip.ab);
  cholmod_free_factor(&pd->Ls, w->cm), cholmod_free_factor(&pd->L, w->cm);
  cholmod_free_dense(&pd->rhs, w->cm), cholmod_free_dense(&pd->sol, w->cm);
  cholmod_free_dense(&pd->Lb, w->cm);
  cholmod_free_dense(&pd->Y, w->cm), cholmod_free_dense(&pd->E, w->cm);
}

#line 315 "paper/pdas.nw"
/* the first active set: all of I; a warm start guesses after condensing */
void pdas_set(Qp_workspace *w, int warm)
{
  Pdas_workspace *pd = &w->pdas;
  pd->warm = warm, pd->condensed = 0, pd->stepped = 1;
  pd->ip.state = GUIDE_OFF, pd->ip.guided = 0;
  for (int c = 0; c < w->nk; c++) pd->act[c] = HELD;
}

/* the size of the active set */
static int count_act(const Qp_workspace *w)
{
  int m = 0;
  for (int c = 0; c < w->nk; c++) m += w->pdas.act[c] == HELD;
  return m;
}

#line 583 "paper/pdas.nw"
/* K = A + diag(A_ii) on the bounded unknowns; the values only */
static void fill_contact_matrix(Qp_workspace *w)
{
  const int *Ap = w->qp->A->p, *Ai = w->qp->A->i;
  double *Kx = w->pdas.K.x;
  memcpy(Kx, w->qp->A->x, (size_t) Ap[w->n] * sizeof *Kx);
  for (int c = 0; c < w->nk; c++) {
    int j = w->ik[c];
    for (int k = Ap[j]; k < Ap[j + 1]; k++)
      if (Ai[k] == j) Kx[k] += w->d[j];
  }
}

#line 603 "paper/pdas.nw"
/* Lcc = the rows and columns first..n-1 of L, row-major, lower */
static void read_trailing_block(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  const cholmod_factor *L = pd->L;
  const double *Lx = L->x;
  int nc = w->nk, first = pd->first;
  memset(pd->Lcc, 0, (size_t) nc * nc * sizeof *pd->Lcc);
  if (L->is_super) {
    
#line 623 "paper/pdas.nw"
const int *super = L->super, *pi = L->pi, *px = L->px, *Ls = L->s;
for (size_t s = 0; s < L->nsuper; s++) {
  int k1 = super[s], k2 = super[s + 1], nrow = pi[s + 1] - pi[s];
  for (int k = k1 > first ? k1 : first; k < k2; k++)
    for (int q = k - k1; q < nrow; q++)
      pd->Lcc[(size_t) (Ls[pi[s] + q] - first) * nc + (k - first)] =
        Lx[px[s] + q + (size_t) (k - k1) * nrow];
}
#line 613 "paper/pdas.nw"
  } else {
    const int *Lp = L->p, *Li = L->i, *Lnz = L->nz;
    for (int k = first; k < w->n; k++)
      for (int q = Lp[k]; q < Lp[k] + Lnz[k]; q++)
        pd->Lcc[(size_t) (Li[q] - first) * nc + (k - first)] = Lx[q];
  }
}

#line 636 "paper/pdas.nw"
static void schur_complement(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  int nc = w->nk;
  if (nc == 0) return;
  gsl_matrix_view L = gsl_matrix_view_array(pd->Lcc, nc, nc),
                  LLt = gsl_matrix_view_array(pd->M, nc, nc);
  gsl_blas_dsyrk(CblasLower, CblasNoTrans, 1.0, &L.matrix, 0.0, &LLt.matrix);
  for (int t = 0; t < nc; t++)
    for (int u = 0; u <= t; u++) {
      int a = pd->tc[t], b = pd->tc[u];
      double v = pd->M[(size_t) t * nc + u] - (t == u ? w->d[w->ik[a]] : 0);
      pd->S[(size_t) a * nc + b] = pd->S[(size_t) b * nc + a] = v;
    }
}

#line 656 "paper/pdas.nw"
static int condensed_load(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  const double *b = w->qp->b;
  memcpy(pd->rhs->x, b, (size_t) w->n * sizeof *b);
  if (solve_pair(w, CHOLMOD_P, CHOLMOD_L, &pd->rhs, st)) return st->code;
  cholmod_dense *swap = pd->Lb;
  pd->Lb = pd->rhs, pd->rhs = swap;      /* keep z, reuse the old vector */
  const double *z = pd->Lb->x;
  pd->bu2 = 0;
  for (int i = 0; i < w->n; i++)
    if (w->bnd[i] < 0) pd->bu2 += b[i] * b[i];
  for (int t = 0; t < w->nk; t++) {
    double s = 0;
    for (int u = 0; u <= t; u++) s += pd->Lcc[(size_t) t * w->nk + u] * z[pd->first + u];
    pd->f[pd->tc[t]] = s;
  }
  return STATUS_OK;
}

#line 559 "paper/pdas.nw"
static int condense(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  cholmod_common *cm = w->cm;
  int print = cm->print, final_ll = cm->final_ll, ok;
  fill_contact_matrix(w);
  cm->print = 0, cm->final_ll = 1;  /* a singular K is our message to give */
  if (!pd->L) pd->L = cholmod_copy_factor(pd->Ls, cm);
  ok = pd->L && cholmod_factorize(&pd->K, pd->L, cm) && cm->status >= CHOLMOD_OK;
  cm->print = print, cm->final_ll = final_ll;
  if (!ok || pd->L->minor < pd->L->n) {
    cholmod_free_factor(&pd->L, cm);     /* the next starts from Ls */
    return ok ? SINGULAR
              : pdas_cholmod_failed(cm, "pdas: CHOLMOD failed to factorise", st);
  }
  read_trailing_block(w);
  schur_complement(w);
  int code = condensed_load(w, st);
  pd->condensed = !code;
  return code;
}

#line 695 "paper/pdas.nw"
/* y = lo on the active set, the solution of the Newton system off it */
static int pdas_newton_step(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  int nk = w->nk, m = 0;
  const double *lo = w->pos;
  
#line 718 "paper/pdas.nw"
for (int c = 0; c < nk; c++)
  if (pd->act[c] == HELD) pd->y[c] = lo[c];
  else pd->fr[m++] = c;
for (int a = 0; a < m; a++) {
  int c0 = pd->fr[a];
  const double *Sa = pd->S + (size_t) c0 * nk;
  double s = pd->f[c0] + (pd->act[c0] == FORCE_HI ? w->fhi[c0] : w->flo[c0]);
  for (int c = 0; c < nk; c++) if (pd->act[c] == HELD) s -= Sa[c] * lo[c];
  pd->r[a] = s;
  for (int b = 0; b < m; b++) pd->M[(size_t) a * m + b] = Sa[pd->fr[b]];
}
#line 702 "paper/pdas.nw"
  if (m == 0) return STATUS_OK;
  gsl_matrix_view M = gsl_matrix_view_array(pd->M, m, m);
  gsl_vector_view r = gsl_vector_view_array(pd->r, m);
  if (gsl_linalg_cholesky_decomp1(&M.matrix) || !qp_factor_regular(pd->M, m))
    return SINGULAR;
  gsl_linalg_cholesky_svx(&M.matrix, &r.vector);
  for (int a = 0; a < m; a++) pd->y[pd->fr[a]] = pd->r[a];
  return STATUS_OK;
}

#line 800 "paper/pdas.nw"
/* 1 if every tangential unknown is free (and there is one): N = the sum
   of their right-hand sides, noise = the rounding it may carry */
static int slide_imbalance(const Qp_workspace *w, double *N, double *noise)
{
  const Pdas_workspace *pd = &w->pdas;
  double sum = 0, size = 0;
  for (int t = w->nc; t < w->nk; t++) {
    if (pd->act[t] == HELD) return 0;
    const double *St = pd->S + (size_t) t * w->nk;
    double F = pd->act[t] == FORCE_HI ? w->fhi[t] : w->flo[t];
    sum += pd->f[t] + F, size += fabs(pd->f[t]) + fabs(F);
    for (int c = 0; c < w->nk; c++)
      if (pd->act[c] == HELD)
        sum -= St[c] * w->pos[c], size += fabs(St[c] * w->pos[c]);
  }
  *N = sum, *noise = (w->nk + 2) * DBL_EPSILON * size;
  return w->nk > w->nc;
}
#line 822 "paper/pdas.nw"
/* the free tangential unknown with an interval, its force of the sign of
   push (any if push is 0), that slides least: the first within TIE of
   the least; -1 if none */
static int least_slide(const Qp_workspace *w, int push)
{
  const double TIE = 1e-6;
  const Pdas_workspace *pd = &w->pdas;
  int least = -1;
  for (int t = w->nc; t < w->nk; t++) {
    double F = pd->act[t] == FORCE_HI ? w->fhi[t] : w->flo[t];
    if (pd->act[t] == HELD || !(w->fhi[t] > w->flo[t]) || (push && !(F * push > 0)))
      continue;
    double slide = fabs(pd->y[t] - w->pos[t]);
    if (least < 0 || slide < (1 - TIE) * fabs(pd->y[least] - w->pos[least]))
      least = t;
  }
  return least;
}

#line 781 "paper/pdas.nw"
/* where every tangential unknown is free, hold those that stop first
   as the net force N pushes the body; 1 if it held any */
static int hold_stopping(Qp_workspace *w)
{
  double N, noise, absorbed = 0;
  int t, held = 0;
  if (!slide_imbalance(w, &N, &noise)) return 0;
  int push = fabs(N) <= noise ? 0 : N > 0 ? 1 : -1;
  while ((t = least_slide(w, push)) >= 0) {
    w->pdas.act[t] = HELD, held++;
    if ((absorbed += 2 * w->fhi[t]) >= fabs(N) - noise) break;
  }
  return held > 0;
}

#line 859 "paper/pdas.nw"
static void condensed_forces(Qp_workspace *w)
{
  const Pdas_workspace *pd = &w->pdas;
  for (int c = 0; c < w->nk; c++) {
    const double *Sc = pd->S + (size_t) c * w->nk;
    double s = -pd->f[c];
    for (int e = 0; e < w->nk; e++) s += Sc[e] * pd->y[e];
    w->T[c] = s;
  }
}

#line 873 "paper/pdas.nw"
static double condensed_kkt(const Qp_workspace *w)
{
  const Pdas_workspace *pd = &w->pdas;
  double tn = 0, inf = 0, comp = 0, axax = pd->bu2, bb = pd->bu2, yy = 0, ll = 0;
  
#line 885 "paper/pdas.nw"
for (int c = 0; c < w->nk; c++) {
  double T = w->T[c], bc = w->qp->b[w->ik[c]];
  if (c < w->nc) {
    double gap = pd->y[c] - w->pos[c];
    if (T < 0) tn += T * T;
    if (gap < 0) inf += gap * gap;
    comp += fabs(T) * fabs(gap);
    ll += w->pos[c] * w->pos[c];
  } else
    qp_slip_terms(w->fhi[c], T, pd->y[c], &tn, &comp);
  bb += bc * bc, axax += (bc + T) * (bc + T);
  yy += pd->y[c] * pd->y[c];
}
#line 878 "paper/pdas.nw"
  double sf = sqrt(bb) + sqrt(axax), su = sqrt(yy) + sqrt(ll);
  double rho = w->gamma * (w->normA * sqrt(yy) + sqrt(bb));
  return qp_kkt_combine(0, sqrt(tn), sqrt(inf), comp, sf, su, rho, w->gamma);
}

#line 907 "paper/pdas.nw"
/* the state of c that y and T call for: with z = T_c + A_ii (pos_c - y_c),
   held where flo_c < z <= fhi_c, at the force flo_c or fhi_c beyond; an
   interval of width 0 (no friction) always gives its one force; after a
   Newton step, a slide that crossed its place sticks first */
static char predicted_state(const Qp_workspace *w, int c)
{
  const Pdas_workspace *pd = &w->pdas;
  if (pd->stepped && pd->act[c] != HELD && w->fhi[c] < INFINITY
      && w->flo[c] != w->fhi[c])
    return pd->act[c] == FORCE_LO ? (pd->y[c] < w->pos[c] ? HELD : FORCE_LO)
                                  : (pd->y[c] > w->pos[c] ? HELD : FORCE_HI);
  double z = w->T[c] + w->d[w->ik[c]] * (w->pos[c] - pd->y[c]);
  if (z <= w->flo[c] || w->flo[c] == w->fhi[c]) return FORCE_LO;
  return z > w->fhi[c] ? FORCE_HI : HELD;
}

/* act = the states that y and T call for; 1 if none changed */
static int predict_active_set(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  int same = 1;
  for (int c = 0; c < w->nk; c++) {
    char a = predicted_state(w, c);
    same &= a == pd->act[c];
    pd->act[c] = a;
  }
  return same;
}

/* y from x, T = S y - f, and the states they call for (no Newton step
   behind them): the guess of a warm start */
static void states_at_x(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  for (int c = 0; c < w->nk; c++) pd->y[c] = w->x[w->ik[c]];
  condensed_forces(w);
  pd->stepped = 0;
  predict_active_set(w);
  pd->stepped = 1;
}

#line 968 "paper/pdas.nw"
static int expand(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  double *v = pd->rhs->x;
  memcpy(v, pd->Lb->x, (size_t) w->n * sizeof *v);
  for (int t = 0; t < w->nk; t++) {
    double s = 0;
    for (int u = t; u < w->nk; u++)
      s += pd->Lcc[(size_t) u * w->nk + t] * pd->y[pd->tc[u]];
    v[pd->first + t] = s;
  }
  if (solve_pair(w, CHOLMOD_Lt, CHOLMOD_Pt, &pd->rhs, st)) return st->code;
  memcpy(w->x, pd->rhs->x, (size_t) w->n * sizeof *w->x);
  for (int c = 0; c < w->nk; c++) w->x[w->ik[c]] = pd->y[c];
  qp_refresh(w);
  return STATUS_OK;
}

#line 993 "paper/pdas.nw"
static int refine(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  double *v = pd->rhs->x;
  for (int i = 0; i < w->n; i++) v[i] = w->bnd[i] < 0 ? -w->g[i] : 0;
  if (solve_pair(w, CHOLMOD_P, CHOLMOD_L, &pd->rhs, st)) return st->code;
  v = pd->rhs->x;
  memset(v + pd->first, 0, (size_t) w->nk * sizeof *v);
  if (solve_pair(w, CHOLMOD_Lt, CHOLMOD_Pt, &pd->rhs, st)) return st->code;
  v = pd->rhs->x;
  for (int i = 0; i < w->n; i++) if (w->bnd[i] < 0) w->x[i] += v[i];
  qp_refresh(w);
  return STATUS_OK;
}

#line 1033 "paper/pdas.nw"
/* c has an interval of positive width for its force: a slip bound */
static int slips(const Qp_workspace *w, int c)
{
  return c >= w->nc && w->fhi[c] > w->flo[c];
}

/* s, t (and b) from (y, T) shifted inside by 1.5 times the largest
   violation, as forces; 0 when there is none (or a value is not finite) */
static int guide_start(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Pdas_guide *ip = &pd->ip;
  int nk = w->nk;
  double worst = 0;
  for (int c = 0; c < nk; c++) {
    double gap = w->d[w->ik[c]] * (pd->y[c] - w->pos[c]);   /* as a force */
    worst = c < w->nc ? fmax(worst, fmax(-gap, -w->T[c]))
          : fmax(worst, fmax(w->T[c] - w->fhi[c], w->flo[c] - w->T[c]));
  }
  double delta = 1.5 * worst;
  if (!(delta > 0 && isfinite(delta))) return 0;
  for (int c = 0; c < nk; c++) {
    const double *Sc = pd->S + (size_t) c * nk;
    double h = -pd->f[c], slide = pd->y[c] - w->pos[c];
    for (int e = 0; e < nk; e++) h += Sc[e] * w->pos[e];
    ip->h[c] = h, ip->b[c] = 0;
    if (c < w->nc) {
      ip->s[c] = slide + delta / w->d[w->ik[c]];
      ip->t[c] = w->T[c] + delta;
      if (!(ip->s[c] > 0 && ip->t[c] > 0)) return 0;
    } else if (!slips(w, c)) {
      ip->s[c] = slide, ip->t[c] = w->flo[c];
    } else {
      
#line 1081 "paper/pdas.nw"
double quarter = 0.25 * (w->fhi[c] - w->flo[c]);
ip->s[c] = fmax(slide, 0) + delta / w->d[w->ik[c]];
ip->b[c] = fmax(-slide, 0) + delta / w->d[w->ik[c]];
ip->t[c] = fmin(fmax(w->T[c], w->flo[c] + quarter), w->fhi[c] - quarter);
if (!(ip->s[c] > 0 && ip->b[c] > 0 && isfinite(ip->t[c]))) return 0;
#line 1067 "paper/pdas.nw"
    }
  }
  memcpy(ip->pred, pd->act, (size_t) nk);   /* its first prediction */
  ip->state = GUIDE_ON;
  return 1;
}

#line 1127 "paper/pdas.nw"
/* e_s and e_b of a slipping unknown c, and its u, v and D */
static void slip_pair(const Qp_workspace *w, int c, double sm, const double *cs,
                      const double *ct, const double *cb, double *es,
                      double *eb, double *u, double *v, double *D)
{
  const Pdas_guide *ip = &w->pdas.ip;
  *u = ip->t[c] - w->flo[c], *v = w->fhi[c] - ip->t[c];
  *es = sm - ip->s[c] * *u - (cs ? cs[c] * ct[c] : 0);
  *eb = sm - ip->b[c] * *v + (cs ? cb[c] * ct[c] : 0);
  *D = 1 / (ip->s[c] / *u + ip->b[c] / *v);
}

/* the largest alpha in (0, 1] that keeps the gaps and slides (primal)
   or the forces' distances to their ends (dual) >= 0 along the step */
static double guide_to_bound(const Qp_workspace *w, const double *ds,
                             const double *dt, const double *db, int dual)
{
  const Pdas_guide *ip = &w->pdas.ip;
  double a = 1;
  for (int c = 0; c < w->nk; c++) {
    if (c >= w->nc && !slips(w, c)) continue;
    if (!dual) {
      if (ds[c] < 0) a = fmin(a, -ip->s[c] / ds[c]);
      if (c >= w->nc && db[c] < 0) a = fmin(a, -ip->b[c] / db[c]);
    } else if (c < w->nc) {
      if (dt[c] < 0) a = fmin(a, -ip->t[c] / dt[c]);
    } else {
      if (dt[c] < 0) a = fmin(a, -(ip->t[c] - w->flo[c]) / dt[c]);
      if (dt[c] > 0) a = fmin(a, (w->fhi[c] - ip->t[c]) / dt[c]);
    }
  }
  return a;
}

/* ds = (S + D)^-1 (-r + D E), dt and db from it; M holds the factor of
   S + D; the corrections from (cs, ct, cb), or 0 when cs is NULL */
static void guide_direction(Qp_workspace *w, double sm, const double *cs,
                            const double *ct, const double *cb, double *ds,
                            double *dt, double *db)
{
  Pdas_guide *ip = &w->pdas.ip;
  int nk = w->nk;
  double es, eb, u, v, D;
  for (int c = 0; c < nk; c++) {
    if (c < w->nc) {
      double e = (sm - (cs ? cs[c] * ct[c] : 0)) / ip->s[c];
      ds[c] = -w->pdas.r[c] - ip->t[c] + e, dt[c] = e;
    } else if (!slips(w, c)) ds[c] = -w->pdas.r[c], dt[c] = 0;
    else {
      slip_pair(w, c, sm, cs, ct, cb, &es, &eb, &u, &v, &D);
      dt[c] = es / u - eb / v;                     /* E, for now */
      ds[c] = -w->pdas.r[c] + D * dt[c];
    }
  }
  gsl_matrix_view M = gsl_matrix_view_array(w->pdas.M, nk, nk);
  gsl_vector_view x = gsl_vector_view_array(ds, nk);
  gsl_linalg_cholesky_svx(&M.matrix, &x.vector);
  for (int c = 0; c < nk; c++) {
    db[c] = 0;
    if (c < w->nc) dt[c] += -ip->t[c] - ip->t[c] / ip->s[c] * ds[c];
    else if (slips(w, c)) {
      slip_pair(w, c, sm, cs, ct, cb, &es, &eb, &u, &v, &D);
      dt[c] = D * (dt[c] - ds[c]);
      ds[c] = (es - ip->s[c] * dt[c]) / u, db[c] = (eb + ip->b[c] * dt[c]) / v;
    }
  }
}

/* the sum of the complementarity products at (s, t, b) + alpha (ds, dt, db)
   (alpha_p for the slides, alpha_d for the forces; at (s, t, b) when ds
   is NULL), and their number */
static double guide_products(const Qp_workspace *w, double ap, double ad,
                             const double *ds, const double *dt,
                             const double *db, int *pairs)
{
  const Pdas_guide *ip = &w->pdas.ip;
  double sum = 0;
  *pairs = 0;
  for (int c = 0; c < w->nk; c++) {
    double s = ds ? ip->s[c] + ap * ds[c] : ip->s[c];
    double t = ds ? ip->t[c] + ad * dt[c] : ip->t[c];
    double b = ds ? ip->b[c] + ap * db[c] : ip->b[c];
    if (c < w->nc) sum += s * t, ++*pairs;
    else if (slips(w, c))
      sum += s * (t - w->flo[c]) + b * (w->fhi[c] - t),
      *pairs += 2;
  }
  return sum;
}

/* one step; nonzero when the factorisation fails or the new point is not
   strictly inside */
static int guide_step(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Pdas_guide *ip = &pd->ip;
  int nk = w->nk, pairs;
  double es, eb, u, v, D;
  for (int c = 0; c < nk; c++) {
    const double *Sc = pd->S + (size_t) c * nk;
    double r = ip->h[c] - ip->t[c];
    for (int e = 0; e < nk; e++) r += Sc[e] * (ip->s[e] - ip->b[e]);
    pd->r[c] = r;
    memcpy(pd->M + (size_t) c * nk, Sc, (size_t) nk * sizeof *pd->M);
    if (c < w->nc) pd->M[(size_t) c * nk + c] += ip->t[c] / ip->s[c];
    else if (slips(w, c)) {
      slip_pair(w, c, 0, NULL, NULL, NULL, &es, &eb, &u, &v, &D);
      pd->M[(size_t) c * nk + c] += D;
    }
  }
  double mu = guide_products(w, 0, 0, NULL, NULL, NULL, &pairs) / pairs;
  gsl_matrix_view M = gsl_matrix_view_array(pd->M, nk, nk);
  if (gsl_linalg_cholesky_decomp1(&M.matrix)) return 1;
  guide_direction(w, 0, NULL, NULL, NULL, ip->as, ip->at, ip->ab);
  double ap = guide_to_bound(w, ip->as, ip->at, ip->ab, 0);
  double ad = guide_to_bound(w, ip->as, ip->at, ip->ab, 1);
  double mua = guide_products(w, ap, ad, ip->as, ip->at, ip->ab, &pairs);
  double sigma = pow(mua / pairs / mu, 3);
  guide_direction(w, sigma * mu, ip->as, ip->at, ip->ab, ip->ds, ip->dt, ip->db);
  double a = fmin(1, 0.995 * fmin(guide_to_bound(w, ip->ds, ip->dt, ip->db, 0),
                                  guide_to_bound(w, ip->ds, ip->dt, ip->db, 1)));
  int inside = 1;
  for (int c = 0; c < nk; c++) {
    ip->s[c] += a * ip->ds[c], ip->t[c] += a * ip->dt[c], ip->b[c] += a * ip->db[c];
    inside &= isfinite(ip->s[c] + ip->t[c] + ip->b[c]);
    if (c < w->nc) inside &= ip->s[c] > 0 && ip->t[c] > 0;
    else if (slips(w, c))
      inside &= ip->s[c] > 0 && ip->b[c] > 0 && ip->t[c] > w->flo[c] && ip->t[c] < w->fhi[c];
  }
  return !inside;
}

#line 1267 "paper/pdas.nw"
static void guide(Qp_workspace *w)
{
  Pdas_workspace *pd = &w->pdas;
  Pdas_guide *ip = &pd->ip;
  int nk = w->nk, changed = 0;
  ip->guided = 0;
  if (ip->state == GUIDE_STOPPED) return;
  if (ip->state == GUIDE_OFF && !guide_start(w)) return;
  if (guide_step(w)) { ip->state = GUIDE_STOPPED; return; }
  for (int c = 0; c < nk; c++) {
    double z = ip->t[c] - w->d[w->ik[c]] * (ip->s[c] - ip->b[c]);
    char a = c < w->nc ? (ip->t[c] > w->d[w->ik[c]] * ip->s[c] ? HELD : FORCE_LO)
           : !slips(w, c) || z <= w->flo[c] ? FORCE_LO : z > w->fhi[c] ? FORCE_HI : HELD;
    changed |= a != ip->pred[c];
    ip->pred[c] = a;
  }
  if (!changed) return;
  memcpy(ip->own, pd->act, (size_t) nk);
  memcpy(pd->act, ip->pred, (size_t) nk);
  ip->guided = 1;
}

#line 482 "paper/pdas.nw"
int pdas_iterate(Qp_workspace *w, Status *st)
{
  Pdas_workspace *pd = &w->pdas;
  int code;
  if (!pd->condensed) {
    
#line 510 "paper/pdas.nw"
if ((code = pdas_condense(w, st))) return code;
if (pd->warm) states_at_x(w);
#line 488 "paper/pdas.nw"
  }
  if (w->qp->slides) hold_stopping(w);
  if (w->iter > 0) guide(w);
  if (w->qp->slides && pd->ip.guided) hold_stopping(w);
  if ((code = pdas_newton_step(w)) == SINGULAR && pd->ip.guided) {
    memcpy(pd->act, pd->ip.own, (size_t) w->nk);  /* the guide's set: retake */
    pd->ip.guided = 0;
    code = pdas_newton_step(w);
  }
  if (code == SINGULAR && w->iter == 0 && pd->warm) {
    pdas_set(w, 0), pd->condensed = 1;  /* the guess holds nothing: go cold */
    code = pdas_newton_step(w);
  }
  if (code == SINGULAR)
    return qp_not_held(w, st, "the Newton matrix is singular", count_act(w));
  condensed_forces(w);
  w->kkt = condensed_kkt(w);
  
#line 526 "paper/pdas.nw"
int same = predict_active_set(w), solved = w->kkt <= w->opt.tol;
if (!same && !solved && w->iter + 1 < w->opt.max_iter) return STATUS_OK;
if ((code = expand(w, st))) return code;
if (w->kkt > w->opt.tol && (same || solved) && (code = refine(w, st))) return code;
if (!same || w->kkt <= w->opt.tol) return STATUS_OK;
return status_set(st, STATUS_NUMERIC, "pdas: the active set repeated at "
  "Newton step %d, and its state, refined once, has kkt = %.3g > tol = "
  "%.3g", w->iter + 1, w->kkt, w->opt.tol);
#line 506 "paper/pdas.nw"
}

#line 1297 "paper/pdas.nw"
/* *c = a workspace of the Newton method for qp, w's problem or a part
   of it, condensed at its current values (NULL when it cannot be
   allocated) */
int pdas_condense_apart(const Qp_workspace *w, const Qp *qp,
                        Qp_workspace **c, Status *st)
{
  Qp_options opt = { QP_PDAS, 1, 1, 1 };
  int code;
  if (!(*c = qp_alloc(qp, &opt, w->cm, st))) return st->code;
  code = qp_read_values(*c, st);
  if (!code && (code = condense(*c, st)) == SINGULAR)
    code = status_set(st, STATUS_NUMERIC, "qp_schur: A is singular even "
                      "with every bounded unknown held");
  return code;
}

#line 1316 "paper/pdas.nw"
/* S = the Schur complement of w, its diagonal raised by shift A_ii */
void pdas_schur(const Qp_workspace *w, double shift, double *S)
{
  int nc = w->nk;
  memcpy(S, w->pdas.S, (size_t) nc * nc * sizeof *S);
  for (int k = 0; k < nc; k++) S[(size_t) k * nc + k] += shift * w->d[w->ik[k]];
}
#line 1335 "paper/pdas.nw"
int pdas_schur_friction(const Qp_workspace *w, double shift, double *S,
                        Status *st)
{
  const Pdas_workspace *pd = &w->pdas;
  int nc = w->nc, nk = w->nk, m = 0, code = STATUS_OK;
  int *fr = malloc((size_t) (nk - nc + 1) * sizeof *fr);
  double *SFF = malloc((size_t) (nk - nc) * (nk - nc) * sizeof *SFF + 1);
  double *SFn = malloc((size_t) (nk - nc) * nc * sizeof *SFn + 1);
  if (!fr || !SFF || !SFn) code = status_set(st, STATUS_MEMORY, "qp_schur: out of memory");
  for (int k = nc; !code && k < nk; k++) if (pd->act[k] != HELD) fr[m++] = k;
  
#line 1353 "paper/pdas.nw"
for (int a = 0; !code && a < m; a++) {
  for (int b = 0; b < m; b++) SFF[(size_t) a * m + b] = pd->S[(size_t) fr[a] * nk + fr[b]];
  for (int c = 0; c < nc; c++) SFn[(size_t) a * nc + c] = pd->S[(size_t) fr[a] * nk + c];
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
        double v = pd->S[(size_t) c * nk + e];
        for (int a = 0; a < m; a++) v -= SFn[(size_t) a * nc + c] * SFn[(size_t) a * nc + e];
        S[(size_t) c * nc + e] = v;
      }
  }
} else if (!code)
  for (int c = 0; c < nc; c++)
    memcpy(S + (size_t) c * nc, pd->S + (size_t) c * nk, (size_t) nc * sizeof *S);
for (int k = 0; !code && k < nc; k++) S[(size_t) k * nc + k] += shift * w->d[w->ik[k]];
#line 1346 "paper/pdas.nw"
  free(fr), free(SFF), free(SFn);
  return code;
}
#line 1386 "paper/pdas.nw"
/* S, f and the factor of K at the current values; a singular K is a
   body that nothing holds */
int pdas_condense(Qp_workspace *w, Status *st)
{
  int code = condense(w, st);
  return code != SINGULAR ? code : qp_not_held(w, st,
    "A is singular even with every bound held", w->nc);
}

/* S and f at the current values, and the states that x calls for: for
   qp_schur after a cgssor solve with friction that took no step */
int pdas_condense_states(Qp_workspace *w, Status *st)
{
  int code = pdas_condense(w, st);
  if (!code) states_at_x(w);
  return code;
}

/* the relative KKT residual of y and T = S y - f */
double pdas_condensed_kkt(const Qp_workspace *w) { return condensed_kkt(w); }

/* the states that the dual's (y, T) call for, by the Newton method's own
   prediction (for qp_schur), then x from y by back substitution, refined
   once if kkt > tol; kkt and T recomputed at x */
int pdas_expand(Qp_workspace *w, Status *st)
{
  w->pdas.stepped = 0;
  predict_active_set(w);
  w->pdas.stepped = 1;
  int code = expand(w, st);
  if (!code && w->kkt > w->opt.tol) code = refine(w, st);
  return code;
}
