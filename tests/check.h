/* check.h: one line of output per check, "ok - what" or "FAIL - what";
   tests/run counts them.  A test program exits non-zero if any check failed. */
#ifndef CHECK_H
#define CHECK_H
#include <stdio.h>
#include <stdarg.h>

static int check_failures = 0;

/* report one check; returns cond so that a test may stop on failure */
static int check(int cond, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  printf("%s - ", cond ? "ok" : "FAIL");
  vprintf(fmt, ap);
  printf("\n");
  va_end(ap);
  if (!cond) check_failures++;
  fflush(stdout);
  return cond;
}

static int check_done(void) { return check_failures ? 1 : 0; }
#endif
