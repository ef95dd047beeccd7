#line 60 "paper/psor.nw"
#include "qp_private.h"
#include "psor.h"

#line 65 "paper/psor.nw"
/* one projected SOR sweep over all unknowns, then the residual */
int psor_iterate(Qp_workspace *w, Status *st)
{
  const cholmod_sparse *A = w->qp->A;
  double *x = w->x, om = w->opt.omega;
  for (int i = 0; i < w->n; i++)
    x[i] = qp_proj(w, i, x[i] - om * (qp_row_dot(A, i, x) - w->qp->b[i])
                                / w->d[i]);
  qp_refresh(w);
  (void) st;      /* a sweep cannot fail; NaN is caught by qp_iterate */
  return STATUS_OK;
}
