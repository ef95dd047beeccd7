#line 45 "paper/main.nw"
#ifndef CONTACTOPT_USAGE_H
#define CONTACTOPT_USAGE_H
/* the version of the program: the one place it is written */
#define CONTACTOPT_VERSION "1.0"
/* the help of the program and of each command, as printed */
extern const char usage_main[], usage_solve[], usage_gradcheck[],
  usage_optimize[], usage_keys[], usage_plot[];
#endif
