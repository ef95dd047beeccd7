/* test_cgssor.c: MPRGP (solver.state = cgssor, paper/cgssor.nw) on the
   small problems of qp_problems.h: against the enumeration and pdas,
   invariant under scaling, warm starts, its failures; then at a weakly
   active node of Examples 5.1 and 5.2 (weakly_active.h), where it must
   agree with pdas.  Then MPRGP on the dual (solver.state = cgssor with
   friction, paper/cgssor.nw) against the active set method on Example 5.1:
   - given friction at g = 1e7, 2.5e8, 1e9 Pa on N = 16 and 64, and Coulomb
     friction F = 0.2: E to 1e-10 relative, the normal and tangential
     forces to 1e-8 of max|T|, the same nodes in contact and sticking, and
     the KKT residual recomputed by qp_kkt <= tol;
   - g = 0 is the frictionless state;
   - Young's modulus, the load and g scaled by 2^24 change no step count
     (every rounding scales exactly, the square roots of the Cholesky
     factors by 2^12), on N = 16 and 64; scaled by 1e7, the same energy;
   - a warm start from the solution takes no step;
   - a body that its contact alone holds (both sides on rollers) makes S
     singular: the scene refuses cgssor, and so does cgssor itself, with
     one line naming pdas, which solves it;
   - max_iter = 1 fails with the state it reached; a tolerance below the
     rounding of the whole state (1e-15, 1e-300) converges to pdas's state,
     exact to rounding (the residual counts only what exceeds rounding);
   (psor, which cannot take friction, refused by qp_alloc: test_qp.c.) */
#include "qp_problems.h"
#include "weakly_active.h"
#include "case.h"

/* the case solved by pdas (k = 0) and by cgssor (k = 1): the overrides
   ov and the method's */
static void open_pair(Case c[2], int n, char **ov)
{
  char *all[8];
  static char *method[] = { "solver.state=pdas", "solver.state=cgssor" };
  memcpy(all, ov, n * sizeof *ov);
  for (int k = 0; k < 2; k++) {
    all[n] = method[k];
    open_case(&c[k], n + 1, all);
  }
}

/* nodes in contact (Q = lo, exactly) and sticking (u1 = 0, exactly) */
static void count_held(const Model *md, int *contact, int *stick)
{
  const Fem_dofs *d = model_dofs(md);
  *contact = *stick = 0;
  for (int c = 0; c < d->nc; c++) *contact += model_state(md)[d->contact[c]] == model_bounds(md)[c];
  for (int k = 0; k < d->nt; k++) *stick += model_state(md)[d->tangent[k]] == 0;
}

/* cgssor's state is pdas's: energy, forces, contact and stick, residual */
static void compare(Case c[2], const char *what)
{
  if (!check(!c[0].rc && !c[1].rc, "%s: pdas and cgssor solve: %s%s", what,
             c[0].st.msg, c[1].st.msg))
    return;
  const Model *p = c[0].md, *m = c[1].md;
  int nk = model_dofs(p)->nc + model_dofs(p)->nt, cp, sp, cm, sm;
  double E = fabs(model_energy(m) - model_energy(p)) / fabs(model_energy(p));
  double T = max_diff(model_forces(m), model_forces(p), nk) / max_abs(model_forces(p), nk);
  check(E <= 1e-10 && T <= 1e-8, "%s: E to %.1e, the %d normal and "
        "tangential forces to %.1e of max|T| (%d pdas, %d cgssor steps)", what,
        E, nk, T, model_report(p)->iterations, model_report(m)->iterations);
  count_held(p, &cp, &sp), count_held(m, &cm, &sm);
  check(cp == cm && sp == sm && cp > 0, "%s: the same %d nodes in contact and "
        "%d sticking, held exactly (cgssor: %d, %d)", what, cp, sp, cm, sm);
  double kkt = qp_kkt(model_qp(m), model_state(m), NULL);
  check(kkt <= c[1].s.solver.tol && model_report(m)->kkt <= c[1].s.solver.tol,
        "%s: cgssor: qp_kkt %.1e <= tol (reported %.1e)", what, kkt,
        model_report(m)->kkt);
}

/* given friction; *mixed += 1 if cgssor's state both sticks and slips */
static void test_tresca(const char *g, const char *refine, int *mixed)
{
  char pg[32], pr[32], what[64], *ov[] = { "contact.model=tresca", pg, pr };
  Case c[2];
  snprintf(pg, sizeof pg, "contact.g=%s", g);
  snprintf(pr, sizeof pr, "mesh.refine=%s", refine);
  snprintf(what, sizeof what, "tresca g = %s, refine %s", g, refine);
  open_pair(c, 3, ov);
  compare(c, what);
  if (!c[1].rc) {
    const Fem_dofs *d = model_dofs(c[1].md);
    int slip = 0;
    for (int k = 0; k < d->nt; k++) slip += model_state(c[1].md)[d->tangent[k]] != 0;
    *mixed += slip > 0 && slip < d->nt;
  }
  close_case(&c[0]), close_case(&c[1]);
}

static void test_coulomb(const char *refine)
{
  char pr[32], what[64], *ov[] = { "contact.model=coulomb",
                                   "contact.friction=0.2", pr };
  Case c[2];
  snprintf(pr, sizeof pr, "mesh.refine=%s", refine);
  snprintf(what, sizeof what, "coulomb F = 0.2, refine %s", refine);
  open_pair(c, 3, ov);
  compare(c, what);
  if (!c[0].rc && !c[1].rc)
    check(model_fixed_point_residual(c[1].md) <= c[1].s.solver.tol,
          "%s: cgssor: the fixed point converged in %d iterations (pdas %d)",
          what, model_fixed_point_iterations(c[1].md), model_fixed_point_iterations(c[0].md));
  close_case(&c[0]), close_case(&c[1]);
}

/* g = 0: every tangential force fixed at 0, the frictionless state */
static void test_g_zero(void)
{
  char *ov0[] = { "mesh.refine=4" },
       *ov1[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=0",
                  "solver.state=cgssor" };
  Case f, c;
  open_case(&f, 1, ov0), open_case(&c, 4, ov1);
  if (check(!f.rc && !c.rc, "g = 0: solved: %s%s", f.st.msg, c.st.msg)) {
    int nc = model_dofs(f.md)->nc;
    double E = fabs(model_energy(c.md) - model_energy(f.md)) / fabs(model_energy(f.md));
    double T = max_diff(model_forces(c.md), model_forces(f.md), nc) / max_abs(model_forces(f.md), nc);
    double Tt = max_abs(model_forces(c.md) + nc, model_dofs(c.md)->nt) / max_abs(model_forces(f.md), nc);
    check(E <= 1e-10 && T <= 1e-8 && Tt <= 1e-8,
          "g = 0: cgssor gives the frictionless state (4.3): E to %.1e, T to %.1e, "
          "tangential forces %.1e of max|T|", E, T, Tt);
  }
  close_case(&f), close_case(&c);
}

/* E, the load and g times f: overrides into ov (4 strings of 48) */
static void scaled(char ov[4][48], const char *g, const char *refine, double f)
{
  snprintf(ov[0], 48, "mesh.refine=%s", refine);
  snprintf(ov[1], 48, "contact.g=%.17g", atof(g) * f);
  snprintf(ov[2], 48, "material.E=%.17g", 2.15e11 * f);
  snprintf(ov[3], 48, "top.P2=%.17g", -5.75e8 * f);
}

/* E, the load and g times 2^24: every rounding scales exactly (an even
   power, so that the Cholesky factors scale by 2^12), so the same steps
   and E exactly 2^24 times; times 1e7, which is not exact in
   binary, the same energy (the step at which the residual crosses the
   tolerance may move by one, so the counts are not compared) */
static void test_scale(const char *g, const char *refine)
{
  char s1[4][48], s2[4][48], s3[4][48];
  char *ov1[] = { s1[0], s1[1], s1[2], s1[3], "contact.model=tresca", "solver.state=cgssor" };
  char *ov2[] = { s2[0], s2[1], s2[2], s2[3], "contact.model=tresca", "solver.state=cgssor" };
  char *ov3[] = { s3[0], s3[1], s3[2], s3[3], "contact.model=tresca", "solver.state=cgssor" };
  const double two24 = 16777216;
  scaled(s1, g, refine, 1), scaled(s2, g, refine, two24), scaled(s3, g, refine, 1e7);
  Case a, b, c;
  open_case(&a, 6, ov1), open_case(&b, 6, ov2), open_case(&c, 6, ov3);
  if (check(!a.rc && !b.rc && !c.rc, "g = %s, refine %s, scaled by 2^24 and "
            "1e7: solved: %s%s%s", g, refine, a.st.msg, b.st.msg, c.st.msg)) {
    int na = model_report(a.md)->iterations, nb = model_report(b.md)->iterations;
    check(na == nb && model_energy(b.md) == two24 * model_energy(a.md),
          "g = %s, refine %s, scaled by 2^24: %d and %d cgssor steps, E "
          "exactly 2^24 times (%.17g)", g, refine, na, nb, model_energy(b.md) / two24);
    double dE = fabs(model_energy(c.md) / 1e7 - model_energy(a.md)) / fabs(model_energy(a.md));
    check(dE <= 1e-10, "g = %s, refine %s, scaled by 1e7: E / 1e7 to %.1e "
          "(%d and %d steps)", g, refine, dE, na, model_report(c.md)->iterations);
  }
  close_case(&a), close_case(&b), close_case(&c);
}

/* solved again at the same design, from its own state: no step */
static void test_warm(void)
{
  char *ov[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=2.5e8",
                 "solver.state=cgssor" };
  Case c;
  if (check(open_case(&c, 4, ov) == 0, "warm: solved: %s", c.st.msg)) {
    int cold = model_report(c.md)->iterations;
    int rc = model_solve(c.md, c.s.alpha0, &c.st);
    check(rc == 0 && model_report(c.md)->iterations == 0 && cold > 0,
          "warm: from its solution, %d steps (cold: %d)",
          model_report(c.md)->iterations, cold);
  }
  close_case(&c);
}

/* both sides on rollers: the contact alone holds the body up, S is
   singular (S 1 = 0 for the vertical translation): pdas solves it, cgssor
   refuses it */
static void test_singular(void)
{
  char *ov[] = { "left.bc=roller", "contact.model=tresca", "contact.g=2.5e8" };
  Case c[2];
  open_pair(c, 3, ov);
  if (check(!c[0].rc, "rollers: pdas solves: %s", c[0].st.msg)) {
    int nc = model_dofs(c[0].md)->nc;
    double *S = malloc((size_t) nc * nc * sizeof *S), s1 = 0, smax = 0;
    int rc = qp_schur(model_solver(c[0].md), 0, S, &c[0].st);
    for (int i = 0; i < nc; i++) {
      double r = 0;
      for (int j = 0; j < nc; j++) r += S[(size_t) i * nc + j], smax = fmax(smax, fabs(S[(size_t) i * nc + j]));
      s1 = fmax(s1, fabs(r));
    }
    check(rc == 0 && s1 <= 1e-10 * nc * smax, "rollers: S 1 = 0 to %.1e of "
          "max|S|: S is singular", s1 / smax);
    free(S);
  }
  check(c[1].rc == STATUS_INPUT && strstr(c[1].st.msg, "positive definite")
        && strstr(c[1].st.msg, "use pdas") && !strchr(c[1].st.msg, '\n'),
        "rollers: the scene refuses cgssor: %s", c[1].st.msg);
  if (!c[0].rc) {           /* the solver's own refusal, past the scene */
    Qp_options cg = qp_options_default(QP_CGSSOR);
    Status st = {STATUS_OK, ""};
    Model *md = model_new(&c[0].s.problem, &cg, &c[0].cm, &st);
    int rc = md ? model_solve(md, c[0].s.alpha0, &st) : (int) st.code;
    check(rc == STATUS_NUMERIC && strstr(st.msg, "positive definite")
          && strstr(st.msg, "solver.state = pdas") && !strchr(st.msg, '\n'),
          "rollers: cgssor itself refuses: %s", st.msg);
    model_free(md);
  }
  close_case(&c[0]), close_case(&c[1]);
}

/* max_iter = 1: not converged, a finite state */
static void test_max_iter(void)
{
  char *ov[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=2.5e8",
                 "solver.state=cgssor", "solver.max_iter=1" };
  Case c;
  open_case(&c, 5, ov);
  int finite = c.md != NULL;
  for (int i = 0; finite && i < model_dofs(c.md)->n; i++) finite = isfinite(model_state(c.md)[i]);
  check(c.rc == STATUS_NUMERIC && strstr(c.st.msg, "not converged") && finite,
        "max_iter = 1: %s", c.st.msg);
  close_case(&c);
}

/* tol = 1e-15 and 1e-300, below the rounding of the whole state (its
   residual without the allowance for rounding is 2e-14): the residual
   counts only what exceeds that rounding, so the solve converges, on
   every BLAS kernel, when its pair and its state are exact to rounding
   (kkt 0), to pdas's state */
static void test_tol_below_rounding(const char *tol)
{
  char pt[32], *ov[] = { "mesh.refine=4", "contact.model=tresca", "contact.g=2.5e8",
                         "solver.state=cgssor", pt, "solver.max_iter=2000" };
  Case c, p;
  snprintf(pt, sizeof pt, "solver.tol=%s", tol);
  open_case(&c, 6, ov);
  ov[3] = "solver.state=pdas";
  open_case(&p, 6, ov);
  if (check(!c.rc && !p.rc, "tol = %s: cgssor converges (%d steps, kkt %.1e) "
            "and pdas (%d, kkt %.1e)%s%s", tol, c.md ? model_report(c.md)->iterations : -1,
            c.md ? model_report(c.md)->kkt : NAN, p.md ? model_report(p.md)->iterations : -1,
            p.md ? model_report(p.md)->kkt : NAN, c.st.msg, p.st.msg)) {
    int nk = model_dofs(c.md)->nc + model_dofs(c.md)->nt;
    double E = fabs(model_energy(c.md) - model_energy(p.md)) / fabs(model_energy(p.md));
    double T = max_diff(model_forces(c.md), model_forces(p.md), nk) / max_abs(model_forces(p.md), nk);
    check(model_report(c.md)->kkt == 0 && E <= 1e-14 && T <= 1e-10, "tol = %s: "
          "cgssor's state exact to rounding (kkt 0), E to %.1e and the forces "
          "to %.1e of pdas's", tol, E, T);
  }
  close_case(&c), close_case(&p);
}

int main(void)
{
  test_start(&cm);
  check_method(2);
  cholmod_l_finish(&cm);
  weakly_active_nodes(QP_CGSSOR);
  static const char *g[] = { "1e7", "2.5e8", "1e9" };
  int mixed = 0;
  for (int r = 0; r < 2; r++)
    for (int k = 0; k < 3; k++) test_tresca(g[k], r ? "4" : "1", &mixed);
  check(mixed >= 2, "tresca: %d of the 6 states both stick and slip", mixed);
  test_coulomb("1");
  test_coulomb("4");
  test_g_zero();
  for (int k = 0; k < 3; k++) test_scale(g[k], "1");
  for (int k = 0; k < 3; k++) test_scale(g[k], "4");
  test_warm();
  test_singular();
  test_max_iter();
  test_tol_below_rounding("1e-15");
  test_tol_below_rounding("1e-300");
  return check_done();
}
