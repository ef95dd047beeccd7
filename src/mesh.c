#line 87 "paper/mesh.nw"
#include <math.h>
#include <stdlib.h>
#include "mesh.h"
#line 95 "paper/mesh.nw"
static void mesh_connect(Mesh *m);
static void mesh_place_fixed(Mesh *m);

Mesh *mesh_new(const Problem *p, Status *st)
{
  Mesh *m = calloc(1, sizeof *m);
  if (!m) { status_set(st, STATUS_MEMORY, "mesh: out of memory"); return NULL; }
  
#line 117 "paper/mesh.nw"
m->N = p->N; m->M = p->M; m->R = p->R;
m->ncol = p->N + 1;
m->nrow = p->M + p->R + 1;
m->nnodes = m->ncol * m->nrow;
m->ntri = 2 * p->N * (p->M + p->R);
m->a = p->a; m->b = p->b; m->gamma = p->gamma; m->C0prime = p->C0prime;
m->h = (p->b - p->a) / p->N;
#line 103 "paper/mesh.nw"
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
#line 132 "paper/mesh.nw"
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
#line 146 "paper/mesh.nw"
static void mesh_place_fixed(Mesh *m)
{
  for (int j = 0; j < m->nrow; j++)
    for (int i = 0; i < m->ncol; i++) {
      int k = j * m->ncol + i;
      m->xy[2 * k] = i == m->N ? m->b : m->a + i * m->h;
      if (j >= m->M)
        m->xy[2 * k + 1] = m->C0prime
          + (m->gamma - m->C0prime) * (j - m->M) / m->R;
    }
}
#line 161 "paper/mesh.nw"
int mesh_move(Mesh *m, const double *X, Status *st)
{
  for (int i = 0; i < m->ncol; i++) {
    
#line 173 "paper/mesh.nw"
if (!(X[i] >= 0))
  return status_set(st, STATUS_INPUT,
    "design: alpha_%d = %g is below the foundation x2 = 0", i, X[i]);
for (int j = 0; j < m->M; j++)
  m->xy[2 * (j * m->ncol + i) + 1] = X[i] + (m->C0prime - X[i]) * j / m->M;
#line 165 "paper/mesh.nw"
  }
  
#line 183 "paper/mesh.nw"
for (int t = 0; t < m->ntri; t++)
  if (!(mesh_area(m, t) > 0)) {
    int i = m->tri[3 * t] % m->ncol;
    return status_set(st, STATUS_INPUT,
      "design: triangle %d is inverted (alpha_%d = %g, alpha_%d = %g, "
      "C0prime = %g): alpha must stay below C0prime", t, i, X[i], i + 1,
      X[i + 1], m->C0prime);
  }
#line 167 "paper/mesh.nw"
  return STATUS_OK;
}
#line 194 "paper/mesh.nw"
double mesh_area(const Mesh *m, int t)
{
  const int *v = m->tri + 3 * t;
  const double *p = m->xy + 2 * v[0], *q = m->xy + 2 * v[1],
               *r = m->xy + 2 * v[2];
  return 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
}
#line 208 "paper/mesh.nw"
double mesh_tributary(const Mesh *m, int i)
{
  double len = 0;
  for (int k = i - 1; k <= i; k++)
    if (k >= 0 && k < m->N)
      len += 0.5 * hypot(m->xy[2 * (k + 1)] - m->xy[2 * k],
                         m->xy[2 * (k + 1) + 1] - m->xy[2 * k + 1]);
  return len;
}
#line 222 "paper/mesh.nw"
double mesh_motion(const Mesh *m, int k)
{
  int j = k / m->ncol;
  return j < m->M ? 1.0 - (double) j / m->M : 0.0;
}
#line 230 "paper/mesh.nw"
void mesh_free(Mesh *m)
{
  if (!m) return;
  free(m->xy);
  free(m->tri);
  free(m);
}
