#line 225 "paper/main.nw"
#include <string.h>
#include "args.h"

int args_read(int argc, char **argv, Args *a, Status *st)
{
  memset(a, 0, sizeof *a);
  for (int k = 2; k < argc; k++) {
    const char *s = argv[k];
    int more = k + 1 < argc;
    if (!strcmp(s, "-o") && more) a->outdir = argv[++k];
    else if (!strcmp(s, "--matrix-market") && more) a->matrix_market = argv[++k];
    else if (!strcmp(s, "--components") && more) a->components = argv[++k];
    else if (!strcmp(s, "--plot-files")) a->plot_files = 1;
    else if (!strcmp(s, "--replace")) a->replace = 1;
    else if (!strcmp(s, "-s") && more && a->noverride == MAX_OVERRIDES)
      return status_set(st, STATUS_INPUT, "command line: more than %d -s",
                        MAX_OVERRIDES);
    else if (!strcmp(s, "-s") && more) a->override[a->noverride++] = argv[++k];
    else if (s[0] != '-' && !a->scene) a->scene = s;
    else return status_set(st, STATUS_INPUT, "command line: %s: %s", s,
                           s[0] == '-' ? "unknown option or missing value"
                                       : "more than one scene");
  }
  if (!a->scene) return status_set(st, STATUS_INPUT, "command line: no SCENE given");
  return STATUS_OK;
}
