#line 197 "paper/setting.nw"
#ifndef CONTACTOPT_SCENE_H
#define CONTACTOPT_SCENE_H
#include "status.h"
#include "qp.h"

/* The three sides of the body other than the contact surface. */
typedef enum { SIDE_LEFT, SIDE_RIGHT, SIDE_TOP, SIDE_COUNT } Side_id;
/* What a side does: nothing, holds u = 0, holds the normal displacement
   (u1 = 0 on left/right, u2 = 0 on top), or carries a traction. */
typedef enum { BC_FREE, BC_CLAMPED, BC_ROLLER, BC_TRACTION } Bc_kind;

typedef struct {
  Bc_kind kind;      /* the condition on the side */
  double from, to;   /* BC_TRACTION: loaded interval of the side's own
                        coordinate (x2 on left/right, x1 on top), from < to */
  double P[2];       /* BC_TRACTION: traction (P1, P2) on it, N/m^2 */
} Side;

typedef enum { MODEL_PLANE_STRESS, MODEL_PLANE_STRAIN } Plane_model;
typedef enum { OPT_SLSQP, OPT_PROJGRAD } Opt_method;
typedef enum { METRIC_SCHUR, METRIC_EUCLIDEAN } Opt_metric;

typedef struct {
  char path[512];      /* the scene file, as given: every message names it */
  /* [geometry]  Omega(alpha) = {a < x1 < b, alpha(x1) < x2 < gamma} */
  double a, b, gamma;
  /* [design]  U_ad: 0 <= alpha <= C0, |alpha'| <= C1, meas Omega = C2 */
  int N;               /* design intervals; X = (alpha_0..alpha_N) */
  double C0, C1, C2;
  double *alpha0;      /* N+1 nodal values of the initial design (owned) */
  char initial[64];    /* "arc", "line", "constant" or "file" */
  /* [mesh]  M moving rows up to C0prime, then R fixed rows up to gamma */
  int M, R;
  double C0prime;
  /* [material]  isotropic, unit thickness */
  double E, nu;
  Plane_model model;
  /* [left] [right] [top]: the boundary conditions */
  Side side[SIDE_COUNT];
  /* [body_force]  constant F = (F1, F2), N/m^3 */
  double F[2];
  int has_body_force;  /* F != 0: only then is its load assembled */
  /* [solver]  the state problem (4.3): method, tol, max_iter, omega */
  Qp_options solver;
  /* [optimizer]  the shape optimisation (Section 4.4, Algorithm 4.1) */
  Opt_method opt;      /* slsqp (NLopt) or projgrad (Algorithm 4.1) */
  Opt_metric metric;   /* the metric of the design space SLSQP starts in */
  double opt_tol;      /* projected-gradient norm at which it stops */
  int opt_max_iter;    /* iteration limit of the optimiser */
} Scene;

/* Read the scene file at path, then apply the overrides "section.key=value"
   (as given by -s on the command line), then check everything. On failure
   *s holds nothing to free and st names the file, the key and the reason. */
int scene_load(Scene *s, const char *path, int noverride,
               char *const *override, Status *st);
void scene_free(Scene *s);
/* a printable name of a state method, of a plane model, of a condition */
const char *scene_opt_name(Opt_method m);
const char *scene_metric_name(Opt_metric m);
const char *scene_model_name(Plane_model m);
const char *scene_bc_name(Bc_kind k);
#endif
