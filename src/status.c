#line 76 "paper/status.nw"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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
#line 99 "paper/status.nw"
const char *status_digits(double x, int digits, char *buf)
{
  char *e;
  snprintf(buf, STATUS_NUMBER, "%.*g", digits, x);
  if ((e = strchr(buf, 'e'))) {
    char *from = e + 1 + (e[1] == '+'), *to = e + 1 + (e[1] == '-');
    if (*from == '-') from++;
    while (*from == '0' && from[1]) from++;
    memmove(to, from, strlen(from) + 1);
  }
  return buf;
}

const char *status_number(double x, char *buf)
{
  int digits = 1;
  while (digits < 17 && strtod(status_digits(x, digits, buf), NULL) != x) digits++;
  return digits < 17 ? buf : status_digits(x, 17, buf);
}
