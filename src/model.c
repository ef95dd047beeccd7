#line 127 "paper/model.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "model.h"

#line 137 "paper/model.nw"
Model *model_new(const Problem *p, const Qp_options *solver,
                 cholmod_common *cm, Status *st)
{
  Model *md = calloc(1, sizeof *md);
  if (!md) { status_set(st, STATUS_SYSTEM, "model: out of memory"); return NULL; }
  md->problem = p;
  md->cm = cm;
  md->hooke = fem_hooke(p);
  if (!(md->mesh = mesh_new(p, st)) || !(md->dofs = fem_dofs_new(md->mesh, p, st))
      || !(md->A = fem_stiffness_new(md->mesh, md->dofs, cm, st))) {
    model_free(md);
    return NULL;
  }
  
#line 157 "paper/model.nw"
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
#line 151 "paper/model.nw"
  
#line 170 "paper/model.nw"
md->qp = (Qp) { md->A, md->b, nc, md->dofs->contact, md->lo };
if (!(md->solver = qp_alloc(&md->qp, solver, cm, st))) {
  model_free(md);
  return NULL;
}
#line 152 "paper/model.nw"
  return md;
}
#line 183 "paper/model.nw"
double model_clock(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

#line 193 "paper/model.nw"
int model_solve(Model *md, const double *X, Status *st)
{
  double start = model_clock();
  int rc;
  if ((rc = mesh_move(md->mesh, X, st))
      || (rc = fem_stiffness_fill(md->A, md->mesh, md->dofs, &md->hooke, st)))
    return rc;
  fem_load(md->mesh, md->dofs, md->problem, md->b);
  for (int c = 0; c < md->dofs->nc; c++) md->lo[c] = -X[md->dofs->contact_col[c]];
  rc = qp_solve(md->solver, md->solved ? md->Q : NULL, md->Q, md->T,
                &md->report, st);
  md->solved = rc == STATUS_OK;
  md->energy = fem_energy(md->mesh, md->dofs, &md->hooke, md->b, md->Q);
  md->seconds = model_clock() - start;
  return rc;
}

#line 222 "paper/model.nw"
static double model_tributary(const Mesh *m, int i)
{
  double len = 0;
  for (int k = i - 1; k <= i; k++)
    if (k >= 0 && k < m->N)
      len += 0.5 * hypot(m->xy[2 * (k + 1)] - m->xy[2 * k],
                         m->xy[2 * (k + 1) + 1] - m->xy[2 * k + 1]);
  return len;
}

#line 234 "paper/model.nw"
double model_pressure(const Model *md, int c)
{
  return md->T[c] / model_tributary(md->mesh, md->dofs->contact_col[c]);
}

#line 242 "paper/model.nw"
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

#line 258 "paper/model.nw"
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
#line 295 "paper/model.nw"
int model_contact_stiffness(Model *md, double *S, Status *st)
{
  const Dofs *d = md->dofs;
  int nc = d->nc, N1 = md->problem->N + 1, rc;
  if (nc == 0)                         /* every contact node held: nothing to see */
    return status_set(st, STATUS_INPUT, "contact stiffness: no contact node is "
                      "free to move; use optimizer.metric = euclidean");
  double *Scc = malloc((size_t) nc * nc * sizeof *Scc), mean = 0;
  if (!Scc) return status_set(st, STATUS_SYSTEM, "contact stiffness: out of memory");
  if ((rc = qp_schur(md->solver, 1e-6, Scc, st))) { free(Scc); return rc; }
  for (int c = 0; c < nc; c++) mean += Scc[(size_t) c * nc + c] / nc;
  
#line 314 "paper/model.nw"
memset(S, 0, (size_t) N1 * N1 * sizeof *S);
for (int i = 0; i < N1; i++) S[(size_t) i * N1 + i] = mean;
for (int c = 0; c < nc; c++)
  for (int e = 0; e < nc; e++)
    S[(size_t) d->contact_col[c] * N1 + d->contact_col[e]] = Scc[(size_t) c * nc + e];
#line 307 "paper/model.nw"
  free(Scc);
  return STATUS_OK;
}
