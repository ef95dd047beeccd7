/* unknown_cpu.c: an LD_PRELOAD shim that makes this machine look, to the
   program and to OpenBLAS, like the 16-core Xeon: a CPU that
   OpenBLAS 0.3.21 does not know, where it falls back to its Prescott
   kernels unasked, with many cores.
   - Run with OPENBLAS_CORETYPE=F: OpenBLAS reads it as it loads and runs
     the kernels of F; the shim removes the variable when the program
     first asks which kernels run, so that the program finds them chosen
     by OpenBLAS, not by the user.
   - UNKNOWN_CPU_CORES=n (optional): the process may run on n CPUs
     (sched_getaffinity, sysconf), so that OpenBLAS starts its threads and
     the program chooses them as on n cores; the threads then share the
     machine's real cores.
   make builds it (build/kernels/unknown_cpu.so); tests/threads.sh and
   make check-kernels use it. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NEXT(fp, name) do { if (!(fp)) { void *s_ = dlsym(RTLD_NEXT, name); \
  memcpy(&(fp), &s_, sizeof (fp)); } } while (0)

char *openblas_get_corename(void)
{
  static char *(*next)(void);
  NEXT(next, "openblas_get_corename");
  unsetenv("OPENBLAS_CORETYPE");
  return next ? next() : "unknown";
}

/* the cores asked for, 0 for the machine's own */
static int cores(void)
{
  const char *v = getenv("UNKNOWN_CPU_CORES");
  int n = v ? atoi(v) : 0;
  return n > 0 && n <= CPU_SETSIZE ? n : 0;
}

int sched_getaffinity(pid_t pid, size_t size, cpu_set_t *set)
{
  static int (*next)(pid_t, size_t, cpu_set_t *);
  int n = cores();
  NEXT(next, "sched_getaffinity");
  if (!n || pid != 0 || size < sizeof (cpu_set_t)) return next(pid, size, set);
  memset(set, 0, size);
  for (int c = 0; c < n; c++) CPU_SET(c, set);
  return 0;
}

long sysconf(int name)
{
  static long (*next)(int);
  int n = cores();
  NEXT(next, "sysconf");
  if (n && (name == _SC_NPROCESSORS_ONLN || name == _SC_NPROCESSORS_CONF)) return n;
  return next(name);
}
