#line 53 "paper/main.nw"
#include "usage.h"
#line 58 "paper/main.nw"
const char usage_main[] =
  "usage: contactopt COMMAND SCENE [options]\n"
  "Shape optimisation of an elastic body on a rigid foundation, frictionless\n"
  "or with friction (Haslinger & Neittaanmaki, M2AN 21, 1987).\n\n"
  "commands:\n"
  "  solve     solve the contact state at the scene's initial shape\n"
  "  gradcheck compare the gradient (4.8) with finite differences of E\n"
  "  optimize  find the contact shape of least energy (Section 4.4)\n"
  "  keys      list every key of a scene: unit, default, values, meaning\n\n"
  "'contactopt COMMAND --help' explains the options of a command;\n"
  "'contactopt --version' prints the version.\n\n"
  "-s section.key=value overrides a key of the scene; an empty value\n"
  "deletes it (-s top.P1=). An override of a choosing key (a side's bc,\n"
  "contact.model, design.initial, optimizer.method) drops the keys of the\n"
  "scene file that the new choice does not use: -s top.bc=free is enough.\n";

const char usage_solve[] =
  "usage: contactopt solve SCENE [-o DIR] [-s section.key=value ...]\n"
  "                  [--matrix-market FILE]\n"
  "Solve the contact state problem (4.3) at the scene's initial design and\n"
  "write the results into DIR.\n\n"
  "  -o DIR                output folder (default: out/NAME for NAME.scene)\n"
  "  -s section.key=value  override a key of the scene (repeatable;\n"
  "                        an empty value deletes it)\n"
  "  --matrix-market FILE  also write the stiffness matrix A(X), Dirichlet\n"
  "                        DOFs removed, in Matrix Market format\n"
  "  -h, --help            this text\n\n"
  "DIR receives summary.dat (energy, kkt_residual, iterations,\n"
  "active_contact_nodes, dofs, seconds, ...), shape.dat, contact.dat,\n"
  "nodes.dat, triangles.dat and solution.vtu (ParaView).\n"
  "Exit status: 0 success, 2 bad input, 3 no convergence, 4 cannot write.\n";

const char usage_gradcheck[] =
  "usage: contactopt gradcheck SCENE [-o DIR] [-s section.key=value ...]\n"
  "Compare the gradient (4.8) at the scene's initial design with finite\n"
  "differences of E (steps C0 * 1e-2 .. 1e-6; one-sided where alpha_i = 0)\n"
  "and print the largest relative error |G - G_fd| / max|G|.\n\n"
  "  -o DIR                output folder (default: out/NAME-gradcheck)\n"
  "  -s section.key=value  override a key of the scene (repeatable;\n"
  "                        an empty value deletes it)\n"
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
  "  -s section.key=value  override a key of the scene (repeatable;\n"
  "                        an empty value deletes it)\n"
  "  -h, --help            this text\n\n"
  "DIR receives history.dat, iterates.dat, summary.dat (energy, iterations,\n"
  "evaluations, projected_gradient, stop_reason, ...), multipliers.dat, and\n"
  "initial/ and final/ with the files of solve.\n"
  "Exit status: 0 converged, 2 bad input, 3 not converged (the files of the\n"
  "last design accepted are written), 4 cannot write.\n";

const char usage_keys[] =
  "usage: contactopt keys [--latex]\n"
  "List every key a scene file may give, one a line: section.key, unit,\n"
  "default (\"required\" if none), the values accepted, and its meaning.\n"
  "The loader reads the same table, so the list is what it accepts.\n\n"
  "  --latex               the same table as rows of a LaTeX longtable\n"
  "  -h, --help            this text\n";
