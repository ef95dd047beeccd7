#line 95 "paper/problem.nw"
#ifndef CONTACTOPT_PROBLEM_H
#define CONTACTOPT_PROBLEM_H
#include <stddef.h>

#line 113 "paper/problem.nw"
/* The three sides of the body other than the contact surface. */
typedef enum { SIDE_LEFT, SIDE_RIGHT, SIDE_TOP, SIDE_COUNT } Problem_side_id;
/* What a side does: nothing, holds u = 0, holds the normal displacement
   (u1 = 0 on left/right, u2 = 0 on top), or carries a traction. */
typedef enum { BC_FREE, BC_CLAMPED, BC_ROLLER, BC_TRACTION, BC_PRESSURE }
  Problem_bc_kind;   /* BC_PRESSURE: on a named curve of a part only */

typedef struct {
  Problem_bc_kind kind; /* the condition on the side */
  double from, to;   /* BC_TRACTION: loaded interval of the side's own
                        coordinate (x2 on left/right, x1 on top), from < to */
  double P[2];       /* BC_TRACTION: traction (P1, P2) on it, N/m^2 */
} Problem_side;
#line 131 "paper/problem.nw"
typedef enum { MODEL_PLANE_STRESS, MODEL_PLANE_STRAIN } Problem_plane_model;
#line 140 "paper/problem.nw"
typedef enum { CONTACT_FRICTIONLESS, CONTACT_TRESCA, CONTACT_COULOMB }
  Problem_contact_law;
#line 152 "paper/problem.nw"
typedef enum { MATERIAL_ISOTROPIC, MATERIAL_ORTHOTROPIC } Problem_material_kind;
typedef struct {
  Problem_material_kind kind;
  double young, nu;          /* isotropic: Young's modulus (Pa), Poisson */
  double E1, E2, nu12, G12;  /* orthotropic, in its axes (Pa, 1, Pa) */
  double E3, nu13, nu23;     /* orthotropic in plane strain */
  double angle;              /* orthotropic: axis 1 from x1, degrees */
} Problem_material;
#line 170 "paper/problem.nw"
enum { PROBLEM_NAME = 64, PROBLEM_NAMED = 32 };
typedef struct {
  char name[PROBLEM_NAME]; /* a physical curve of the geometry */
  Problem_bc_kind kind;    /* free, clamped, roller, traction, pressure */
  double P[2];             /* BC_TRACTION: the traction (P1, P2), Pa */
  double pressure;         /* BC_PRESSURE: Pa, pushing into the body */
  int normal;              /* BC_ROLLER: the component it holds, 0 (u1,
                              a vertical curve) or 1 (u2, a horizontal
                              one), found in the geometry by the scene */
} Problem_curve;
typedef struct {
  char name[PROBLEM_NAME]; /* a physical surface of the geometry */
  Problem_material material;
} Problem_region;
typedef struct {
  char geometry[4096];     /* the geometry's absolute path; "": rectangle */
  int refine;              /* mesh.refine: the geometry's own mesh sizes
                              are divided by it (N, M are multiplied) */
  int ncurve, nregion;     /* named curves and surfaces given a value */
  double area;             /* found by the scene in the geometry's mesh: */
  double load[2];          /* its area and the resultant of its curves'
                              loads (N/m), for the check of a body that
                              friction holds sideways */
  int nodes;               /* and its nodes, those of the joining segment
                              not counted: for the memory estimate */
  Problem_curve curve[PROBLEM_NAMED];
  Problem_region region[PROBLEM_NAMED];
} Problem_part;
#line 201 "paper/problem.nw"
typedef struct {
  /* Omega(alpha) = {a < x1 < b, alpha(x1) < x2 < gamma} */
  double a, b, gamma;
  /* U_ad (2.1): 0 <= alpha <= C0, |alpha'| <= C1, meas Omega = C2, and
     its discretisation by N intervals: X = (alpha_0 .. alpha_N) */
  int N;
  double C0, C1, C2;
  /* the mesh: M moving rows of cells up to C0prime, R fixed ones above */
  int M, R;
  double C0prime;
  /* the material of the strip (and of a part outside its named
     surfaces), unit thickness, and the plane model of the whole body */
  Problem_material material;
  Problem_plane_model model;
  /* a part of the user's own above the strip, or the rectangle */
  Problem_part part;
  /* the conditions of the sides: Gamma_D and Gamma_P */
  Problem_side side[SIDE_COUNT];
  /* the body force F = (F1, F2), N/m^3, constant */
  double body_force[2];
  int has_body_force;  /* F != 0: only then is its load assembled */
  /* the foundation {x2 <= 0}: frictionless, given friction with the slip
     bound g (Pa), or Coulomb friction with the coefficient friction */
  Problem_contact_law contact;
  double slip_bound;   /* CONTACT_TRESCA: g >= 0 */
  double friction;     /* CONTACT_COULOMB: the coefficient, >= 0 */
  int max_fixed_point; /* CONTACT_COULOMB: the most rounds of its fixed
                          point after the first solve, >= 1 */
} Problem;

#line 250 "paper/problem.nw"
extern const char *const problem_model_names[]; /* plane_stress, ... */
extern const char *const problem_bc_names[];    /* free, clamped, ... */
extern const char *const problem_contact_names[]; /* frictionless, ... */
const char *problem_model_name(Problem_plane_model m);
const char *problem_bc_name(Problem_bc_kind k);
const char *problem_contact_name(Problem_contact_law law);
/* x_i = a + i (b - a) / N, with x_0 = a and x_N = b exactly */
double problem_node_x(const Problem *p, int i);
/* buf = the conditions that could hold the body, for a message:
   "left.bc = .., right.bc = .., top.bc = .." (a part: its curves instead
   of the top, "boundary.* free or loaded" when none holds anything) */
void problem_supports(const Problem *p, char *buf, size_t size);
/* the slot of part.curve (part.region) with this name, or -1 */
int problem_curve_slot(const Problem *p, const char *name);
int problem_region_slot(const Problem *p, const char *name);
#line 107 "paper/problem.nw"
#endif
