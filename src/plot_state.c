#line 252 "paper/figures.nw"
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "plot_private.h"
#line 479 "paper/figures.nw"
/* the value of the attribute name in line, into buf; NULL if none */
static const char *attribute(const char *line, const char *name, char *buf, size_t size)
{
  char key[64];
  const char *s, *e;
  snprintf(key, sizeof key, " %s=\"", name);
  if (!(s = strstr(line, key))) return NULL;
  s += strlen(key);
  if (!(e = strchr(s, '"')) || (size_t) (e - s) >= size) return NULL;
  memcpy(buf, s, e - s);
  buf[e - s] = 0;
  return buf;
}
#line 498 "paper/figures.nw"
typedef struct {
  long points;                   /* NumberOfPoints */
  int native;                    /* written in this machine's byte order */
  long long at[2];               /* the offsets of Points and displacement, or -1 */
  long base;                     /* where the raw block begins in the file */
} Vtu_head;

static int vtu_head(FILE *f, Vtu_head *h)
{
  static const char *const names[2] = { "Points", "displacement" };
  const uint16_t one = 1;
  char line[1024], v[64];
  int c;
  h->points = -1, h->native = 0, h->at[0] = h->at[1] = -1;
  while (fgets(line, sizeof line, f) && !strstr(line, "<AppendedData")) {
    if (attribute(line, "byte_order", v, sizeof v))
      h->native = !strcmp(v, *(const uint8_t *) &one ? "LittleEndian" : "BigEndian");
    if (attribute(line, "NumberOfPoints", v, sizeof v)) h->points = atol(v);
    for (int k = 0; k < 2; k++)
      if (attribute(line, "Name", v, sizeof v) && !strcmp(v, names[k])
          && attribute(line, "offset", v, sizeof v))
        h->at[k] = atoll(v);
  }
  while ((c = fgetc(f)) != EOF && c != '_') ;
  h->base = ftell(f);
  return c == '_' && h->points > 0 && h->at[0] >= 0 && h->at[1] >= 0;
}
#line 529 "paper/figures.nw"
static int vtu_pairs(FILE *f, const Vtu_head *h, int k, double *out, double *buf)
{
  uint64_t bytes;
  size_t n = (size_t) h->points;
  if (fseek(f, h->base + (long) h->at[k], SEEK_SET) || fread(&bytes, sizeof bytes, 1, f) != 1
      || bytes != 3 * n * sizeof(double) || fread(buf, sizeof(double), 3 * n, f) != 3 * n)
    return 0;
  for (size_t j = 0; j < n; j++) out[2 * j] = buf[3 * j], out[2 * j + 1] = buf[3 * j + 1];
  return 1;
}
#line 543 "paper/figures.nw"
int plot_state_read(const char *dir, const Problem *p, const Mesh *part, Plot_state *s,
                    Status *st)
{
  char path[1200];
  Vtu_head h;
  double *buf = NULL;
  int rc = STATUS_OK;
  FILE *f;
  memset(s, 0, sizeof *s);
  s->ncol = p->N + 1, s->nrow = part ? part->nrow : p->M + p->R + 1;
  s->n = part ? part->nnodes : s->ncol * s->nrow, s->part = part;
  snprintf(path, sizeof path, "%s/solution.vtu", dir);
  if (!(f = fopen(path, "rb")))
    return status_set(st, STATUS_INPUT, "plot: cannot read %s: %s", path, strerror(errno));
  if (!vtu_head(f, &h))
    rc = status_set(st, STATUS_INPUT, "plot: %s: not a state of contactopt (no "
                    "Points, displacement and appended data)", path);
  else if (!h.native)
    rc = status_set(st, STATUS_INPUT, "plot: %s: written in the other byte order", path);
  else if (h.points != (long) s->n)
    rc = status_set(st, STATUS_INPUT, "plot: %s: %ld points, where the scene's mesh "
                    "has %d", path, h.points, s->n);
  else if (!(s->xy = malloc(2 * h.points * sizeof(double)))
           || !(s->u = malloc(2 * h.points * sizeof(double)))
           || !(buf = malloc(3 * h.points * sizeof(double))))
    rc = status_set(st, STATUS_MEMORY, "plot: %s: out of memory", path);
  else if (!vtu_pairs(f, &h, 0, s->xy, buf) || !vtu_pairs(f, &h, 1, s->u, buf))
    rc = status_set(st, STATUS_INPUT, "plot: %s: cut short", path);
  free(buf);
  fclose(f);
  if (rc) plot_state_free(s);
  return rc;
}

void plot_state_free(Plot_state *s)
{
  free(s->xy), free(s->u);
  s->xy = s->u = NULL;
}
