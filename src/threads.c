#line 112 "paper/threads.nw"
#define _GNU_SOURCE             /* dladdr, RTLD_NEXT, CPU_COUNT */
#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/resource.h>
#include <gsl/gsl_cblas.h>
#include "threads.h"
#line 128 "paper/threads.nw"
#define CHOLMOD_OMP 4           /* CHOLMOD 3.0's CHOLMOD_OMP_NUM_THREADS */
#define ASKED "CONTACTOPT_BLAS_THREADS_ASKED"   /* set by the restart */
typedef struct {
  void (*set)(int);            /* openblas_set_num_threads, or NULL */
  int (*get)(void);            /* openblas_get_num_threads */
  char *(*core)(void);         /* openblas_get_corename */
  char *(*config)(void);       /* openblas_get_config */
  int (*parallel)(void);       /* openblas_get_parallel: 0, 1 pthreads, 2 OpenMP */
  void (*omp_levels)(int);     /* omp_set_max_active_levels (libgomp) */
  char blas[64];               /* "OpenBLAS-0.3.21", or "unknown" */
  char library[PATH_MAX];      /* the file that defines dgemm_ */
  char kernels[32];            /* OpenBLAS's kernel family, or "unknown" */
  int cores, physical;         /* CPUs the process may run on; their cores */
  double load;                 /* the 15-minute load average at start */
  int asked;                   /* BLAS threads the user asked for (0: none) */
  const char *asked_by;        /* the variable that asked */
  int omp_asked;               /* OMP_NUM_THREADS, 0 if unset */
  int blas_threads;            /* the most threads a BLAS call may use */
  int by_size;                 /* 1: each level-3 call gets threads by size */
  int omp_threads;             /* threads of CHOLMOD's parallel regions */
  const char *chosen_by;       /* "program", the variable, or "memory" */
  int found, started;
} Threads;
static Threads T;
#line 175 "paper/threads.nw"
/* s begins with prefix: the rest of s, else NULL */
static const char *after(const char *s, const char *prefix)
{
  while (*prefix && *s == *prefix) s++, prefix++;
  return *prefix ? NULL : s;
}

static void restart_alone(int argc, char **argv, char **envp)
{
  static char mark[128] = ASKED "=";
  struct rlimit lim;
  const char *asked = "", *v;
  int n = 0, m = 0;
  (void) argc;
  if (!envp || getrlimit(RLIMIT_AS, &lim) || lim.rlim_cur == RLIM_INFINITY) return;
  for (; envp[n]; n++) {
    if (after(envp[n], ASKED "=")) return;              /* restarted */
    if ((v = after(envp[n], "OPENBLAS_NUM_THREADS="))) asked = v;
  }
  if (asked[0] == '1' && !asked[1]) return;              /* alone already */
  char *env[n + 3];
  for (int k = 0; k < n; k++)
    if (!after(envp[k], "OPENBLAS_NUM_THREADS=")) env[m++] = envp[k];
  for (int k = sizeof ASKED; *asked && k < (int) sizeof mark - 1; ) mark[k++] = *asked++;
  env[m++] = "OPENBLAS_NUM_THREADS=1", env[m++] = mark, env[m] = NULL;
  execve("/proc/self/exe", argv, env);
}
__attribute__((section(".preinit_array"), used))
static void (*restart_entry)(int, char **, char **) = restart_alone;
#line 214 "paper/threads.nw"
/* *fp = the symbol name of the libraries after this executable, or NULL */
static void find(void *fp, size_t size, void *where, const char *name)
{
  void *s = dlsym(where, name);
  memcpy(fp, &s, size);
}
#define FIND(fp, where, name) find(&(fp), sizeof (fp), where, name)

#line 244 "paper/threads.nw"
static void put_back_asked(void)
{
  const char *asked = getenv(ASKED);
  if (!asked) return;
  if (asked[0]) setenv("OPENBLAS_NUM_THREADS", asked, 1);
  else unsetenv("OPENBLAS_NUM_THREADS");
  unsetenv(ASKED);
}
#line 258 "paper/threads.nw"
static void name_blas(Threads *t)
{
  void *dgemm;
  Dl_info info;
  char name[32] = "", version[32] = "";
  snprintf(t->blas, sizeof t->blas, "unknown");
  snprintf(t->kernels, sizeof t->kernels, "unknown");
  snprintf(t->library, sizeof t->library, "unknown");
  if (t->config && sscanf(t->config(), "%31s %31s", name, version) == 2)
    snprintf(t->blas, sizeof t->blas, "%s-%s", name, version);
  if (t->core) snprintf(t->kernels, sizeof t->kernels, "%s", t->core());
  FIND(dgemm, RTLD_NEXT, "dgemm_");
  if (dgemm && dladdr(dgemm, &info) && info.dli_fname
      && !realpath(info.dli_fname, t->library))
    snprintf(t->library, sizeof t->library, "%s", info.dli_fname);
}
#line 280 "paper/threads.nw"
/* the first CPU of cpu's core (its thread siblings), or cpu */
static int first_sibling(int cpu)
{
  char path[96];
  int first = cpu;
  snprintf(path, sizeof path,
           "/sys/devices/system/cpu/cpu%d/topology/thread_siblings_list", cpu);
  FILE *f = fopen(path, "r");
  if (f && fscanf(f, "%d", &first) != 1) first = cpu;
  if (f) fclose(f);
  return first;
}

static void count_cores(Threads *t)
{
  cpu_set_t set;
  t->cores = t->physical = 0;
  if (sched_getaffinity(0, sizeof set, &set)) {
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    t->cores = t->physical = n > 0 ? (int) n : 1;
    return;
  }
  t->cores = CPU_COUNT(&set);
  for (int c = 0; c < CPU_SETSIZE; c++) {
    int s = CPU_ISSET(c, &set) ? first_sibling(c) : -1;
    t->physical += s == c || (s >= 0 && s < CPU_SETSIZE && !CPU_ISSET(s, &set));
  }
  if (t->physical < 1) t->physical = t->cores;
}

/* the 15-minute load average, 0 if unknown */
static double load_average(void)
{
  double load[3];
  return getloadavg(load, 3) == 3 ? load[2] : 0;
}

#line 226 "paper/threads.nw"
static void threads_find(Threads *t)
{
  if (t->found) return;
  t->found = 1;
  put_back_asked();
  FIND(t->set, RTLD_DEFAULT, "openblas_set_num_threads");
  FIND(t->get, RTLD_DEFAULT, "openblas_get_num_threads");
  FIND(t->core, RTLD_DEFAULT, "openblas_get_corename");
  FIND(t->config, RTLD_DEFAULT, "openblas_get_config");
  FIND(t->parallel, RTLD_DEFAULT, "openblas_get_parallel");
  FIND(t->omp_levels, RTLD_DEFAULT, "omp_set_max_active_levels");
  name_blas(t);
  count_cores(t);
  t->load = load_average();
}
#line 335 "paper/threads.nw"
/* a positive count from the environment variable name, else 0 */
static int count_from(const char *name)
{
  const char *v = getenv(name);
  long n = v ? strtol(v, NULL, 10) : 0;
  return n > 0 && n < INT_MAX ? (int) n : 0;
}

static void choose(Threads *t)
{
  static const char *const names[] =
    { "OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS" };
  t->asked = 0, t->asked_by = NULL;
  for (int k = 0; k < 3 && !t->asked; k++)
    if ((t->asked = count_from(names[k]))) t->asked_by = names[k];
  t->omp_asked = count_from("OMP_NUM_THREADS");
  int idle = t->physical - (int) floor(t->load + 0.1);
  t->blas_threads = t->asked ? t->asked : idle > 1 ? idle : 1;
  t->by_size = !t->asked;
  t->chosen_by = t->asked ? t->asked_by : "program";
  t->omp_threads = t->omp_asked > 1 ? CHOLMOD_OMP : 1;
  if (!t->set) t->blas_threads = t->get ? t->get() : 1, t->by_size = 0;
  if (t->parallel && t->parallel() == 2) t->omp_threads = CHOLMOD_OMP;
}
#line 378 "paper/threads.nw"
#define OPENBLAS_BUFFER (32.0 * (1 << 22))  /* BUFFER_SIZE, x86-64 */

/* bytes: the address-space limit (INFINITY if none), what is mapped */
static double limit_bytes(void)
{
  struct rlimit lim;
  if (getrlimit(RLIMIT_AS, &lim) || lim.rlim_cur == RLIM_INFINITY) return INFINITY;
  return (double) lim.rlim_cur;
}

static double mapped_bytes(void)
{
  unsigned long pages = 0;
  FILE *f = fopen("/proc/self/statm", "r");
  if (f && fscanf(f, "%lu", &pages) != 1) pages = 0;
  if (f) fclose(f);
  return (double) pages * (double) sysconf(_SC_PAGESIZE);
}

/* bytes: the stack of a new thread and its guard */
static double stack_bytes(void)
{
  pthread_attr_t a;
  size_t size = 8 << 20, guard = 4096;
  if (!pthread_getattr_default_np(&a)) {
    pthread_attr_getstacksize(&a, &size), pthread_attr_getguardsize(&a, &guard);
    pthread_attr_destroy(&a);
  }
  return (double) size + (double) guard;
}
#line 420 "paper/threads.nw"
static int fit(Threads *t, const char *origin, double need, Status *st)
{
  double L = limit_bytes(), M = mapped_bytes(), S = stack_bytes();
  double B = t->set ? OPENBLAS_BUFFER : 0, room = L - M - B - need;
  if (!(M + B > L)) {
    double omp = t->omp_threads > 1 ? (CHOLMOD_OMP - 1) * S : 0;
    if (omp > 0 && !(omp <= room)) t->omp_threads = 1, omp = 0;
    double workers = floor((room - omp) / (B + S));
    if (isfinite(L) && t->blas_threads > 1 + workers) {
      int fits = workers > 0 ? 1 + (int) workers : 1;
      if (t->asked)
        fprintf(stderr, "contactopt: %s=%d: %d BLAS thread%s in the %.3g GB "
                "this process may use (%s reserves %.3g GB per thread)\n",
                t->asked_by, t->asked, fits, fits > 1 ? "s fit" : " fits", L / 1e9,
                t->blas, (B + S) / 1e9);
      t->blas_threads = fits, t->chosen_by = "memory";
    }
    return STATUS_OK;
  }
  return status_set(st, STATUS_MEMORY, "%s: the BLAS (%s) reserves %.3g GB for "
                    "each thread: one thread needs about %.3g GB with the %.3g GB "
                    "this process maps already, more than the %.3g GB it may use",
                    origin, t->blas, B / 1e9, (M + B) / 1e9, M / 1e9, L / 1e9);
}
#line 455 "paper/threads.nw"
#define WARM_N 16384             /* > 10^4, >= any count of threads used */
static void warm(int threads)
{
  static double a[1], c[1], x[2 * WARM_N];
  cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, 1, 1, 1.0, a, 1, 0.0, c, 1);
  if (threads > 1) cblas_daxpy(WARM_N, 1.0, x, 1, x + WARM_N, 1);
}
#line 481 "paper/threads.nw"
const char *threads_coretype_advice(const char *kernels, int coretype_set,
                                    int avx2, int avx512)
{
  static const char *const wide[] = { "Haswell", "Zen", "SkylakeX",
    "Cooperlake", "SapphireRapids", "Excavator" };
  if (coretype_set || !avx2 || !strcmp(kernels, "unknown")) return NULL;
  for (size_t k = 0; k < sizeof wide / sizeof *wide; k++)
    if (!strcmp(kernels, wide[k])) return NULL;
  return avx512 ? "SkylakeX" : "Haswell";
}

/* the family that fits this CPU where OpenBLAS runs an older one that
   the user did not choose, else NULL */
static const char *kernels_advised(const Threads *t)
{
  __builtin_cpu_init();
  int avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw")
               && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
  return threads_coretype_advice(t->kernels, getenv("OPENBLAS_CORETYPE") != NULL,
                                 __builtin_cpu_supports("avx2")
                                 && __builtin_cpu_supports("fma"), avx512);
}

static void advise_kernels(const Threads *t, FILE *f)
{
  const char *fits = kernels_advised(t);
  if (fits)
    fprintf(f, "contactopt: note: %s runs its %s kernels, which use no AVX2, on a "
            "CPU with %s; OPENBLAS_CORETYPE=%s selects the kernels for it\n",
            t->blas, t->kernels, strcmp(fits, "SkylakeX") ? "AVX2" : "AVX-512", fits);
}
#line 531 "paper/threads.nw"
__attribute__((constructor))
static void threads_load(void)
{
  threads_find(&T);
  choose(&T);
  if (T.omp_threads == 1 && T.omp_levels) T.omp_levels(0);
}

int threads_start(const char *origin, double need, Status *st)
{
  Threads *t = &T;
  int rc;
  threads_find(t);
  choose(t);
  if ((rc = fit(t, origin, need, st))) return rc;
  if (t->by_size) threads_by_size(t->blas_threads);
  else if (t->set) {
    t->set(t->blas_threads);
    if (t->get && t->get() < t->blas_threads) t->blas_threads = t->get();
    warm(t->blas_threads);
  }
  if (t->omp_threads == 1 && t->omp_levels) t->omp_levels(0);
  if (t->omp_threads == 1 && !t->omp_levels) t->omp_threads = CHOLMOD_OMP;
  if (!t->started && isatty(STDERR_FILENO)) advise_kernels(t, stderr);
  t->started = 1;
  return STATUS_OK;
}

void threads_by_size(int most)
{
  Threads *t = &T;
  threads_find(t);
  if (!t->set) return;
  t->set(most);
  t->blas_threads = t->get && t->get() < most ? t->get() : most;
  warm(t->blas_threads);
  t->set(1);
  t->by_size = 1;
}
#line 586 "paper/threads.nw"
int threads_for(double f)
{
  double k = floor(f / THREADS_WORK);
  if (!T.by_size) return 0;
  return k < 2 ? 1 : k < T.blas_threads ? (int) k : T.blas_threads;
}

/* the threads a call of f flops gets (set now), or 0 if left as it is */
static int enter(double f)
{
  int n = threads_for(f);
  if (n < 2) return 0;
  T.set(n);
  return n;
}
static void leave(int n) { if (n) T.set(1); }

#define NEXT(type, name) static type next; \
  if (!next) FIND(next, RTLD_NEXT, name)
#line 611 "paper/threads.nw"
typedef void (*gemm_f)(const char *, const char *, const int *, const int *,
                       const int *, const double *, const double *, const int *,
                       const double *, const int *, const double *, double *,
                       const int *);
void dgemm_(const char *ta, const char *tb, const int *m, const int *n,
            const int *k, const double *alpha, const double *A, const int *lda,
            const double *B, const int *ldb, const double *beta, double *C,
            const int *ldc)
{
  NEXT(gemm_f, "dgemm_");
  int use = enter(2.0 * *m * *n * *k);
  next(ta, tb, m, n, k, alpha, A, lda, B, ldb, beta, C, ldc);
  leave(use);
}

typedef void (*syrk_f)(const char *, const char *, const int *, const int *,
                       const double *, const double *, const int *,
                       const double *, double *, const int *);
void dsyrk_(const char *uplo, const char *trans, const int *n, const int *k,
            const double *alpha, const double *A, const int *lda,
            const double *beta, double *C, const int *ldc)
{
  NEXT(syrk_f, "dsyrk_");
  int use = enter(1.0 * *n * *n * *k);
  next(uplo, trans, n, k, alpha, A, lda, beta, C, ldc);
  leave(use);
}

typedef void (*trsm_f)(const char *, const char *, const char *, const char *,
                       const int *, const int *, const double *, const double *,
                       const int *, double *, const int *);
void dtrsm_(const char *side, const char *uplo, const char *trans,
            const char *diag, const int *m, const int *n, const double *alpha,
            const double *A, const int *lda, double *B, const int *ldb)
{
  NEXT(trsm_f, "dtrsm_");
  int left = *side == 'L' || *side == 'l';
  int use = enter(1.0 * *m * *n * (left ? *m : *n));
  next(side, uplo, trans, diag, m, n, alpha, A, lda, B, ldb);
  leave(use);
}

typedef void (*potrf_f)(const char *, const int *, double *, const int *, int *);
void dpotrf_(const char *uplo, const int *n, double *A, const int *lda, int *info)
{
  NEXT(potrf_f, "dpotrf_");
  int use = enter(*n * (double) *n * *n / 3);
  next(uplo, n, A, lda, info);
  leave(use);
}
#line 664 "paper/threads.nw"
typedef void (*cgemm_f)(enum CBLAS_ORDER, enum CBLAS_TRANSPOSE,
                        enum CBLAS_TRANSPOSE, int, int, int, double,
                        const double *, int, const double *, int, double,
                        double *, int);
void cblas_dgemm(const enum CBLAS_ORDER order, const enum CBLAS_TRANSPOSE ta,
                 const enum CBLAS_TRANSPOSE tb, const int m, const int n,
                 const int k, const double alpha, const double *A, const int lda,
                 const double *B, const int ldb, const double beta, double *C,
                 const int ldc)
{
  NEXT(cgemm_f, "cblas_dgemm");
  int use = enter(2.0 * m * n * k);
  next(order, ta, tb, m, n, k, alpha, A, lda, B, ldb, beta, C, ldc);
  leave(use);
}

typedef void (*csyrk_f)(enum CBLAS_ORDER, enum CBLAS_UPLO, enum CBLAS_TRANSPOSE,
                        int, int, double, const double *, int, double, double *, int);
void cblas_dsyrk(const enum CBLAS_ORDER order, const enum CBLAS_UPLO uplo,
                 const enum CBLAS_TRANSPOSE trans, const int n, const int k,
                 const double alpha, const double *A, const int lda,
                 const double beta, double *C, const int ldc)
{
  NEXT(csyrk_f, "cblas_dsyrk");
  int use = enter(1.0 * n * n * k);
  next(order, uplo, trans, n, k, alpha, A, lda, beta, C, ldc);
  leave(use);
}

typedef void (*ctrsm_f)(enum CBLAS_ORDER, enum CBLAS_SIDE, enum CBLAS_UPLO,
                        enum CBLAS_TRANSPOSE, enum CBLAS_DIAG, int, int, double,
                        const double *, int, double *, int);
void cblas_dtrsm(const enum CBLAS_ORDER order, const enum CBLAS_SIDE side,
                 const enum CBLAS_UPLO uplo, const enum CBLAS_TRANSPOSE trans,
                 const enum CBLAS_DIAG diag, const int m, const int n,
                 const double alpha, const double *A, const int lda, double *B,
                 const int ldb)
{
  NEXT(ctrsm_f, "cblas_dtrsm");
  int use = enter(1.0 * m * n * (side == CblasLeft ? m : n));
  next(order, side, uplo, trans, diag, m, n, alpha, A, lda, B, ldb);
  leave(use);
}
#line 712 "paper/threads.nw"
/* the choice made, or, before threads_start, the one it would make */
static Threads described(void)
{
  threads_find(&T);
  Threads d = T;
  if (!d.started) choose(&d);
  return d;
}

void threads_summary(FILE *f)
{
  Threads d = described(), *t = &d;
  const char *fits = kernels_advised(t);
  fprintf(f, "blas %s\nblas_library %s\nblas_kernels %s\nblas_kernels_advised %s\n",
          t->blas, t->library, t->kernels, fits ? fits : "none");
  fprintf(f, "blas_threads %d\nblas_threads_by_size %d\nthreads_chosen_by %s\n",
          t->blas_threads, t->by_size, t->chosen_by);
  fprintf(f, "openmp_threads %d\ncores %d\nphysical_cores %d\nload_average %.2f\n",
          t->omp_threads, t->cores, t->physical, t->load);
}

void threads_version(FILE *f)
{
  Threads d = described(), *t = &d;
  fprintf(f, "BLAS: %s (%s), %s kernels\n", t->blas, t->library, t->kernels);
  if (t->by_size)
    fprintf(f, "threads: a BLAS call on up to %d by its size (one under %.3g flops), "
            "CHOLMOD's OpenMP regions on one; %d cores, %d physical, 15-minute "
            "load %.2f\n", t->blas_threads, 2 * THREADS_WORK, t->cores,
            t->physical, t->load);
  else
    fprintf(f, "threads: a BLAS call on %d (%s), CHOLMOD's OpenMP regions on %d; "
            "%d cores, %d physical\n", t->blas_threads, t->asked_by ? t->asked_by
            : "the BLAS's own", t->omp_threads, t->cores, t->physical);
  advise_kernels(t, f);
}
