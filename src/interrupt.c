#line 444 "paper/main.nw"
#include <signal.h>
#include <string.h>
#include "interrupt.h"

static volatile sig_atomic_t noted;  /* the signal received, or 0 */
static void note(int sig) { noted = sig; }
static struct sigaction before[2];   /* SIGINT's and SIGTERM's, while caught */
static int caught;

void interrupt_catch(int on)
{
  struct sigaction sa;
  if (on == caught) return;
  caught = on;
  if (!on) {
    sigaction(SIGINT, &before[0], NULL);
    sigaction(SIGTERM, &before[1], NULL);
    return;
  }
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = note;
  sa.sa_flags = SA_RESETHAND | SA_RESTART;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &before[0]);
  sigaction(SIGTERM, &sa, &before[1]);
}

int interrupt_signal(void) { return noted; }
