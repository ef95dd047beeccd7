#!/bin/sh
# suite-table.sh OUT: the table of the robustness suite from the runs
# OUT/<scene>-newton and OUT/<scene>-slsqp (LaTeX, on standard output).
# Tangled from paper/opt.nw; do not edit.
out=$1
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
printf '%s\n' '\begin{tabular}{@{}lrrrrlr@{}}\toprule' \
  'scene & $N$ & $E^*$ [J/m] & Newton & SLSQP & SLSQP stops & $\Delta E^*$\\\midrule'
for d in "$out"/*-newton; do
  n=$(basename "$d" -newton); s=$out/$n-slsqp
  if [ ! -f "$d/summary.dat" ] || [ ! -f "$s/summary.dat" ]; then
    echo "suite-table.sh: $n: no runs" >&2; exit 1
  fi
  awk -v n="$n" -v N="$(v N $d)" -v e="$(v energy $d)" -v f="$(v energy $s)" \
      -v a="$(v iterations $d)/$(v evaluations $d)" -v b="$(v iterations $s)/$(v evaluations $s)" \
      -v stop="$(v stop_reason $s)" 'BEGIN {
    gsub("_", "\\_", n); gsub("_", "\\_", stop)
    d = (f - e) / (e < 0 ? -e : e)
    printf "%s & %d & $%.9g$ & %s & %s & %s & $%.1e$\\\\\n", n, N, e, a, b, stop, d }'
done
printf '%s\n' '\bottomrule\end{tabular}'
