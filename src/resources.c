#line 29 "paper/resources.nw"
#include <math.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>
#include <sys/resource.h>
#include "resources.h"
#line 40 "paper/resources.nw"
double resources_clock(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
#line 72 "paper/resources.nw"
/* the unknowns of the mesh, and the entries of the sparse factor of K */
static double resources_unknowns(const Problem *p)
{
  return 2 * ((p->N + 1.0) * (p->M + p->R + 1.0) + p->part.nodes);
}

static double resources_factor_entries(const Problem *p)
{
  double n = resources_unknowns(p);
  return 5.1 * n * log2(n > 2 ? n : 2);
}

double resources_memory(const Problem *p)
{
  double n = resources_unknowns(p);
  double nk = (p->N + 1.0) * (p->contact == CONTACT_FRICTIONLESS ? 1 : 2);
  return 3 * 8 * nk * nk + 12 * resources_factor_entries(p) + 400 * n;
}
#line 107 "paper/resources.nw"
int resources_fits(const Problem *p, double extra, const char *origin, Status *st)
{
  double need = resources_memory(p) + extra;
  double have = (double) sysconf(_SC_PHYS_PAGES) * (double) sysconf(_SC_PAGESIZE);
  struct rlimit lim;
  if (!getrlimit(RLIMIT_AS, &lim) && lim.rlim_cur != RLIM_INFINITY)
    have = fmin(have, (double) lim.rlim_cur);
  if (!(have > 0) || need <= have) return STATUS_OK;
  char part[64] = "";
  if (p->part.nodes) snprintf(part, sizeof part, " and a part of %d nodes", p->part.nodes);
  return status_set(st, STATUS_MEMORY, "%s: N = %d (%d rows of cells)%s needs "
                    "about %.3g GB, more than the %.3g GB this process may use",
                    origin, p->N, p->M + p->R, part, need / 1e9, have / 1e9);
}
