#!/bin/sh
# coulomb.sh SCENE OUT: the runs of the section "Shape optimisation with
# Coulomb friction": SCENE as a Coulomb scene optimised by SLSQP for
# F = 0, 0.1, 0.2, 0.3 at N = 16 and 64 into OUT/N<N>-F<F>, the gradient
# check and the solve at its initial design, the Tresca optimum at
# g = F p* and the Coulomb state at its shape; the lists OUT/*.dat and
# their tables with their macros (LaTeX, on standard output).
# Tangled from paper/coulomb.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
scene=$1; out=$2
mkdir -p "$out"
co="-s contact.model=coulomb -s contact.g="
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
# zones DIR: the contact nodes, stick, slip, the mean pressure sum T /
# sum omega over them, and the contact zone as its intervals of nodes
# next to each other (a,b;c,d)
zones() { awk 'function close_() {
                 if (on) z = z (z == "" ? "" : ";") a (b == a ? "" : "," b); on = 0 }
               /^#/ { next }
               $4 == 0 { if (!on) a = $1; b = $1; on = 1; n++; sT += $5; sw += $5 / $6
                        if ($7 != 0) slip++; else if ($8 != 0) stick++; next }
               { close_() }
               END { close_(); printf "%d %d %d %.6e %s", n, stick, slip, sT / sw, z }' \
           "$1/contact.dat"; }
echo "# N F J_F*[J/m] contact stick slip p_mean[Pa] zone[m]" \
     "fixed_point_iterations iterations evaluations" > "$out/optima.dat"
for r in 1 4; do
  for F in 0 0.1 0.2 0.3; do
    d=$out/N$((16 * r))-F$F
    "$bin" optimize "$scene" $co -s contact.friction=$F -s optimizer.method=slsqp \
        -s mesh.refine=$r -o "$d" > "$d.log"
    echo "$((16 * r)) $F $(v energy $d) $(zones $d/final) $(v fixed_point_iterations $d)" \
         "$(v iterations $d) $(v evaluations $d)" >> "$out/optima.dat"
  done
done
echo "# F J_F[J/m] max_relative_error fixed_point_to_tol fixed_point_to_rounding" \
     > "$out/initial.dat"
for F in 0.1 0.2 0.3; do
  "$bin" gradcheck "$scene" $co -s contact.friction=$F -o "$out/gc-F$F" > /dev/null
  "$bin" solve "$scene" $co -s contact.friction=$F -o "$out/solve-F$F" > /dev/null
  echo "$F $(v energy $out/gc-F$F) $(v max_relative_error $out/gc-F$F)" \
       "$(v fixed_point_iterations $out/solve-F$F) $(v fixed_point_iterations $out/gc-F$F)" \
       >> "$out/initial.dat"
done
echo "# N F g[Pa] E_T*[J/m] J_F(alpha_T)[J/m] J_F*[J/m] max|alpha_T-alpha_C|[m]" \
     "stick_T slip_T" > "$out/tresca.dat"
for r in 1 4; do
  for F in 0.1 0.2 0.3; do
    c=$out/N$((16 * r))-F$F; t=$out/N$((16 * r))-T$F
    g=$(zones $c/final | awk -v F=$F '{ printf "%.6e", F * $4 }')
    "$bin" optimize "$scene" -s contact.g=$g -s mesh.refine=$r -o "$t" > "$t.log"
    "$bin" solve "$scene" $co -s contact.friction=$F -s mesh.refine=$r \
        -s design.initial=file -s design.file="$(cd "$t/final" && pwd)/shape.dat" \
        -o "$t-coulomb" > /dev/null
    dx=$(paste "$t/final/shape.dat" "$c/final/shape.dat" | awk '!/^#/ {
           d = $2 - $4; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3e", m }')
    echo "$((16 * r)) $F $g $(v energy $t) $(v energy $t-coulomb) $(v energy $c) $dx" \
         "$(zones $t/final | cut -d' ' -f2,3)" >> "$out/tresca.dat"
  done
done
awk 'function sci(x,  e) { if (x == 0) return "0"
                          e = int(log(x < 0 ? -x : x) / log(10) + 100) - 100
                          return sprintf("%.1f\\cdot10^{%d}", x / 10^e, e) }
  BEGIN { nl = "\\\\" }
  FILENAME ~ /initial/ && !/^#/ { e = $3 > e ? $3 : e
    lo = lo == "" || $4 < lo ? $4 : lo; hi = $5 > hi ? $5 : hi
    row[++n] = sprintf("$%s$ & $%.10g$ & $%s$ & %d & %d" nl, $1, $2, sci($3), $4, $5) }
  END { printf "\\gdef\\coulombgraderr{%s}\\gdef\\coulombfplo{%d}" \
               "\\gdef\\coulombfphi{%d}\n", sci(e), lo, hi
        print "\\begin{tabular}{@{}rrrrr@{}}\\toprule"
        print "$\\mathcal F$ & $J_{\\mathcal F}$ [J/m] & gradient error" \
              " & \\multicolumn{2}{c}{fixed-point its}" nl
        print "& & & to $10^{-10}$ & to rounding" nl "\\midrule"
        for (i = 1; i <= n; i++) print row[i]
        print "\\bottomrule\\end{tabular}" }' "$out/initial.dat"
echo '\par\medskip'
awk 'BEGIN { nl = "\\\\"; print "\\begin{tabular}{@{}rrrcrrrr@{}}\\toprule"
             print "$N$ & $\\mathcal F$ & $J_{\\mathcal F}^*$ [J/m] & contact zone [m]" \
                   " & stick & slip" \
                   " & fixed-point its & SLSQP its/solves" nl "\\midrule" }
  !/^#/ { if (N && $1 != N) print "\\midrule"; N = $1
          z = $8; gsub(/,/, ", ", z); gsub(/;/, "], [", z)
          printf "%d & $%s$ & $%.10g$ & $[%s]$ & %d & %d & %d & %d/%d" nl "\n",
                 $1, $2, $3, z, $5, $6, $9, $10, $11 }
  END { print "\\bottomrule\\end{tabular}" }' "$out/optima.dat"
echo '\par\medskip'
awk 'BEGIN { nl = "\\\\"; print "\\begin{tabular}{@{}rrrrrrrr@{}}\\toprule"
             print "$N$ & $\\mathcal F$ & $g = \\mathcal F\\bar p^*$ [MPa] & $E_T^*$ [J/m]" \
                   " & $J_{\\mathcal F}(\\alpha_T^*)$ [J/m] & $J_{\\mathcal F}^*$ [J/m]" \
                   " & $\\max|\\alpha_T^* - \\alpha^*|$ [mm] & stick/slip" nl "\\midrule" }
  !/^#/ { if (N && $1 != N) print "\\midrule"; N = $1
          printf "%d & $%s$ & %.1f & $%.10g$ & $%.10g$ & $%.10g$ & %.3f & %d/%d" nl "\n",
                 $1, $2, $3 / 1e6, $4, $5, $6, $7 * 1000, $8, $9 }
  END { print "\\bottomrule\\end{tabular}" }' "$out/tresca.dat"
