#line 62 "paper/threads.nw"
#ifndef CONTACTOPT_THREADS_H
#define CONTACTOPT_THREADS_H
#include <stdio.h>
#include "status.h"

/* flops a BLAS call must bring per thread before it gets one more
   thread: about 0.5 ms of a core's work, twice what engaging a
   sleeping worker was measured to cost (Performance) */
#define THREADS_WORK 16777216.0

/* choose the threads of the BLAS and of CHOLMOD's OpenMP regions for a
   run whose model needs about need bytes, create them and reserve the
   BLAS's buffers now; STATUS_MEMORY when not one BLAS thread fits */
int threads_start(const char *origin, double need, Status *st);
/* the program's rule, which threads_start sets with the idle cores: a
   level-3 call gets threads by its size, at most `most`; creates them */
void threads_by_size(int most);
/* the threads the rule gives a call of f flops, 0 when it is not set */
int threads_for(double f);
/* the lines of summary.dat that say what computed the run */
void threads_summary(FILE *f);
/* the same for a person (contactopt --version) */
void threads_version(FILE *f);
/* the OPENBLAS_CORETYPE that fits a CPU with AVX2 or AVX-512 whose BLAS
   runs the kernels of an older family, or NULL when none is due */
const char *threads_coretype_advice(const char *kernels, int coretype_set,
                                    int avx2, int avx512);
#endif
