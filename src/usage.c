#line 50 "paper/main.nw"
#include "usage.h"
#line 55 "paper/main.nw"
const char usage_main[] =
  "usage: contactopt COMMAND SCENE [options]\n"
  "Shape optimisation of an elastic body on a rigid foundation, frictionless\n"
  "or with friction (Haslinger & Neittaanmaki, M2AN 21, 1987).\n\n"
  "commands:\n"
  "  solve     solve the contact state at the scene's initial shape\n"
  "  gradcheck compare the gradient (4.8) with finite differences of E\n"
  "  optimize  find the contact shape of least energy (Section 4.4)\n\n"
  "'contactopt COMMAND --help' explains the options of a command.\n";

const char usage_solve[] =
  "usage: contactopt solve SCENE [-o DIR] [-s section.key=value ...]\n"
  "                  [--matrix-market FILE]\n"
  "Solve the contact state problem (4.3) at the scene's initial design and\n"
  "write the results into DIR.\n\n"
  "  -o DIR                output folder (default: out/NAME for NAME.scene)\n"
  "  -s section.key=value  override a key of the scene (repeatable)\n"
  "  --matrix-market FILE  also write the stiffness matrix A(X), Dirichlet\n"
  "                        DOFs removed, in Matrix Market format\n"
  "  --plot-files          also write nodes.dat and triangles.dat (gnuplot)\n"
  "  -h, --help            this text\n\n"
  "DIR receives summary.dat (energy, kkt_residual, iterations,\n"
  "active_contact_nodes, dofs, seconds, ...), shape.dat, contact.dat and\n"
  "solution.vtu (ParaView: displacement, gap, pressure, stress).\n"
  "Exit status: 0 success, 2 bad input, 3 no convergence, 4 cannot write.\n";

const char usage_gradcheck[] =
  "usage: contactopt gradcheck SCENE [-o DIR] [-s section.key=value ...]\n"
  "Compare the gradient (4.8) at the scene's initial design with finite\n"
  "differences of E (steps C0 * 1e-2 .. 1e-6; one-sided where alpha_i = 0)\n"
  "and print the largest relative error |G - G_fd| / max|G|.\n\n"
  "  -o DIR                output folder (default: out/NAME-gradcheck)\n"
  "  -s section.key=value  override a key of the scene (repeatable)\n"
  "  -h, --help            this text\n\n"
  "DIR receives gradient.dat (i, x1, analytic dE/dX_i, best finite\n"
  "difference, relative error) and summary.dat (max_relative_error, ...).\n";

const char usage_optimize[] =
  "usage: contactopt optimize SCENE [-o DIR] [-s section.key=value ...]\n"
  "Minimise the total potential energy E over the design set B (4.4) from\n"
  "the scene's initial design (projected onto B if outside), by\n"
  "optimizer.method = newton (default), slsqp or projgrad (Algorithm 4.1).\n"
  "Prints a line per iteration: E, projected gradient, contact, seconds.\n\n"
  "  -o DIR                output folder (default: out/NAME-optimize)\n"
  "  -s section.key=value  override a key of the scene (repeatable)\n"
  "  --plot-files          also write nodes.dat and triangles.dat (gnuplot)\n"
  "  -h, --help            this text\n\n"
  "DIR receives history.dat, iterates.dat, summary.dat (energy, iterations,\n"
  "evaluations, projected_gradient, stop_reason, ...), multipliers.dat,\n"
  "initial/ and final/ with the files of solve, and iterates.pvd with\n"
  "iterates/ (the state at each iterate: ParaView plays it as an animation).\n"
  "Exit status: 0 converged, 2 bad input, 3 not converged (the files of the\n"
  "last design accepted are written), 4 cannot write.\n";
