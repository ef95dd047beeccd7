#!/bin/sh
# hard-units.sh OUT: Example 5.1 with Young's modulus and every load (the
# top traction and steel's weight as a body force) times f = 1, 1e-9,
# 1e9, 2^-30, 2^30, solved by each state solver and optimised by SLSQP and
# Algorithm 4.1 into OUT/<f>-<method>; the table of the section "Units"
# (LaTeX, on standard output), one line per factor, and the macros
# \unitsN{KEY} of its largest differences from f = 1 over every factor and
# method: disp (the displacements, relative to the largest), energy (E/f,
# relative), force (T/f, relative to the largest), shape (alpha, in C0).
# Tangled from paper/stability.nw; do not edit.
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
    "$bin" solve $ex -o "$out/$f-$s" --plot-files $(units $f) -s solver.state=$s \
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
# apart FILE COLS SCALE METHOD SCALED: the largest |x_f / s - x_1| over the columns COLS
# (a,b) of the rows of FILE in every run OUT/<f>-<method> against
# OUT/1-<method>, relative to the largest |x_1| (or, with SCALE, to it);
# s is f where the column scales with the load (SCALED 1), 1 where not
apart() { for d in "$out"/*-"$4"; do
    case $d in "$out"/1-*) continue ;; esac
    f=${d#"$out"/}; f=${f%-"$4"}
    awk -v f="$f" -v c="$2" -v sc="$3" -v scaled="$5" '
      FNR == 1 { n++ } /^#/ { next }
      { split(c, k, ","); for (j in k) if (n == 1) x[FNR, j] = $(k[j])
          else { y = scaled ? $(k[j]) / f : $(k[j]); d = y - x[FNR, j]; d = d < 0 ? -d : d
                 if (d > m) m = d } }
      n == 1 { for (j in k) { a = $(k[j]) < 0 ? -$(k[j]) : $(k[j]); if (a > big) big = a } }
      END { printf "%.17g\n", m / (sc > 0 ? sc : big) }' "$out/1-$4/$1" "$d/$1"
  done; }
energy() { for d in "$out"/*-"$1"; do
    f=${d#"$out"/}; f=${f%-"$1"}
    awk -v f="$f" -v e1="$(v energy "$out/1-$1")" -v e="$(v energy "$d")" \
      'BEGIN { d = e / f - e1; printf "%.17g\n", (d < 0 ? -d : d) / (e1 < 0 ? -e1 : e1) }'
  done; }
# the largest of standard input as $a\cdot10^{k}$ (0 as $0$)
most() { sort -g | tail -1 | awk '{ if ($1 == 0) { print "$0$"; exit }
  split(sprintf("%.1e", $1), p, "e"); printf "$%s\\cdot10^{%d}$\n", p[1], p[2] }'; }
dis=$(for s in pdas cgssor psor; do apart nodes.dat 6,7 0 $s 0; done | most)
ene=$(for m in pdas cgssor psor slsqp projgrad; do energy $m; done | most)
frc=$(for s in pdas cgssor psor; do apart contact.dat 5,5 0 $s 1; done | most)
shp=$(for o in slsqp projgrad; do apart final/shape.dat 2,2 0.05 $o 0; done | most)
printf '%s\n' '\gdef\unitsN#1{\csname units:#1\endcsname}'
for kv in "disp $dis" "energy $ene" "force $frc" "shape $shp"; do
  printf '\\expandafter\\gdef\\csname units:%s\\endcsname{%s}\n' ${kv%% *} "${kv#* }"
done
