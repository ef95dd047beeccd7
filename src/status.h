#line 15 "paper/status.nw"
#ifndef CONTACTOPT_STATUS_H
#define CONTACTOPT_STATUS_H
#include <stddef.h>

typedef enum {
  STATUS_OK = 0,
  STATUS_INPUT = 2,   /* bad scene, bad command line: exit status 2 */
  STATUS_NUMERIC = 3, /* a solver did not converge, a NaN appeared */
  STATUS_SYSTEM = 4,  /* a file that cannot be written, a library failure */
  STATUS_MEMORY = 5,  /* too large for this machine's memory or CHOLMOD's integers,
                         or out of memory */
  STATUS_INTERRUPTED = 130 /* SIGINT or SIGTERM: stopped at a safe point,
                              the files of the best design so far written */
} Status_code;

typedef struct {
  Status_code code;   /* STATUS_OK until something fails */
  char msg[1024];     /* one line, no trailing newline */
} Status;

#line 43 "paper/status.nw"
int status_set(Status *st, Status_code code, const char *fmt, ...)
#if defined(__GNUC__)
  __attribute__((format(printf, 3, 4)))
#endif
  ;
#line 63 "paper/status.nw"
/* room for any double written by status_number, its terminator included */
#define STATUS_NUMBER 32
/* buf (size >= STATUS_NUMBER) = x in %g with the fewest significant digits
   that read back as x exactly; returns buf */
const char *status_number(double x, char *buf);
/* buf (size >= STATUS_NUMBER) = x in %g to digits (1..17) significant
   digits, the exponent tidied likewise; returns buf */
const char *status_digits(double x, int digits, char *buf);
#line 36 "paper/status.nw"
#endif
