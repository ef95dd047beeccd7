/* orderings: the fill of the factor of the stiffness of Example 5.1 under
   the orderings the state solver could use, analysis only (no numbers are
   factorised).  Run by tests/bench/orderings.sh (make bench); not a test.

     orderings SCENE [section.key=value ...]

   On the scene's mesh at its initial shape it orders the unknowns four
   ways and prints one line for each:
     N ordering lnz flops seconds
   lnz the entries of the factor L, flops those of the factorisation
   (CHOLMOD's estimates from its symbolic analysis), seconds the time of
   the ordering and the analysis.  The orderings:
     camd-last    CAMD with the contact unknowns constrained last (the
                  state solver's, paper/condense.nw);
     metis-last   METIS nested dissection of the other unknowns, the
                  contact unknowns appended last;
     amd          AMD, unconstrained (CHOLMOD's default, as bench_cholmod);
     metis        METIS, unconstrained.
   The last two cannot serve the condensation (the contact must come
   last); they show what the constraint costs. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <cholmod.h>
#include <gsl/gsl_errno.h>
#include "scene.h"
#include "mesh.h"
#include "fem.h"

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void die(const char *what, const char *why)
{
  fprintf(stderr, "orderings: %s: %s\n", what, why);
  exit(1);
}

/* analyse A under perm (or CHOLMOD's own choice, method, when perm is
   NULL), print the line, free the symbolic factor */
static void report(int N, const char *name, cholmod_sparse *A, Sparse_index *perm,
                   int method, double t0, cholmod_common *cm)
{
  cm->nmethods = 1, cm->method[0].ordering = perm ? CHOLMOD_GIVEN : method;
  cm->postorder = !perm;
  cholmod_factor *L = perm ? cholmod_l_analyze_p(A, perm, NULL, 0, cm)
                           : cholmod_l_analyze(A, cm);
  if (!L) die(name, "the analysis failed");
  printf("%d %s %.4e %.4e %.2f\n", N, name, cm->lnz, cm->fl, now() - t0);
  fflush(stdout);
  cholmod_l_free_factor(&L, cm);
}

int main(int argc, char **argv)
{
  Scene s;
  Status st;
  cholmod_common cm;
  if (argc < 2) die("usage", "orderings SCENE [section.key=value ...]");
  if (scene_load(&s, argv[1], argc - 2, argv + 2, &st)) die(argv[1], st.msg);
  cholmod_l_start(&cm);
  cm.print = 0;
  gsl_set_error_handler_off();
  Mesh *m = mesh_new(&s.problem, &st);
  if (!m || mesh_move(m, s.alpha0, &st)) die("mesh", st.msg);
  Fem_dofs *d = fem_dofs_new(m, &s.problem, &st);
  if (!d) die("fem_dofs_new", st.msg);
  cholmod_sparse *A = fem_stiffness_new(m, d, &cm, &st);
  if (!A) die("fem_stiffness_new", st.msg);
  A->stype = 1;                 /* both triangles are stored: read the upper */
  size_t n = A->ncol;
  Sparse_index ni = 0, *last = calloc(n + 1, sizeof *last), *perm = malloc((n + 1) * sizeof *perm),
               *inner = malloc(n * sizeof *inner), *pi = malloc(n * sizeof *pi);
  if (!last || !perm || !inner || !pi) die("orderings", "out of memory");
  for (int c = 0; c < d->nc; c++) last[d->contact[c]] = 1;
  int N = s.problem.N;
  double t0 = now();
  if (!cholmod_l_camd(A, NULL, 0, last, perm, &cm)) die("camd-last", "CAMD failed");
  report(N, "camd-last", A, perm, 0, t0, &cm);
  t0 = now();
  for (size_t i = 0; i < n; i++) if (!last[i]) inner[ni++] = (Sparse_index) i;
  cholmod_sparse *Af = cholmod_l_copy(A, 0, 1, &cm);       /* both triangles */
  cholmod_sparse *Aii = Af ? cholmod_l_submatrix(Af, inner, ni, inner, ni, 1, 1, &cm) : NULL;
  if (!Aii) die("metis-last", "out of memory for the interior");
  Aii->stype = 1;                                          /* its upper triangle */
  if (!cholmod_l_metis(Aii, NULL, 0, 1, pi, &cm)) die("metis-last", "METIS failed");
  for (Sparse_index k = 0; k < ni; k++) perm[k] = inner[pi[k]];
  Sparse_index q = ni;
  for (size_t i = 0; i < n; i++) if (last[i]) perm[q++] = (Sparse_index) i;
  cholmod_l_free_sparse(&Aii, &cm), cholmod_l_free_sparse(&Af, &cm);
  report(N, "metis-last", A, perm, 0, t0, &cm);
  report(N, "amd", A, NULL, CHOLMOD_AMD, now(), &cm);
  report(N, "metis", A, NULL, CHOLMOD_METIS, now(), &cm);
  free(last), free(perm), free(inner), free(pi);
  cholmod_l_free_sparse(&A, &cm);
  fem_dofs_free(d);
  mesh_free(m);
  scene_free(&s);
  cholmod_l_finish(&cm);
  return 0;
}
