#line 1436 "paper/output.nw"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include "output_private.h"
#include "threads.h"
#line 1465 "paper/output.nw"
int output_solve(Output *o, const Output_run *run, const Model *md,
                 const double *X, Status *st)
{
  const Problem *p = model_problem(md);
  Model_summary ms;
  Objective_values J;
  int rc = output_state(o, "", md, X, st);
  if (!rc) rc = model_summary(md, &ms, st);
  if (!rc) rc = output_objectives(md, run->objective ? run->objective->q : 8, &J, st);
  FILE *f = rc ? NULL : output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\ncommand %s\n", o->command);
  fprintf(f, "scene %s\nstate_solver %s\nmodel %s\n", run->scene,
          run->state_solver, problem_model_name(p->model));
  fprintf(f, "N %d\nM %d\nR %d\ntriangles %d\ndofs %d\ncontact_nodes %d\n",
          p->N, p->M, p->R, model_mesh(md)->ntri, model_dofs(md)->n, model_dofs(md)->nc);
  fprintf(f, "energy %.15g\n", model_energy(md));
  for (int k = 0; objective_names[k]; k++)     /* E: above; undefined: no line */
    if (!objective_is_energy(k) && !isnan(J.value[k]))
      fprintf(f, "%s %.15g\n", objective_names[k], J.value[k]);
  fprintf(f, "kkt_residual %.3e\niterations %d\n", model_report(md)->kkt,
          model_report(md)->iterations);
  fprintf(f, "active_contact_nodes %d\nseconds %.6f\n", model_report(md)->active,
          model_seconds(md));
  output_reactions(f, md, &ms);
  output_friction(f, md);
  threads_summary(f);
  return output_close(o, f, st);
}
#line 1511 "paper/output.nw"
void output_reactions(FILE *f, const Model *md, const Model_summary *ms)
{
  static const char *const side[SIDE_COUNT] = { "left", "right", "top" };
  const Problem *p = model_problem(md);
  for (int s = 0; s < SIDE_COUNT; s++) {
    Problem_bc_kind kind = p->side[s].kind;
    if (kind == BC_CLAMPED || kind == BC_ROLLER)
      fprintf(f, "reaction_%s_x1 %.15g\nreaction_%s_x2 %.15g\n", side[s],
              ms->reaction[s][0], side[s], ms->reaction[s][1]);
  }
  for (int s = 0; s < p->part.ncurve; s++) {
    Problem_bc_kind kind = p->part.curve[s].kind;
    const char *name = p->part.curve[s].name;
    const double *r = ms->reaction[SIDE_COUNT + s];
    if (kind == BC_CLAMPED || kind == BC_ROLLER)
      fprintf(f, "reaction_boundary.%s_x1 %.15g\nreaction_boundary.%s_x2 %.15g\n", name, r[0],
              name, r[1]);
  }
  fprintf(f, "contact_pressure_max %.15g\ncontact_length %.15g\n"
             "von_mises_max %.15g\n", ms->pressure_max, ms->contact_length,
          ms->von_mises_max);
}
#line 1558 "paper/output.nw"
int output_objectives(const Model *md, double q, Objective_values *J, Status *st)
{
  for (int k = 0; objective_names[k]; k++) {
    Objective o = { (Objective_kind) k, q };
    Status why;
    int rc = objective_value(md, &o, &J->value[k], &why);
    if (rc == STATUS_NUMERIC) J->value[k] = NAN;
    else if (rc) return status_set(st, rc, "%s", why.msg);
  }
  return STATUS_OK;
}
#line 1576 "paper/output.nw"
void output_friction(FILE *f, const Model *md)
{
  const Problem *p = model_problem(md);
  char v[STATUS_NUMBER];
  if (p->contact == CONTACT_FRICTIONLESS) return;
  fprintf(f, "contact %s\n", problem_contact_name(p->contact));
  if (p->contact == CONTACT_TRESCA)
    fprintf(f, "slip_bound %s\n", status_number(p->slip_bound, v));
  else fprintf(f, "friction %s\n", status_number(p->friction, v));
  fprintf(f, "friction_energy %.15g\n", model_friction_energy(md));
  if (p->contact == CONTACT_COULOMB)
    fprintf(f, "fixed_point_iterations %d\nfixed_point_residual %.3e\n",
            model_fixed_point_iterations(md), model_fixed_point_residual(md));
}
#line 1595 "paper/output.nw"
int output_matrix_market(const char *path, const Model *md, Status *st)
{
  char tmp[1100];
  snprintf(tmp, sizeof tmp, "%s.partial", path);
  FILE *f = fopen(tmp, "w");
  if (!f) return output_errno(st, errno, path, "cannot write");
  /* CHOLMOD's prototype wants a writable A; it only reads it */
  cholmod_sparse *A = (cholmod_sparse *) model_stiffness(md);
  int ok = cholmod_l_write_sparse(f, A, NULL, NULL, model_cholmod(md)) >= 0;
  int memory = !ok && model_cholmod(md)->status == CHOLMOD_OUT_OF_MEMORY;
  ok = !ferror(f) && ok;    /* CHOLMOD does not check every fprintf */
  ok = !fclose(f) && ok;
  if (ok && rename(tmp, path)) {
    int rc = output_errno(st, errno, path, "cannot move into place");
    remove(tmp);
    return rc;
  }
  if (!ok) {
    remove(tmp);
    return memory ? status_set(st, STATUS_MEMORY, "%s: out of memory", path)
                  : status_set(st, STATUS_SYSTEM, "%s: write failed", path);
  }
  return STATUS_OK;
}
#line 1631 "paper/output.nw"
static int output_gradient(Output *o, const Model *md, const Grad_check *gc,
                           Status *st)
{
  FILE *f = output_open(o, "gradient.dat", st);
  if (!f) return st->code;
  Objective_kind J = (gc->objective ? *gc->objective : objective_default()).kind;
  const char *unit = *objective_unit(J) ? "[J/m^2]" : "[1/m]";
  fprintf(f, "# i x1[m] d%s/dX_i%s finite_difference%s relative_error\n",
          objective_symbol(J), unit, unit);
  for (int k = 0; k < gc->ncheck; k++) {
    int i = gc->check[k];
    fprintf(f, "%d %.10g %.15g %.15g %.3e\n", i, model_mesh(md)->xy[2 * i],
            gc->G[i], gc->fd[i], gc->err[i]);
  }
  return output_close(o, f, st);
}

int output_gradcheck(Output *o, const Output_run *run, const Model *md,
                     const Grad_check *gc, Status *st)
{
  const Problem *p = model_problem(md);
  Objective J = gc->objective ? *gc->objective : objective_default();
  double value;
  int rc = objective_value(md, &J, &value, st);
  FILE *f = rc ? NULL : output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\ncommand %s\n", o->command);
  fprintf(f, "scene %s\nmodel %s\nN %d\nenergy %.15g\n"
             "objective %s\nobjective_value %.15g\n"
             "max_relative_error %.3e\nworst_node %d\nnodes_checked %d\n",
          run->scene, problem_model_name(p->model), p->N, model_energy(md),
          objective_name(J.kind), value,
          gc->err[gc->worst], gc->worst, gc->ncheck);
  output_friction(f, md);
  threads_summary(f);
  rc = output_close(o, f, st);
  return rc ? rc : output_gradient(o, md, gc, st);
}
