#!/bin/sh
# reproduction.sh OUT: the table of the section "Reproduction", from the
# runs in OUT (written by make figures); LaTeX on standard output.
out=${1:-out}
v() { awk -v k=$1 '$1 == k { print $2 }' $out/$2/summary.dat; }
sci() { awk -v x=$1 'BEGIN { e = int(log(x < 0 ? -x : x) / log(10)); if ((x < 0 ? -x : x) < 1) e--;
          printf "$%.6f\\cdot10^{%d}$\n", x / 10 ^ e, e }'; }
within() { awk -v f=$1 '!/^#/ { it[n] = $1; E[n++] = $2 } END {
  for (k = 0; k < n; k++) { d = E[k] - E[n-1]; if (d < 0) d = -d
    if (d <= f * (E[0] - E[n-1])) { print it[k]; exit } } }' $out/$2/history.dat; }
shapediff() { case $2 in $1|*C2arc*) echo --; return;; esac
  paste $out/$1/final/shape.dat $out/$2/final/shape.dat | awk '!/^#/ {
    d = $2 - $4; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.1e\n", m }'; }
runs="example-5.1-optimize example-5.2-optimize example-5.2-flat-optimize
      example-5.1-C2arc-optimize"
each() { for r in $runs; do "$@" $r; done; }
row() { printf '%s & %s & %s & %s & %s\\\\\n' "$1" "$2" "$3" "$4" "$5"; }
line() { printf '%s\n' "$1"; }
to() { printf '%s$\\to$%s\n' "$1" "$2"; }
has() { [ -f $out/$1/summary.dat ] || { echo --; return 1; }; }
E_alpha0() { has ${1%-optimize} && sci $(v energy ${1%-optimize}); }
E_start() { sci $(v initial_energy $1); }
E_final() { sci $(v energy $1); }
E_strain() { s=${1%-optimize}-strain-optimize; has $s && sci $(v energy $s); }
solves() { printf '%s/%s\n' $(v iterations $1) $(v evaluations $1); }
touching() { awk '!/^#/ && $4 == 0' $out/$1/initial/contact.dat | wc -l; }
contact_nodes() { to $(touching $1) $(v active_contact_nodes $1); }
cv() { v contact_pressure_cv_$1 $2 | cut -c1-5; }
spread() { to $(cv initial $1) $(cv final $1); }
pmax() { awk '!/^#/ && $6 > m { m = $6 } END { printf "%.2f", m / 1e8 }' $out/$1/$2/contact.dat; }
peak() { to $(pmax $1 initial) $(pmax $1 final); }
line '\begin{tabular}{lcccc}\toprule'
row '' 'Example 5.1' 'Example 5.2' '5.2, $\alpha^0 = 0.05$' '5.1, $C_2 = 3.933$'
line '\midrule'
row '$E_h(\alpha^0)$, J/m' $(each E_alpha0)
row '$E_h$ at the start $P_B(\alpha^0)$' $(each E_start)
row '$E_h^*$ (plane stress)' $(each E_final)
row 'iterations to within 1\,\% of $E_h^*-E_h^0$' $(each within 1e-2)
row 'iterations to within 0.1\,\%' $(each within 1e-3)
row 'iterations / state solves' $(each solves)
row 'stop' $(each v stop_reason)
row 'contact nodes in contact, start $\to$ end' $(each contact_nodes)
row 'pressure: std./mean, start $\to$ end' $(each spread)
row 'largest pressure, $10^8$\,Pa, start $\to$ end' $(each peak)
row 'max. $|\alpha^* - \alpha^*_{5.1}|$, m' $(each shapediff example-5.1-optimize)
row '$E_h^*$ (plane strain)' $(each E_strain)
line '\bottomrule\end{tabular}'
