#line 359 "paper/overview.nw"
/* example.c: the contact shape of least energy of the body of a scene,
   as contactopt optimize finds it, without the files: example SCENE */
#include <stdio.h>
#include <stdlib.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "scene.h"
#include "model.h"
#include "grad.h"
#include "design.h"
#include "opt.h"

int main(int argc, char **argv)
{
  Scene s;
  Status st = { STATUS_OK, "" };
  cholmod_common cm;
  Opt_report rep;
  if (argc != 2) { fprintf(stderr, "usage: example SCENE\n"); return STATUS_INPUT; }
  if (scene_load(&s, argv[1], 0, NULL, &st)) { fprintf(stderr, "%s\n", st.msg); return st.code; }
  cholmod_l_start(&cm);
  cm.print = 0;                       /* failures come back as a Status */
  gsl_set_error_handler_off();
  Design_set B = design_set(&s.problem);
  Model *md = model_new(&s.problem, &s.solver, &cm, &st);
  double *X = malloc((s.problem.N + 1) * sizeof *X), violation, moved;
  int rc = STATUS_OK;
  if (!md) rc = st.code;
  else if (!X) rc = status_set(&st, STATUS_MEMORY, "example: out of memory");
  if (!rc) rc = design_feasible_start(&B, s.alpha0, 1e-12, X, &violation, &moved, &st);
  if (!rc) rc = opt_minimize(md, &B, &s.optimizer, X, NULL, NULL, &rep, &st);
  if (rc) fprintf(stderr, "%s\n", st.msg);
  else printf("%.17g J/m after %d iterations: %s\n", rep.energy, rep.iterations,
              rep.stop_reason);
  free(X);
  model_free(md);
  cholmod_l_finish(&cm);
  scene_free(&s);
  return rc;
}
