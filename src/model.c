#line 55 "paper/model.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_blas.h>
#include "model.h"

#line 68 "paper/model.nw"
Model *model_new(const Scene *s, cholmod_common *cm, Status *st)
{
  Model *md = calloc(1, sizeof *md);
  if (!md) { status_set(st, STATUS_SYSTEM, "model: out of memory"); return NULL; }
  md->scene = s;
  md->cm = cm;
  md->hooke = fem_hooke(s);
  if (!(md->mesh = mesh_new(s, st)) || !(md->dofs = fem_dofs_new(md->mesh, s, st))
      || !(md->A = fem_stiffness_new(md->mesh, md->dofs, cm, st))) {
    model_free(md);
    return NULL;
  }
  
#line 87 "paper/model.nw"
int n = md->dofs->n, nc = md->dofs->nc;
md->b = malloc(n * sizeof *md->b);
md->Q = calloc(n, sizeof *md->Q);
md->lo = malloc((nc ? nc : 1) * sizeof *md->lo);
md->T = calloc(nc ? nc : 1, sizeof *md->T);
if (!md->b || !md->Q || !md->lo || !md->T) {
  model_free(md);
  status_set(st, STATUS_SYSTEM, "model: out of memory for %d unknowns", n);
  return NULL;
}
#line 81 "paper/model.nw"
  
#line 100 "paper/model.nw"
md->qp = (Qp) { md->A, md->b, nc, md->dofs->contact, md->lo };
Qp_options opt = { s->state, s->tol, s->max_iter, s->omega };
if (!(md->solver = qp_alloc(&md->qp, &opt, cm, st))) {
  model_free(md);
  return NULL;
}
#line 82 "paper/model.nw"
  return md;
}
#line 112 "paper/model.nw"
static double model_clock(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

int model_solve(Model *md, const double *X, Status *st)
{
  double start = model_clock();
  int rc;
  if ((rc = mesh_move(md->mesh, X, st))
      || (rc = fem_stiffness_fill(md->A, md->mesh, md->dofs, &md->hooke, st)))
    return rc;
  fem_load(md->mesh, md->dofs, md->scene, md->b);
  for (int c = 0; c < md->dofs->nc; c++) md->lo[c] = -X[md->dofs->contact_col[c]];
  rc = qp_solve(md->solver, md->solved ? md->Q : NULL, md->Q, md->T,
                &md->report, st);
  md->solved = rc == STATUS_OK;
  md->energy = fem_energy(md->A, md->b, md->Q);
  md->seconds = model_clock() - start;
  return rc;
}

#line 145 "paper/model.nw"
static double model_tributary(const Mesh *m, int i)
{
  double len = 0;
  for (int k = i - 1; k <= i; k++)
    if (k >= 0 && k < m->N)
      len += 0.5 * hypot(m->xy[2 * (k + 1)] - m->xy[2 * k],
                         m->xy[2 * (k + 1) + 1] - m->xy[2 * k + 1]);
  return len;
}

double model_pressure(const Model *md, int c)
{
  return md->T[c] / model_tributary(md->mesh, md->dofs->contact_col[c]);
}

double model_pressure_cv(const Model *md)
{
  double sum = 0, sum2 = 0;
  int count = 0;
  for (int c = 0; c < md->dofs->nc; c++)
    if (md->Q[md->dofs->contact[c]] <= md->lo[c] && md->T[c] > 0) {
      double p = model_pressure(md, c);
      sum += p; sum2 += p * p; count++;
    }
  if (count == 0) return 0;                  /* no contact, no spread */
  double mean = sum / count, var = fmax(sum2 / count - mean * mean, 0);
  return sqrt(var) / mean;
}

void model_free(Model *md)
{
  if (!md) return;
  qp_free(md->solver);
  cholmod_free_sparse(&md->A, md->cm);
  mesh_free(md->mesh);
  fem_dofs_free(md->dofs);
  free(md->b); free(md->Q); free(md->lo); free(md->T);
  free(md);
}
#line 212 "paper/model.nw"
/* the lower triangle of A, contact diagonals raised by 1e-6 of themselves,
   ordered by CAMD with the contact unknowns last, and factorised */
static cholmod_factor *contact_last_factor(Model *md, Status *st)
{
  cholmod_common *cm = md->cm;
  const Dofs *d = md->dofs;
  int n = d->n, *member = calloc(n, sizeof *member), *perm = malloc(n * sizeof *perm);
  cholmod_sparse *K = cholmod_copy(md->A, -1, 1, cm);
  cholmod_factor *L = NULL;
  if (member && perm && K) {
    const int *Kp = K->p, *Ki = K->i;
    double *Kx = K->x;
    for (int c = 0; c < d->nc; c++) {
      int j = d->contact[c];
      member[j] = 1;
      for (int k = Kp[j]; k < Kp[j + 1]; k++)
        if (Ki[k] == j) Kx[k] *= 1 + 1e-6;
    }
    
#line 244 "paper/model.nw"
int nmethods = cm->nmethods, ordering = cm->method[0].ordering;
int postorder = cm->postorder, print = cm->print;
cm->nmethods = 1, cm->method[0].ordering = CHOLMOD_GIVEN, cm->postorder = 0;
cm->print = 0;
if (cholmod_camd(K, NULL, 0, member, perm, cm)
    && (L = cholmod_analyze_p(K, perm, NULL, 0, cm))
    && !(cholmod_factorize(K, L, cm) && L->minor == (size_t) n
         && cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, L, cm)))
  cholmod_free_factor(&L, cm);
cm->nmethods = nmethods, cm->method[0].ordering = ordering;
cm->postorder = postorder, cm->print = print;
#line 231 "paper/model.nw"
  }
  if (!L) status_set(st, STATUS_NUMERIC, "contact stiffness: CHOLMOD could not "
                     "factorise A (CHOLMOD status %d)", cm->status);
  cholmod_free_sparse(&K, cm);
  free(member); free(perm);
  return L;
}
#line 260 "paper/model.nw"
int model_contact_stiffness(Model *md, double *S, Status *st)
{
  const Dofs *d = md->dofs;
  int n = d->n, nc = d->nc, N1 = md->scene->N + 1, first = n - nc;
  if (nc == 0)                         /* every contact node held: nothing to see */
    return status_set(st, STATUS_INPUT, "contact stiffness: no contact node is "
                      "free to move; use optimizer.metric = euclidean");
  cholmod_factor *L = contact_last_factor(md, st);
  if (!L) return st->code;
  gsl_matrix *Lcc = gsl_matrix_calloc(nc, nc), *Scc = gsl_matrix_alloc(nc, nc);
  int *col = malloc((n + 1) * sizeof *col), rc = STATUS_OK;
  if (!Lcc || !Scc || !col) rc = status_set(st, STATUS_SYSTEM, "contact stiffness: out of memory");
  else {
    
#line 282 "paper/model.nw"
for (int k = 0; k < n; k++) col[k] = -1;
for (int c = 0; c < nc; c++) col[d->contact[c]] = d->contact_col[c];
int ok = 1;
for (int k = first; k < n; k++) {
  const int *Lp = L->p, *Li = L->i, *perm = L->Perm;
  const double *Lx = L->x;
  ok = ok && col[perm[k]] >= 0;          /* CAMD kept the contact unknowns last */
  for (int q = Lp[k]; q < Lp[k + 1]; q++) gsl_matrix_set(Lcc, Li[q] - first, k - first, Lx[q]);
}
if (!ok)
  rc = status_set(st, STATUS_SYSTEM, "contact stiffness: the ordering did "
                  "not put the contact unknowns last");
else
  
#line 299 "paper/model.nw"
{
  const int *perm = L->Perm;
  gsl_blas_dsyrk(CblasLower, CblasNoTrans, 1.0, Lcc, 0.0, Scc);
  double mean = 0;
  for (int k = 0; k < nc; k++) mean += gsl_matrix_get(Scc, k, k) / nc;
  memset(S, 0, (size_t) N1 * N1 * sizeof *S);
  for (int i = 0; i < N1; i++) S[(size_t) i * N1 + i] = mean;
  for (int k = 0; k < nc; k++)
    for (int l = 0; l <= k; l++) {
      int i = col[perm[first + k]], j = col[perm[first + l]];
      S[(size_t) i * N1 + j] = S[(size_t) j * N1 + i] = gsl_matrix_get(Scc, k, l);
    }
}
#line 274 "paper/model.nw"
  }
  cholmod_free_factor(&L, md->cm);
  gsl_matrix_free(Lcc); gsl_matrix_free(Scc); free(col);
  return rc;
}
