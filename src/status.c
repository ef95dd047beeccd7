#line 51 "paper/status.nw"
#include <stdarg.h>
#include <stdio.h>
#include "status.h"

int status_set(Status *st, Status_code code, const char *fmt, ...)
{
  if (st) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(st->msg, sizeof st->msg, fmt, ap);
    va_end(ap);
    st->code = code;
  }
  return code;
}
