/* test_friction: given friction (Tresca) and Coulomb friction, checked
   against what the program did not compute:
   - no friction (g = 0, F = 0) is the frictionless state, to 1e-12;
   - on meshes of N <= 4 intervals, every combination of contact/free and
     stick/slip-left/slip-right per node is solved as a linear system with
     GSL, unless its system is singular (reciprocal condition number from
     the singular values below RCOND_MIN); the one that satisfies every
     condition is the state (energy and forces to 1e-10);
   - E is nondecreasing in g (J grows with g pointwise), and for a large g
     every node in contact sticks;
   - the KKT residual with stick and slip, recomputed by qp_kkt;
   - the Coulomb fixed point: |Tt| <= F Tn nodewise, equality where a node
     slips;
   - Young's modulus, loads and g scaled by 1e7 change no iteration count;
   - the gradient against central differences at designs with sticking and
     slipping nodes, and at a node brought to the stick/slip threshold,
     where E is still differentiable: both one-sided differences converge to
     the gradient, at the rate of their step. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "case.h"
#include "grad.h"


/* g = 0 and F = 0 give the frictionless state */
static void test_no_friction(const char *refine)
{
  char r[32], *ov0[] = { r }, *ovt[] = { r, "contact.model=tresca", "contact.g=0" },
       *ovc[] = { r, "contact.model=coulomb", "contact.friction=0" };
  Case f, t, c;
  snprintf(r, sizeof r, "mesh.refine=%s", refine);
  open_case(&f, 1, ov0), open_case(&t, 3, ovt), open_case(&c, 3, ovc);
  if (check(!f.rc && !t.rc && !c.rc, "refine %s: the three solves succeed: %s%s%s",
            refine, f.st.msg, t.st.msg, c.st.msg)) {
    int n = model_dofs(f.md)->n, nc = model_dofs(f.md)->nc;
    double Q = max_abs(model_state(f.md), n), T = max_abs(model_forces(f.md), nc),
           E = fabs(model_energy(f.md));
    for (Case *x = &t; x; x = x == &t ? &c : NULL) {
      const char *law = x == &t ? "tresca g = 0" : "coulomb F = 0";
      check(fabs(model_energy(x->md) - model_energy(f.md)) <= 1e-12 * E
            && max_diff(model_state(x->md), model_state(f.md), n) <= 1e-12 * Q
            && max_diff(model_forces(x->md), model_forces(f.md), nc) <= 1e-12 * T,
            "refine %s: %s is frictionless (4.3): E %.1e, Q %.1e, T %.1e relative", refine,
            law, fabs(model_energy(x->md) - model_energy(f.md)) / E,
            max_diff(model_state(x->md), model_state(f.md), n) / Q, max_diff(model_forces(x->md), model_forces(f.md), nc) / T);
      check(model_dofs(x->md)->nt > 0 && model_friction_energy(x->md) == 0
            && max_abs(model_forces(x->md) + nc, model_dofs(x->md)->nt) <= 1e-12 * T,
            "refine %s: %s: %d tangential unknowns, no friction force, no work",
            refine, law, model_dofs(x->md)->nt);
    }
    check(model_dofs(f.md)->nt == 0, "refine %s: frictionless: no tangential unknown "
          "is listed", refine);
  }
  close_case(&f), close_case(&t), close_case(&c);
}

/* ---- enumeration of every state on a tiny mesh ------------------------ */

/* A combination whose system has a reciprocal condition number below
   RCOND_MIN is refused: its solution cannot be trusted to the 1e-9 of the
   largest force and displacement that the sign tests allow.  LU with
   partial pivoting leaves a backward error of about n u (n <= 24
   unknowns here, u = 1.1e-16), and the forward error is at most the
   condition number times that: 1e5 keeps it below 2.7e-10.  With the left
   side on rollers, a combination that holds no normal unknown leaves the
   body free to move vertically: its matrix is singular, and rounding
   makes its zero pivot exactly zero (one BLAS kernel) or a tiny number
   (another), whose solution, with displacements of 1e13, passed every
   sign test.  Measured, under the nine OpenBLAS kernels this x86-64 runs: such combinations
   have rcond 1.1e-16 or less (an SVD, which does not depend on where the
   LU meets its zero), every other combination 4.6e-4 or more, and the
   valid ones 7.6e-4 or more. */
#define RCOND_MIN 1e-5

typedef struct {
  int n, nc, nt;
  gsl_matrix *A;     /* dense A */
  const double *b, *lo, *slip;
  const int *ic, *it;
  double *x, *T;     /* the solution found, its forces (nc + nt) */
  int found;         /* valid combinations */
  double J;          /* its energy with friction */
  int refused;       /* combinations refused as ill-conditioned */
  double rc_kept;    /* the smallest rcond of a combination not refused */
  double rc_valid;   /* the smallest of a combination that was valid */
  double rc_refused; /* the largest of a combination that was refused */
} Enum;

/* the reciprocal condition number sigma_min / sigma_max of M (n x n),
   from its singular values (M is overwritten) */
static double rcond(gsl_matrix *M)
{
  size_t n = M->size1;
  gsl_matrix *V = gsl_matrix_alloc(n, n);
  gsl_vector *sv = gsl_vector_alloc(n), *scratch = gsl_vector_alloc(n);
  int bad = gsl_linalg_SV_decomp(M, V, sv, scratch);
  double rc = bad ? 0 : gsl_vector_get(sv, n - 1) / gsl_vector_get(sv, 0);
  gsl_matrix_free(V), gsl_vector_free(sv), gsl_vector_free(scratch);
  return rc == rc ? rc : 0;                      /* NaN: singular */
}

/* solve the linear system of one combination: state[c] 0 free / 1 contact
   for the normal unknowns, then 0 stick / 1 slip with T = -s / 2 slip with
   T = +s for the tangential ones; 1 if it is well conditioned (RCOND_MIN,
   above) and its solution satisfies every condition.  The rows of the
   free equations are divided by A_ii, so that every row has a unit
   diagonal, like the rows x_i = lo_i of the held unknowns: the condition
   number is then that of the mechanics, not of the units. */
static int try_states(Enum *e, const int *state, double *x, double *T,
                      double tf, double tu)
{
  gsl_matrix *M = gsl_matrix_alloc(e->n, e->n), *C = gsl_matrix_alloc(e->n, e->n);
  gsl_vector *r = gsl_vector_alloc(e->n), *sol = gsl_vector_alloc(e->n);
  gsl_permutation *p = gsl_permutation_alloc(e->n);
  gsl_matrix_memcpy(M, e->A);
  for (int i = 0; i < e->n; i++) gsl_vector_set(r, i, e->b[i]);
  for (int c = 0; c < e->nc + e->nt; c++) {
    int i = c < e->nc ? e->ic[c] : e->it[c - e->nc], s = state[c];
    int held = c < e->nc ? s == 1 : s == 0;
    if (held) {
      for (int j = 0; j < e->n; j++) gsl_matrix_set(M, i, j, i == j);
      gsl_vector_set(r, i, c < e->nc ? e->lo[c] : 0);
    } else if (c >= e->nc)
      gsl_vector_set(r, i, e->b[i] + (s == 1 ? -1 : 1) * e->slip[c - e->nc]);
  }
  for (int i = 0; i < e->n; i++) {               /* unit diagonal */
    gsl_vector_view row = gsl_matrix_row(M, i);
    double d = gsl_matrix_get(M, i, i);
    gsl_vector_scale(&row.vector, 1 / d);
    gsl_vector_set(r, i, gsl_vector_get(r, i) / d);
  }
  gsl_matrix_memcpy(C, M);
  double rc = rcond(C);
  if (rc >= RCOND_MIN) e->rc_kept = fmin(e->rc_kept, rc);
  int sign, ok = rc >= RCOND_MIN && !gsl_linalg_LU_decomp(M, p, &sign)
                 && !gsl_linalg_LU_solve(M, p, r, sol);
  if (!(rc >= RCOND_MIN)) e->refused++, e->rc_refused = fmax(e->rc_refused, rc);
  for (int i = 0; ok && i < e->n; i++) x[i] = gsl_vector_get(sol, i);
  for (int c = 0; ok && c < e->nc + e->nt; c++) {
    int i = c < e->nc ? e->ic[c] : e->it[c - e->nc], s = state[c];
    double Ax = 0;
    for (int j = 0; j < e->n; j++) Ax += gsl_matrix_get(e->A, i, j) * x[j];
    T[c] = Ax - e->b[i];
    if (c < e->nc) ok = s ? T[c] >= -tf : x[i] >= e->lo[c] - tu;
    else {
      double sl = e->slip[c - e->nc];
      ok = s == 0 ? fabs(T[c]) <= sl + tf : s == 1 ? x[i] >= -tu : x[i] <= tu;
    }
  }
  if (ok) e->rc_valid = fmin(e->rc_valid, rc);
  gsl_matrix_free(M), gsl_matrix_free(C), gsl_vector_free(r), gsl_vector_free(sol);
  gsl_permutation_free(p);
  return ok;
}

/* every combination; e->x, e->T the last valid one, e->found how many */
static void enumerate(Enum *e, double tf, double tu)
{
  int m = e->nc + e->nt, *state = calloc(m, sizeof *state);
  double *x = malloc(e->n * sizeof *x), *T = malloc(m * sizeof *T);
  for (;;) {
    if (try_states(e, state, x, T, tf, tu)) {
      if (e->found && max_diff(x, e->x, e->n) > 1e-9 * max_abs(e->x, e->n) + tu)
        e->found = -1000000;          /* two different solutions: impossible */
      memcpy(e->x, x, e->n * sizeof *x), memcpy(e->T, T, m * sizeof *T);
      e->found++;
    }
    int c = 0;
    while (c < m && ++state[c] == (c < e->nc ? 2 : 3)) state[c++] = 0;
    if (c == m) break;
  }
  free(state), free(x), free(T);
}

static void test_enumeration(const char *bcs, const char *P1, const char *g,
                             int *stick, int *slip)
{
  char pg[32], pp[32], *ov[] = { "design.N=4", "mesh.R=1", "contact.model=tresca",
                                 pg, pp, (char *) bcs };
  snprintf(pg, sizeof pg, "contact.g=%s", g);
  snprintf(pp, sizeof pp, "top.P1=%s", P1);
  Case k;
  if (!check(open_case(&k, 6, ov) == 0, "N = 4, %s, P1 = %s, g = %s: solved: %s",
             bcs, P1, g, k.st.msg)) { close_case(&k); return; }
  Model *md = k.md;
  const Fem_dofs *d = model_dofs(md);
  Enum e = { d->n, d->nc, d->nt, gsl_matrix_calloc(d->n, d->n),
             model_load(md), model_bounds(md), model_slip(md), d->contact, d->tangent,
             malloc(d->n * sizeof(double)),
             malloc((d->nc + d->nt) * sizeof(double)), 0, 0,
             0, INFINITY, INFINITY, 0 };
  const Sparse_index *Ap = model_stiffness(md)->p, *Ai = model_stiffness(md)->i;
  const double *Ax = model_stiffness(md)->x;
  for (int j = 0; j < e.n; j++)
    for (Sparse_index q = Ap[j]; q < Ap[j + 1]; q++) gsl_matrix_set(e.A, Ai[q], j, Ax[q]);
  int m = e.nc + e.nt;
  double Tmax = max_abs(model_forces(md), m), umax = max_abs(model_state(md), e.n);
  enumerate(&e, 1e-9 * Tmax, 1e-9 * umax);
  check(e.rc_refused < 1e-12 && e.rc_kept >= 10 * RCOND_MIN, "N = 4, %s, "
        "P1 = %s, g = %s: the %d combinations refused as singular have rcond "
        "<= %.1e, the others >= %.1e (the valid ones >= %.1e): a decade or "
        "more from RCOND_MIN = %.0e", bcs, P1, g, e.refused, e.rc_refused,
        e.rc_kept, e.rc_valid, RCOND_MIN);
  if (check(e.found >= 1, "N = 4, %s, P1 = %s, g = %s: one state among the %d "
            "combinations satisfies every condition (%d found)", bcs, P1, g,
            (1 << e.nc) * (int) pow(3, e.nt), e.found)) {
    double J = 0;
    for (int i = 0; i < e.n; i++) {
      double Ax_i = 0;
      for (int j = 0; j < e.n; j++) Ax_i += gsl_matrix_get(e.A, i, j) * e.x[j];
      J += e.x[i] * (0.5 * Ax_i - e.b[i]);
    }
    for (int t = 0; t < e.nt; t++) J += e.slip[t] * fabs(e.x[e.it[t]]);
    check(fabs(J - model_energy(md)) <= 1e-10 * fabs(J)
          && max_diff(e.T, model_forces(md), m) <= 1e-10 * max_abs(e.T, m),
          "N = 4, %s, P1 = %s, g = %s: E and the forces (normal and tangential) "
          "are those of the enumeration: %.1e, %.1e", bcs, P1, g,
          fabs(J - model_energy(md)) / fabs(J), max_diff(e.T, model_forces(md), m) / max_abs(e.T, m));
    for (int t = 0; t < e.nt; t++) {
      int s = fabs(e.x[e.it[t]]) > 1e-9 * umax;
      *slip += s, *stick += !s;
    }
  }
  gsl_matrix_free(e.A), free(e.x), free(e.T);
  close_case(&k);
}

static void test_enumerations(void)
{
  static const char *bcs[] = { "left.bc=clamped", "left.bc=roller" };
  static const char *P1[] = { "0", "2e8" };
  static const char *g[] = { "0", "1e7", "1e8", "3e8", "1e9", "1e11" };
  int stick = 0, slip = 0;
  for (int b = 0; b < 2; b++)
    for (int p = 0; p < 2; p++)
      for (int k = 0; k < 6; k++) test_enumeration(bcs[b], P1[p], g[k], &stick, &slip);
  check(stick > 10 && slip > 10, "the enumerated states stick and slip: %d "
        "sticking and %d slipping nodes over the 24 cases", stick, slip);
}

/* ---- E against g, large g, the KKT residual, scaling ------------------ */

static void test_monotone(void)
{
  static const char *g[] = { "0", "1e5", "1e6", "1e7", "3e7", "1e8", "3e8",
                             "1e9", "1e10" };
  double last = -INFINITY;
  int mono = 1, ok = 1;
  for (int k = 0; k < 9; k++) {
    char pg[32], *ov[] = { "mesh.refine=2", "contact.model=tresca", pg };
    snprintf(pg, sizeof pg, "contact.g=%s", g[k]);
    Case c;
    ok &= open_case(&c, 3, ov) == 0;
    if (!c.rc) {
      mono &= model_energy(c.md) >= last - 1e-12 * fabs(last);
      last = model_energy(c.md);
      double kkt = qp_kkt(model_qp(c.md), model_state(c.md), NULL);
      check(kkt <= c.s.solver.tol && model_report(c.md)->kkt <= c.s.solver.tol,
            "g = %s: qp_kkt with stick and slip %.1e <= tol (solver: %.1e)",
            g[k], kkt, model_report(c.md)->kkt);
    }
    close_case(&c);
  }
  check(ok && mono, "E is nondecreasing in g over 0 .. 1e10 Pa (last %.10g)", last);
}

static void test_large_g(void)
{
  char *ov[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=1e12" };
  Case c;
  if (check(open_case(&c, 3, ov) == 0, "g = 1e12: solved: %s", c.st.msg)) {
    const Fem_dofs *d = model_dofs(c.md);
    const double *Q = model_state(c.md), *lo = model_bounds(c.md),
                 *T = model_forces(c.md), *slip = model_slip(c.md);
    int touching = 0, stuck = 0;
    for (int k = 0, j = 0; k < d->nt; k++) {
      while (j < d->nc && d->contact_col[j] < d->tangent_col[k]) j++;
      if (j == d->nc || d->contact_col[j] != d->tangent_col[k]) continue;
      if (Q[d->contact[j]] <= lo[j] && T[j] > 0) {
        touching++;
        stuck += Q[d->tangent[k]] == 0 && fabs(T[d->nc + k]) < slip[k];
      }
    }
    check(touching > 0 && stuck == touching, "g = 1e12: every node in contact "
          "sticks (%d of %d, u1 = 0 exactly, |Tt| < g omega)", stuck, touching);
  }
  close_case(&c);
}

/* E, loads and g scaled by 1e7: the same steps, forces and energy scaled */
static void test_scale(void)
{
  char *ov1[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=3e8" };
  char *ov2[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=3e15",
                  "material.E=2.15e18", "top.P2=-5.75e15" };
  Case a, b;
  open_case(&a, 3, ov1), open_case(&b, 5, ov2);
  if (check(!a.rc && !b.rc, "scaled by 1e7: both solved"))
    check(model_report(a.md)->iterations == model_report(b.md)->iterations
          && fabs(model_energy(b.md) / 1e7 - model_energy(a.md)) <= 1e-9 * fabs(model_energy(a.md)),
          "scaled by 1e7: %d and %d active-set steps, E / 1e7 to %.1e",
          model_report(a.md)->iterations, model_report(b.md)->iterations,
          fabs(model_energy(b.md) / 1e7 - model_energy(a.md)) / fabs(model_energy(a.md)));
  close_case(&a), close_case(&b);
}

/* ---- Coulomb ------------------------------------------------------------ */

static void test_coulomb(const char *F)
{
  char pf[32], *ov[] = { "mesh.refine=2", "contact.model=coulomb", pf };
  snprintf(pf, sizeof pf, "contact.friction=%s", F);
  Case c;
  if (check(open_case(&c, 3, ov) == 0, "coulomb F = %s: converged: %s", F, c.st.msg)) {
    const Fem_dofs *d = model_dofs(c.md);
    double f = atof(F), Tmax = max_abs(model_forces(c.md), d->nc), umax = max_abs(model_state(c.md), d->n);
    double over = 0, miss = 0;
    int slipping = 0;
    for (int k = 0, j = 0; k < d->nt; k++) {
      while (j < d->nc && d->contact_col[j] < d->tangent_col[k]) j++;
      double Tn = j < d->nc && d->contact_col[j] == d->tangent_col[k] ? model_forces(c.md)[j] : 0;
      double Tt = fabs(model_forces(c.md)[d->nc + k]);
      over = fmax(over, Tt - f * Tn);
      if (fabs(model_state(c.md)[d->tangent[k]]) > 1e-9 * umax)
        slipping++, miss = fmax(miss, fabs(Tt - f * Tn));
    }
    check(over <= 1e-8 * Tmax && miss <= 1e-8 * Tmax && slipping > 0,
          "coulomb F = %s: |Tt| <= F Tn to %.1e, equality at the %d slipping "
          "nodes to %.1e (of max T), after %d fixed-point iterations", F,
          over / Tmax, slipping, miss / Tmax, model_fixed_point_iterations(c.md));
    check(model_fixed_point_residual(c.md) <= c.s.solver.tol,
          "coulomb F = %s: the normal forces changed by %.1e <= tol at the end",
          F, model_fixed_point_residual(c.md));
  }
  close_case(&c);
}

/* ---- the gradient --------------------------------------------------------- */

static void test_gradcheck(const char *g, const char *shape)
{
  char pg[32], *ov[] = { "contact.model=tresca", pg, (char *) shape };
  snprintf(pg, sizeof pg, "contact.g=%s", g);
  Case c;
  if (!check(open_case(&c, shape ? 3 : 2, ov) == 0, "gradcheck g = %s: solved", g)) {
    close_case(&c);
    return;
  }
  const Fem_dofs *d = model_dofs(c.md);
  int stick = 0, slip = 0;
  for (int k = 0; k < d->nt; k++) {
    double u = fabs(model_state(c.md)[d->tangent[k]]);
    stick += u == 0, slip += u > 0;
  }
  Grad_check *gc = grad_check_new(c.s.problem.N, &c.st);
  int rc = grad_check(c.md, c.s.alpha0, gc, NULL, NULL, &c.st);
  check(rc == 0 && gc->err[gc->worst] <= 1e-6 && stick > 0 && slip > 0,
        "gradcheck g = %s%s%s: %d sticking, %d slipping nodes: largest error "
        "of (4.8) %.1e of max|G| (node %d)", g, shape ? ", " : "", shape ? shape : "",
        stick, slip, gc->err[gc->worst], gc->worst);
  grad_check_free(gc);
  close_case(&c);
}

/* the one-sided differences of E in X_i at X, steps h and h/10 */
static void one_sided(Model *md, double *X, int i, double h, double d[4])
{
  Status st;
  double x0 = X[i], E0;
  model_solve(md, X, &st), E0 = model_energy(md);
  for (int k = 0; k < 4; k++) {
    double s = (k % 2 ? -1 : 1) * (k < 2 ? h : h / 10);
    X[i] = x0 + s;
    model_solve(md, X, &st);
    d[k] = (model_energy(md) - E0) / s;
  }
  X[i] = x0;
  model_solve(md, X, &st);
}

/* bring the sticking node next to the slip zone to the threshold by
   bisection on g; there both one-sided differences approach G */
static void test_threshold(void)
{
  char *ov[] = { "contact.model=tresca", "contact.g=2.5e8" };
  Case c;
  if (!check(open_case(&c, 2, ov) == 0, "threshold: solved")) { close_case(&c); return; }
  Problem *p = &c.s.problem;
  const Fem_dofs *d = model_dofs(c.md);
  int k = -1;
  for (int j = 0; j + 1 < d->nt; j++)      /* a stick node beside a slipping one */
    if (model_state(c.md)[d->tangent[j]] == 0 && model_state(c.md)[d->tangent[j + 1]] != 0) k = j;
  if (!check(k >= 0, "threshold: a sticking node beside a slipping one")) {
    close_case(&c);
    return;
  }
  double lo = 0, hi = p->slip_bound;          /* slips at lo = 0, sticks at hi */
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
    p->slip_bound = 0.5 * (lo + hi);
    model_solve(c.md, c.s.alpha0, &c.st);
    if (model_state(c.md)[d->tangent[k]] == 0) hi = p->slip_bound; else lo = p->slip_bound;
  }
  p->slip_bound = hi;
  model_solve(c.md, c.s.alpha0, &c.st);
  int i = d->tangent_col[k], N = p->N;
  double *G = malloc((N + 1) * sizeof *G), *X = malloc((N + 1) * sizeof *X), D[4];
  grad_energy(c.md, G, &c.st);
  double Tt = fabs(model_forces(c.md)[d->nc + k]), Gmax = max_abs(G, N + 1);
  check(model_state(c.md)[d->tangent[k]] == 0 && Tt >= (1 - 1e-6) * model_slip(c.md)[k],
        "threshold: node %d sticks with |Tt| = g omega to %.1e (g = %.12g Pa)", i,
        1 - Tt / model_slip(c.md)[k], p->slip_bound);
  memcpy(X, c.s.alpha0, (N + 1) * sizeof *X);
  double h = 1e-4 * p->C0;
  one_sided(c.md, X, i, h, D);
  double ef = fabs(D[0] - G[i]) / Gmax, eb = fabs(D[1] - G[i]) / Gmax,
         ef10 = fabs(D[2] - G[i]) / Gmax, eb10 = fabs(D[3] - G[i]) / Gmax;
  check(ef <= 1e-3 && eb <= 1e-3 && ef10 <= 0.2 * ef + 1e-9 && eb10 <= 0.2 * eb + 1e-9,
        "threshold: the forward and backward differences in X_%d tend to G_%d "
        "of (4.8) at the rate of their step: %.1e -> %.1e and %.1e -> %.1e of max|G| "
        "(h = %.0e, h/10)", i, i, ef, ef10, eb, eb10, h);
  free(G), free(X);
  close_case(&c);
}

int main(void)
{
  test_no_friction("1");
  test_no_friction("4");
  test_enumerations();
  test_monotone();
  test_large_g();
  test_scale();
  test_coulomb("0.1");
  test_coulomb("0.2");
  test_coulomb("0.3");
  test_gradcheck("1.5e8", NULL);
  test_gradcheck("2.5e8", NULL);
  test_gradcheck("3e8", NULL);
  test_gradcheck("2.5e8", "mesh.refine=2");
  test_threshold();
  return check_done();
}
