/* test_pdas.c: the primal-dual active set method (paper/pdas.nw) on the
   small problems of qp_problems.h: against the enumeration, invariant
   under scaling, warm starts, its failures; then at a weakly active node
   of Examples 5.1 and 5.2 (weakly_active.h). */
#include "qp_problems.h"
#include "weakly_active.h"

/* pdas from psor's solution at a tighter tolerance: the active set guessed
   from it is right, and one active-set step ends the solve */
static void check_warm_pdas(Qp_problem *P)
{
  double *x = malloc(P->n * sizeof *x);
  Qp_options o = options(QP_PSOR);
  Run r = run(P, o, NULL, x, NULL);
  o = options(QP_PDAS), o.tol = 1e-14;
  Run r2 = run(P, o, x, x, NULL);
  check(!r.code && !r2.code && r2.rep.iterations == 1, "%s pdas, tol 1e-14, "
        "warm from psor's solution (kkt %.2g): %d active-set step, kkt %.3g%s",
        P->name, r.rep.kkt, r2.rep.iterations, r2.rep.kkt, r2.st.msg);
  free(x);
}

/* a warm start that holds nothing (A semidefinite): pdas starts cold again */
static void check_warm_floating(Qp_problem *P)
{
  double *x = malloc(P->n * sizeof *x);
  for (int i = 0; i < P->n; i++) x[i] = 10;
  Run r = run(P, options(QP_PDAS), x, x, NULL);
  check(!r.code && r.rep.converged, "%s pdas, warm from a floating start: "
        "converged in %d iterations (%s)", P->name, r.rep.iterations, r.st.msg);
  free(x);
}

/* values of A that are not symmetric (outside the contract: pdas reads the
   lower triangle, the residual the columns): pdas's state, refined once,
   misses the tolerance with its active set repeated, and says what it
   measured */
static void check_repeated(void)
{
  Qp_problem *P = obstacle_1d("unsymmetric values", 30, 3);
  double *Ax = P->A->x, x[30];
  const Sparse_index *Ap = P->A->p, *Ai = P->A->i;
  for (Sparse_index k = Ap[1]; k < Ap[2]; k++)  /* A(0,1), not A(1,0): unknown 1 is free */
    if (Ai[k] == 0) Ax[k] *= 1.5;
  Run r = run(P, options(QP_PDAS), NULL, x, NULL);
  check(r.code == STATUS_NUMERIC && has(r.st.msg, "repeated")
        && has(r.st.msg, "kkt = ") && !has(r.st.msg, "\n"),
        "unsymmetric values, pdas: STATUS_NUMERIC \"%s\"", r.st.msg);
  problem_free(P);
}

int main(void)
{
  test_start(&cm);
  check_method(0);
  Qp_problem *P[6];
  problems_new(P);
  check_warm_pdas(P[5]);
  check_warm_floating(P[2]);
  check_repeated();
  problems_free(P);
  cholmod_l_finish(&cm);
  weakly_active_nodes(QP_PDAS);
  return check_done();
}
