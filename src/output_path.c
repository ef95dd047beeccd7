#line 523 "paper/output.nw"
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "output_private.h"
#line 545 "paper/output.nw"
/* status_set with the code of errno e: STATUS_MEMORY for ENOMEM */
int output_errno(Status *st, int e, const char *path, const char *what)
{
  return status_set(st, e == ENOMEM ? STATUS_MEMORY : STATUS_SYSTEM, "%s: %s: %s",
                    path, what, strerror(e));
}
#line 557 "paper/output.nw"
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
#line 585 "paper/output.nw"
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
#line 670 "paper/output.nw"
/* the command of the run in dir, from its summary.dat: its command line,
   or (written before there was one) optimize where it names an optimizer,
   gradcheck where it counts nodes_checked, solve otherwise */
static int output_run_command(const char *dir, char *command, size_t size,
                              Status *st)
{
  char path[1200], line[256], word[64];
  const char *guess = "solve";
  snprintf(path, sizeof path, "%s/summary.dat", dir);
  FILE *f = fopen(path, "r");
  if (!f) return output_errno(st, errno, path, "cannot read");
  *command = '\0';
  while (!*command && fgets(line, sizeof line, f))
    if (sscanf(line, "command %63s", word) == 1) snprintf(command, size, "%s", word);
    else if (!strncmp(line, "optimizer ", 10)) guess = "optimize";
    else if (!strncmp(line, "nodes_checked ", 14)) guess = "gradcheck";
  if (!*command) snprintf(command, size, "%s", guess);
  fclose(f);
  return STATUS_OK;
}

/* whether the existing folder dir can be renamed (tried, and undone) */
static int output_movable(const char *dir, Status *st)
{
  char aside[1200];
  sigset_t s, saved;
  int e = 0;
  snprintf(aside, sizeof aside, "%s.check-%ld", dir, (long) getpid());
  sigemptyset(&s), sigaddset(&s, SIGINT), sigaddset(&s, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &s, &saved);
  if (rename(dir, aside)) e = errno;
  else if (rename(aside, dir) && rename(aside, dir)) {
    e = errno;
    pthread_sigmask(SIG_SETMASK, &saved, NULL);
    return status_set(st, STATUS_SYSTEM, "%s: moved to %s to check that it can be "
                      "replaced, and cannot be moved back: %s", dir, aside,
                      strerror(e));
  }
  pthread_sigmask(SIG_SETMASK, &saved, NULL);
  return e ? output_errno(st, e, dir, "cannot replace it (it cannot be moved "
                          "aside)") : STATUS_OK;
}

int output_check(const char *dir, const char *command, int replace, Status *st)
{
  struct stat sb;
  char path[1200], other[64];
  int rc = output_creatable(dir, 1, st);
  if (rc) return rc;
  if (stat(dir, &sb)) return STATUS_OK;                 /* absent */
  if (!S_ISDIR(sb.st_mode))
    return status_set(st, STATUS_INPUT, "%s: exists and is not a folder", dir);
  snprintf(path, sizeof path, "%s/summary.dat", dir);
  if (!stat(path, &sb)) {
    if ((rc = output_run_command(dir, other, sizeof other, st))) return rc;
    if (!replace && strcmp(other, command))
      return status_set(st, STATUS_INPUT, "%s: holds the run of contactopt %s: "
                        "%s would replace it; choose another -o, or give --replace",
                        dir, other, command);
    return output_movable(dir, st);
  }
  DIR *d = opendir(dir);
  struct dirent *e;
  int empty = d != NULL;
  while (d && empty && (e = readdir(d)))
    empty = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..");
  if (d) closedir(d);
  return !empty ? status_set(st, STATUS_INPUT, "%s: exists and holds files that "
                             "are not a run's (no summary.dat): choose another -o", dir)
                : output_movable(dir, st);
}
#line 769 "paper/output.nw"
void output_default_dir(const char *scene, const char *suffix, char *dir,
                        size_t size)
{
  const char *base = strrchr(scene, '/');
  base = base ? base + 1 : scene;
  size_t len = strlen(base);
  if (len > 6 && !strcmp(base + len - 6, ".scene")) len -= 6;
  snprintf(dir, size, "out/%.*s%s", (int) len, base, suffix);
}
