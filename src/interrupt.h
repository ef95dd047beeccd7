#line 714 "paper/main.nw"
#ifndef CONTACTOPT_INTERRUPT_H
#define CONTACTOPT_INTERRUPT_H
/* on: SIGINT and SIGTERM are caught, but one that was ignored before
   stays ignored.  The first writes message (one line) on the standard
   error at once and is noted; a second calls cleanup(arg), which must be
   async-signal-safe, and then has its default effect.  off: both have
   the effect they had before again. */
void interrupt_catch(int on, const char *message, void (*cleanup)(void *),
                     void *arg);
/* the signal noted since the program started, or 0 */
int interrupt_signal(void);
#endif
