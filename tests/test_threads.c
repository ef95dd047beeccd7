/* test_threads: the program's threads (paper/threads.nw).  First the rule
   that gives a level-3 call threads by its size, forced to four threads
   whatever the machine's load: a call of f flops gets floor(f / W) threads
   (W = THREADS_WORK), one under 2W, at most four; the calls made through
   the program's definitions (dgemm_, dpotrf_, cblas_dsyrk) return the
   results of the same calls on one thread, to rounding, and leave the BLAS
   at one thread.  Then the advice on OpenBLAS's kernels.  A
   family whose kernels use no AVX2 (Prescott, OpenBLAS's fallback for a
   CPU it does not know, and the older families) on a CPU with AVX2 or
   AVX-512 gets the OPENBLAS_CORETYPE that fits: SkylakeX for AVX-512,
   Haswell for AVX2; a family with AVX2 kernels, a family the user chose,
   a CPU without AVX2 or an unknown BLAS get none.  The families are
   OpenBLAS 0.3.21's names (openblas_get_corename). */
#include <dlfcn.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cblas.h>
#include "check.h"
#include "status.h"
#include "threads.h"

void dgemm_(const char *, const char *, const int *, const int *, const int *,
            const double *, const double *, const int *, const double *,
            const int *, const double *, double *, const int *);
void dpotrf_(const char *, const int *, double *, const int *, int *);

/* the BLAS's own thread count, or -1 without the control */
static int blas_count(void)
{
  int (*get)(void);
  void *s = dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  memcpy(&get, &s, sizeof get);
  return get ? get() : -1;
}
static void blas_set(int n)
{
  void (*set)(int);
  void *s = dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
  memcpy(&set, &s, sizeof set);
  if (set) set(n);
}

/* max |a - b| / max |b| over n values */
static double rel(const double *a, const double *b, size_t n)
{
  double d = 0, m = 0;
  for (size_t i = 0; i < n; i++) d = fmax(d, fabs(a[i] - b[i])), m = fmax(m, fabs(b[i]));
  return d / m;
}

/* C = A B (n x n) through the program's dgemm_, at the rule's threads,
   and through the BLAS at one thread: they agree, and the BLAS rests at 1 */
static void check_gemm(int n, const double *A, const double *B)
{
  double one = 1, zero = 0, *C = malloc(2 * (size_t) n * n * sizeof *C), *C1 = C + (size_t) n * n;
  dgemm_("N", "N", &n, &n, &n, &one, A, &n, B, &n, &zero, C, &n);
  int rest = blas_count();
  blas_set(1);
  cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, n, n, n, 1.0, A, n, B, n, 0.0, C1, n);
  blas_set(1);
  check(rel(C, C1, (size_t) n * n) <= 1e-14 && rest == 1,
        "dgemm_ %dx%d (threads by the rule: %d): the one-thread product to %.1e, the BLAS rests at %d thread",
        n, n, threads_for(2.0 * n * n * n), rel(C, C1, (size_t) n * n), rest);
  free(C);
}

/* A = L L^T through the program's dpotrf_ (the rule's threads): L L^T = A */
static void check_potrf(int n, const double *A)
{
  double *L = malloc(2 * (size_t) n * n * sizeof *L), *LLt = L + (size_t) n * n;
  int info;
  memcpy(L, A, (size_t) n * n * sizeof *L);
  dpotrf_("L", &n, L, &n, &info);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      double s = 0;
      for (int k = 0; k <= (i < j ? i : j); k++) s += L[i + (size_t) k * n] * L[j + (size_t) k * n];
      LLt[i + (size_t) j * n] = s;
    }
  check(info == 0 && rel(LLt, A, (size_t) n * n) <= 1e-13 && blas_count() == 1,
        "dpotrf_ %d (threads by the rule: %d): L L^T = A to %.1e, the BLAS rests at one thread",
        n, threads_for(n * (double) n * n / 3), rel(LLt, A, (size_t) n * n));
  free(L);
}

static void check_rule(void)
{
  const double W = THREADS_WORK;
  threads_by_size(4);
  check(threads_for(1) == 1 && threads_for(2 * W - 1) == 1 && threads_for(2 * W) == 2
        && threads_for(3.5 * W) == 3 && threads_for(4 * W) == 4 && threads_for(1e15) == 4,
        "the rule: one thread under 2W flops, floor(f / W) above, at most the four set");
  if (blas_count() < 0) { printf("# the BLAS has no thread control: its calls not checked\n"); return; }
  check(blas_count() == 1, "after the rule is set the BLAS rests at one thread (%d)", blas_count());
  int n = 640;
  double *A = malloc(2 * (size_t) n * n * sizeof *A), *B = A + (size_t) n * n;
  for (size_t i = 0; i < (size_t) n * n; i++) A[i] = sin(0.37 * i), B[i] = cos(0.11 * i);
  check_gemm(n, A, B);
  check_gemm(40, A, B);
  for (int j = 0; j < n; j++)             /* B = A A^T + n I: positive definite */
    for (int i = 0; i < n; i++) B[i + (size_t) j * n] = i == j ? n : 0;
  cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, n, n, 1.0, A, n, 1.0, B, n);
  for (int j = 0; j < n; j++) for (int i = 0; i < j; i++) B[i + (size_t) j * n] = B[j + (size_t) i * n];
  check_potrf(n, B);
  free(A);
}

/* the advice is want (NULL: none) */
static int advises(const char *kernels, int set, int avx2, int avx512, const char *want)
{
  const char *got = threads_coretype_advice(kernels, set, avx2, avx512);
  return want ? got && !strcmp(got, want) : !got;
}

int main(void)
{
  check_rule();
  static const char *const old[] = { "Prescott", "Core2", "Penryn", "Nehalem",
    "Sandybridge", "Atom", "Opteron", "Barcelona", "Bulldozer" };
  static const char *const wide[] = { "Haswell", "Zen", "SkylakeX", "Cooperlake" };
  for (size_t k = 0; k < sizeof old / sizeof *old; k++) {
    check(advises(old[k], 0, 1, 1, "SkylakeX"), "%s kernels on a CPU with AVX-512: OPENBLAS_CORETYPE=SkylakeX", old[k]);
    check(advises(old[k], 0, 1, 0, "Haswell"), "%s kernels on a CPU with AVX2 only: OPENBLAS_CORETYPE=Haswell", old[k]);
    check(advises(old[k], 1, 1, 1, NULL), "%s chosen by OPENBLAS_CORETYPE: no advice", old[k]);
    check(advises(old[k], 0, 0, 0, NULL), "%s on a CPU without AVX2: no advice", old[k]);
  }
  for (size_t k = 0; k < sizeof wide / sizeof *wide; k++)
    check(advises(wide[k], 0, 1, 1, NULL), "%s kernels (AVX2 or wider): no advice", wide[k]);
  check(advises("unknown", 0, 1, 1, NULL), "a BLAS that names no kernels: no advice");
  return check_done();
}
