#line 384 "paper/main.nw"
#include <signal.h>
#include <string.h>
#include "interrupt.h"

static volatile sig_atomic_t noted;  /* the signal received, or 0 */
static void note(int sig) { noted = sig; }

void interrupt_catch(int on)
{
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on ? note : SIG_DFL;
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);
}

int interrupt_signal(void) { return noted; }
