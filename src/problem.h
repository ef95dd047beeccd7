#line 95 "paper/problem.nw"
#ifndef CONTACTOPT_PROBLEM_H
#define CONTACTOPT_PROBLEM_H

#line 110 "paper/problem.nw"
/* The three sides of the body other than the contact surface. */
typedef enum { SIDE_LEFT, SIDE_RIGHT, SIDE_TOP, SIDE_COUNT } Problem_side_id;
/* What a side does: nothing, holds u = 0, holds the normal displacement
   (u1 = 0 on left/right, u2 = 0 on top), or carries a traction. */
typedef enum { BC_FREE, BC_CLAMPED, BC_ROLLER, BC_TRACTION } Problem_bc_kind;

typedef struct {
  Problem_bc_kind kind; /* the condition on the side */
  double from, to;   /* BC_TRACTION: loaded interval of the side's own
                        coordinate (x2 on left/right, x1 on top), from < to */
  double P[2];       /* BC_TRACTION: traction (P1, P2) on it, N/m^2 */
} Problem_side;
#line 127 "paper/problem.nw"
typedef enum { MODEL_PLANE_STRESS, MODEL_PLANE_STRAIN } Problem_plane_model;
#line 136 "paper/problem.nw"
typedef enum { CONTACT_FRICTIONLESS, CONTACT_TRESCA, CONTACT_COULOMB }
  Problem_contact_law;
#line 141 "paper/problem.nw"
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
  /* the material: isotropic, unit thickness, Young's modulus in N/m^2
     (the scene's key E) and Poisson's ratio */
  double young, nu;
  Problem_plane_model model;
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

#line 188 "paper/problem.nw"
extern const char *const problem_model_names[]; /* plane_stress, ... */
extern const char *const problem_bc_names[];    /* free, clamped, ... */
extern const char *const problem_contact_names[]; /* frictionless, ... */
const char *problem_model_name(Problem_plane_model m);
const char *problem_bc_name(Problem_bc_kind k);
const char *problem_contact_name(Problem_contact_law law);
/* x_i = a + i (b - a) / N, with x_0 = a and x_N = b exactly */
double problem_node_x(const Problem *p, int i);
#line 104 "paper/problem.nw"
#endif
