#!/bin/sh
# friction.sh SCENE OUT: the runs of the section "Given friction": SCENE
# optimised for each slip bound g into OUT/g<g>, the Coulomb state at its
# initial design for three coefficients into OUT/coulomb-F<F>, the lists
# OUT/energy.dat and OUT/coulomb.dat, and their table (LaTeX, on standard
# output).  Tangled from paper/friction.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
scene=$1; out=$2
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
zones() { awk 'NR > 1 { if ($7 != 0) slip++; else if ($8 != 0) stick++ }
               END { printf "%d %d", stick, slip }' "$1/contact.dat"; }
echo "# g[Pa] E*[J/m] friction_energy[J/m] iterations solves stick slip" > "$out/energy.dat"
for g in 0 2e7 5e7 1e8 2e8 3e8 4e8 5e8 6e8 7e8 8e8 1e9; do
  d=$out/g$g
  "$bin" optimize "$scene" -s contact.g=$g -o "$d" > "$d.log"
  echo "$g $(v energy $d) $(v friction_energy $d) $(v iterations $d)" \
       "$(v evaluations $d) $(zones $d/final)" >> "$out/energy.dat"
done
echo "# F E[J/m] friction_energy[J/m] fixed_point_iterations residual" \
     "stick slip" > "$out/coulomb.dat"
for F in 0.1 0.2 0.3; do
  d=$out/coulomb-F$F
  "$bin" solve "$scene" -s contact.model=coulomb -s contact.g= \
      -s contact.friction=$F -o "$d" > "$d.log"
  echo "$F $(v energy $d) $(v friction_energy $d) $(v fixed_point_iterations $d)" \
       "$(v fixed_point_residual $d) $(zones $d)" >> "$out/coulomb.dat"
done
awk 'function sci(x,  e) { if (x == 0) return "0"; e = int(log(x) / log(10) + 1e-9)
                          return sprintf("%g\\cdot10^{%d}", x / 10^e, e) }
  BEGIN { print "\\begin{tabular}{@{}rrrrrr@{}}\\toprule"; w = "friction work [MJ/m]"
          nl = "\\\\"; row = "$%s$ & $%.9g$ & $%.4f$ & " }
  FNR == 1 && FILENAME ~ /energy/ {
    print "$g$ [Pa] & $E^*$ [J/m] & " w " & iterations/solves & stick & slip" nl "\\midrule"
    next }
  FNR == 1 {
    print "\\midrule $\\mathcal F$ & $E$ [J/m] & " w " & fixed-point its & residual" \
          " & stick/slip" nl "\\midrule"; next }
  FILENAME ~ /energy/ {
    printf row "%d/%d & %d & %d" nl "\n", sci($1), $2, $3 / 1e6, $4, $5, $6, $7; next }
  { printf row "%d & $%.1e$ & %d/%d" nl "\n", $1, $2, $3 / 1e6, $4, $5, $6, $7 }
  END { print "\\bottomrule\\end{tabular}" }' "$out/energy.dat" "$out/coulomb.dat"
