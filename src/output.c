#line 53 "paper/output.nw"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "output.h"

#line 72 "paper/output.nw"
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
#line 98 "paper/output.nw"
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
#line 131 "paper/output.nw"
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
#line 174 "paper/output.nw"
static double output_u(const Model *md, int node, int c)
{
  int k = md->dofs->unknown[2 * node + c];
  return k < 0 ? 0.0 : md->Q[k];
}

static FILE *output_open_in(Output *o, const char *sub, const char *name,
                            Status *st)
{
  char path[256];
  snprintf(path, sizeof path, "%s%s%s", sub, *sub ? "/" : "", name);
  return output_open(o, path, st);
}
#line 190 "paper/output.nw"
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
#line 203 "paper/output.nw"
static int output_contact(Output *o, const char *sub, const Model *md,
                          const double *X, Status *st)
{
  FILE *f = output_open_in(o, sub, "contact.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa]\n");
  for (int c = 0; c < md->dofs->nc; c++) {
    int i = md->dofs->contact_col[c];
    double u2 = md->Q[md->dofs->contact[c]];
    fprintf(f, "%.10g %.15g %.15g %.15g %.15g %.15g\n", md->mesh->xy[2 * i],
            X[i], u2, u2 + X[i], md->T[c],
            model_pressure(md, c));
  }
  return output_close(o, f, st);
}
#line 221 "paper/output.nw"
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
#line 256 "paper/output.nw"
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
  
#line 278 "paper/output.nw"
fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
for (int t = 0; t < m->ntri; t++) fprintf(f, "%d\n", 3 * (t + 1));
fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
for (int t = 0; t < m->ntri; t++) fprintf(f, "5\n");
fprintf(f, "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n"
           "<DataArray type=\"Float64\" Name=\"displacement\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n");
for (int k = 0; k < m->nnodes; k++)
  fprintf(f, "%.15g %.15g 0\n", output_u(md, k, 0), output_u(md, k, 1));
fprintf(f, "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
#line 273 "paper/output.nw"
  return output_close(o, f, st);
}
#line 291 "paper/output.nw"
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
