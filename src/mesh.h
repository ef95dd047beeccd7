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
  /* a part of the user's own (NULL, 0 for the rectangle): */
  int *material;     /* ntri: 0 the problem's material, 1 + s region s's */
  int *region;       /* ntri: 0 the strip, 1 the part outside its named
                        surfaces, 2 + k the geometry's physical surface k */
  int nedge;         /* the part's boundary edges, */
  int *edge;         /* 2*nedge: their nodes, the body on their left, */
  int *edge_curve;   /* nedge: the slot s of part.curve naming it, or -1 */
} Mesh;

#line 68 "paper/mesh.nw"
Mesh *mesh_new(const Problem *p, Status *st);     /* topology, fixed nodes */
int mesh_move(Mesh *m, const double *X, Status *st); /* place nodes for X */
double mesh_motion(const Mesh *m, int k); /* d x2(node k) / d alpha_i, (4.2) */
double mesh_area(const Mesh *m, int t);   /* signed area of triangle t */
/* the tributary length of contact node A_i: half of each contact edge
   that meets it, the trapezoid weight along Gamma_C */
double mesh_tributary(const Mesh *m, int i);
/* the material of triangle t: 0 the problem's, 1 + s region s's */
int mesh_material(const Mesh *m, int t);
/* the component a roller on the part's curve of this slot holds: 1 (u2)
   when the curve is one horizontal line, 0 (u1) one vertical line, else -1 */
int mesh_curve_normal(const Mesh *m, int slot);
void mesh_free(Mesh *m);
#line 64 "paper/mesh.nw"
#endif
