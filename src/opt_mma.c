#line 373 "paper/opt.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <nlopt.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include "opt_private.h"
#line 1296 "paper/opt.nw"
typedef struct {
  Opt_evaluator *ev;
  nlopt_opt opt;
  int n;                  /* N+1 */
  int ny;                 /* MMA's variables y: n - 1 less the fixed faces */
  double *X0;             /* n: the design at y = 0, in B */
  double *R;              /* n x ny, row-major: X = X0 + C0 R y */
  double scale;           /* sigma: the objective is J / sigma */
  double dual_tol;        /* delta J / sigma at the (re)start: where NLopt's
                             own dual of a pressure objective stops */
  double *S, *Z;          /* n x n, n x ny: scratch of the metric */
  gsl_matrix *A;          /* n x 2n: the area's and the faces' normals */
  Design_multipliers *mult;  /* of the iterate's KKT conditions */
  char *fixed, *faces;    /* 4n - 2 each: the faces fixed at the start, at
                             the last iterate (1 each, in opt_constraints' order) */
  double *X, *w;          /* n each: scratch */
  int *rows, nrows;       /* 4n - 2: the inequalities that vary with y, as
                             many as nrows, passed to NLopt (below) */
  double *c;              /* 4n - 2: scratch, all inequalities */
  double best, best_noise;  /* the lowest J of an iterate, its rounding */
  double *bestX;          /* n: the last accepted iterate */
  int k;                  /* accepted iterates so far */
  int stalled;            /* evaluations since the last accepted one */
  int fresh;              /* iterates accepted since MMA (re)started */
  int own_dual;           /* this start solves the dual by MMA's own method */
  double outside;         /* seconds in this file's callbacks, this start */
} Mma;
enum { MMA_STALL = 20 };
#line 1327 "paper/opt.nw"
/* X = X0 + C0 R y */
static void mma_design(const Mma *q, const double *y, double *X)
{
  int n = q->n, ny = q->ny;
  for (int i = 0; i < n; i++) {
    double s = 0;
    for (int j = 0; j < ny; j++) s += q->R[(size_t) i * ny + j] * y[j];
    X[i] = q->X0[i] + q->ev->B->C0 * s;
  }
}

/* grad = C0 R' G / sigma */
static void mma_gradient(const Mma *q, const double *G, double *grad)
{
  int n = q->n, ny = q->ny;
  for (int j = 0; j < ny; j++) grad[j] = 0;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < ny; j++) grad[j] += q->R[(size_t) i * ny + j] * G[i];
  for (int j = 0; j < ny; j++) grad[j] *= q->ev->B->C0 / q->scale;
}
#line 1353 "paper/opt.nw"
/* g (ny) = d c_k / d y for the inequality k of opt_constraints; its
   largest entry */
static double mma_row(const Mma *q, int k, double *g)
{
  int n = q->n, ny = q->ny, i = k < 2 * n ? k / 2 : (k - 2 * n) / 2;
  double sign = k % 2 ? 1 : -1, top = 0;
  const double *Ri = q->R + (size_t) i * ny, *Rj = Ri + ny;
  for (int j = 0; j < ny; j++) {
    g[j] = k < 2 * n ? sign * Ri[j] : -sign * (Rj[j] - Ri[j]);
    top = fmax(top, fabs(g[j]));
  }
  return top;
}

static void mma_constraints(unsigned m, double *c, unsigned ny,
                            const double *y, double *grad, void *data)
{
  Mma *q = data;
  double *X = q->w, start = resources_clock();
  mma_design(q, y, X);
  opt_constraints(q->ev->B, X, q->n, q->c);
  for (unsigned r = 0; r < m; r++) {
    c[r] = q->c[q->rows[r]];
    if (grad) mma_row(q, q->rows[r], grad + (size_t) r * ny);
  }
  q->outside += resources_clock() - start;
}
#line 1392 "paper/opt.nw"
static void mma_accept(Mma *q);
static int mma_faces(Mma *q, const double *X, char *face);
/* J(X(y)) / sigma, and its gradient in y */
static double mma_value(Mma *q, const double *y, double *grad)
{
  Opt_evaluator *ev = q->ev;
  mma_design(q, y, q->X);
  if (design_violation(ev->B, q->X) > 0
      && (ev->failed = design_project(ev->B, q->X, q->X, NULL, ev->st))) {
    nlopt_force_stop(q->opt);
    return HUGE_VAL;
  }
  if ((ev->failed = opt_evaluate(ev, q->X))) { nlopt_force_stop(q->opt); return HUGE_VAL; }
  if (grad) mma_gradient(q, ev->G, grad);
  if (ev->J <= q->best + q->best_noise + ev->noise
      && (q->k == 0 || memcmp(ev->X, q->bestX, q->n * sizeof *ev->X))) mma_accept(q);
  else if (++q->stalled >= MMA_STALL) nlopt_force_stop(q->opt);    /* restart */
  return ev->J / q->scale;
}
#line 1416 "paper/opt.nw"
static double mma_objective(unsigned ny, const double *y, double *grad,
                            void *data)
{
  Mma *q = data;
  double start = resources_clock(), J = mma_value(q, y, grad);
  q->outside += resources_clock() - start;
  (void) ny;
  return J;
}
#line 1428 "paper/opt.nw"
static void mma_stop(Mma *q, const char *why)
{
  snprintf(q->ev->rep->stop_reason, sizeof q->ev->rep->stop_reason, "%s", why);
  nlopt_force_stop(q->opt);
}

static void mma_accept(Mma *q)
{
  Opt_evaluator *ev = q->ev;
  if (ev->J < q->best) q->best = ev->J, q->best_noise = ev->noise;
  q->stalled = 0;
  q->fresh += q->k > 0;
  const char *why = opt_nlopt_iterate(ev, q->k, q->bestX);
  if (ev->failed) { nlopt_force_stop(q->opt); return; }
  if (why) mma_stop(q, why);
  else if ((ev->failed = mma_faces(q, ev->X, q->faces))) nlopt_force_stop(q->opt);
  else if (memcmp(q->faces, q->fixed, 4 * q->n - 2)) nlopt_force_stop(q->opt);  /* restart */
  q->k++;
}
#line 1452 "paper/opt.nw"
/* face[c] = 1 for each inequality c of opt_constraints on which X lies,
   within 1e-3 tol C0, with a positive multiplier */
static int mma_faces(Mma *q, const double *X, char *face)
{
  Opt_evaluator *ev = q->ev;
  const Design_multipliers *mu = q->mult;
  int n = q->n, rc;
  double *c = q->A->data, near = -1e-3 * ev->o->tol;  /* 4n - 2 <= 2n^2; A is
                                      filled by mma_basis, after */
  if ((rc = design_kkt(ev->B, X, ev->G, ev->tau, NULL, q->mult, NULL, ev->st))) return rc;
  opt_constraints(ev->B, X, n, c);
  for (int i = 0; i < n; i++) {
    face[2 * i] = c[2 * i] >= near && mu->lower[i] > 0;
    face[2 * i + 1] = c[2 * i + 1] >= near && mu->upper[i] > 0;
  }
  for (int i = 0; i + 1 < n; i++) {
    face[2 * n + 2 * i] = c[2 * n + 2 * i] >= near && mu->up[i] > 0;
    face[2 * n + 2 * i + 1] = c[2 * n + 2 * i + 1] >= near && mu->down[i] > 0;
  }
  return STATUS_OK;
}
#line 1482 "paper/opt.nw"
static int mma_basis(Mma *q)
{
  int n = q->n, k = 1, rank = 0, signum;
  gsl_matrix_set_zero(q->A);
  for (int i = 0; i < n; i++) gsl_matrix_set(q->A, i, 0, i == 0 || i == n - 1 ? 0.5 : 1.0);
  for (int i = 0; i < n; i++)
    if (q->fixed[2 * i] || q->fixed[2 * i + 1]) gsl_matrix_set(q->A, i, k++, 1.0);
  for (int i = 0; i + 1 < n; i++)
    if (q->fixed[2 * n + 2 * i] || q->fixed[2 * n + 2 * i + 1]) {
      gsl_matrix_set(q->A, i, k, -1.0);
      gsl_matrix_set(q->A, i + 1, k++, 1.0);
    }
  int r = k < n ? k : n;
  gsl_matrix_view A = gsl_matrix_submatrix(q->A, 0, 0, n, k);
  gsl_matrix_view Q = gsl_matrix_view_array(q->S, n, n);
  gsl_matrix *Rf = gsl_matrix_alloc(n, k);
  gsl_vector *tau = gsl_vector_alloc(r), *norm = gsl_vector_alloc(k);
  gsl_permutation *p = gsl_permutation_alloc(k);
  if (!Rf || !tau || !norm || !p) {
    gsl_matrix_free(Rf), gsl_vector_free(tau), gsl_vector_free(norm), gsl_permutation_free(p);
    return status_set(q->ev->st, STATUS_MEMORY, "optimiser: out of memory");
  }
  gsl_linalg_QRPT_decomp(&A.matrix, tau, p, &signum, norm);
  gsl_linalg_QR_unpack(&A.matrix, tau, &Q.matrix, Rf);
  double top = fabs(gsl_matrix_get(Rf, 0, 0));
  while (rank < r && fabs(gsl_matrix_get(Rf, rank, rank)) > 1e-12 * top) rank++;
  q->ny = n - rank;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < q->ny; j++)
      q->Z[(size_t) i * q->ny + j] = gsl_matrix_get(&Q.matrix, i, rank + j);
  gsl_matrix_free(Rf), gsl_vector_free(tau), gsl_vector_free(norm), gsl_permutation_free(p);
  return STATUS_OK;
}
#line 1518 "paper/opt.nw"
static int mma_basis(Mma *q);
static int mma_schur(Mma *q);
static void mma_varying(Mma *q);
/* the faces, Z, R and sigma at X, the evaluator's design */
static int mma_setup(Mma *q, const double *X)
{
  int n = q->n, rc;
  double Gmax = 0;
  memcpy(q->X0, X, n * sizeof *X);
  if ((rc = mma_faces(q, X, q->fixed)) || (rc = mma_basis(q)) || q->ny == 0) return rc;
  if (q->ev->o->metric == OPT_METRIC_SCHUR) rc = mma_schur(q);
  else {
    for (int i = 0; i < n; i++) Gmax = fmax(Gmax, fabs(q->ev->G[i]));
    memcpy(q->R, q->Z, (size_t) n * q->ny * sizeof *q->R);
    q->scale = q->ev->B->C0 * (Gmax > 0 ? Gmax : 1.0);
  }
  if (!rc) mma_varying(q);
  q->dual_tol = q->ev->noise / q->scale;
  return rc;
}
#line 1544 "paper/opt.nw"
static int mma_schur(Mma *q)
{
  Opt_evaluator *ev = q->ev;
  int n = q->n, m = q->ny, rc;
  double start = resources_clock();
  if ((rc = model_contact_stiffness(ev->md, q->S, ev->st))) return rc;
  gsl_matrix_view S = gsl_matrix_view_array(q->S, n, n);
  gsl_matrix_view Z = gsl_matrix_view_array(q->Z, n, m), R = gsl_matrix_view_array(q->R, n, m);
  gsl_matrix *K = gsl_matrix_alloc(m, m);
  gsl_vector *g = gsl_vector_alloc(m);
  if (!K || !g) rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  else {
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &S.matrix, &Z.matrix, 0.0, &R.matrix);
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, &Z.matrix, &R.matrix, 0.0, K);
    
#line 1568 "paper/opt.nw"
if (gsl_linalg_cholesky_decomp1(K))
  rc = status_set(ev->st, STATUS_NUMERIC, "optimiser: the contact stiffness "
                  "is not positive definite");
else {
  gsl_vector_const_view G = gsl_vector_const_view_array(ev->G, n);
  gsl_blas_dgemv(CblasTrans, 1.0, &Z.matrix, &G.vector, 0.0, g);
  gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, K, g);
  double sigma = pow(gsl_blas_dnrm2(g), 2);
  q->scale = sigma > 0 ? sigma : 1.0;
  gsl_matrix_memcpy(&R.matrix, &Z.matrix);                  /* R = Z L^{-T} */
  gsl_blas_dtrsm(CblasRight, CblasLower, CblasTrans, CblasNonUnit, 1.0, K, &R.matrix);
  gsl_matrix_scale(&R.matrix, sqrt(q->scale) / ev->B->C0);
}
#line 1559 "paper/opt.nw"
  }
  gsl_matrix_free(K);
  gsl_vector_free(g);
  ev->rep->metric_seconds += resources_clock() - start;
  return rc;
}
#line 1588 "paper/opt.nw"
static int mma_run(Mma *q, double *y, double *tol, int *more);
int opt_mma(Opt_evaluator *ev, double *X)
{
  int n = ev->n, rc = STATUS_OK;
  size_t nn = (size_t) n * n;
  double *scratch = malloc((3 * nn + 12 * (size_t) n + 2) * sizeof *scratch);
  Mma q = { .ev = ev, .n = n, .best = HUGE_VAL, .bestX = X,
            .fixed = malloc(8 * (size_t) n), .A = gsl_matrix_alloc(n, 2 * n),
            .mult = design_multipliers_new(ev->B, ev->st),
            .rows = malloc(4 * (size_t) n * sizeof(int)) };
  if (!scratch || !q.fixed || !q.A || !q.mult || !q.rows)
    rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory");
  for (int more = !rc; more && !rc; ) {
    q.S = scratch, q.Z = q.S + nn, q.R = q.Z + nn, q.X0 = q.R + nn;
    q.X = q.X0 + n, q.w = q.X + n, q.faces = q.fixed + 4 * n;
    double *y = q.w + n, *tol = y + n;          /* n - 1 and 4n - 2 */
    q.c = tol + 4 * n;                          /* 4n - 2 */
    if ((rc = opt_evaluate(ev, X)) || (rc = mma_setup(&q, X))) break;
    rc = mma_run(&q, y, tol, &more);
  }
  free(scratch), free(q.fixed), free(q.rows), gsl_matrix_free(q.A), design_multipliers_free(q.mult);
  return rc;
}
#line 1615 "paper/opt.nw"
static int mma_run(Mma *q, double *y, double *tol, int *more)
{
  Opt_evaluator *ev = q->ev;
  int m = q->nrows, rc = STATUS_OK;
  double f;
  if (q->ny == 0) 
#line 1642 "paper/opt.nw"
{
  *more = 0;
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "no_progress");
  snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "MMA: every "
           "direction of the design is fixed by a face of B that presses");
  return opt_evaluate(ev, q->bestX);
}
#line 1621 "paper/opt.nw"
  if (!(q->opt = nlopt_create(NLOPT_LD_MMA, q->ny)))
    return status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
  for (int i = 0; i < m; i++) tol[i] = 0;
  for (int i = 0; i < q->ny; i++) y[i] = 0;
  nlopt_result r = nlopt_add_inequality_mconstraint(q->opt, m, mma_constraints, q, tol);
  if (r > 0) r = nlopt_set_min_objective(q->opt, mma_objective, q);
  if (r > 0) r = nlopt_set_maxeval(q->opt, 50 * (ev->o->max_iter + 1) - ev->rep->evaluations + 1);
  
#line 1778 "paper/opt.nw"
if (r > 0 && !q->own_dual && (ev->o->metric == OPT_METRIC_EUCLIDEAN
                              || objective_fits_schur(&ev->o->objective)))
  r = nlopt_set_param(q->opt, "dual_algorithm", NLOPT_LD_LBFGS);
else if (r > 0 && !objective_fits_schur(&ev->o->objective))
  r = nlopt_set_param(q->opt, "dual_ftol_abs", q->dual_tol);
#line 1629 "paper/opt.nw"
  double start = resources_clock();
  q->outside = 0;
  if (r > 0) r = nlopt_optimize(q->opt, y, &f);
  ev->rep->subproblem_seconds += resources_clock() - start - q->outside;
  nlopt_destroy(q->opt);
  
#line 1655 "paper/opt.nw"
if (!(rc = ev->failed) && r == NLOPT_OUT_OF_MEMORY)
  rc = status_set(ev->st, STATUS_MEMORY, "optimiser: out of memory (NLopt)");
int retry = !rc && !ev->rep->stop_reason[0] && r == NLOPT_FAILURE && !q->own_dual;
*more = !rc && !ev->rep->stop_reason[0] && r != NLOPT_MAXEVAL_REACHED
        && (q->fresh > 0 || retry);
q->own_dual = retry;
if (!rc && !*more && !ev->rep->stop_reason[0]) {
  snprintf(ev->rep->stop_reason, sizeof ev->rep->stop_reason, "%s",
           r == NLOPT_MAXEVAL_REACHED ? "max_iter" : "no_progress");
  if (r != NLOPT_MAXEVAL_REACHED)
    snprintf(ev->rep->stop_detail, sizeof ev->rep->stop_detail, "MMA, %s, found no "
             "new iterate in %d evaluations (NLopt: %s)", ev->rep->iterations
             ? "restarted from its last iterate" : "from the start", q->stalled,
             nlopt_result_to_string(r));
}
if (!rc) rc = opt_evaluate(ev, q->bestX);
q->fresh = q->stalled = 0;
(void) f;
#line 1635 "paper/opt.nw"
  return rc;
}
#line 1765 "paper/opt.nw"
/* rows: the inequalities whose gradient in y is not zero (to rounding) */
static void mma_varying(Mma *q)
{
  int m = 4 * q->n - 2;
  double top = 0, *g = q->X;         /* ny <= n: the row, in scratch */
  for (int k = 0; k < m; k++) top = fmax(top, mma_row(q, k, g));
  q->nrows = 0;
  for (int k = 0; k < m; k++)
    if (!q->fixed[k] && mma_row(q, k, g) > 1e-12 * top) q->rows[q->nrows++] = k;
}
