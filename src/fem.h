#line 77 "paper/fem.nw"
#ifndef CONTACTOPT_FEM_H
#define CONTACTOPT_FEM_H
#include "sparse.h"
#include "status.h"
#include "problem.h"
#include "mesh.h"

typedef struct {
  int ndof;          /* 2*nnodes: DOF 2k is u1, 2k+1 is u2 of node k */
  int n;             /* unknowns: the DOFs that no side holds */
  int *unknown;      /* ndof: the unknown of each DOF, or -1 when held */
  int nc;            /* |I|: contact nodes whose u2 is an unknown */
  int *contact;      /* nc: the unknown of u2 at each of them */
  int *contact_col;  /* nc: its column i, the node A_i */
  int nt;            /* with friction: contact nodes whose u1 is an
                        unknown; 0 on a frictionless foundation */
  int *tangent;      /* nt: the unknown of u1 at each of them */
  int *tangent_col;  /* nt: its column i */
} Fem_dofs;

/* Hooke's law: stress (s11, s22, s12) = D strain, strains (e11, e22,
   2 e12); the stress across the plane s33 = D33 . strain, 0 in plane
   stress */
typedef struct { double D[3][3]; double D33[3]; } Fem_hooke;

#line 107 "paper/fem.nw"
Fem_dofs *fem_dofs_new(const Mesh *m, const Problem *p, Status *st);
void fem_dofs_free(Fem_dofs *d);
Fem_hooke fem_hooke(const Problem *p);
Fem_hooke fem_hooke_of(const Problem_material *m, Problem_plane_model model);
const char *fem_material_refusal(const Problem_material *m,
                                 Problem_plane_model model, char *buf,
                                 size_t size);
#line 673 "paper/fem.nw"
/* xy = (x1, y1, x2, y2, x3, y3), the vertices of triangle t */
void fem_element_xy(const Mesh *m, int t, double xy[6]);
/* q = (u1, u2) at the three vertices of triangle t; 0 where held */
void fem_element_q(const Mesh *m, const Fem_dofs *d, const double *Q, int t,
                   double q[6]);
/* gx, gy = 2|T| times the shape-function gradients; returns 2|T| */
double fem_element_gradients(const double xy[6], double gx[3], double gy[3]);
/* e = the unnormalised strain 2|T| (e11, e22, 2 e12) of q */
void fem_element_strain(const double gx[3], const double gy[3],
                        const double q[6], long double e[3]);
/* e = the strain (e11, e22, 2 e12) of triangle t under the displacement
   Q, constant on it; returns 2|T| */
double fem_triangle_strain(const Mesh *m, const Fem_dofs *d, const double *Q,
                           int t, long double e[3]);
/* s = D e, the stress (s11, s22, s12) of the strain e [Pa when Young's modulus is] */
void fem_element_stress(const Fem_hooke *H, const long double e[3], long double s[3]);
/* s33 = D33 e, the stress across the plane of the strain e (plane strain) */
long double fem_element_stress33(const Fem_hooke *H, const long double e[3]);
#line 115 "paper/fem.nw"
void fem_element_stiffness(const double xy[6], const Fem_hooke *H,
                           double K[6][6]);
cholmod_sparse *fem_stiffness_new(const Mesh *m, const Fem_dofs *d,
                                  cholmod_common *cm, Status *st);
int fem_stiffness_fill(cholmod_sparse *A, const Mesh *m, const Fem_dofs *d,
                       const Fem_hooke *H, Status *st);
void fem_load(const Mesh *m, const Fem_dofs *d, const Problem *p, double *b);
/* L = the resultant of the loads on a part's curves, N/m */
void fem_curve_resultant(const Mesh *m, const Problem *p, double L[2]);
/* E = 1/2 Q'AQ - b'Q, summed element by element as a strain energy */
double fem_energy(const Mesh *m, const Fem_dofs *d, const Fem_hooke *H,
                  const double *b, const double *Q);
#line 1169 "paper/fem.nw"
/* r (ndof) = K u - f at the held DOFs, the force of the sides on the
   body [N/m when Young's modulus is in Pa]; 0 at the unknowns */
void fem_reactions(const Mesh *m, const Fem_dofs *d, const Fem_hooke *H,
                   const Problem *p, const double *Q, double *r);
/* the side whose reaction the held DOF k takes, SIDE_COUNT + s for the
   slot s of a part's curve, -1 if nothing holds it */
int fem_reaction_side(const Mesh *m, const Problem *p, int k);
#line 103 "paper/fem.nw"
#endif
