#!/bin/sh
# cgssor-table.sh OUT: Example 5.1 with given friction, g = 2.5e8 Pa, solved
# by pdas and by cgssor (MPRGP on the dual) on N = 16, 64, 256 into
# OUT/<solver>-<N>, each three times; the table of the paragraph "Cost" of
# paper/cgssor.nw (LaTeX, on standard output): the steps and the best of
# the three times (the seconds of summary.dat: the whole solve, the
# condensation included), the machine's load under it, and the macro
# \cgssorexponent, the observed exponent p of MPRGP's steps ~ N^p from
# N = 16 to 256.  Timed, so rebuilt and not tracked.  Tangled from
# paper/cgssor.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
out=$1; sc=data/example-5.1-tresca.scene
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
# best N SOLVER: the steps and the least of three times of one solve
best() { for i in 1 2 3; do
    "$bin" solve $sc -o "$out/$2-$1" -s contact.g=2.5e8 -s mesh.refine=$(($1 / 16)) \
      -s solver.state=$2 > "$out/$2-$1.log"
    echo "$(v iterations "$out/$2-$1") $(v seconds "$out/$2-$1")"
  done | awk 'NR == 1 || $2 < t { t = $2 } { n = $1 } END { printf "%d & %.2g", n, t }'; }
echo "% written by src/cgssor-table.sh; do not edit"
printf '%s\n' '\begin{tabular}{rrrrr}' '\toprule' \
  '$N$ & \multicolumn{2}{c}{\texttt{pdas}} & \multicolumn{2}{c}{\texttt{cgssor}} \\' \
  '    & steps & s & steps & s \\' '\midrule'
for N in 16 64 256; do
  printf '%d & %s & %s \\\\\n' $N "$(best $N pdas)" "$(best $N cgssor)"
done
printf '%s\n' '\bottomrule' '\end{tabular}'
printf '%s %s, %s cores, load %s.}\n' \
  '\par\smallskip{\footnotesize Measured by \texttt{make figures} on' \
  "$(date -u +%F)" "$(v cores "$out/cgssor-256")" "$(v load_average "$out/cgssor-256")"
printf '\\gdef\\cgssorexponent{%.2f}\n' "$(awk -v a="$(v iterations "$out/cgssor-16")" \
  -v b="$(v iterations "$out/cgssor-256")" 'BEGIN { print log(b / a) / log(16) }')"
