#line 741 "paper/main.nw"
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>
#include "interrupt.h"

static const int caught_signals[2] = { SIGINT, SIGTERM };
static volatile sig_atomic_t noted;  /* the first signal received, or 0 */
static char line[512];               /* the line of the first signal */
static size_t length;                /* its length */
static void (*cleanup)(void *);      /* what a second signal does first */
static void *cleanup_arg;
static pthread_t main_thread;        /* the thread that runs the handler */
static struct sigaction before[2];   /* SIGINT's and SIGTERM's, while caught */
static struct sigaction fallback;    /* the default action */
static int caught[2];                /* whether each is caught now */

#line 766 "paper/main.nw"
static void on_signal(int sig)
{
  int saved = errno;
  if (!pthread_equal(pthread_self(), main_thread))
    pthread_kill(main_thread, sig);
  else if (!noted) {
    noted = sig;
    ssize_t w = write(STDERR_FILENO, line, length);
    (void) w;                        /* a line that cannot be written is lost */
  } else {
    if (cleanup) cleanup(cleanup_arg);
    sigaction(sig, &fallback, NULL);
    raise(sig);                      /* delivered when the handler returns */
  }
  errno = saved;
}
#line 787 "paper/main.nw"
void interrupt_catch(int on, const char *message, void (*fn)(void *),
                     void *arg)
{
  struct sigaction sa;
  for (int k = 0; k < 2 && !on; k++)
    if (caught[k]) sigaction(caught_signals[k], &before[k], NULL), caught[k] = 0;
  if (!on || caught[0] || caught[1]) return;
  main_thread = pthread_self();
  length = strlen(message) < sizeof line ? strlen(message) : sizeof line - 1;
  memcpy(line, message, length);
  cleanup = fn, cleanup_arg = arg;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sa.sa_flags = SA_RESTART;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  fallback = sa;
  fallback.sa_handler = SIG_DFL;
  for (int k = 0; k < 2; k++) {
    sigaction(caught_signals[k], NULL, &before[k]);
    if (before[k].sa_handler != SIG_IGN)
      caught[k] = !sigaction(caught_signals[k], &sa, NULL);
  }
}

#line 762 "paper/main.nw"
int interrupt_signal(void) { return noted; }
