#line 503 "paper/output.nw"
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "output_private.h"
#line 518 "paper/output.nw"
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
#line 546 "paper/output.nw"
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
#line 617 "paper/output.nw"
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
#line 665 "paper/output.nw"
void output_default_dir(const char *scene, const char *suffix, char *dir,
                        size_t size)
{
  const char *base = strrchr(scene, '/');
  base = base ? base + 1 : scene;
  size_t len = strlen(base);
  if (len > 6 && !strcmp(base + len - 6, ".scene")) len -= 6;
  snprintf(dir, size, "out/%.*s%s", (int) len, base, suffix);
}
