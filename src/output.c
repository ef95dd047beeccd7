#line 250 "paper/output.nw"
#define _XOPEN_SOURCE 700   /* nftw, to remove a folder tree */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "output.h"
#include "threads.h"

#line 311 "paper/output.nw"
/* status_set with the code of errno e: STATUS_MEMORY for ENOMEM */
static int output_errno(Status *st, int e, const char *path, const char *what)
{
  return status_set(st, e == ENOMEM ? STATUS_MEMORY : STATUS_SYSTEM, "%s: %s: %s",
                    path, what, strerror(e));
}
#line 375 "paper/output.nw"
#define ITERATE_PREFIX "iterate-"     /* the VTU of an iterate, in iterates/ */
#define ITERATE_VTU ITERATE_PREFIX "%04d.vtu"

/* *mark = v, after every write before it, as a signal handler sees them */
static void output_publish(volatile sig_atomic_t *mark, int v)
{
  atomic_signal_fence(memory_order_seq_cst);
  *mark = v;
  atomic_signal_fence(memory_order_seq_cst);
}

/* buf = a, b and c joined (async-signal-safe: copies only) */
static char *output_cat(char *buf, size_t size, const char *a, const char *b,
                        const char *c)
{
  size_t n = 0;
  for (const char *s[3] = { a, b, c }, **p = s; p < s + 3; p++)
    for (const char *q = *p; *q && n + 1 < size; q++) buf[n++] = *q;
  buf[n] = '\0';
  return buf;
}

/* remove iterates/iterate-0000.vtu .. of the folder at path */
static void output_unlink_iterates(const char *folder, int n)
{
  char path[1400], digits[16];
  for (int j = 0; j < n; j++) {
    int d = 0, k = j;
    char *p = digits + sizeof digits - 1;
    *p = '\0';
    do *--p = (char) ('0' + k % 10), k /= 10, d++; while (k || d < 4);
    output_cat(path, sizeof path, folder, "/" ITERATE_PREFIX, p);
    unlink(output_cat(path, sizeof path, path, ".vtu", ""));
  }
}

void output_abort_now(void *arg)
{
  Output *o = arg;
  char path[1400];
  size_t root = strlen(o->stage);
  if (!o->staged) return;
  int n = o->nfiles + o->opening;
  for (int k = (n < OUTPUT_MAX_FILES ? n : OUTPUT_MAX_FILES) - 1; k >= 0; k--) {
    size_t len = strlen(output_cat(path, sizeof path, o->stage, "/", o->file[k]));
    if (path[len - 1] == '/') {                 /* a folder staged whole */
      path[len - 1] = '\0';
      output_unlink_iterates(path, o->iterates);
      rmdir(path);
    } else unlink(path);
    for (char *slash; (slash = strrchr(path, '/')) > path + root; ) {
      *slash = '\0';
      rmdir(path);                              /* its folders, once empty */
    }
  }
  rmdir(o->stage);
}

#line 327 "paper/output.nw"
static int output_mkdirs(const char *path, Status *st)
{
  char p[1200];
  snprintf(p, sizeof p, "%s", path);
  for (char *s = p + 1; ; s++)
    if (*s == '/' || *s == '\0') {
      char c = *s;
      *s = '\0';
      if (mkdir(p, 0777) && errno != EEXIST)
        return output_errno(st, errno, p, "cannot create");
      if (!(*s = c)) return STATUS_OK;
    }
}

#line 435 "paper/output.nw"
static int output_remove_one(const char *path, const struct stat *sb, int flag,
                             struct FTW *ftw)
{
  (void) sb, (void) flag, (void) ftw;
  return remove(path);
}

static void output_remove_tree(const char *path)
{
  nftw(path, output_remove_one, 16, FTW_DEPTH | FTW_PHYS);
}
#line 452 "paper/output.nw"
int output_dir_name(const char *given, char *dir, size_t size, Status *st)
{
  size_t n = strlen(given);
  while (n > 1 && given[n - 1] == '/') n--;
  const char *last = given + n;
  while (last > given && last[-1] != '/') last--;
  if (n == 0)
    return status_set(st, STATUS_INPUT, "-o '': the output folder has an empty name");
  size_t len = given + n - last;      /* of the last part */
  if (n >= size)
    return status_set(st, STATUS_INPUT, "-o %.40s...: the output folder's name is "
                      "longer than %zu characters", given, size - 1);
  if ((len == 1 || len == 2) && !strncmp(last, "..", len))
    return status_set(st, STATUS_INPUT, "-o %s: cannot replace the folder %.*s: name "
                      "a folder by its own name", given, (int) len, last);
  snprintf(dir, size, "%.*s", (int) n, given);
  return STATUS_OK;
}
#line 480 "paper/output.nw"
/* parent = the folder of path: all before its last slash, "." or "/" */
static void output_parent(const char *path, char *parent, size_t size)
{
  const char *slash = strrchr(path, '/');
  if (!slash) snprintf(parent, size, ".");
  else if (slash == path) snprintf(parent, size, "/");
  else snprintf(parent, size, "%.*s", (int) (slash - path), path);
}

/* out = path with its empty and "." parts dropped ("." if none is left) */
static void output_lexical(const char *path, char *out, size_t size)
{
  size_t n = 0;
  if (*path == '/' && n + 1 < size) out[n++] = '/';
  for (const char *p = path; *p; ) {
    size_t len = strcspn(p, "/");
    if (len && !(len == 1 && *p == '.') && n + len + 2 < size) {
      if (n && out[n - 1] != '/') out[n++] = '/';
      memcpy(out + n, p, len), n += len;
    }
    p += len + (p[len] == '/');
  }
  if (!n) out[n++] = '.';
  out[n] = '\0';
}

/* whether path can be created: its folder (with parents, its deepest
   ancestor that exists) is a folder this process may write into */
static int output_creatable(const char *path, int parents, Status *st)
{
  char at[1100], up[1100];
  struct stat sb;
  output_parent(path, at, sizeof at);
  while (stat(at, &sb)) {
    int e = errno;
    if (e != ENOENT || !parents || !strcmp(at, ".") || !strcmp(at, "/"))
      return status_set(st, e == ENOMEM ? STATUS_MEMORY : STATUS_SYSTEM,
                        "%s: cannot create it in %s: %s", path, at, strerror(e));
    snprintf(up, sizeof up, "%s", at);
    output_parent(up, at, sizeof at);
  }
  int e = !S_ISDIR(sb.st_mode) ? ENOTDIR
        : faccessat(AT_FDCWD, at, W_OK | X_OK, AT_EACCESS) ? errno : 0;
  return e ? status_set(st, e == ENOMEM ? STATUS_MEMORY : STATUS_SYSTEM,
                        "%s: cannot create it in %s: %s", path, at, strerror(e))
           : STATUS_OK;
}

int output_check_file(const char *path, const char *dir, Status *st)
{
  char folder[1100], a[1100], b[1100];
  struct stat sb;
  if (!*path)
    return status_set(st, STATUS_INPUT, "--matrix-market '': the file has an empty name");
  if (strlen(path) >= OUTPUT_PATH)
    return status_set(st, STATUS_INPUT, "--matrix-market %.40s...: the file's name is "
                      "longer than %d characters", path, OUTPUT_PATH - 1);
  if (!stat(path, &sb) && S_ISDIR(sb.st_mode))
    return output_errno(st, EISDIR, path, "cannot write");
  output_parent(path, folder, sizeof folder);
  output_lexical(folder, a, sizeof a);
  output_lexical(dir, b, sizeof b);
  if (stat(folder, &sb) && errno == ENOENT && !strcmp(a, b)) return STATUS_OK;
  return output_creatable(path, 0, st);
}
#line 551 "paper/output.nw"
int output_check(const char *dir, Status *st)
{
  struct stat sb;
  char path[1200];
  int rc = output_creatable(dir, 1, st);
  if (rc) return rc;
  if (stat(dir, &sb)) return STATUS_OK;                 /* absent */
  if (!S_ISDIR(sb.st_mode))
    return status_set(st, STATUS_INPUT, "%s: exists and is not a folder", dir);
  snprintf(path, sizeof path, "%s/summary.dat", dir);
  if (!stat(path, &sb)) return STATUS_OK;
  DIR *d = opendir(dir);
  struct dirent *e;
  int empty = d != NULL;
  while (d && empty && (e = readdir(d)))
    empty = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..");
  if (d) closedir(d);
  return empty ? STATUS_OK : status_set(st, STATUS_INPUT, "%s: exists and "
    "holds files that are not a run's (no summary.dat): choose another -o", dir);
}
#line 575 "paper/output.nw"
static void output_remove_dead(const char *dir)
{
  char parent[1100], prefix[300], path[1400];
  const char *slash = strrchr(dir, '/');
  snprintf(parent, sizeof parent, "%.*s", slash ? (int) (slash - dir) : 1,
           slash ? dir : ".");
  snprintf(prefix, sizeof prefix, "%s.partial-", slash ? slash + 1 : dir);
  DIR *d = opendir(*parent ? parent : "/");
  struct dirent *e;
  while (d && (e = readdir(d))) {
    char *end;
    if (strncmp(e->d_name, prefix, strlen(prefix))) continue;
    long pid = strtol(e->d_name + strlen(prefix), &end, 10);
    if (*end || pid <= 0 || !(kill((pid_t) pid, 0) && errno == ESRCH)) continue;
    snprintf(path, sizeof path, "%s/%s", *parent ? parent : "", e->d_name);
    output_remove_tree(path);
  }
  if (d) closedir(d);
}

#line 347 "paper/output.nw"
int output_begin(Output *o, const char *dir, Status *st)
{
  memset(o, 0, sizeof *o);
  snprintf(o->dir, sizeof o->dir, "%s", dir);
  snprintf(o->stage, sizeof o->stage, "%s.partial-%ld", dir, (long) getpid());
  output_publish(&o->staged, 1);
  int rc = output_check(dir, st);
  if (!rc) output_remove_dead(dir);
  return rc ? rc : output_mkdirs(o->stage, st);
}
#line 599 "paper/output.nw"
void output_default_dir(const char *scene, const char *suffix, char *dir,
                        size_t size)
{
  const char *base = strrchr(scene, '/');
  base = base ? base + 1 : scene;
  size_t len = strlen(base);
  if (len > 6 && !strcmp(base + len - 6, ".scene")) len -= 6;
  snprintf(dir, size, "out/%.*s%s", (int) len, base, suffix);
}
#line 613 "paper/output.nw"
FILE *output_open(Output *o, const char *name, Status *st)
{
  char path[1300];
  if (o->nfiles == OUTPUT_MAX_FILES) {
    status_set(st, STATUS_SYSTEM, "%s: too many output files", o->dir);
    return NULL;
  }
  snprintf(o->file[o->nfiles], sizeof o->file[0], "%s", name);
  output_publish(&o->opening, 1);
  snprintf(path, sizeof path, "%s/%s", o->stage, name);
  char *slash = strrchr(path, '/');
  *slash = '\0';
  FILE *f = NULL;
  if (!output_mkdirs(path, st)) {
    *slash = '/';
    if (!(f = fopen(path, "w"))) {
      int e = errno;
      snprintf(path, sizeof path, "%s/%s", o->dir, name);
      output_errno(st, e, path, "cannot write");
    } else o->nfiles++;
  }
  output_publish(&o->opening, 0);
  return f;
}

static int output_finish(FILE *f, const char *dir, const char *name,
                         Status *st)
{
  int bad = ferror(f);
  if (fclose(f) || bad)
    return status_set(st, STATUS_SYSTEM, "%s/%s: write failed", dir, name);
  return STATUS_OK;
}

int output_close(Output *o, FILE *f, Status *st)
{
  return output_finish(f, o->dir, o->file[o->nfiles - 1], st);
}
#line 656 "paper/output.nw"
static int output_folder(Output *o, const char *name, Status *st)
{
  char path[1300];
  if (o->nfiles == OUTPUT_MAX_FILES)
    return status_set(st, STATUS_SYSTEM, "%s: too many output files", o->dir);
  snprintf(path, sizeof path, "%s/%s", o->stage, name);
  snprintf(o->file[o->nfiles], sizeof o->file[0], "%s/", name);
  output_publish(&o->opening, 1);
  int rc = output_mkdirs(path, st);
  if (!rc) o->nfiles++;
  output_publish(&o->opening, 0);
  return rc;
}

static FILE *output_open_in_folder(Output *o, const char *folder,
                                   const char *name, Status *st)
{
  char path[1300];
  snprintf(path, sizeof path, "%s/%s/%s", o->stage, folder, name);
  FILE *f = fopen(path, "w");
  if (!f) {
    int e = errno;
    snprintf(path, sizeof path, "%s/%s/%s", o->dir, folder, name);
    output_errno(st, e, path, "cannot write");
  }
  return f;
}
#line 763 "paper/output.nw"
typedef struct {
  char **path;              /* relative to the root; "" is the root */
  int n, size;
} Output_tree;

/* buf = a/b, or a if b is "": -1 with ENAMETOOLONG if it does not fit */
static int output_join(char *buf, size_t size, const char *a, const char *b)
{
  if ((size_t) snprintf(buf, size, "%s%s%s", a, *b ? "/" : "", b) < size) return 0;
  errno = ENAMETOOLONG;
  return -1;
}

static int output_tree_add(Output_tree *t, const char *rel)
{
  if (t->n == t->size) {
    int size = 2 * t->size + 16;
    char **p = realloc(t->path, size * sizeof *p);
    if (!p) return -1;
    t->path = p, t->size = size;
  }
  if (!(t->path[t->n] = malloc(strlen(rel) + 1))) return -1;
  strcpy(t->path[t->n++], rel);
  return 0;
}

/* t += the tree at root/rel (rel "" for root); -1 with errno on failure */
static int output_tree_list(Output_tree *t, const char *root, const char *rel)
{
  char path[1400], sub[1400];
  struct stat sb;
  DIR *d = output_join(path, sizeof path, root, rel) ? NULL : opendir(path);
  struct dirent *e;
  int rc = d ? 0 : -1;
  while (!rc) {
    errno = 0;
    if (!(e = readdir(d))) { rc = errno ? -1 : 0; break; }
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    if (output_join(sub, sizeof sub, rel, e->d_name)
        || output_join(path, sizeof path, root, sub) || lstat(path, &sb)) rc = -1;
    else if (S_ISDIR(sb.st_mode)) rc = output_tree_list(t, root, sub);
    else rc = output_tree_add(t, sub);
  }
  if (d) { int saved = errno; closedir(d); errno = saved; }
  return rc ? rc : output_tree_add(t, rel);
}

/* remove the listed tree, now at root: -1 with errno on failure */
static int output_tree_remove(const Output_tree *t, const char *root)
{
  char path[1400];
  for (int k = 0; k < t->n; k++)
    if (output_join(path, sizeof path, root, t->path[k]) || remove(path)) return -1;
  return 0;
}

static void output_tree_free(Output_tree *t)
{
  for (int k = 0; k < t->n; k++) free(t->path[k]);
  free(t->path);
}

#line 705 "paper/output.nw"
/* hold SIGINT and SIGTERM (on), or let them through again (off) */
static void output_hold_signals(int on, sigset_t *saved)
{
  sigset_t s;
  sigemptyset(&s);
  sigaddset(&s, SIGINT);
  sigaddset(&s, SIGTERM);
  if (on) pthread_sigmask(SIG_BLOCK, &s, saved);
  else pthread_sigmask(SIG_SETMASK, saved, NULL);
}

void output_abort(Output *o)
{
  sigset_t saved;
  output_hold_signals(1, &saved);
  output_remove_tree(o->stage);
  output_publish(&o->staged, 0);
  output_hold_signals(0, &saved);
}

static int output_move_into_place(Output *o, Status *st)
{
  char old[1200];
  struct stat sb;
  Output_tree t = { NULL, 0, 0 };
  int had = !stat(o->dir, &sb), rc = STATUS_OK;
  snprintf(old, sizeof old, "%s.old-%ld", o->dir, (long) getpid());
  if (had && output_tree_list(&t, o->dir, ""))
    rc = output_errno(st, errno, o->dir, "cannot list the old run's files");
  else if (had && rename(o->dir, old))
    rc = output_errno(st, errno, o->dir, "cannot move the old run aside");
  else if (rename(o->stage, o->dir)) {
    rc = output_errno(st, errno, o->dir, "cannot move into place");
    if (had) rename(old, o->dir);
  } else if (output_publish(&o->staged, 0), had && output_tree_remove(&t, old))
    rc = status_set(st, STATUS_SYSTEM, "%s: the run is in place, but the old "
                    "run's files in %s cannot be removed: %s", o->dir, old,
                    strerror(errno));
  output_tree_free(&t);
  if (rc && stat(o->stage, &sb) == 0) output_abort(o);
  return rc;
}

int output_commit(Output *o, Status *st)
{
  sigset_t saved;
  output_hold_signals(1, &saved);
  int rc = output_move_into_place(o, st);
  output_hold_signals(0, &saved);
  return rc;
}
#line 828 "paper/output.nw"
int output_end(Output *o, int rc, Status *st)
{
  if (rc) output_abort(o);
  return rc ? rc : output_commit(o, st);
}
#line 841 "paper/output.nw"
static double output_u(const Model *md, int node, int c)
{
  int k = md->dofs->unknown[2 * node + c];
  return k < 0 ? 0.0 : md->Q[k];
}
#line 850 "paper/output.nw"
static FILE *output_open_in(Output *o, const char *sub, const char *name,
                            Status *st)
{
  char path[256];
  snprintf(path, sizeof path, "%s%s%s", sub, *sub ? "/" : "", name);
  return output_open(o, path, st);
}
#line 860 "paper/output.nw"
static int output_shape(Output *o, const char *sub, const Model *md,
                        const double *X, Status *st)
{
  FILE *f = output_open_in(o, sub, "shape.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m]\n");
  for (int i = 0; i < md->mesh->ncol; i++)
    fprintf(f, "%.10g %.15g\n", md->mesh->xy[2 * i], X[i]);
  return output_close(o, f, st);
}
#line 873 "paper/output.nw"
static int output_contact(Output *o, const char *sub, const Model *md,
                          const double *X, Status *st)
{
  const Dofs *d = md->dofs;
  FILE *f = output_open_in(o, sub, "contact.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa]%s\n",
          d->nt ? " u1[m] Tt[N/m]" : "");
  for (int c = 0, k = 0; c < d->nc; c++) {
    int i = d->contact_col[c];
    double u2 = md->Q[d->contact[c]];
    fprintf(f, "%.10g %.15g %.15g %.15g %.15g %.15g", md->mesh->xy[2 * i],
            X[i], u2, u2 + X[i], md->T[c],
            model_pressure(md, c));
    
#line 897 "paper/output.nw"
if (d->nt) {
  while (k < d->nt && d->tangent_col[k] < i) k++;
  int here = k < d->nt && d->tangent_col[k] == i;
  fprintf(f, " %.15g %.15g", here ? md->Q[d->tangent[k]] : 0.0,
          here ? md->T[d->nc + k] : 0.0);
}
#line 888 "paper/output.nw"
    fputc('\n', f);
  }
  return output_close(o, f, st);
}
#line 906 "paper/output.nw"
static int output_nodes(Output *o, const char *sub, const Model *md,
                        Status *st)
{
  const Mesh *m = md->mesh;
  FILE *f = output_open_in(o, sub, "nodes.dat", st);
  if (!f) return st->code;
  fprintf(f, "# node column row x1[m] x2[m] u1[m] u2[m]\n");
  for (int k = 0; k < m->nnodes; k++)
    fprintf(f, "%d %d %d %.15g %.15g %.15g %.15g\n", k, k % m->ncol,
            k / m->ncol, m->xy[2 * k], m->xy[2 * k + 1], output_u(md, k, 0),
            output_u(md, k, 1));
  return output_close(o, f, st);
}
#line 922 "paper/output.nw"
static int output_triangles(Output *o, const char *sub, const Model *md,
                            Status *st)
{
  const Mesh *m = md->mesh;
  FILE *f = output_open_in(o, sub, "triangles.dat", st);
  if (!f) return st->code;
  fprintf(f, "# x1[m] x2[m] u1[m] u2[m]: each triangle closed, blank-separated\n");
  for (int t = 0; t < m->ntri; t++) {
    for (int v = 0; v <= 3; v++) {
      int k = m->tri[3 * t + v % 3];
      fprintf(f, "%.15g %.15g %.15g %.15g\n", m->xy[2 * k], m->xy[2 * k + 1],
              output_u(md, k, 0), output_u(md, k, 1));
    }
    fprintf(f, "\n");
  }
  return output_close(o, f, st);
}
#line 960 "paper/output.nw"
typedef struct {
  const Model *md;          /* the state written */
  const double *X;          /* its design */
  double *stress;           /* 5 per triangle: sigma11, sigma22, sigma12,
                               sigma33, von Mises [Pa] */
} Vtu_state;

typedef struct {
  const char *section;      /* PointData, CellData, Points or Cells */
  const char *name;         /* the array's Name */
  const char *type;         /* Float64, Int32 or UInt8 */
  int components;           /* values per point or per cell */
  size_t count;             /* points or cells */
  size_t size;              /* bytes per value */
  int which;                /* the quantity, for a fill of several */
  void (*fill)(const Vtu_state *s, int which, void *values);
} Vtu_array;
#define VTU_MAX_ARRAYS 16

static size_t vtu_bytes(const Vtu_array *a)
{
  return a->count * a->components * a->size;
}
#line 1019 "paper/output.nw"
static void vtu_displacement(const Vtu_state *s, int which, void *values)
{
  double *v = values;
  (void) which;
  for (int k = 0; k < s->md->mesh->nnodes; k++) {
    v[3 * k] = output_u(s->md, k, 0);
    v[3 * k + 1] = output_u(s->md, k, 1);
    v[3 * k + 2] = 0;
  }
}

/* which 0: the gap u2 + alpha_i [m]; 1: the contact pressure [Pa] */
static void vtu_contact(const Vtu_state *s, int which, void *values)
{
  const Dofs *d = s->md->dofs;
  double *v = values;
  memset(v, 0, s->md->mesh->nnodes * sizeof *v);
  for (int c = 0; c < d->nc; c++) {
    int i = d->contact_col[c];
    v[i] = which == 0 ? s->md->Q[d->contact[c]] + s->X[i]
                      : model_pressure(s->md, c);
  }
}

static void vtu_contact_node(const Vtu_state *s, int which, void *values)
{
  uint8_t *v = values;
  (void) which;
  memset(v, 0, s->md->mesh->nnodes);
  for (int c = 0; c < s->md->dofs->nc; c++) v[s->md->dofs->contact_col[c]] = 1;
}

/* the nodal friction force T_t [N/m], 0 where u1 is held */
static void vtu_tangential(const Vtu_state *s, int which, void *values)
{
  const Dofs *d = s->md->dofs;
  double *v = values;
  (void) which;
  memset(v, 0, s->md->mesh->nnodes * sizeof *v);
  for (int k = 0; k < d->nt; k++) v[d->tangent_col[k]] = s->md->T[d->nc + k];
}
#line 1079 "paper/output.nw"
static void vtu_triangle_stress(const Model *md, int t, double s[5])
{
  long double e[3], sigma[3];
  fem_triangle_strain(md->mesh, md->dofs, md->Q, t, e);
  fem_element_stress(&md->hooke, e, sigma);
  for (int r = 0; r < 3; r++) s[r] = (double) sigma[r];
  s[3] = md->problem->model == MODEL_PLANE_STRAIN
       ? (double) (md->hooke.D[0][1] * (e[0] + e[1])) : 0.0;
  s[4] = sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[3]) * (s[1] - s[3])
                     + (s[3] - s[0]) * (s[3] - s[0])) + 3 * s[2] * s[2]);
}

static void vtu_stress(const Vtu_state *s, int which, void *values)
{
  double *v = values;
  for (int t = 0; t < s->md->mesh->ntri; t++) v[t] = s->stress[5 * t + which];
}
#line 1103 "paper/output.nw"
static void vtu_points(const Vtu_state *s, int which, void *values)
{
  const double *xy = s->md->mesh->xy;
  double *v = values;
  (void) which;
  for (int k = 0; k < s->md->mesh->nnodes; k++)
    v[3 * k] = xy[2 * k], v[3 * k + 1] = xy[2 * k + 1], v[3 * k + 2] = 0;
}

/* which 0: the connectivity, 3 vertices per triangle; 1: the offsets */
static void vtu_cells(const Vtu_state *s, int which, void *values)
{
  const Mesh *m = s->md->mesh;
  int32_t *v = values;
  for (int t = 0; t < m->ntri; t++)
    if (which == 1) v[t] = 3 * (t + 1);
    else for (int k = 0; k < 3; k++) v[3 * t + k] = m->tri[3 * t + k];
}

static void vtu_types(const Vtu_state *s, int which, void *values)
{
  (void) which;
  memset(values, 5, s->md->mesh->ntri);   /* VTK_TRIANGLE */
}
#line 988 "paper/output.nw"
static const char *const vtu_stress_names[5] =
  { "sigma11", "sigma22", "sigma12", "sigma33", "von_mises" };

static int vtu_arrays(const Model *md, Vtu_array a[VTU_MAX_ARRAYS])
{
  size_t np = md->mesh->nnodes, nt = md->mesh->ntri, d = sizeof(double);
  int n = 0;
  a[n++] = (Vtu_array) { "PointData", "displacement", "Float64", 3, np, d, 0, vtu_displacement };
  a[n++] = (Vtu_array) { "PointData", "gap", "Float64", 1, np, d, 0, vtu_contact };
  a[n++] = (Vtu_array) { "PointData", "pressure", "Float64", 1, np, d, 1, vtu_contact };
  a[n++] = (Vtu_array) { "PointData", "contact_node", "UInt8", 1, np, 1, 0, vtu_contact_node };
  if (md->dofs->nt)
    a[n++] = (Vtu_array) { "PointData", "tangential_force", "Float64", 1, np, d,
                           0, vtu_tangential };
  for (int k = 0; k < 5; k++)
    a[n++] = (Vtu_array) { "CellData", vtu_stress_names[k], "Float64", 1, nt, d, k, vtu_stress };
  a[n++] = (Vtu_array) { "Points", "Points", "Float64", 3, np, d, 0, vtu_points };
  a[n++] = (Vtu_array) { "Cells", "connectivity", "Int32", 1, 3 * nt, 4, 0, vtu_cells };
  a[n++] = (Vtu_array) { "Cells", "offsets", "Int32", 1, nt, 4, 1, vtu_cells };
  a[n++] = (Vtu_array) { "Cells", "types", "UInt8", 1, nt, 1, 0, vtu_types };
  return n;
}
#line 1132 "paper/output.nw"
static const char *vtu_byte_order(void)
{
  const uint16_t one = 1;
  return *(const uint8_t *) &one ? "LittleEndian" : "BigEndian";
}

static void vtu_header(FILE *f, const Mesh *m, const Vtu_array *a, int n)
{
  unsigned long long offset = 0;
  fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
             "version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
             "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" "
             "NumberOfCells=\"%d\">\n", vtu_byte_order(), m->nnodes, m->ntri);
  for (int k = 0; k < n; k++) {
    if (k > 0 && strcmp(a[k].section, a[k - 1].section))
      fprintf(f, "</%s>\n", a[k - 1].section);
    if (k == 0 || strcmp(a[k].section, a[k - 1].section))
      fprintf(f, "<%s>\n", a[k].section);
    fprintf(f, "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
               "format=\"appended\" offset=\"%llu\"/>\n", a[k].type, a[k].name,
            a[k].components, offset);
    offset += sizeof(uint64_t) + vtu_bytes(&a[k]);
  }
  fprintf(f, "</%s>\n</Piece>\n</UnstructuredGrid>\n"
             "<AppendedData encoding=\"raw\">\n_", a[n - 1].section);
}
#line 1163 "paper/output.nw"
static void vtu_data(FILE *f, const Vtu_state *s, const Vtu_array *a, int n,
                     void *values)
{
  for (int k = 0; k < n; k++) {
    uint64_t bytes = vtu_bytes(&a[k]);
    a[k].fill(s, a[k].which, values);
    fwrite(&bytes, sizeof bytes, 1, f);
    fwrite(values, 1, bytes, f);
  }
  fprintf(f, "\n</AppendedData>\n</VTKFile>\n");
}
#line 1179 "paper/output.nw"
static int vtu_write(FILE *f, const Model *md, const double *X, Status *st)
{
  Vtu_array a[VTU_MAX_ARRAYS];
  int n = vtu_arrays(md, a);
  size_t most = 0, nt = md->mesh->ntri;
  for (int k = 0; k < n; k++) most = vtu_bytes(&a[k]) > most ? vtu_bytes(&a[k]) : most;
  Vtu_state s = { md, X, malloc(5 * nt * sizeof(double)) };
  void *values = malloc(most);
  if (!s.stress || !values) {
    free(s.stress), free(values);
    return status_set(st, STATUS_MEMORY, "solution.vtu: out of memory");
  }
  for (size_t t = 0; t < nt; t++) vtu_triangle_stress(md, (int) t, s.stress + 5 * t);
  vtu_header(f, md->mesh, a, n);
  vtu_data(f, &s, a, n, values);
  free(s.stress), free(values);
  return STATUS_OK;
}
#line 1200 "paper/output.nw"
static int output_vtu(Output *o, const char *sub, const Model *md,
                      const double *X, Status *st)
{
  FILE *f = output_open_in(o, sub, "solution.vtu", st);
  if (!f) return st->code;
  int rc = vtu_write(f, md, X, st);
  int rc_close = output_close(o, f, st);
  return rc ? rc : rc_close;
}
#line 1213 "paper/output.nw"
int output_state(Output *o, const char *sub, const Model *md,
                 const double *X, Status *st)
{
  int rc;
  if ((rc = output_shape(o, sub, md, X, st))
      || (rc = output_contact(o, sub, md, X, st))
      || (o->plot_files && ((rc = output_nodes(o, sub, md, st))
                            || (rc = output_triangles(o, sub, md, st))))
      || (rc = output_vtu(o, sub, md, X, st)))
    return rc;
  return STATUS_OK;
}
#line 1260 "paper/output.nw"
static void output_friction(FILE *f, const Model *md)
{
  const Problem *p = md->problem;
  char v[STATUS_NUMBER];
  if (p->contact == CONTACT_FRICTIONLESS) return;
  fprintf(f, "contact %s\n", problem_contact_name(p->contact));
  if (p->contact == CONTACT_TRESCA)
    fprintf(f, "slip_bound %s\n", status_number(p->slip_bound, v));
  else fprintf(f, "friction %s\n", status_number(p->friction, v));
  fprintf(f, "friction_energy %.15g\n", md->friction_energy);
  if (p->contact == CONTACT_COULOMB)
    fprintf(f, "fixed_point_iterations %d\nfixed_point_residual %.3e\n",
            md->fixed_point_iterations, md->fixed_point_residual);
}
#line 1233 "paper/output.nw"
int output_solve(Output *o, const Output_run *run, const Model *md,
                 const double *X, Status *st)
{
  const Problem *p = md->problem;
  int rc = output_state(o, "", md, X, st);
  FILE *f = rc ? NULL : output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\n");
  fprintf(f, "scene %s\nstate_solver %s\nmodel %s\n", run->scene,
          run->state_solver, problem_model_name(p->model));
  fprintf(f, "N %d\nM %d\nR %d\ntriangles %d\ndofs %d\ncontact_nodes %d\n",
          p->N, p->M, p->R, md->mesh->ntri, md->dofs->n, md->dofs->nc);
  fprintf(f, "energy %.15g\nkkt_residual %.3e\niterations %d\n", md->energy,
          md->report.kkt, md->report.iterations);
  fprintf(f, "active_contact_nodes %d\nseconds %.6f\n", md->report.active,
          md->seconds);
  output_friction(f, md);
  threads_summary(f);
  return output_close(o, f, st);
}
#line 1279 "paper/output.nw"
int output_matrix_market(const char *path, const Model *md, Status *st)
{
  char tmp[1100];
  snprintf(tmp, sizeof tmp, "%s.partial", path);
  FILE *f = fopen(tmp, "w");
  if (!f) return output_errno(st, errno, path, "cannot write");
  int ok = cholmod_write_sparse(f, md->A, NULL, NULL, md->cm) >= 0;
  int memory = !ok && md->cm->status == CHOLMOD_OUT_OF_MEMORY;
  ok = !ferror(f) && ok;    /* CHOLMOD does not check every fprintf */
  ok = !fclose(f) && ok;
  if (ok && rename(tmp, path)) {
    int rc = output_errno(st, errno, path, "cannot move into place");
    remove(tmp);
    return rc;
  }
  if (!ok) {
    remove(tmp);
    return memory ? status_set(st, STATUS_MEMORY, "%s: out of memory", path)
                  : status_set(st, STATUS_SYSTEM, "%s: write failed", path);
  }
  return STATUS_OK;
}
#line 1312 "paper/output.nw"
static int output_gradient(Output *o, const Model *md, const Grad_check *gc,
                           Status *st)
{
  FILE *f = output_open(o, "gradient.dat", st);
  if (!f) return st->code;
  fprintf(f, "# i x1[m] dE/dX_i[J/m^2] finite_difference[J/m^2] relative_error\n");
  for (int k = 0; k < gc->ncheck; k++) {
    int i = gc->check[k];
    fprintf(f, "%d %.10g %.15g %.15g %.3e\n", i, md->mesh->xy[2 * i],
            gc->G[i], gc->fd[i], gc->err[i]);
  }
  return output_close(o, f, st);
}

int output_gradcheck(Output *o, const Output_run *run, const Model *md,
                     const Grad_check *gc, Status *st)
{
  const Problem *p = md->problem;
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\nscene %s\nmodel %s\nN %d\nenergy %.15g\n"
             "max_relative_error %.3e\nworst_node %d\nnodes_checked %d\n",
          run->scene, problem_model_name(p->model), p->N, md->energy,
          gc->err[gc->worst], gc->worst, gc->ncheck);
  output_friction(f, md);
  threads_summary(f);
  int rc = output_close(o, f, st);
  return rc ? rc : output_gradient(o, md, gc, st);
}
#line 1519 "paper/output.nw"
int output_start(Output *o, const Model *md, const double *X, double moved,
                 Output_start *start, Status *st)
{
  int rc = output_state(o, "initial", md, X, st);
  if (rc) return rc;
  start->energy = md->energy;
  start->cv = model_pressure_cv(md);
  start->moved = moved;
  return STATUS_OK;
}
#line 1410 "paper/output.nw"
static void history_vtu(Output_history *h, int iteration, const double *X)
{
  const Mesh *m = h->md->mesh;
  char name[64], path[80];
  for (int i = 0; i < m->ncol; i++)
    if (m->xy[2 * i + 1] != X[i]) {
      status_set(&h->vtu, STATUS_INPUT, "iterates/: the model is not at "
                 "iterate %d (alpha_%d = %.17g, the mesh at %.17g)",
                 iteration, i, X[i], m->xy[2 * i + 1]);
      return;
    }
  snprintf(name, sizeof name, ITERATE_VTU, iteration);
  snprintf(path, sizeof path, "iterates/%s", name);
  if (iteration + 1 > h->o->iterates) output_publish(&h->o->iterates, iteration + 1);
  FILE *f = output_open_in_folder(h->o, "iterates", name, &h->vtu);
  if (!f) return;
  if (vtu_write(f, h->md, X, &h->vtu)) fclose(f);
  else output_finish(f, h->o->dir, path, &h->vtu);
}

#line 1351 "paper/output.nw"
Output_history *output_history_new(int ndesign, Status *st)
{
  Output_history *h = calloc(1, sizeof *h);
  if (!h) status_set(st, STATUS_MEMORY, "optimize: out of memory");
  else h->ndesign = ndesign;
  return h;
}

static int history_grow(Output_history *h)
{
  int size = 2 * h->size + 16;
  Opt_progress *p = realloc(h->p, size * sizeof *p);
  if (p) h->p = p;
  double *X = realloc(h->X, (size_t) size * h->ndesign * sizeof *X);
  if (X) h->X = X;
  if (!p || !X) return h->failed = 1;
  h->size = size;
  return 0;
}

void output_history_add(Output_history *h, const Opt_progress *p,
                        const double *X)
{
  if (h->o && !h->vtu.code) history_vtu(h, p->iteration, X);
  if (h->failed || (h->n == h->size && history_grow(h))) return;
  memcpy(h->X + (size_t) h->n * h->ndesign, X, h->ndesign * sizeof *X);
  h->p[h->n++] = *p;
}

int output_history_vtu(Output_history *h, Output *o, const Model *md,
                       Status *st)
{
  int rc = output_folder(o, "iterates", st);
  if (!rc) h->o = o, h->md = md;
  return rc;
}

void output_history_free(Output_history *h)
{
  if (!h) return;
  free(h->p);
  free(h->X);
  free(h);
}
#line 1474 "paper/output.nw"
static int history_pvd(Output *o, const Output_history *h, Status *st)
{
  FILE *f = output_open(o, "iterates.pvd", st);
  if (!f) return st->code;
  fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
             "version=\"0.1\">\n<Collection>\n");
  for (int k = 0; k < h->n; k++)
    fprintf(f, "<DataSet timestep=\"%d\" part=\"0\" file=\"iterates/"
               ITERATE_VTU "\"/>\n", h->p[k].iteration, h->p[k].iteration);
  fputs("</Collection>\n</VTKFile>\n", f);
  return output_close(o, f, st);
}
#line 1438 "paper/output.nw"
static int history_iterates(Output *o, const Problem *p,
                            const Output_history *h, Status *st)
{
  FILE *f = output_open(o, "iterates.dat", st);
  if (!f) return st->code;
  fprintf(f, "# iteration i x1[m] alpha[m]: one block per iteration, "
             "two blank lines apart (gnuplot: index k)\n");
  for (int k = 0; k < h->n; k++)
    for (int i = 0; i < h->ndesign; i++)
      fprintf(f, "%s%d %d %.10g %.17g\n", k && !i ? "\n\n" : "",
              h->p[k].iteration, i, p->a + i * (p->b - p->a) / p->N,
              h->X[(size_t) k * h->ndesign + i]);
  return output_close(o, f, st);
}

int output_history(Output *o, const Problem *p, const Output_history *h,
                   Status *st)
{
  int rc;
  if (h->failed) return status_set(st, STATUS_MEMORY, "optimize: out of memory");
  if (h->vtu.code) return status_set(st, h->vtu.code, "%s", h->vtu.msg);
  FILE *f = output_open(o, "history.dat", st);
  if (!f) return st->code;
  fprintf(f, "# iteration E[J/m] projected_gradient state_solves seconds\n");
  for (int k = 0; k < h->n; k++)
    fprintf(f, "%d %.15g %.6e %d %.6f\n", h->p[k].iteration, h->p[k].energy,
            h->p[k].pgnorm, h->p[k].state_solves, h->p[k].seconds);
  if ((rc = output_close(o, f, st)) || (rc = history_iterates(o, p, h, st)))
    return rc;
  return h->o ? history_pvd(o, h, st) : STATUS_OK;
}
#line 1497 "paper/output.nw"
int output_multipliers(Output *o, const Problem *p, const double *X,
                       const double *G, const Design_multipliers *m,
                       Status *st)
{
  double h = (p->b - p->a) / p->N;
  if (m->N != p->N)
    return status_set(st, STATUS_INPUT, "multipliers.dat: multipliers made "
                      "for N = %d, the problem has N = %d", m->N, p->N);
  FILE *f = output_open(o, "multipliers.dat", st);
  if (!f) return st->code;
  fprintf(f, "# i x1[m] alpha[m] dE/dX_i lower(-X_i<=0) upper(X_i-C0<=0) "
             "rise(X_i+1-X_i-d<=0) fall(X_i-X_i+1-d<=0); mu = %.15g\n", m->mu);
  for (int i = 0; i <= p->N; i++)
    fprintf(f, "%d %.10g %.17g %.15g %.15g %.15g %.15g %.15g\n", i,
            p->a + i * h, X[i], G[i], m->lower[i], m->upper[i],
            i < p->N ? m->up[i] : 0.0, i < p->N ? m->down[i] : 0.0);
  return output_close(o, f, st);
}
#line 1535 "paper/output.nw"
int output_opt_summary(Output *o, const Output_run *run, const Model *md,
                       const Output_start *start, const Opt_report *r,
                       double mu, Status *st)
{
  const Problem *p = md->problem;
  FILE *f = output_open(o, "summary.dat", st);
  if (!f) return st->code;
  fprintf(f, "# name value\nscene %s\noptimizer %s\nmetric %s\nstate_solver %s\n"
          "model %s\n", run->scene, run->optimizer, run->metric,
          run->state_solver, problem_model_name(p->model));
  fprintf(f, "N %d\nM %d\nR %d\ninitial_projected %d\ninitial_moved %.6e\n",
          p->N, p->M, p->R, start->moved > 0, start->moved);
  fprintf(f, "initial_energy %.15g\nenergy %.15g\niterations %d\nevaluations %d\n",
          start->energy, r->energy, r->iterations, r->evaluations);
  fprintf(f, "projected_gradient %.6e\nstop_reason %s\n", r->pgnorm, r->stop_reason);
  fprintf(f, "seconds %.6f\nmetric_seconds %.6f\nstate_seconds %.6f\n",
          r->seconds, r->metric_seconds, r->state_seconds);
  if (r->model_seconds > 0) fprintf(f, "model_seconds %.6f\n", r->model_seconds);
  fprintf(f, "monitor_seconds %.6f\n", r->monitor_seconds);
  fprintf(f, "contact_pressure_cv_initial %.6f\ncontact_pressure_cv_final %.6f\n",
          start->cv, model_pressure_cv(md));
  fprintf(f, "active_contact_nodes %d\nkkt_residual %.3e\narea_multiplier %.15g\n",
          md->report.active, md->report.kkt, mu);
  output_friction(f, md);
  threads_summary(f);
  return output_close(o, f, st);
}
