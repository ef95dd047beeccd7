#line 63 "paper/contactopt.nw"
#ifndef CONTACTOPT_STATUS_H
#define CONTACTOPT_STATUS_H
#include <stddef.h>

typedef enum {
  STATUS_OK = 0,
  STATUS_INPUT = 2,   /* bad scene, bad command line: exit status 2 */
  STATUS_NUMERIC = 3, /* a solver did not converge, a NaN appeared */
  STATUS_SYSTEM = 4   /* out of memory, a file that cannot be written */
} Status_code;

typedef struct {
  Status_code code;   /* STATUS_OK until something fails */
  char msg[1024];     /* one line, no trailing newline */
} Status;

#line 86 "paper/contactopt.nw"
int status_set(Status *st, Status_code code, const char *fmt, ...)
#if defined(__GNUC__)
  __attribute__((format(printf, 3, 4)))
#endif
  ;
#line 80 "paper/contactopt.nw"
#endif
