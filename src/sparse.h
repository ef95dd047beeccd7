#line 67 "paper/fem.nw"
#ifndef CONTACTOPT_SPARSE_H
#define CONTACTOPT_SPARSE_H
#include <cholmod.h>
/* an index into CHOLMOD's arrays (A->p, A->i, L->p, L->super, Perm, ...):
   the long-integer interface, cholmod_l_* */
typedef SuiteSparse_long Sparse_index;
#endif
