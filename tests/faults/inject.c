/* inject.c: an LD_PRELOAD shim that makes the k-th allocation or the
   k-th write of a program fail, for tests/faults.sh.

   FAULT_ALLOC=k   the k-th allocation (malloc, calloc, realloc,
                   reallocarray, posix_memalign, aligned_alloc, memalign,
                   valloc, pvalloc) returns NULL with errno ENOMEM
   FAULT_WRITE=k   the k-th write operation fails: on a stream opened for
                   writing (fprintf, vfprintf, their _chk forms, fputs,
                   fputc, putc, fwrite, fflush, fclose) it returns the
                   error with errno ENOSPC and the stream's error flag set
                   (fclose closes the stream first); fopen for writing
                   returns NULL, mkdir (of a path not there yet: one that
                   is there fails with EEXIST first) and rename return -1
                   with ENOSPC and do nothing
   FAULT_PROGRAM=P count only in a program whose argv[0] ends in /P (or is
                   P), not in a launcher (valgrind) that runs it
   FAULT_REPORT=F  at exit, append to F one line:
                   "allocs A writes W site S", A and W the operations
                   counted, S the call site of the injected failure (the
                   operation's caller outside this shim and the sanitizer
                   runtimes, then the innermost frame of the program
                   itself) or "-" if none was injected

   Counting starts when main starts (the libraries' own start-up, OpenBLAS's
   buffers among them, is not counted) and covers the main thread only, so
   that k names the same operation in every run of the same command when
   the helper threads are off (OPENBLAS_NUM_THREADS=1, OMP_NUM_THREADS=1).
   Standard output and error are not counted: the write faults are those of
   the files the program creates. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <execinfo.h>
#include <fcntl.h>
#include <malloc.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static long alloc_fail = -1, write_fail = -1;  /* k, or -1 for none */
static long allocs, writes;                    /* counted so far */
static __thread int in_main_thread, busy;      /* busy: inside the shim */
static int started;
static void *site[64];                         /* the failed call's stack */
static int nsite;

/* ---- the real functions ------------------------------------------------ */
/* dlsym may allocate before the real allocator is known: a small arena
   serves those calls, and free ignores its blocks. */
static char arena[1 << 14];
static size_t arena_used;
static void *arena_alloc(size_t n)
{
  n = (n + 15) & ~(size_t) 15;
  if (arena_used + n > sizeof arena) return NULL;
  void *p = arena + arena_used;
  arena_used += n;
  return p;
}
static int in_arena(const void *p)
{
  return (const char *) p >= arena && (const char *) p < arena + sizeof arena;
}

#define REAL(name) static __typeof__(name) *real_##name
REAL(malloc); REAL(calloc); REAL(realloc); REAL(free); REAL(posix_memalign);
REAL(aligned_alloc); REAL(memalign); REAL(valloc); REAL(pvalloc);
REAL(reallocarray);
REAL(fopen); REAL(fopen64); REAL(vfprintf); REAL(fputs); REAL(fputc);
REAL(putc); REAL(fwrite); REAL(fflush); REAL(fclose); REAL(mkdir); REAL(rename);
static int (*real___vfprintf_chk)(FILE *, int, const char *, va_list);

static int resolving;
static void resolve(void)
{
  if (real_malloc || resolving) return;
  resolving = 1;
#define GET(name) real_##name = (__typeof__(real_##name)) dlsym(RTLD_NEXT, #name)
  GET(calloc); GET(realloc); GET(free); GET(posix_memalign); GET(aligned_alloc);
  GET(memalign); GET(valloc); GET(pvalloc); GET(reallocarray);
  GET(fopen); GET(fopen64); GET(vfprintf); GET(fputs); GET(fputc); GET(putc);
  GET(fwrite); GET(fflush); GET(fclose); GET(mkdir); GET(rename);
  GET(__vfprintf_chk);
  GET(malloc);
  resolving = 0;
}

/* ---- deciding ---------------------------------------------------------------- */
static void remember_site(void)
{
  nsite = backtrace(site, 64);
}

/* 1 if this counted operation is the one to fail */
static int strike(long *count, long fail)
{
  if (!started || !in_main_thread || busy) return 0;
  if (++*count != fail) return 0;
  busy = 1;
  remember_site();
  busy = 0;
  return 1;
}
#define ALLOC_FAILS() strike(&allocs, alloc_fail)

/* ---- allocation ---------------------------------------------------------- */
void *malloc(size_t n)
{
  resolve();
  if (!real_malloc) return arena_alloc(n);
  if (ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_malloc(n);
}

void *calloc(size_t m, size_t n)
{
  resolve();
  if (!real_calloc) {
    void *p = n && m > (size_t) -1 / n ? NULL : arena_alloc(m * n);
    return p ? memset(p, 0, m * n) : NULL;
  }
  if (ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_calloc(m, n);
}

void *realloc(void *p, size_t n)
{
  resolve();
  if (in_arena(p)) {            /* grow an arena block into a real one */
    void *q = malloc(n);
    if (q) memcpy(q, p, n < (size_t) (arena + sizeof arena - (char *) p)
                        ? n : (size_t) (arena + sizeof arena - (char *) p));
    return q;
  }
  if (!real_realloc) return p ? NULL : arena_alloc(n);  /* while resolving */
  if (ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_realloc(p, n);
}

void *reallocarray(void *p, size_t m, size_t n)
{
  resolve();
  if (!real_reallocarray) return p || (n && m > (size_t) -1 / n) ? NULL : arena_alloc(m * n);
  if (ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_reallocarray(p, m, n);
}

void free(void *p)
{
  if (in_arena(p)) return;
  resolve();
  if (real_free) real_free(p);
}

int posix_memalign(void **p, size_t align, size_t n)
{
  resolve();
  if (!real_posix_memalign || ALLOC_FAILS()) return ENOMEM;
  return real_posix_memalign(p, align, n);
}

void *aligned_alloc(size_t align, size_t n)
{
  resolve();
  if (!real_aligned_alloc || ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_aligned_alloc(align, n);
}

void *memalign(size_t align, size_t n)
{
  resolve();
  if (!real_memalign || ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_memalign(align, n);
}

void *valloc(size_t n)
{
  resolve();
  if (!real_valloc || ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_valloc(n);
}

void *pvalloc(size_t n)
{
  resolve();
  if (!real_pvalloc || ALLOC_FAILS()) { errno = ENOMEM; return NULL; }
  return real_pvalloc(n);
}

/* ---- writing ------------------------------------------------------------------ */
/* The streams the program opened for writing (not stdout, not stderr, not
   the files it reads). */
#define MAX_STREAMS 256
static FILE *stream[MAX_STREAMS];

static int written(FILE *f)
{
  for (int k = 0; k < MAX_STREAMS; k++) if (f && stream[k] == f) return 1;
  return 0;
}
static void track(FILE *f, int on)
{
  for (int k = 0; k < MAX_STREAMS; k++)
    if (on ? !stream[k] : stream[k] == f) { stream[k] = on ? f : NULL; return; }
}
static int writing_mode(const char *mode)
{
  return strchr(mode, 'w') || strchr(mode, 'a') || strchr(mode, '+');
}
/* 1 (errno ENOSPC, the stream's error flag set) if this write fails */
static int write_fails(FILE *f)
{
  if (f && !written(f)) return 0;
  if (!strike(&writes, write_fail)) return 0;
  if (f) f->_flags |= _IO_ERR_SEEN;
  errno = ENOSPC;
  return 1;
}

static FILE *open_stream(FILE *(**real)(const char *, const char *),
                         const char *path, const char *mode)
{
  resolve();                    /* before *real is read */
  int w = writing_mode(mode);
  if (w && write_fails(NULL)) return NULL;
  FILE *f = (*real)(path, mode);
  if (f && w) track(f, 1);
  return f;
}
FILE *fopen(const char *path, const char *mode)
{
  return open_stream(&real_fopen, path, mode);
}
FILE *fopen64(const char *path, const char *mode)
{
  return open_stream(&real_fopen64, path, mode);
}

int vfprintf(FILE *f, const char *fmt, va_list ap)
{
  resolve();
  return write_fails(f) ? -1 : real_vfprintf(f, fmt, ap);
}
int fprintf(FILE *f, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int r = vfprintf(f, fmt, ap);
  va_end(ap);
  return r;
}
int __vfprintf_chk(FILE *f, int flag, const char *fmt, va_list ap)
{
  resolve();
  return write_fails(f) ? -1 : real___vfprintf_chk(f, flag, fmt, ap);
}
int __fprintf_chk(FILE *f, int flag, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int r = __vfprintf_chk(f, flag, fmt, ap);
  va_end(ap);
  return r;
}
int fputs(const char *s, FILE *f)
{
  resolve();
  return write_fails(f) ? EOF : real_fputs(s, f);
}
int fputc(int c, FILE *f)
{
  resolve();
  return write_fails(f) ? EOF : real_fputc(c, f);
}
int putc(int c, FILE *f)
{
  resolve();
  return write_fails(f) ? EOF : real_putc(c, f);
}
size_t fwrite(const void *p, size_t size, size_t n, FILE *f)
{
  resolve();
  return write_fails(f) ? 0 : real_fwrite(p, size, n, f);
}
int fflush(FILE *f)
{
  resolve();
  return f && write_fails(f) ? EOF : real_fflush(f);
}
int fclose(FILE *f)
{
  resolve();
  int fails = write_fails(f);
  if (written(f)) track(f, 0);
  int r = real_fclose(f);
  if (fails) errno = ENOSPC;
  return fails ? EOF : r;
}
int mkdir(const char *path, mode_t mode)
{
  struct stat sb;
  resolve();
  if (stat(path, &sb) == 0) return real_mkdir(path, mode);  /* EEXIST */
  return write_fails(NULL) ? -1 : real_mkdir(path, mode);
}
int rename(const char *from, const char *to)
{
  resolve();
  return write_fails(NULL) ? -1 : real_rename(from, to);
}

/* ---- start and report --------------------------------------------------- */
static long env_long(const char *name)
{
  const char *s = getenv(name);
  return s && *s ? atol(s) : -1;
}

/* a frame as module:symbol+offset (module+offset without a symbol) */
static void frame_name(void *a, char *buf, size_t size)
{
  Dl_info d;
  if (!dladdr(a, &d) || !d.dli_fname) { snprintf(buf, size, "%p", a); return; }
  const char *mod = strrchr(d.dli_fname, '/');
  mod = mod ? mod + 1 : d.dli_fname;
  if (d.dli_sname)
    snprintf(buf, size, "%s:%s+%#lx", mod, d.dli_sname,
             (unsigned long) ((char *) a - (char *) d.dli_saddr));
  else
    snprintf(buf, size, "%s+%#lx", mod,
             (unsigned long) ((char *) a - (char *) d.dli_fbase));
}

/* the site: the caller of the failed operation (the first frame outside
   the shim) and the innermost frame in the program itself (the module of
   main), where the call left the program for a library */
typedef int (*main_fn)(int, char **, char **);
static main_fn real_main;
static void site_name(char *buf, size_t size)
{
  char a[256] = "-", b[256] = "";
  Dl_info self, exe, d;
  int k = 0;
  dladdr((void *) site_name, &self);
  dladdr((void *) real_main, &exe);
  while (k < nsite && dladdr(site[k], &d)
         && (d.dli_fbase == self.dli_fbase || strstr(d.dli_fname, "/libasan")
             || strstr(d.dli_fname, "/libubsan")))
    k++;
  if (k < nsite) frame_name(site[k], a, sizeof a);
  for (; k < nsite; k++)
    if (dladdr(site[k], &d) && d.dli_fbase == exe.dli_fbase) {
      frame_name(site[k], b, sizeof b);
      break;
    }
  snprintf(buf, size, "%s%s%s", a, *b ? "<-" : "", b);
}

static void report(void)
{
  const char *path = getenv("FAULT_REPORT");
  char line[700], s[600] = "-";
  busy = 1;
  if (!path) return;
  if (nsite) site_name(s, sizeof s);
  int n = snprintf(line, sizeof line, "allocs %ld writes %ld site %s\n",
                   allocs, writes, s);
  int fd = open(path, O_WRONLY | O_CREAT | O_APPEND, 0666);
  if (fd >= 0) {
    if (write(fd, line, n) != n) {}
    close(fd);
  }
}

/* main is wrapped through __libc_start_main: counting starts in it */
static int counted_main(int argc, char **argv, char **envp)
{
  const char *p = getenv("FAULT_PROGRAM"), *base = strrchr(argv[0], '/');
  if (p && strcmp(base ? base + 1 : argv[0], p))
    return real_main(argc, argv, envp);
  alloc_fail = env_long("FAULT_ALLOC");
  write_fail = env_long("FAULT_WRITE");
  void *warm[4];
  backtrace(warm, 4);           /* loads the unwinder before counting */
  atexit(report);
  in_main_thread = 1;
  started = 1;
  return real_main(argc, argv, envp);
}

int __libc_start_main(main_fn main, int argc, char **argv,
                      void (*init)(void), void (*fini)(void),
                      void (*rtld_fini)(void), void *stack_end)
{
  int (*real)(main_fn, int, char **, void (*)(void), void (*)(void),
              void (*)(void), void *) =
    (__typeof__(real)) dlsym(RTLD_NEXT, "__libc_start_main");
  real_main = main;
  return real(counted_main, argc, argv, init, fini, rtld_fini, stack_end);
}
