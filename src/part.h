#line 73 "paper/part.nw"
#ifndef CONTACTOPT_PART_H
#define CONTACTOPT_PART_H
#include "status.h"
#include "problem.h"

typedef struct {
  int nnodes;        /* nodes of the mesh of Omega' */
  double *xy;        /* 2*nnodes: x1, x2 of node k */
  int *column;       /* nnodes: i when node k is the strip's top node
                        (x_i, C0prime) on the joining segment
                        [a,b]x{C0prime}; its xy is then EXACTLY
                        (problem_node_x(p,i), p->C0prime); -1 otherwise */
  int ntri;
  int *tri;          /* 3*ntri, counter-clockwise (positive area) */
  int *region;       /* ntri: index in surface_name of the triangle's
                        physical surface, -1 when in none */
  int nedge;
  int *edge;         /* 2*nedge: the boundary edges of Omega', except those
                        on the joining segment (inside the body); each
                        runs with the body on its left */
  int *curve;        /* nedge: index in curve_name of the edge's physical
                        curve, -1 when in none */
  int ncurve, nsurface;
  char (*curve_name)[PROBLEM_NAME];    /* names of gmsh's physical groups of dimension 1 */
  char (*surface_name)[PROBLEM_NAME];  /* of dimension 2 */
} Part_mesh;

Part_mesh *part_mesh_new(const Problem *p, Status *st); /* NULL with st set on failure */
void part_mesh_free(Part_mesh *pm); /* accepts NULL */
#endif
