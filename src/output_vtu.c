#line 1115 "paper/output.nw"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "output_private.h"

#line 1160 "paper/output.nw"
typedef struct {
  const Model *md;          /* the state written */
  const double *X;          /* its design */
  double *stress;           /* 5 per triangle: sigma11, sigma22, sigma12,
                               sigma33, von Mises [Pa] */
} Vtu_state;

typedef struct {
  const char *section;      /* PointData, CellData, Points or Cells */
  const char *name;         /* the array's Name */
  const char *type;         /* Float64, Int32 or UInt8 */
  int components;           /* values per point or per cell */
  size_t count;             /* points or cells */
  size_t size;              /* bytes per value */
  int which;                /* the quantity, for a fill of several */
  void (*fill)(const Vtu_state *s, int which, void *values);
} Vtu_array;
#define VTU_MAX_ARRAYS 16

static size_t vtu_bytes(const Vtu_array *a)
{
  return a->count * a->components * a->size;
}
#line 1219 "paper/output.nw"
double output_u(const Model *md, int node, int c)
{
  int k = model_dofs(md)->unknown[2 * node + c];
  return k < 0 ? 0.0 : model_state(md)[k];
}
#line 1233 "paper/output.nw"
static void vtu_displacement(const Vtu_state *s, int which, void *values)
{
  double *v = values;
  (void) which;
  for (int k = 0; k < model_mesh(s->md)->nnodes; k++) {
    v[3 * k] = output_u(s->md, k, 0);
    v[3 * k + 1] = output_u(s->md, k, 1);
    v[3 * k + 2] = 0;
  }
}

/* which 0: the gap u2 + alpha_i [m]; 1: the contact pressure [Pa] */
static void vtu_contact(const Vtu_state *s, int which, void *values)
{
  const Fem_dofs *d = model_dofs(s->md);
  double *v = values;
  memset(v, 0, model_mesh(s->md)->nnodes * sizeof *v);
  for (int c = 0; c < d->nc; c++) {
    int i = d->contact_col[c];
    v[i] = which == 0 ? model_state(s->md)[d->contact[c]] + s->X[i]
                      : model_pressure(s->md, c);
  }
}

static void vtu_contact_node(const Vtu_state *s, int which, void *values)
{
  uint8_t *v = values;
  (void) which;
  const Fem_dofs *d = model_dofs(s->md);
  memset(v, 0, model_mesh(s->md)->nnodes);
  for (int c = 0; c < d->nc; c++) v[d->contact_col[c]] = 1;
}

/* the nodal friction force T_t [N/m], 0 where u1 is held */
static void vtu_tangential(const Vtu_state *s, int which, void *values)
{
  const Fem_dofs *d = model_dofs(s->md);
  double *v = values;
  (void) which;
  memset(v, 0, model_mesh(s->md)->nnodes * sizeof *v);
  for (int k = 0; k < d->nt; k++) v[d->tangent_col[k]] = model_forces(s->md)[d->nc + k];
}
#line 1283 "paper/output.nw"
static void vtu_stress(const Vtu_state *s, int which, void *values)
{
  double *v = values;
  for (int t = 0; t < model_mesh(s->md)->ntri; t++) v[t] = s->stress[5 * t + which];
}
#line 1295 "paper/output.nw"
static void vtu_points(const Vtu_state *s, int which, void *values)
{
  const double *xy = model_mesh(s->md)->xy;
  double *v = values;
  (void) which;
  for (int k = 0; k < model_mesh(s->md)->nnodes; k++)
    v[3 * k] = xy[2 * k], v[3 * k + 1] = xy[2 * k + 1], v[3 * k + 2] = 0;
}

/* which 0: the connectivity, 3 vertices per triangle; 1: the offsets */
static void vtu_cells(const Vtu_state *s, int which, void *values)
{
  const Mesh *m = model_mesh(s->md);
  int32_t *v = values;
  for (int t = 0; t < m->ntri; t++)
    if (which == 1) v[t] = 3 * (t + 1);
    else for (int k = 0; k < 3; k++) v[3 * t + k] = m->tri[3 * t + k];
}

/* a part's triangles, which 0: the region (0 the strip, 1 the part
   outside its named surfaces, 2 + k the geometry's physical surface k);
   1: the material (0 the scene's [material], 1 + s its s-th named one) */
static void vtu_part(const Vtu_state *s, int which, void *values)
{
  const Mesh *m = model_mesh(s->md);
  int32_t *v = values;
  for (int t = 0; t < m->ntri; t++) v[t] = which ? m->material[t] : m->region[t];
}

static void vtu_types(const Vtu_state *s, int which, void *values)
{
  (void) which;
  memset(values, 5, model_mesh(s->md)->ntri);   /* VTK_TRIANGLE */
}
#line 1188 "paper/output.nw"
static const char *const vtu_stress_names[5] =
  { "sigma11", "sigma22", "sigma12", "sigma33", "von_mises" };

static int vtu_arrays(const Model *md, Vtu_array a[VTU_MAX_ARRAYS])
{
  size_t np = model_mesh(md)->nnodes, nt = model_mesh(md)->ntri, d = sizeof(double);
  int n = 0;
  a[n++] = (Vtu_array) { "PointData", "displacement", "Float64", 3, np, d, 0, vtu_displacement };
  a[n++] = (Vtu_array) { "PointData", "gap", "Float64", 1, np, d, 0, vtu_contact };
  a[n++] = (Vtu_array) { "PointData", "pressure", "Float64", 1, np, d, 1, vtu_contact };
  a[n++] = (Vtu_array) { "PointData", "contact_node", "UInt8", 1, np, 1, 0, vtu_contact_node };
  if (model_dofs(md)->nt)
    a[n++] = (Vtu_array) { "PointData", "tangential_force", "Float64", 1, np, d,
                           0, vtu_tangential };
  for (int k = 0; k < 5; k++)
    a[n++] = (Vtu_array) { "CellData", vtu_stress_names[k], "Float64", 1, nt, d, k, vtu_stress };
  if (model_mesh(md)->material) {
    a[n++] = (Vtu_array) { "CellData", "region", "Int32", 1, nt, 4, 0, vtu_part };
    a[n++] = (Vtu_array) { "CellData", "material", "Int32", 1, nt, 4, 1, vtu_part };
  }
  a[n++] = (Vtu_array) { "Points", "Points", "Float64", 3, np, d, 0, vtu_points };
  a[n++] = (Vtu_array) { "Cells", "connectivity", "Int32", 1, 3 * nt, 4, 0, vtu_cells };
  a[n++] = (Vtu_array) { "Cells", "offsets", "Int32", 1, nt, 4, 1, vtu_cells };
  a[n++] = (Vtu_array) { "Cells", "types", "UInt8", 1, nt, 1, 0, vtu_types };
  return n;
}
#line 1334 "paper/output.nw"
static const char *vtu_byte_order(void)
{
  const uint16_t one = 1;
  return *(const uint8_t *) &one ? "LittleEndian" : "BigEndian";
}

static void vtu_header(FILE *f, const Mesh *m, const Vtu_array *a, int n)
{
  unsigned long long offset = 0;
  fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
             "version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
             "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" "
             "NumberOfCells=\"%d\">\n", vtu_byte_order(), m->nnodes, m->ntri);
  for (int k = 0; k < n; k++) {
    if (k > 0 && strcmp(a[k].section, a[k - 1].section))
      fprintf(f, "</%s>\n", a[k - 1].section);
    if (k == 0 || strcmp(a[k].section, a[k - 1].section))
      fprintf(f, "<%s>\n", a[k].section);
    fprintf(f, "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
               "format=\"appended\" offset=\"%llu\"/>\n", a[k].type, a[k].name,
            a[k].components, offset);
    offset += sizeof(uint64_t) + vtu_bytes(&a[k]);
  }
  fprintf(f, "</%s>\n</Piece>\n</UnstructuredGrid>\n"
             "<AppendedData encoding=\"raw\">\n_", a[n - 1].section);
}
#line 1365 "paper/output.nw"
static void vtu_data(FILE *f, const Vtu_state *s, const Vtu_array *a, int n,
                     void *values)
{
  for (int k = 0; k < n; k++) {
    uint64_t bytes = vtu_bytes(&a[k]);
    a[k].fill(s, a[k].which, values);
    fwrite(&bytes, sizeof bytes, 1, f);
    fwrite(values, 1, bytes, f);
  }
  fprintf(f, "\n</AppendedData>\n</VTKFile>\n");
}
#line 1382 "paper/output.nw"
int output_vtu_write(FILE *f, const Model *md, const double *X, Status *st)
{
  Vtu_array a[VTU_MAX_ARRAYS];
  int n = vtu_arrays(md, a);
  size_t most = 0, nt = model_mesh(md)->ntri;
  for (int k = 0; k < n; k++) most = vtu_bytes(&a[k]) > most ? vtu_bytes(&a[k]) : most;
  Vtu_state s = { md, X, malloc(5 * nt * sizeof(double)) };
  void *values = malloc(most);
  if (!s.stress || !values) {
    free(s.stress), free(values);
    return status_set(st, STATUS_MEMORY, "solution.vtu: out of memory");
  }
  for (size_t t = 0; t < nt; t++) model_stress(md, (int) t, s.stress + 5 * t);
  vtu_header(f, model_mesh(md), a, n);
  vtu_data(f, &s, a, n, values);
  free(s.stress), free(values);
  return STATUS_OK;
}
#line 1403 "paper/output.nw"
int output_vtu(Output *o, const char *sub, const Model *md,
               const double *X, Status *st)
{
  FILE *f = output_open_in(o, sub, "solution.vtu", st);
  if (!f) return st->code;
  int rc = output_vtu_write(f, md, X, st);
  int rc_close = output_close(o, f, st);
  return rc ? rc : rc_close;
}
