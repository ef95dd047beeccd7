#line 1022 "paper/output.nw"
#include <stdio.h>
#include "output_private.h"
#line 1028 "paper/output.nw"
static int output_shape(Output *o, const char *sub, const Model *md,
                        const double *X, Status *st)
{
  FILE *f = output_open_in(o, sub, "shape.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m]\n");
  for (int i = 0; i < model_mesh(md)->ncol; i++)
    fprintf(f, "%.10g %.15g\n", model_mesh(md)->xy[2 * i], X[i]);
  return output_close(o, f, st);
}
#line 1041 "paper/output.nw"
static int output_contact(Output *o, const char *sub, const Model *md,
                          const double *X, Status *st)
{
  const Fem_dofs *d = model_dofs(md);
  FILE *f = output_open_in(o, sub, "contact.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa]%s\n",
          d->nt ? " u1[m] Tt[N/m]" : "");
  for (int c = 0, k = 0; c < d->nc; c++) {
    int i = d->contact_col[c];
    double u2 = model_state(md)[d->contact[c]];
    fprintf(f, "%.10g %.15g %.15g %.15g %.15g %.15g", model_mesh(md)->xy[2 * i],
            X[i], u2, u2 + X[i], model_forces(md)[c],
            model_pressure(md, c));
    
#line 1065 "paper/output.nw"
if (d->nt) {
  while (k < d->nt && d->tangent_col[k] < i) k++;
  int here = k < d->nt && d->tangent_col[k] == i;
  fprintf(f, " %.15g %.15g", here ? model_state(md)[d->tangent[k]] : 0.0,
          here ? model_forces(md)[d->nc + k] : 0.0);
}
#line 1056 "paper/output.nw"
    fputc('\n', f);
  }
  return output_close(o, f, st);
}
#line 1074 "paper/output.nw"
static int output_nodes(Output *o, const char *sub, const Model *md,
                        Status *st)
{
  const Mesh *m = model_mesh(md);
  FILE *f = output_open_in(o, sub, "nodes.dat", st);
  if (!f) return st->code;
  fprintf(f, "# node column row x1[m] x2[m] u1[m] u2[m]\n");
  for (int k = 0; k < m->nnodes; k++)
    fprintf(f, "%d %d %d %.15g %.15g %.15g %.15g\n", k, k % m->ncol,
            k / m->ncol, m->xy[2 * k], m->xy[2 * k + 1], output_u(md, k, 0),
            output_u(md, k, 1));
  return output_close(o, f, st);
}
#line 1090 "paper/output.nw"
static int output_triangles(Output *o, const char *sub, const Model *md,
                            Status *st)
{
  const Mesh *m = model_mesh(md);
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
#line 1416 "paper/output.nw"
int output_state(Output *o, const char *sub, const Model *md,
                 const double *X, Status *st)
{
  int rc;
  if ((rc = output_shape(o, sub, md, X, st))
      || (rc = output_contact(o, sub, md, X, st))
      || (o->plot_files && ((rc = output_nodes(o, sub, md, st))
                            || (rc = output_triangles(o, sub, md, st))))
      || (rc = output_vtu(o, sub, md, X, st)))
    return rc;
  return STATUS_OK;
}
