#!/bin/sh
# hard-thin.sh OUT: the thin bodies tests/scenes/hard-thin.scene and
# hard-thinner.scene in both plane models, solved by each state solver
# and optimised by SLSQP and Algorithm 4.1 into OUT/<body>-<model>-<method>,
# the four bodies side by side; the table of the section "Thin bodies"
# (LaTeX, on standard output) and its macro \thinN{same}.  Projected SOR
# does not converge there in its 10^5 sweeps (exit 3): its cell is the
# residual it gave up at, read from its one line on the standard error.
# Tangled from paper/stability.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
out=$1
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
# body BODY MODEL: every run of one body in one model
body() { sc=tests/scenes/hard-$1.scene; n=$out/$1-$2; m="-s material.model=$2"
  for s in pdas cgssor; do
    "$bin" solve $sc -o $n-$s $m -s solver.state=$s > $n-$s.log
  done
  "$bin" solve $sc -o $n-psor $m -s solver.state=psor > $n-psor.log \
    2> $n-psor.err || true
  for o in slsqp projgrad; do
    "$bin" optimize $sc -o $n-$o $m -s optimizer.method=$o > $n-$o.log
  done; }
for b in thin thinner; do
  for m in plane_stress plane_strain; do body $b $m & done
done
wait
echo "% written by src/hard-thin.sh; do not edit"
printf '%s\n' '\begin{tabular}{@{}llrrrrrr@{}}' '\toprule' \
  'body & model & \texttt{pdas} & \texttt{cgssor} & \texttt{psor}' \
  '& SLSQP it./solves & Alg.~4.1 it./solves & $-E^*$ [MJ/m]\\' \
  '\midrule'
for b in thin thinner; do
  g=$(awk '$1 == "gamma" { print $3 }' tests/scenes/hard-$b.scene)
  for m in plane_stress plane_strain; do
    n=$out/$b-$m
    # psor: its sweeps where it converged, else the residual it stopped at
    if [ -f $n-psor/summary.dat ]; then p=$(v iterations $n-psor)
    else p=$(sed -n 's/.*kkt = \([0-9.e+-]*\) .*/\1/p' $n-psor.err |
      awk '{ x = $1 + 0; e = int(log(x) / log(10) - (x < 1))
        printf "$%.1f\\cdot10^{%d}$", x / 10^e, e }')
    fi
    printf '%s & %s & %d & %d & %s & %d / %d & %d / %d & %.6f\\\\\n' \
      "$([ $m = plane_stress ] && echo "\$\\gamma = $g\$")" "${m#plane_}" \
      "$(v iterations $n-pdas)" "$(v iterations $n-cgssor)" "$p" \
      "$(v iterations $n-slsqp)" "$(v evaluations $n-slsqp)" \
      "$(v iterations $n-projgrad)" "$(v evaluations $n-projgrad)" \
      "$(v energy $n-projgrad | awk '{ printf "%.6f", -$1 / 1e6 }')"
  done
done
printf '%s\n' '\bottomrule' '\end{tabular}\\[2pt]' \
  '{\footnotesize \texttt{psor}: its sweeps, or the residual at which' \
  'it gives up after $10^5$ (exit 3).}'
# \thinN{same}: the largest relative difference of E* between SLSQP and
# Algorithm 4.1 over the four bodies
for n in "$out"/*-plane_*-slsqp; do
  echo "$(v energy $n) $(v energy ${n%-slsqp}-projgrad)"
done | awk '{ d = ($1 - $2) / $2; d = d < 0 ? -d : d; if (d > m) m = d }
  END { printf "\\gdef\\thinN#1{\\csname thin:#1\\endcsname}\n"
    if (m == 0) s = "$0$"
    else { split(sprintf("%.1e", m), p, "e"); s = sprintf("$%s\\cdot10^{%d}$", p[1], p[2]) }
    printf "\\expandafter\\gdef\\csname thin:same\\endcsname{%s}\n", s }'
