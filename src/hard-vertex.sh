#!/bin/sh
# hard-vertex.sh OUT: Example 5.1 optimised by SLSQP and Algorithm 4.1 in
# both plane models from four vertices of B (rise, fall, V, Lambda:
# OUT/<start>.dat, read with design.initial = file) into
# OUT/<start>-<model>-<method>; the table of the section "Optimisations
# from the corners of B" (LaTeX, on standard output).  E(X^0) is the
# energy of iteration 0 of SLSQP in plane stress, at the start projected
# onto B.  hard-vertex.sh --starts OUT writes the four starts alone
# (tests/hard_cases.sh optimises from them).  Tangled from
# paper/stability.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
starts=; [ "$1" = --starts ] && { starts=1; shift; }
out=$1; ex=data/example-5.1.scene
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
# the four starts on the article's mesh: C0 = 0.05, C1 = 0.025, area 0.09
awk -v o="$out" 'BEGIN { C0 = 0.05; C1 = 0.025
  w = 2 - sqrt(3.6); p = sqrt(0.09 * C1)
  for (i = 0; i <= 16; i++) { x = i / 4
    r = C1 * (x - 1.2); r = r < 0 ? 0 : r > C0 ? C0 : r
    f = C1 * (2.8 - x); f = f < 0 ? 0 : f > C0 ? C0 : f
    a = x < 2 ? 2 - x : x - 2
    v = C1 * (a - w); v = v < 0 ? 0 : v > C0 ? C0 : v
    l = p - C1 * a; l = l < 0 ? 0 : l
    printf "%g %.17g\n", x, r > (o "/rise.dat")
    printf "%g %.17g\n", x, f > (o "/fall.dat")
    printf "%g %.17g\n", x, v > (o "/V.dat")
    printf "%g %.17g\n", x, l > (o "/Lambda.dat") } }'
[ -z "$starts" ] || exit 0
noarc="-s design.arc_x1= -s design.arc_x2= -s design.arc_radius="
# design.file is read relative to the scene's folder: the starts by
# their full path
dir=$(cd "$out" && pwd)
echo "% written by src/hard-vertex.sh; do not edit"
printf '%s\n' '\begin{tabular}{@{}lrrrrr@{}}' '\toprule' \
  'start & $-E(X^0)$ [MJ/m] & SLSQP stress & Alg.~4.1 stress' \
  '& SLSQP strain & Alg.~4.1 strain\\' \
  '\midrule'
for s in rise fall V Lambda; do
  cells=
  for m in plane_stress plane_strain; do
    for o in slsqp projgrad; do
      n=$out/$s-$m-$o
      "$bin" optimize $ex -o $n $noarc -s design.initial=file \
        -s design.file=$dir/$s.dat \
        -s material.model=$m -s optimizer.method=$o > $n.log
      cells="$cells & $(v iterations $n) / $(v evaluations $n)"
    done
  done
  e=$(awk '!/^#/ { printf "%.2f", -$2 / 1e6; exit }' \
    $out/$s-plane_stress-slsqp/history.dat)
  name=$s; [ $s = Lambda ] && name='$\Lambda$'
  printf '%s & %s%s\\\\\n' "$name" "$e" "$cells"
done
printf '%s\n' '\bottomrule' '\end{tabular}\\[2pt]' \
  '{\footnotesize iterations / state solves; $E(X^0)$ in plane stress.}'
# \vertexN{KEY}: ref, stressrel, strain, strainspread, pglo, pghi, moved,
# worst; a number grouped by thousands, a ratio as $a\cdot10^{k}$
ref=$(awk '$1 == "energy_final" { print $2 }' data/reference/example-5.1.dat)
for n in "$out"/*-plane_*-*/; do
  n=${n%/}; m=${n#"$out"/}; m=${m#*-}; m=${m%-*}
  printf '%s %s %s %s %s\n' "${n##*/}" "$m" "$(v energy $n)" \
    "$(v projected_gradient $n)" "$(v initial_moved $n)"
done | awk -v ref="$ref" -v e0="$(for s in rise fall V Lambda; do
    awk '!/^#/ { print $2; exit }' $out/$s-plane_stress-slsqp/history.dat; done)" '
  function abs(x) { return x < 0 ? -x : x }
  function sci(x,  p) { if (x == 0) return "$0$"
    split(sprintf("%.1e", x), p, "e"); return sprintf("$%s\\cdot10^{%d}$", p[1], p[2]) }
  function group(x, d,  t, i, w, g) { t = sprintf("%." d "f", abs(x)); i = index(t, ".")
    w = i ? substr(t, 1, i - 1) : t; g = ""
    while (length(w) > 3) { g = "\\," substr(w, length(w) - 2) g; w = substr(w, 1, length(w) - 3) }
    return (x < 0 ? "-" : "") w g (i ? substr(t, i) : "") }
  function def(k, v) { printf "\\expandafter\\gdef\\csname vertex:%s\\endcsname{%s}\n", k, v }
  BEGIN { n0 = split(e0, z, "\n"); lo0 = abs(z[1])
    for (i = 2; i <= n0; i++) if (abs(z[i]) < lo0) lo0 = abs(z[i]) }
  { e = $3; pg = $4 + 0
    if (NR == 1 || pg < pglo) pglo = pg; if (NR == 1 || pg > pghi) pghi = pg
    if ($1 ~ /^(V|Lambda)-/ && $5 + 0 > moved) moved = $5 + 0
    if ($2 == "plane_stress") { r = abs(e - ref) / abs(ref); if (r > rel) rel = r
      if (abs(e) > best) best = abs(e) }
    else { if (!ns++ || e < slo) slo = e; if (ns == 1 || e > shi) shi = e } }
  END { print "\\gdef\\vertexN#1{\\csname vertex:#1\\endcsname}"
    def("ref", group(ref, 4)); def("stressrel", sci(rel)); def("strain", group(slo, 3))
    def("strainspread", sci((shi - slo) / abs(slo))); def("pglo", sci(pglo)); def("pghi", sci(pghi))
    def("moved", sci(moved)); def("worst", sprintf("%.0f", best / lo0)) }'
