#line 433 "paper/main.nw"
#ifndef CONTACTOPT_INTERRUPT_H
#define CONTACTOPT_INTERRUPT_H
/* on: SIGINT and SIGTERM are noted, once (a second one has its default
   effect); off: both have the effect they had before again */
void interrupt_catch(int on);
/* the signal noted since the program started, or 0 */
int interrupt_signal(void);
#endif
