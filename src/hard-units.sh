#!/bin/sh
# hard-units.sh OUT: Example 5.1 with Young's modulus and every load (the
# top traction and steel's weight as a body force) times f = 1, 1e-9,
# 1e9, 2^-30, 2^30, solved by each state solver and optimised by SLSQP and
# Algorithm 4.1 into OUT/<f>-<method>; the table of the section "Units"
# (LaTeX, on standard output), one line per factor.  Tangled from
# paper/stability.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
out=$1; ex=data/example-5.1.scene
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
units() { awk -v f="$1" 'BEGIN {
  printf "-s material.E=%.17g -s top.P2=%.17g -s body_force.F2=%.17g",
  f * 2.15e11, f * -5.75e8, f * -7.7e4 }'; }
echo "% written by src/hard-units.sh; do not edit"
printf '%s\n' '\begin{tabular}{@{}lrrrrr@{}}' '\toprule' \
  '$f$ & \texttt{pdas} & \texttt{cgssor} & \texttt{psor}' \
  '& SLSQP it./solves & Alg.~4.1 it./solves\\' \
  '\midrule'
for f in 1 1e-9 1e9 9.31322574615478515625e-10 1073741824; do
  for s in pdas cgssor psor; do
    "$bin" solve $ex -o "$out/$f-$s" $(units $f) -s solver.state=$s \
      > "$out/$f-$s.log"
  done
  for o in slsqp projgrad; do
    "$bin" optimize $ex -o "$out/$f-$o" $(units $f) -s optimizer.method=$o \
      > "$out/$f-$o.log"
  done
  case $f in 1) t='$1$' ;; 1e-9) t='$10^{-9}$' ;; 1e9) t='$10^{9}$' ;;
    9.3*) t='$2^{-30}$' ;; *) t='$2^{30}$' ;; esac
  printf '%s & %d & %d & %d & %d / %d & %d / %d\\\\\n' "$t" \
    "$(v iterations "$out/$f-pdas")" "$(v iterations "$out/$f-cgssor")" \
    "$(v iterations "$out/$f-psor")" \
    "$(v iterations "$out/$f-slsqp")" "$(v evaluations "$out/$f-slsqp")" \
    "$(v iterations "$out/$f-projgrad")" "$(v evaluations "$out/$f-projgrad")"
done
printf '%s\n' '\bottomrule' '\end{tabular}'
