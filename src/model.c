#line 47 "paper/model.nw"
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "model.h"

#line 58 "paper/model.nw"
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
  
#line 77 "paper/model.nw"
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
#line 71 "paper/model.nw"
  
#line 90 "paper/model.nw"
md->qp = (Qp) { md->A, md->b, nc, md->dofs->contact, md->lo };
Qp_options opt = { s->state, s->tol, s->max_iter, s->omega };
if (!(md->solver = qp_alloc(&md->qp, &opt, cm, st))) {
  model_free(md);
  return NULL;
}
#line 72 "paper/model.nw"
  return md;
}
#line 102 "paper/model.nw"
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
