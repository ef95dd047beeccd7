#line 347 "paper/output.nw"
#define _XOPEN_SOURCE 700   /* nftw, to remove a folder tree */
#include <dirent.h>
#include <errno.h>
#include <ftw.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "output_private.h"
#line 447 "paper/output.nw"
/* *mark = v, after every write before it, as a signal handler sees them */
void output_publish(volatile sig_atomic_t *mark, int v)
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

#line 391 "paper/output.nw"
/* path and its parents; a failure names the parent, or the folder
   shown (the user's) where it is path itself, the staging folder */
static int output_mkdirs(const char *path, const char *shown, Status *st)
{
  char p[1200];
  snprintf(p, sizeof p, "%s", path);
  for (char *s = p + 1; ; s++)
    if (*s == '/' || *s == '\0') {
      char c = *s;
      *s = '\0';
      if (mkdir(p, 0777) && errno != EEXIST)
        return output_errno(st, errno, c ? p : shown, "cannot create");
      if (!(*s = c)) return STATUS_OK;
    }
}

#line 504 "paper/output.nw"
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
#line 745 "paper/output.nw"
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

#line 410 "paper/output.nw"
int output_begin(Output *o, const char *dir, const char *command, int replace,
                 Status *st)
{
  memset(o, 0, sizeof *o);
  snprintf(o->dir, sizeof o->dir, "%s", dir);
  snprintf(o->command, sizeof o->command, "%s", command);
  snprintf(o->stage, sizeof o->stage, "%s.partial-%ld", dir, (long) getpid());
  output_publish(&o->staged, 1);
  int rc = output_check(dir, command, replace, st);
  if (!rc) output_remove_dead(dir);
  return rc ? rc : output_mkdirs(o->stage, dir, st);
}
#line 783 "paper/output.nw"
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
  if (!output_mkdirs(path, path, st)) {
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

int output_finish(FILE *f, const char *dir, const char *name,
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
#line 825 "paper/output.nw"
FILE *output_open_in(Output *o, const char *sub, const char *name,
                     Status *st)
{
  char path[256];
  snprintf(path, sizeof path, "%s%s%s", sub, *sub ? "/" : "", name);
  return output_open(o, path, st);
}
#line 837 "paper/output.nw"
int output_folder(Output *o, const char *name, Status *st)
{
  char path[1300];
  if (o->nfiles == OUTPUT_MAX_FILES)
    return status_set(st, STATUS_SYSTEM, "%s: too many output files", o->dir);
  snprintf(path, sizeof path, "%s/%s", o->stage, name);
  snprintf(o->file[o->nfiles], sizeof o->file[0], "%s/", name);
  output_publish(&o->opening, 1);
  int rc = output_mkdirs(path, path, st);
  if (!rc) o->nfiles++;
  output_publish(&o->opening, 0);
  return rc;
}

FILE *output_open_in_folder(Output *o, const char *folder,
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
#line 944 "paper/output.nw"
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

#line 886 "paper/output.nw"
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
#line 1009 "paper/output.nw"
int output_end(Output *o, int rc, Status *st)
{
  if (rc) output_abort(o);
  return rc ? rc : output_commit(o, st);
}
