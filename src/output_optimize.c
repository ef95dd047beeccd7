#line 1679 "paper/output.nw"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "output_private.h"
#include "threads.h"
#line 1691 "paper/output.nw"
static int history_pvd(Output *o, const Output_history *h, Status *st);
#line 1540 "paper/output.nw"
static void output_objectives_summary(FILE *f, const Objective *ob,
                                      const double *J, const Output_start *start)
{
  fprintf(f, "objective %s\nobjective_value %.15g\n", objective_name(ob->kind),
          J[ob->kind]);
  for (int k = 0; objective_names[k]; k++) {  /* an undefined one: no line */
    if (!objective_is_energy(k) && !isnan(start->J.value[k]))  /* initial_energy: above */
      fprintf(f, "initial_%s %.15g\n", objective_names[k], start->J.value[k]);
    if (!isnan(J[k])) fprintf(f, "final_%s %.15g\n", objective_names[k], J[k]);
  }
}
#line 1759 "paper/output.nw"
static void history_vtu(Output_history *h, int iteration, const double *X)
{
  const Mesh *m = model_mesh(h->md);
  char name[64], path[80];
  for (int i = 0; i < m->ncol; i++)
    if (m->xy[2 * i + 1] != X[i]) {
      status_set(&h->vtu, STATUS_INPUT, "iterates/: the model is not at "
                 "iterate %d (alpha_%d = %.17g, the mesh at %.17g)",
                 iteration, i, X[i], m->xy[2 * i + 1]);
      return;
    }
  snprintf(name, sizeof name, ITERATE_VTU, iteration);
  snprintf(path, sizeof path, "iterates/%s", name);
  if (iteration + 1 > h->o->iterates) output_publish(&h->o->iterates, iteration + 1);
  FILE *f = output_open_in_folder(h->o, "iterates", name, &h->vtu);
  if (!f) return;
  if (output_vtu_write(f, h->md, X, &h->vtu)) fclose(f);
  else output_finish(f, h->o->dir, path, &h->vtu);
}

#line 1698 "paper/output.nw"
Output_history *output_history_new(int ndesign, Status *st)
{
  Output_history *h = calloc(1, sizeof *h);
  if (!h) status_set(st, STATUS_MEMORY, "optimize: out of memory");
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
  if (h->o && !h->vtu.code) history_vtu(h, p->iteration, X);
  if (h->failed || (h->n == h->size && history_grow(h))) return;
  memcpy(h->X + (size_t) h->n * h->ndesign, X, h->ndesign * sizeof *X);
  h->p[h->n++] = *p;
}

int output_history_vtu(Output_history *h, Output *o, const Model *md,
                       Status *st)
{
  int rc = output_folder(o, "iterates", st);
  if (!rc) h->o = o, h->md = md;
  return rc;
}

void output_history_free(Output_history *h)
{
  if (!h) return;
  free(h->p);
  free(h->X);
  free(h);
}
#line 1787 "paper/output.nw"
static int history_iterates(Output *o, const Problem *p,
                            const Output_history *h, Status *st)
{
  FILE *f = output_open(o, "iterates.dat", st);
  if (!f) return st->code;
  fprintf(f, "# iteration i x1[m] alpha[m]: one block per iteration, "
             "two blank lines apart (gnuplot: index k)\n");
  for (int k = 0; k < h->n; k++)
    for (int i = 0; i < h->ndesign; i++)
      fprintf(f, "%s%d %d %.10g %.17g\n", k && !i ? "\n\n" : "",
              h->p[k].iteration, i, p->a + i * (p->b - p->a) / p->N,
              h->X[(size_t) k * h->ndesign + i]);
  return output_close(o, f, st);
}

int output_history(Output *o, const Problem *p, const Output_history *h,
                   Status *st)
{
  int rc;
  if (h->failed) return status_set(st, STATUS_MEMORY, "optimize: out of memory");
  if (h->vtu.code) return status_set(st, h->vtu.code, "%s", h->vtu.msg);
  FILE *f = output_open(o, "history.dat", st);
  if (!f) return st->code;
  const char *unit = objective_unit(h->objective);
  fprintf(f, "# iteration %s%s%s%s projected_gradient state_solves seconds\n",
          objective_symbol(h->objective), *unit ? "[" : "", unit + !!*unit, *unit ? "]" : "");
  for (int k = 0; k < h->n; k++)
    fprintf(f, "%d %.15g %.6e %d %.6f\n", h->p[k].iteration, h->p[k].value,
            h->p[k].pgnorm, h->p[k].state_solves, h->p[k].seconds);
  if ((rc = output_close(o, f, st)) || (rc = history_iterates(o, p, h, st)))
    return rc;
  return h->o ? history_pvd(o, h, st) : STATUS_OK;
}
#line 1825 "paper/output.nw"
static int history_pvd(Output *o, const Output_history *h, Status *st)
{
  FILE *f = output_open(o, "iterates.pvd", st);
  if (!f) return st->code;
  fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
             "version=\"0.1\">\n<Collection>\n");
  for (int k = 0; k < h->n; k++)
    fprintf(f, "<DataSet timestep=\"%d\" part=\"0\" file=\"iterates/"
               ITERATE_VTU "\"/>\n", h->p[k].iteration, h->p[k].iteration);
  fputs("</Collection>\n</VTKFile>\n", f);
  return output_close(o, f, st);
}
#line 1848 "paper/output.nw"
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
#line 1870 "paper/output.nw"
int output_start(Output *o, const Model *md, const double *X, double moved,
                 double q, Output_start *start, Status *st)
{
  int rc = output_state(o, "initial", md, X, st);
  if (rc) return rc;
  start->energy = model_energy(md);
  start->cv = model_pressure_cv(md);
  start->moved = moved;
  return output_objectives(md, q, &start->J, st);
}
#line 1889 "paper/output.nw"
int output_opt_summary(Output *o, const Output_run *run, const Model *md,
                       const Output_start *start, const Opt_report *r,
                       double mu, Status *st)
{
  const Problem *p = model_problem(md);
  Model_summary ms;
  Objective_values J;
  FILE *f = model_summary(md, &ms, st)
            || output_objectives(md, run->objective->q, &J, st)
            ? NULL : output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\ncommand %s\n", o->command);
  fprintf(f, "scene %s\noptimizer %s\nmetric %s\nstate_solver %s\n"
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
  
#line 1933 "paper/output.nw"
if (p && (!strcmp(run->optimizer, "slsqp") || !strcmp(run->optimizer, "mma")))
  fprintf(f, "subproblem_seconds %.6f\n", r->subproblem_seconds);
#line 1913 "paper/output.nw"
  
#line 1941 "paper/output.nw"
if (r->starts > 1)
  fprintf(f, "starts %d\nstarts_best %d\nstarts_min %.15g\nstarts_max %.15g\n"
          "starts_evaluations %d\nstarts_seconds %.6f\n", r->starts, r->starts_best,
          r->starts_min, r->starts_max, r->starts_evaluations, r->starts_seconds);
#line 1914 "paper/output.nw"
  fprintf(f, "monitor_seconds %.6f\n", r->monitor_seconds);
  if (r->levels > 1)
    fprintf(f, "levels %d\ncoarse_evaluations %d\ncoarse_seconds %.6f\n",
            r->levels, r->coarse_evaluations, r->coarse_seconds);
  fprintf(f, "contact_pressure_cv_initial %.6f\ncontact_pressure_cv_final %.6f\n",
          start->cv, model_pressure_cv(md));
  fprintf(f, "active_contact_nodes %d\nkkt_residual %.3e\narea_multiplier %.15g\n",
          model_report(md)->active, model_report(md)->kkt, mu);
  output_reactions(f, md, &ms);
  output_objectives_summary(f, run->objective, J.value, start);
  output_friction(f, md);
  threads_summary(f);
  return output_close(o, f, st);
}
