/* walltime FILE COMMAND [ARG...]: run COMMAND and write to FILE one line,
   "seconds maxrss_MiB": its wall-clock time (CLOCK_MONOTONIC, which date(1)
   and the shell do not offer) and its peak resident set.  Exits with
   COMMAND's status, or 1 if it could not be run or was killed, so that a
   failed run fails the benchmark (tests/bench/performance.sh). */
#include <stdio.h>
#include <time.h>
#include <unistd.h>
#include <sys/resource.h>
#include <sys/wait.h>

int main(int argc, char **argv)
{
  struct timespec t0, t1;
  struct rusage ru;
  int status;
  if (argc < 3) {
    fputs("usage: walltime FILE COMMAND [ARG...]\n", stderr);
    return 1;
  }
  clock_gettime(CLOCK_MONOTONIC, &t0);
  pid_t pid = fork();
  if (pid < 0) { perror("walltime: fork"); return 1; }
  if (pid == 0) {
    execvp(argv[2], argv + 2);
    perror(argv[2]);
    _exit(127);
  }
  if (waitpid(pid, &status, 0) != pid) { perror("walltime: waitpid"); return 1; }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  if (getrusage(RUSAGE_CHILDREN, &ru)) { perror("walltime: getrusage"); return 1; }
  FILE *f = fopen(argv[1], "w");
  if (!f || fprintf(f, "%.6f %.1f\n", (t1.tv_sec - t0.tv_sec)
                    + 1e-9 * (t1.tv_nsec - t0.tv_nsec), ru.ru_maxrss / 1024.0) < 0
      || fclose(f)) {
    perror(argv[1]);
    return 1;
  }
  if (WIFSIGNALED(status)) {
    fprintf(stderr, "walltime: %s killed by signal %d\n", argv[2], WTERMSIG(status));
    return 1;
  }
  return WEXITSTATUS(status);
}
