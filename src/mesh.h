#line 40 "paper/mesh.nw"
#ifndef CONTACTOPT_MESH_H
#define CONTACTOPT_MESH_H
#include "status.h"
#include "problem.h"

typedef struct {
  int N, M, R;       /* design intervals, moving rows, fixed rows */
  int ncol, nrow;    /* N+1 columns and M+R+1 rows of nodes */
  int nnodes;        /* ncol*nrow; node (i,j) has index j*ncol + i */
  int ntri;          /* 2N(M+R) triangles */
  double a, b, gamma, C0prime;
  double h;          /* (b-a)/N, the design step */
  double *xy;        /* 2*nnodes: x1 of node k at xy[2k], x2 at xy[2k+1] */
  int *tri;          /* 3*ntri: the nodes of each triangle, counter-clockwise */
} Mesh;

#line 61 "paper/mesh.nw"
Mesh *mesh_new(const Problem *p, Status *st);     /* topology, fixed nodes */
int mesh_move(Mesh *m, const double *X, Status *st); /* place nodes for X */
double mesh_motion(const Mesh *m, int k); /* d x2(node k) / d alpha_i, (4.2) */
double mesh_area(const Mesh *m, int t);   /* signed area of triangle t */
/* the tributary length of contact node A_i: half of each contact edge
   that meets it, the trapezoid weight along Gamma_C */
double mesh_tributary(const Mesh *m, int i);
void mesh_free(Mesh *m);
#line 57 "paper/mesh.nw"
#endif
