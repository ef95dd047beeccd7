#!/bin/sh
# objectives.sh SCENE OUT: the runs of the section "Designing for the
# pressure": SCENE optimised by SLSQP (euclidean metric) for each
# objective at N = 16 and 64 into OUT/N<N>-<kind>; the list
# OUT/optima.dat and its table (LaTeX, on standard output).
# Tangled from paper/objective.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
scene=$1; out=$2
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
# zone DIR: the pressed nodes, the spread (sd/mean) and the peak of their
# pressure, and the zone as intervals of neighbouring nodes (a,b;c,d)
zone() { awk 'function close_() {
                if (on) z = z (z == "" ? "" : ";") a (b == a ? "" : "," b); on = 0 }
              /^#/ { next }
              $4 == 0 { if (!on) a = $1; b = $1; on = 1; n++; s += $6; s2 += $6 * $6
                        if ($6 > m) m = $6; next }
              { close_() }
              END { close_(); mu = s / n; sd = s2 / n - mu * mu
                    printf "%d %.3e %.6e %s", n, sqrt(sd > 0 ? sd : 0) / mu, m, z }' \
          "$1/contact.dat"; }
echo "# N kind stop_reason iterations E[J/m] compliance[J/m] pressure_spread" \
     "pressure_peak nodes pressure_cv peak_pressure[Pa] zone[m]" > "$out/optima.dat"
for r in 1 4; do
  for k in energy compliance pressure_spread pressure_peak; do
    d=$out/N$((16 * r))-$k
    "$bin" optimize "$scene" -s objective.kind=$k -s optimizer.method=slsqp \
        -s optimizer.metric=euclidean -s optimizer.max_iter=1000 \
        -s mesh.refine=$r -o "$d" > "$d.log" 2>&1 \
      || [ $? -eq 3 ]                            # not converged: its files are there
    echo "$((16 * r)) $k $(v stop_reason $d) $(v iterations $d) $(v final_energy $d)" \
         "$(v final_compliance $d) $(v final_pressure_spread $d)" \
         "$(v final_pressure_peak $d) $(zone $d/final)" >> "$out/optima.dat"
  done
done
awk 'BEGIN { nl = "\\\\"; split("energy compliance spread peak", nm, " ")
             print "\\begin{tabular}{@{}rlrrrrrrrrl@{}}\\toprule"
             print "$N$ & objective & $E$ [J/m] & $J_c$ [J/m] & $J_s$ & $J_q$" \
                   " & nodes & zone [m] & spread & peak [MPa] & stop (its)" nl "\\midrule" }
  !/^#/ { if (N && $1 != N) print "\\midrule"; N = $1
          z = $12; gsub(/,/, ", ", z); gsub(/;/, "], [", z)
          k = $2; gsub(/_/, "\\_", k); st = $3; gsub(/_/, "\\_", st)
          printf "%d & %s & $%.10g$ & $%.10g$ & $%.8g$ & $%.8g$ & %d & $[%s]$ & %.1e & %.1f" \
                 " & %s (%d)" nl "\n",
                 $1, k, $5, $6, $7, $8, $9, z, $10, $11 / 1e6, st, $4
          i = $2 == "energy" ? 1 : $2 == "compliance" ? 2 : $2 == "pressure_spread" ? 3 : 4
          n = $1 == 16 ? "sixteen" : "sixtyfour"
          mac = mac sprintf("\\gdef\\objopt%s%s{%.8g}\\gdef\\objstop%s%s{%s}",
                            n, nm[i], $(4 + i), n, nm[i], st) }
  END { print "\\bottomrule\\end{tabular}"; print mac }' "$out/optima.dat"
