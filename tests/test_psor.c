/* test_psor.c: projected SOR (paper/psor.nw) on the small problems of qp_problems.h:
   against the enumeration and pdas, invariant under scaling, warm starts,
   its failures; then at a weakly active node of Examples 5.1 and 5.2
   (weakly_active.h), where it must agree with pdas. */
#include "qp_problems.h"
#include "weakly_active.h"

int main(void)
{
  test_start(&cm);
  check_method(1);
  cholmod_l_finish(&cm);
  weakly_active_nodes(QP_PSOR);
  return check_done();
}
