/* test_qp.c: the interface of the state problem (4.3) (paper/qp.nw): the
   enumeration that the solvers' tests compare with finds the solution of
   each small problem of qp_problems.h; qp_alloc refuses the input errors
   of the contract and psor with friction; qp_solve refuses NaN in the
   data.  The solvers themselves: test_pdas.c, test_psor.c, test_cgssor.c;
   the Schur complement that qp_schur hands over: test_condense.c. */
#include "qp_problems.h"
#include "case.h"

/* the reference of each small problem exists, with bounds active and not */
static void check_reference(Qp_problem *P)
{
  double *xr = malloc(P->n * sizeof *xr);
  int found = reference(P, xr);
  int m = found ? count_touching(P, xr) : -1;
  check(found && m > 0 && m < P->nc, "%s: the enumeration finds the solution "
        "of (4.3), %d of %d bounds active", P->name, m, P->nc);
  free(xr);
}

/* the input errors of the contract, and NaN in the data */
static void check_input_errors(Qp_problem *P)
{
  Qp_options o = options(QP_PSOR);
  Status st = { STATUS_OK, "" };
  P->A->stype = 1;
  check(!qp_alloc(&P->qp, &o, &cm, &st) && st.code == STATUS_INPUT,
        "A with stype 1 refused: \"%s\"", st.msg);
  P->A->stype = 0;
  o.omega = 2;
  check(!qp_alloc(&P->qp, &o, &cm, &st) && st.code == STATUS_INPUT,
        "omega = 2 refused: \"%s\"", st.msg);
  o = options(QP_PDAS), o.tol = 0;
  check(!qp_alloc(&P->qp, &o, &cm, &st) && st.code == STATUS_INPUT,
        "tol = 0 refused: \"%s\"", st.msg);
  o = options(QP_PDAS);
  int ic1 = P->ic[1];
  P->ic[1] = P->ic[0];
  check(!qp_alloc(&P->qp, &o, &cm, &st) && st.code == STATUS_INPUT,
        "repeated bounded unknown refused: \"%s\"", st.msg);
  P->ic[1] = ic1;
  double *x = malloc(P->n * sizeof *x), b1 = P->b[1], lo0 = P->lo[0];
  P->b[1] = NAN;
  Run r = run(P, o, NULL, x, NULL);
  check(r.code == STATUS_NUMERIC && has(r.st.msg, "b[1]"),
        "NaN in b: STATUS_NUMERIC \"%s\"", r.st.msg);
  P->b[1] = b1, P->lo[0] = INFINITY;
  r = run(P, o, NULL, x, NULL);
  check(r.code == STATUS_NUMERIC && has(r.st.msg, "lo[0]"),
        "infinite lo: STATUS_NUMERIC \"%s\"", r.st.msg);
  P->lo[0] = lo0;
  for (int i = 0; i < P->n; i++) x[i] = i == 2 ? NAN : 0;
  r = run(P, o, x, x, NULL);
  check(r.code == STATUS_NUMERIC && has(r.st.msg, "starting point"),
        "NaN in x0: STATUS_NUMERIC \"%s\"", r.st.msg);
  free(x);
}

/* a pattern that is not symmetric, and a zero diagonal entry */
static void check_bad_matrices(void)
{
  Qp_problem *P = obstacle_1d("unsymmetric", 6, 2);
  Status st = { STATUS_OK, "" };
  Qp_options o = options(QP_PDAS);
  cholmod_l_free_sparse(&P->A, &cm);
  P->D[0 * 6 + 3] = 0.5;
  problem_finish(P);
  check(!qp_alloc(&P->qp, &o, &cm, &st) && st.code == STATUS_INPUT,
        "unsymmetric pattern refused: \"%s\"", st.msg);
  problem_free(P);
  P = obstacle_1d("zero diagonal", 6, 2);
  ((double *) P->A->x)[0] = 0;       /* A(0,0): the first entry of column 0 */
  double x[6];
  Run r = run(P, o, NULL, x, NULL);
  check(r.code == STATUS_INPUT && has(r.st.msg, "diagonal"),
        "zero diagonal refused: \"%s\"", r.st.msg);
  problem_free(P);
}

/* psor with friction: qp_alloc refuses it, naming the two that take it */
static void test_psor_refused(void)
{
  char *ov[] = { "contact.model=tresca", "contact.g=2.5e8", "solver.state=cgssor" };
  Case c;
  if (check(open_case(&c, 3, ov) == 0, "psor: the problem solved by cgssor: %s",
            c.st.msg)) {
    Qp_options opt = qp_options_default(QP_PSOR);
    Status st = { STATUS_OK, "" };
    Qp_workspace *w = qp_alloc(model_qp(c.md), &opt, &c.cm, &st);
    check(!w && st.code == STATUS_INPUT && strstr(st.msg, "psor")
          && strstr(st.msg, "pdas or cgssor"), "psor: refused: %s", st.msg);
    qp_free(w);
  }
  close_case(&c);
}

int main(void)
{
  test_start(&cm);
  Qp_problem *P[6];
  problems_new(P);
  for (int k = 0; k < 5; k++) check_reference(P[k]);
  check_input_errors(P[0]);
  check_bad_matrices();
  test_psor_refused();
  problems_free(P);
  cholmod_l_finish(&cm);
  return check_done();
}
