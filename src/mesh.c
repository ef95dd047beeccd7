#line 99 "paper/mesh.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "part.h"
#include "mesh.h"
#line 109 "paper/mesh.nw"
static void mesh_connect(Mesh *m);
static void mesh_place_fixed(Mesh *m);
static Mesh *mesh_join_part(Mesh *m, const Problem *p, Status *st);

Mesh *mesh_new(const Problem *p, Status *st)
{
  Mesh *m = calloc(1, sizeof *m);
  if (!m) { status_set(st, STATUS_MEMORY, "mesh: out of memory"); return NULL; }
  if (p->part.geometry[0]) return mesh_join_part(m, p, st);
  
#line 133 "paper/mesh.nw"
m->N = p->N; m->M = p->M; m->R = p->R;
m->ncol = p->N + 1;
m->nrow = p->M + p->R + 1;
m->nnodes = m->ncol * m->nrow;
m->ntri = 2 * p->N * (p->M + p->R);
m->a = p->a; m->b = p->b; m->gamma = p->gamma; m->C0prime = p->C0prime;
m->h = (p->b - p->a) / p->N;
#line 119 "paper/mesh.nw"
  m->xy = malloc(2 * (size_t) m->nnodes * sizeof *m->xy);
  m->tri = malloc(3 * (size_t) m->ntri * sizeof *m->tri);
  if (!m->xy || !m->tri) {
    status_set(st, STATUS_MEMORY, "mesh: out of memory for %d nodes", m->nnodes);
    mesh_free(m);
    return NULL;
  }
  mesh_connect(m);
  mesh_place_fixed(m);
  return m;
}
#line 148 "paper/mesh.nw"
static void mesh_connect(Mesh *m)
{
  int *t = m->tri;
  for (int j = 0; j < m->nrow - 1; j++)
    for (int i = 0; i < m->N; i++) {
      int n00 = j * m->ncol + i, n10 = n00 + 1;
      int n01 = n00 + m->ncol, n11 = n01 + 1;
      *t++ = n00; *t++ = n10; *t++ = n11;
      *t++ = n00; *t++ = n11; *t++ = n01;
    }
}
#line 164 "paper/mesh.nw"
static void mesh_place_fixed(Mesh *m)
{
  for (int j = 0; j < m->nrow; j++)
    for (int i = 0; i < m->ncol; i++) {
      int k = j * m->ncol + i;
      m->xy[2 * k] = i == m->N ? m->b : m->a + i * m->h;
      if (j >= m->M)
        m->xy[2 * k + 1] = j == m->M ? m->C0prime : m->C0prime
          + (m->gamma - m->C0prime) * (j - m->M) / m->R;
    }
}
#line 179 "paper/mesh.nw"
int mesh_move(Mesh *m, const double *X, Status *st)
{
  for (int i = 0; i < m->ncol; i++) {
    
#line 191 "paper/mesh.nw"
if (!(X[i] >= 0))
  return status_set(st, STATUS_INPUT,
    "design: alpha_%d = %g is below the foundation x2 = 0", i, X[i]);
for (int j = 0; j < m->M; j++)
  m->xy[2 * (j * m->ncol + i) + 1] = X[i] + (m->C0prime - X[i]) * j / m->M;
#line 183 "paper/mesh.nw"
  }
  
#line 201 "paper/mesh.nw"
for (int t = 0; t < m->ntri; t++)
  if (!(mesh_area(m, t) > 0)) {
    int i = m->tri[3 * t] % m->ncol;
    return status_set(st, STATUS_INPUT,
      "design: triangle %d is inverted (alpha_%d = %g, alpha_%d = %g, "
      "C0prime = %g): alpha must stay below C0prime", t, i, X[i], i + 1,
      X[i + 1], m->C0prime);
  }
#line 185 "paper/mesh.nw"
  return STATUS_OK;
}
#line 212 "paper/mesh.nw"
double mesh_area(const Mesh *m, int t)
{
  const int *v = m->tri + 3 * t;
  const double *p = m->xy + 2 * v[0], *q = m->xy + 2 * v[1],
               *r = m->xy + 2 * v[2];
  return 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
}
#line 226 "paper/mesh.nw"
double mesh_tributary(const Mesh *m, int i)
{
  double len = 0;
  for (int k = i - 1; k <= i; k++)
    if (k >= 0 && k < m->N)
      len += 0.5 * hypot(m->xy[2 * (k + 1)] - m->xy[2 * k],
                         m->xy[2 * (k + 1) + 1] - m->xy[2 * k + 1]);
  return len;
}
#line 240 "paper/mesh.nw"
double mesh_motion(const Mesh *m, int k)
{
  int j = k / m->ncol;
  return j < m->M ? 1.0 - (double) j / m->M : 0.0;
}
#line 248 "paper/mesh.nw"
void mesh_free(Mesh *m)
{
  if (!m) return;
  free(m->xy);
  free(m->tri);
  free(m->material);
  free(m->region);
  free(m->edge);
  free(m->edge_curve);
  free(m);
}
#line 282 "paper/mesh.nw"
static int mesh_join_sizes(Mesh *m, const Problem *p, const Part_mesh *pm);
static int mesh_join_names(Mesh *m, const Problem *p, const Part_mesh *pm,
                           Status *st);
static int mesh_check_rollers(const Mesh *m, const Problem *p, Status *st);

static Mesh *mesh_join_part(Mesh *m, const Problem *p, Status *st)
{
  Part_mesh *pm = part_mesh_new(p, st);
  int rc = !pm || mesh_join_sizes(m, p, pm);
  if (pm && rc)
    status_set(st, STATUS_MEMORY, "mesh: out of memory for %d nodes", m->nnodes);
  if (!rc) {
    mesh_connect(m);
    mesh_place_fixed(m);
    rc = mesh_join_names(m, p, pm, st) || mesh_check_rollers(m, p, st);
  }
  part_mesh_free(pm);
  if (rc) { mesh_free(m); return NULL; }
  return m;
}
#line 306 "paper/mesh.nw"
static int mesh_join_sizes(Mesh *m, const Problem *p, const Part_mesh *pm)
{
  int own = 0;
  for (int k = 0; k < pm->nnodes; k++) own += pm->column[k] < 0;
  m->N = p->N; m->M = p->M; m->R = 0;
  m->ncol = p->N + 1;
  m->nrow = p->M + 1;
  m->nnodes = m->ncol * m->nrow + own;
  m->ntri = 2 * p->N * p->M + pm->ntri;
  m->nedge = pm->nedge;
  m->a = p->a; m->b = p->b; m->C0prime = p->C0prime;
  m->h = (p->b - p->a) / p->N;
  m->gamma = p->C0prime;
  m->xy = malloc(2 * (size_t) m->nnodes * sizeof *m->xy);
  m->tri = malloc(3 * (size_t) m->ntri * sizeof *m->tri);
  m->material = calloc((size_t) m->ntri, sizeof *m->material);
  m->region = calloc((size_t) m->ntri, sizeof *m->region);
  m->edge = malloc(2 * (size_t) (m->nedge + 1) * sizeof *m->edge);
  m->edge_curve = malloc((size_t) (m->nedge + 1) * sizeof *m->edge_curve);
  return !m->xy || !m->tri || !m->material || !m->region || !m->edge
         || !m->edge_curve;
}
#line 334 "paper/mesh.nw"
static int mesh_missing(const Problem *p, const Part_mesh *pm, Status *st);

static int mesh_join_names(Mesh *m, const Problem *p, const Part_mesh *pm,
                           Status *st)
{
  int *to = malloc((size_t) (pm->nnodes + 1) * sizeof *to);
  if (!to) return status_set(st, STATUS_MEMORY, "mesh: out of memory");
  for (int k = 0, next = m->ncol * m->nrow; k < pm->nnodes; k++) {
    to[k] = pm->column[k] >= 0 ? m->M * m->ncol + pm->column[k] : next++;
    m->xy[2 * to[k]] = pm->xy[2 * k];
    m->xy[2 * to[k] + 1] = pm->xy[2 * k + 1];
    m->gamma = fmax(m->gamma, pm->xy[2 * k + 1]);
  }
  for (int t = 0, first = 2 * m->N * m->M; t < pm->ntri; t++) {
    for (int v = 0; v < 3; v++) m->tri[3 * (first + t) + v] = to[pm->tri[3 * t + v]];
    m->material[first + t] = 1 + (pm->region[t] < 0 ? -1
      : problem_region_slot(p, pm->surface_name[pm->region[t]]));
    m->region[first + t] = 2 + pm->region[t];
  }
  for (int e = 0; e < pm->nedge; e++) {
    for (int v = 0; v < 2; v++) m->edge[2 * e + v] = to[pm->edge[2 * e + v]];
    m->edge_curve[e] = pm->curve[e] < 0 ? -1
      : problem_curve_slot(p, pm->curve_name[pm->curve[e]]);
  }
  free(to);
  return mesh_missing(p, pm, st);
}
#line 366 "paper/mesh.nw"
static int mesh_has(char (*names)[PROBLEM_NAME], int n, const char *name)
{
  for (int k = 0; k < n; k++)
    if (strcmp(names[k], name) == 0) return 1;
  return 0;
}

static int mesh_missing(const Problem *p, const Part_mesh *pm, Status *st)
{
  for (int s = 0; s < p->part.ncurve; s++)
    if (!mesh_has(pm->curve_name, pm->ncurve, p->part.curve[s].name))
      return status_set(st, STATUS_INPUT, "%s: boundary.%s: the geometry has "
                        "no physical curve %s", p->part.geometry,
                        p->part.curve[s].name, p->part.curve[s].name);
  for (int s = 0; s < p->part.nregion; s++)
    if (!mesh_has(pm->surface_name, pm->nsurface, p->part.region[s].name))
      return status_set(st, STATUS_INPUT, "%s: material.%s: the geometry has "
                        "no physical surface %s", p->part.geometry,
                        p->part.region[s].name, p->part.region[s].name);
  return STATUS_OK;
}
#line 392 "paper/mesh.nw"
int mesh_curve_normal(const Mesh *m, int slot)
{
  double tol = 1e-12 * (m->b - m->a), lo[2] = {INFINITY, INFINITY},
         hi[2] = {-INFINITY, -INFINITY};
  for (int e = 0; e < m->nedge; e++)
    if (m->edge_curve[e] == slot)
      for (int v = 0; v < 2; v++)
        for (int c = 0; c < 2; c++) {
          double x = m->xy[2 * m->edge[2 * e + v] + c];
          lo[c] = fmin(lo[c], x), hi[c] = fmax(hi[c], x);
        }
  if (hi[1] - lo[1] <= tol) return 1;         /* one height: u2 */
  if (hi[0] - lo[0] <= tol) return 0;         /* one abscissa: u1 */
  return -1;
}

static int mesh_check_rollers(const Mesh *m, const Problem *p, Status *st)
{
  for (int s = 0; s < p->part.ncurve; s++)
    if (p->part.curve[s].kind == BC_ROLLER && mesh_curve_normal(m, s) < 0)
      return status_set(st, STATUS_INPUT, "%s: boundary.%s.bc = roller: the "
                        "curve %s is not a straight line along x1 or x2 (a "
                        "roller holds u1 or u2)", p->part.geometry,
                        p->part.curve[s].name, p->part.curve[s].name);
  return STATUS_OK;
}
#line 422 "paper/mesh.nw"
int mesh_material(const Mesh *m, int t)
{
  return m->material ? m->material[t] : 0;
}
