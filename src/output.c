#line 171 "paper/output.nw"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "output.h"

#line 212 "paper/output.nw"
static int output_mkdirs(const char *path, Status *st)
{
  char p[1200];
  snprintf(p, sizeof p, "%s", path);
  for (char *s = p + 1; ; s++)
    if (*s == '/' || *s == '\0') {
      char c = *s;
      *s = '\0';
      if (mkdir(p, 0777) && errno != EEXIST)
        return status_set(st, STATUS_SYSTEM, "%s: cannot create: %s", p,
                          strerror(errno));
      if (!(*s = c)) return STATUS_OK;
    }
}

int output_begin(Output *o, const char *dir, Status *st)
{
  memset(o, 0, sizeof *o);
  snprintf(o->dir, sizeof o->dir, "%s", dir);
  snprintf(o->stage, sizeof o->stage, "%s.partial-%ld", dir, (long) getpid());
  return output_mkdirs(o->stage, st);
}
#line 239 "paper/output.nw"
void output_default_dir(const char *scene, const char *suffix, char *dir,
                        size_t size)
{
  const char *base = strrchr(scene, '/');
  base = base ? base + 1 : scene;
  size_t len = strlen(base);
  if (len > 6 && !strcmp(base + len - 6, ".scene")) len -= 6;
  snprintf(dir, size, "out/%.*s%s", (int) len, base, suffix);
}
#line 252 "paper/output.nw"
FILE *output_open(Output *o, const char *name, Status *st)
{
  char path[1300];
  if (o->nfiles == OUTPUT_MAX_FILES) {
    status_set(st, STATUS_SYSTEM, "%s: too many output files", o->dir);
    return NULL;
  }
  snprintf(o->file[o->nfiles], sizeof o->file[0], "%s", name);
  snprintf(path, sizeof path, "%s/%s", o->stage, name);
  char *slash = strrchr(path, '/');
  *slash = '\0';
  if (output_mkdirs(path, st)) return NULL;
  *slash = '/';
  FILE *f = fopen(path, "w");
  if (!f) status_set(st, STATUS_SYSTEM, "%s: cannot write: %s", path,
                     strerror(errno));
  else o->nfiles++;
  return f;
}

int output_close(Output *o, FILE *f, Status *st)
{
  int bad = ferror(f);
  if (fclose(f) || bad)
    return status_set(st, STATUS_SYSTEM, "%s/%s: write failed", o->dir,
                      o->file[o->nfiles - 1]);
  return STATUS_OK;
}
#line 285 "paper/output.nw"
static void output_remove_stage(Output *o, int unlink_files)
{
  char path[1300];
  for (int k = o->nfiles - 1; k >= 0; k--) {
    snprintf(path, sizeof path, "%s/%s", o->stage, o->file[k]);
    if (unlink_files) unlink(path);
    for (char *s; (s = strrchr(path, '/')) && s > path + strlen(o->stage); ) {
      *s = '\0';
      rmdir(path);
    }
  }
  rmdir(o->stage);
}

int output_commit(Output *o, Status *st)
{
  char from[1300], to[1300];
  for (int k = 0; k < o->nfiles; k++) {
    snprintf(from, sizeof from, "%s/%s", o->stage, o->file[k]);
    snprintf(to, sizeof to, "%s/%s", o->dir, o->file[k]);
    *strrchr(to, '/') = '\0';
    if (output_mkdirs(to, st)) { output_abort(o); return st ? st->code : 1; }
    snprintf(to, sizeof to, "%s/%s", o->dir, o->file[k]);
    if (rename(from, to)) {
      status_set(st, STATUS_SYSTEM, "%s: cannot move into place: %s", to,
                 strerror(errno));
      output_abort(o);
      return STATUS_SYSTEM;
    }
  }
  output_remove_stage(o, 0);
  return STATUS_OK;
}

void output_abort(Output *o) { output_remove_stage(o, 1); }
#line 324 "paper/output.nw"
int output_end(Output *o, int rc, Status *st)
{
  if (rc) output_abort(o);
  return rc ? rc : output_commit(o, st);
}
#line 337 "paper/output.nw"
static double output_u(const Model *md, int node, int c)
{
  int k = md->dofs->unknown[2 * node + c];
  return k < 0 ? 0.0 : md->Q[k];
}
#line 346 "paper/output.nw"
static FILE *output_open_in(Output *o, const char *sub, const char *name,
                            Status *st)
{
  char path[256];
  snprintf(path, sizeof path, "%s%s%s", sub, *sub ? "/" : "", name);
  return output_open(o, path, st);
}
#line 356 "paper/output.nw"
static int output_shape(Output *o, const char *sub, const Model *md,
                        const double *X, Status *st)
{
  FILE *f = output_open_in(o, sub, "shape.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m]\n");
  for (int i = 0; i < md->mesh->ncol; i++)
    fprintf(f, "%.10g %.15g\n", md->mesh->xy[2 * i], X[i]);
  return output_close(o, f, st);
}
#line 369 "paper/output.nw"
static int output_contact(Output *o, const char *sub, const Model *md,
                          const double *X, Status *st)
{
  const Dofs *d = md->dofs;
  FILE *f = output_open_in(o, sub, "contact.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa]%s\n",
          d->nt ? " u1[m] Tt[N/m]" : "");
  for (int c = 0, k = 0; c < d->nc; c++) {
    int i = d->contact_col[c];
    double u2 = md->Q[d->contact[c]];
    fprintf(f, "%.10g %.15g %.15g %.15g %.15g %.15g", md->mesh->xy[2 * i],
            X[i], u2, u2 + X[i], md->T[c],
            model_pressure(md, c));
    
#line 393 "paper/output.nw"
if (d->nt) {
  while (k < d->nt && d->tangent_col[k] < i) k++;
  int here = k < d->nt && d->tangent_col[k] == i;
  fprintf(f, " %.15g %.15g", here ? md->Q[d->tangent[k]] : 0.0,
          here ? md->T[d->nc + k] : 0.0);
}
#line 384 "paper/output.nw"
    fputc('\n', f);
  }
  return output_close(o, f, st);
}
#line 402 "paper/output.nw"
static int output_nodes(Output *o, const char *sub, const Model *md,
                        Status *st)
{
  const Mesh *m = md->mesh;
  FILE *f = output_open_in(o, sub, "nodes.dat", st);
  if (!f) return st->code;
  fprintf(f, "# node column row x1[m] x2[m] u1[m] u2[m]\n");
  for (int k = 0; k < m->nnodes; k++)
    fprintf(f, "%d %d %d %.15g %.15g %.15g %.15g\n", k, k % m->ncol,
            k / m->ncol, m->xy[2 * k], m->xy[2 * k + 1], output_u(md, k, 0),
            output_u(md, k, 1));
  return output_close(o, f, st);
}
#line 418 "paper/output.nw"
static int output_triangles(Output *o, const char *sub, const Model *md,
                            Status *st)
{
  const Mesh *m = md->mesh;
  FILE *f = output_open_in(o, sub, "triangles.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] x2[m] u1[m] u2[m]: each triangle closed, blank-separated\n");
  for (int t = 0; t < m->ntri; t++) {
    for (int v = 0; v <= 3; v++) {
      int k = m->tri[3 * t + v % 3];
      fprintf(f, "%.15g %.15g %.15g %.15g\n", m->xy[2 * k], m->xy[2 * k + 1],
              output_u(md, k, 0), output_u(md, k, 1));
    }
    fprintf(f, "\n");
  }
  return output_close(o, f, st);
}
#line 477 "paper/output.nw"
static void output_vtu_friction(FILE *f, const Model *md)
{
  const Dofs *d = md->dofs;
  fprintf(f, "<DataArray type=\"Float64\" Name=\"tangential_force\" "
             "format=\"ascii\">\n");
  for (int node = 0, k = 0; node < md->mesh->nnodes; node++) {
    int here = k < d->nt && d->tangent_col[k] == node;  /* row 0 first */
    fprintf(f, "%.15g\n", here ? md->T[d->nc + k] : 0.0);
    k += here;
  }
  fprintf(f, "</DataArray>\n");
}
#line 439 "paper/output.nw"
static int output_vtu(Output *o, const char *sub, const Model *md, Status *st)
{
  const Mesh *m = md->mesh;
  FILE *f = output_open_in(o, sub, "solution.vtu", st);
  if (!f) return st->code;
  fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
             "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
             "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n"
             "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
          m->nnodes, m->ntri);
  for (int k = 0; k < m->nnodes; k++)
    fprintf(f, "%.15g %.15g 0\n", m->xy[2 * k], m->xy[2 * k + 1]);
  fprintf(f, "</DataArray>\n</Points>\n<Cells>\n"
             "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
  for (int t = 0; t < m->ntri; t++)
    fprintf(f, "%d %d %d\n", m->tri[3 * t], m->tri[3 * t + 1], m->tri[3 * t + 2]);
  
#line 461 "paper/output.nw"
fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
for (int t = 0; t < m->ntri; t++) fprintf(f, "%d\n", 3 * (t + 1));
fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
for (int t = 0; t < m->ntri; t++) fprintf(f, "5\n");
fprintf(f, "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n"
           "<DataArray type=\"Float64\" Name=\"displacement\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n");
for (int k = 0; k < m->nnodes; k++)
  fprintf(f, "%.15g %.15g 0\n", output_u(md, k, 0), output_u(md, k, 1));
fprintf(f, "</DataArray>\n");
if (md->dofs->nt) output_vtu_friction(f, md);
fprintf(f, "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
#line 456 "paper/output.nw"
  return output_close(o, f, st);
}
#line 492 "paper/output.nw"
int output_state(Output *o, const char *sub, const Model *md,
                 const double *X, Status *st)
{
  int rc;
  if ((rc = output_shape(o, sub, md, X, st))
      || (rc = output_contact(o, sub, md, X, st))
      || (rc = output_nodes(o, sub, md, st))
      || (rc = output_triangles(o, sub, md, st))
      || (rc = output_vtu(o, sub, md, st)))
    return rc;
  return STATUS_OK;
}
#line 536 "paper/output.nw"
static void output_friction(FILE *f, const Model *md)
{
  const Problem *p = md->problem;
  if (p->contact == CONTACT_FRICTIONLESS) return;
  fprintf(f, "contact %s\n", problem_contact_name(p->contact));
  if (p->contact == CONTACT_TRESCA) fprintf(f, "slip_bound %.17g\n", p->slip_bound);
  else fprintf(f, "friction %.17g\n", p->friction);
  fprintf(f, "friction_energy %.15g\n", md->friction_energy);
  if (p->contact == CONTACT_COULOMB)
    fprintf(f, "fixed_point_iterations %d\nfixed_point_residual %.3e\n",
            md->fixed_point_iterations, md->fixed_point_residual);
}
#line 512 "paper/output.nw"
int output_solve(Output *o, const Output_run *run, const Model *md,
                 const double *X, Status *st)
{
  const Problem *p = md->problem;
  int rc = output_state(o, "", md, X, st);
  FILE *f = rc ? NULL : output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\n");
  fprintf(f, "scene %s\nstate_solver %s\nmodel %s\n", run->scene,
          run->state_solver, problem_model_name(p->model));
  fprintf(f, "N %d\nM %d\nR %d\ntriangles %d\ndofs %d\ncontact_nodes %d\n",
          p->N, p->M, p->R, md->mesh->ntri, md->dofs->n, md->dofs->nc);
  fprintf(f, "energy %.15g\nkkt_residual %.3e\niterations %d\n", md->energy,
          md->report.kkt, md->report.iterations);
  fprintf(f, "active_contact_nodes %d\nseconds %.6f\n", md->report.active,
          md->seconds);
  output_friction(f, md);
  return output_close(o, f, st);
}
#line 552 "paper/output.nw"
int output_matrix_market(const char *path, const Model *md, Status *st)
{
  char tmp[1100];
  snprintf(tmp, sizeof tmp, "%s.partial", path);
  FILE *f = fopen(tmp, "w");
  if (!f) return status_set(st, STATUS_SYSTEM, "%s: cannot write", path);
  int ok = cholmod_write_sparse(f, md->A, NULL, NULL, md->cm) >= 0;
  ok = !fclose(f) && ok;
  if (!ok || rename(tmp, path)) {
    remove(tmp);
    return status_set(st, STATUS_SYSTEM, "%s: cannot write", path);
  }
  return STATUS_OK;
}
#line 575 "paper/output.nw"
static int output_gradient(Output *o, const Model *md, const Grad_check *gc,
                           Status *st)
{
  FILE *f = output_open(o, "gradient.dat", st);
  if (!f) return st->code;
  fprintf(f, "# i x1[m] dE/dX_i[J/m^2] finite_difference[J/m^2] relative_error\n");
  for (int i = 0; i < md->mesh->ncol; i++)
    fprintf(f, "%d %.10g %.15g %.15g %.3e\n", i, md->mesh->xy[2 * i],
            gc->G[i], gc->fd[i], gc->err[i]);
  return output_close(o, f, st);
}

int output_gradcheck(Output *o, const Output_run *run, const Model *md,
                     const Grad_check *gc, Status *st)
{
  const Problem *p = md->problem;
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\nscene %s\nmodel %s\nN %d\nenergy %.15g\n"
             "max_relative_error %.3e\nworst_node %d\n", run->scene,
          problem_model_name(p->model), p->N, md->energy,
          gc->err[gc->worst], gc->worst);
  output_friction(f, md);
  int rc = output_close(o, f, st);
  return rc ? rc : output_gradient(o, md, gc, st);
}
#line 708 "paper/output.nw"
int output_start(Output *o, const Model *md, const double *X, double moved,
                 Output_start *start, Status *st)
{
  int rc = output_state(o, "initial", md, X, st);
  if (rc) return rc;
  start->energy = md->energy;
  start->cv = model_pressure_cv(md);
  start->moved = moved;
  return STATUS_OK;
}
#line 609 "paper/output.nw"
Output_history *output_history_new(int ndesign, Status *st)
{
  Output_history *h = calloc(1, sizeof *h);
  if (!h) status_set(st, STATUS_SYSTEM, "optimize: out of memory");
  else h->ndesign = ndesign;
  return h;
}

static int history_grow(Output_history *h)
{
  int size = 2 * h->size + 16;
  Opt_progress *p = realloc(h->p, size * sizeof *p);
  if (p) h->p = p;
  double *X = realloc(h->X, (size_t) size * h->ndesign * sizeof *X);
  if (X) h->X = X;
  if (!p || !X) return h->failed = 1;
  h->size = size;
  return 0;
}

void output_history_add(Output_history *h, const Opt_progress *p,
                        const double *X)
{
  if (h->failed || (h->n == h->size && history_grow(h))) return;
  memcpy(h->X + (size_t) h->n * h->ndesign, X, h->ndesign * sizeof *X);
  h->p[h->n++] = *p;
}

void output_history_free(Output_history *h)
{
  if (!h) return;
  free(h->p);
  free(h->X);
  free(h);
}
#line 653 "paper/output.nw"
int output_history(Output *o, const Problem *p, const Output_history *h,
                   Status *st)
{
  int rc;
  if (h->failed) return status_set(st, STATUS_SYSTEM, "optimize: out of memory");
  FILE *f = output_open(o, "history.dat", st);
  if (!f) return st->code;
  fprintf(f, "# iteration E[J/m] projected_gradient state_solves seconds\n");
  for (int k = 0; k < h->n; k++)
    fprintf(f, "%d %.15g %.6e %d %.6f\n", h->p[k].iteration, h->p[k].energy,
            h->p[k].pgnorm, h->p[k].state_solves, h->p[k].seconds);
  if ((rc = output_close(o, f, st))) return rc;
  if (!(f = output_open(o, "iterates.dat", st))) return st->code;
  fprintf(f, "# iteration i x1[m] alpha[m]: one block per iteration, "
             "two blank lines apart (gnuplot: index k)\n");
  for (int k = 0; k < h->n; k++)
    for (int i = 0; i < h->ndesign; i++)
      fprintf(f, "%s%d %d %.10g %.17g\n", k && !i ? "\n\n" : "",
              h->p[k].iteration, i, p->a + i * (p->b - p->a) / p->N,
              h->X[(size_t) k * h->ndesign + i]);
  return output_close(o, f, st);
}
#line 686 "paper/output.nw"
int output_multipliers(Output *o, const Problem *p, const double *X,
                       const double *G, const Design_multipliers *m,
                       Status *st)
{
  double h = (p->b - p->a) / p->N;
  if (m->N != p->N)
    return status_set(st, STATUS_INPUT, "multipliers.dat: multipliers made "
                      "for N = %d, the problem has N = %d", m->N, p->N);
  FILE *f = output_open(o, "multipliers.dat", st);
  if (!f) return st->code;
  fprintf(f, "# i x1[m] alpha[m] dE/dX_i lower(-X_i<=0) upper(X_i-C0<=0) "
             "rise(X_i+1-X_i-d<=0) fall(X_i-X_i+1-d<=0); mu = %.15g\n", m->mu);
  for (int i = 0; i <= p->N; i++)
    fprintf(f, "%d %.10g %.17g %.15g %.15g %.15g %.15g %.15g\n", i,
            p->a + i * h, X[i], G[i], m->lower[i], m->upper[i],
            i < p->N ? m->up[i] : 0.0, i < p->N ? m->down[i] : 0.0);
  return output_close(o, f, st);
}
#line 724 "paper/output.nw"
int output_opt_summary(Output *o, const Output_run *run, const Model *md,
                       const Output_start *start, const Opt_report *r,
                       double mu, Status *st)
{
  const Problem *p = md->problem;
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\nscene %s\noptimizer %s\nmetric %s\nstate_solver %s\n"
          "model %s\n", run->scene, run->optimizer, run->metric,
          run->state_solver, problem_model_name(p->model));
  fprintf(f, "N %d\nM %d\nR %d\ninitial_projected %d\ninitial_moved %.6e\n",
          p->N, p->M, p->R, start->moved > 0, start->moved);
  fprintf(f, "initial_energy %.15g\nenergy %.15g\niterations %d\nevaluations %d\n",
          start->energy, r->energy, r->iterations, r->evaluations);
  fprintf(f, "projected_gradient %.6e\nstop_reason %s\n", r->pgnorm, r->stop_reason);
  fprintf(f, "seconds %.6f\nmetric_seconds %.6f\nstate_seconds %.6f\n",
          r->seconds, r->metric_seconds, r->state_seconds);
  if (r->model_seconds > 0) fprintf(f, "model_seconds %.6f\n", r->model_seconds);
  fprintf(f, "contact_pressure_cv_initial %.6f\ncontact_pressure_cv_final %.6f\n",
          start->cv, model_pressure_cv(md));
  fprintf(f, "active_contact_nodes %d\nkkt_residual %.3e\narea_multiplier %.15g\n",
          md->report.active, md->report.kkt, mu);
  output_friction(f, md);
  return output_close(o, f, st);
}
