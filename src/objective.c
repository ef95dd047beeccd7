#line 172 "paper/objective.nw"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "objective.h"
#line 180 "paper/objective.nw"
const char *const objective_names[] = {"energy", "compliance", "pressure_spread",
                                       "pressure_peak", NULL};

Objective objective_default(void) { return (Objective) { OBJECTIVE_ENERGY, 8 }; }

const char *objective_name(Objective_kind k)
{
  return (unsigned) k < OBJECTIVE_COUNT ? objective_names[k] : "?";
}

const char *objective_symbol(Objective_kind k)
{
  return k == OBJECTIVE_ENERGY ? "E" : objective_name(k);
}

const char *objective_unit(Objective_kind k)
{
  return k == OBJECTIVE_ENERGY || k == OBJECTIVE_COMPLIANCE ? " J/m" : "";
}
#line 206 "paper/objective.nw"
int objective_is_energy(Objective_kind k) { return k == OBJECTIVE_ENERGY; }

int objective_has_exponent(Objective_kind k) { return k == OBJECTIVE_PEAK; }

int objective_has_kinks(const Model *md, const Objective *o)
{
  return !objective_is_energy(o->kind) || model_problem(md)->contact == CONTACT_COULOMB;
}
#line 224 "paper/objective.nw"
int objective_fits_schur(const Objective *o)
{
  return o->kind == OBJECTIVE_ENERGY || o->kind == OBJECTIVE_COMPLIANCE;
}
#line 234 "paper/objective.nw"
/* T_c >= 0 of each contact unknown, and omega_c its tributary length */
static void objective_forces(const Model *md, double *T, double *w)
{
  const Fem_dofs *d = model_dofs(md);
  const double *Q = model_state(md), *lo = model_bounds(md), *Tm = model_forces(md);
  for (int c = 0; c < d->nc; c++) {
    T[c] = Q[d->contact[c]] <= lo[c] ? fmax(Tm[c], 0) : 0;
    w[c] = mesh_tributary(model_mesh(md), d->contact_col[c]);
  }
}
#line 251 "paper/objective.nw"
/* J_s of T, omega (nc) and S1 = sum T > 0; dT, dw its partial derivatives */
static double spread(int nc, const double *T, const double *w, double S1,
                     double *dT, double *dw)
{
  double L = 0, S2 = 0;
  for (int c = 0; c < nc; c++) L += w[c], S2 += T[c] * T[c] / w[c];
  for (int c = 0; c < nc; c++) {
    double p = T[c] / w[c];
    dT[c] = 2 * L * (p - S2 / S1) / (S1 * S1);
    dw[c] = (S2 - L * p * p) / (S1 * S1);
  }
  return L * S2 / (S1 * S1) - 1;
}
#line 271 "paper/objective.nw"
/* J_q of T, omega (nc), S1 = sum T > 0 and the exponent q >= 1 */
static double peak(int nc, const double *T, const double *w, double S1,
                   double q, double *dT, double *dw)
{
  double L = 0, pm = 0, Sq = 0;
  for (int c = 0; c < nc; c++) L += w[c], pm = fmax(pm, T[c] / w[c]);
  for (int c = 0; c < nc; c++) Sq += w[c] * pow(T[c] / w[c] / pm, q);
  double J = pm * pow(Sq / L, 1 / q) * L / S1;
  for (int c = 0; c < nc; c++) {
    double r = T[c] / w[c] / pm;
    dT[c] = J * (pow(r, q - 1) / (pm * Sq) - 1 / S1);
    dw[c] = J * (1 - 1 / q) * (1 / L - pow(r, q) / Sq);
  }
  return J;
}
#line 291 "paper/objective.nw"
/* J, and dT, dw (nc, may be NULL) its partial derivatives in T and omega */
int objective_partials(const Model *md, const Objective *o, double *J,
                       double *dT, double *dw, Status *st)
{
  const Fem_dofs *d = model_dofs(md);
  const double *Q = model_state(md), *lo = model_bounds(md);
  int nc = d->nc, code = STATUS_OK;
  double *v = malloc(4 * ((size_t) nc + 1) * sizeof *v), S1 = 0;
  if (!v) return status_set(st, STATUS_MEMORY, "objective: out of memory");
  double *T = v, *w = v + nc + 1, *gT = dT ? dT : w + nc + 1, *gw = dw ? dw : gT + nc + 1;
  memset(gT, 0, nc * sizeof *gT), memset(gw, 0, nc * sizeof *gw);
  objective_forces(md, T, w);
  for (int c = 0; c < nc; c++) S1 += T[c];
  if (o->kind == OBJECTIVE_ENERGY) *J = model_energy(md);
  else if (o->kind == OBJECTIVE_COMPLIANCE) {
    long double W = 0;
    const double *b = model_load(md);
    for (int i = 0; i < d->n; i++) W += (long double) b[i] * Q[i];
    *J = (double) W;
  } else if (!(S1 > 0))
    code = status_set(st, STATUS_NUMERIC, "objective: %s is undefined: no "
                      "contact node presses (the body lifts off its foundation)",
                      objective_name(o->kind));
  else *J = o->kind == OBJECTIVE_SPREAD ? spread(nc, T, w, S1, gT, gw)
                                        : peak(nc, T, w, S1, o->q, gT, gw);
  for (int c = 0; c < nc; c++)     /* a free node's T is 0 on these sets */
    if (Q[d->contact[c]] > lo[c]) gT[c] = 0;
  free(v);
  return code;
}

int objective_value(const Model *md, const Objective *o, double *J, Status *st)
{
  return objective_partials(md, o, J, NULL, NULL, st);
}
#line 330 "paper/objective.nw"
int objective_same_sets(const Model *md, char *held, int write)
{
  const Fem_dofs *d = model_dofs(md);
  const double *Q = model_state(md), *lo = model_bounds(md);
  int nc = d->nc, nt = d->nt, same = 1;
  for (int k = 0; k < nc + nt; k++) {
    char h = k < nc ? Q[d->contact[k]] <= lo[k] : Q[d->tangent[k - nc]] == 0;
    if (write) held[k] = h; else same &= held[k] == h;
  }
  return same;
}
