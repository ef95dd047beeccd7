#!/bin/sh
# hard-parts.sh OUT: the convergence studies of a part of the user's own
# (the section "A part of the user's own"): Kirsch's hole, measured by
# the test program tests/test_kirsch.c (KIRSCH, default
# build/tests/test_kirsch) at mesh.refine = 1, 2, 4, 8; Example 5.1
# optimised on its built-in rectangle and on tests/parts/example-5.1.geo
# at the same levels, into OUT/rect<k> and OUT/geo<k>.  The two tables
# (LaTeX, on standard output) and the macros \partsN{KEY} of the prose.
# Tangled from paper/stability.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
kirsch=${KIRSCH:-build/tests/test_kirsch}
out=$1; levels="1 2 4 8"
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
"$kirsch" $levels > $out/kirsch.dat
echo "% written by src/hard-parts.sh; do not edit"
awk '
  function def(k, v) { printf "\\expandafter\\gdef\\csname parts:%s\\endcsname{%s}\n", k, v }
  BEGIN { n = 0 }
  /^#/ { next }
  { k[n] = $1; t[n] = $2; q[n] = $3; e[n++] = $4 }
  END { print "\\gdef\\partsN#1{\\csname parts:#1\\endcsname}"
    print "\\begin{tabular}{@{}rrrrr@{}}"; print "\\toprule"
    print "refine & triangles & $\\sigma_{22}/(-p)$ at the hole & error from 3 & rate\\\\"
    print "\\midrule"
    for (i = 0; i < n; i++)
      printf "%d & %d & %.4f & %.4f & %s\\\\\n", k[i], t[i], q[i], e[i],
        i ? sprintf("%.2f", log(e[i-1] / e[i]) / log(k[i] / k[i-1])) : ""
    print "\\bottomrule"; print "\\end{tabular}\\\\[6pt]"
    def("kirsch:err", sprintf("%.1f\\,\\%%", 100 * e[n-1] / 3))
    def("kirsch:finest", k[n-1])
    def("kirsch:rate", sprintf("%.2f", log(e[0] / e[n-1]) / log(k[n-1] / k[0]))) }' $out/kirsch.dat
geo=$(cd tests/parts && pwd)/example-5.1.geo
# the scene without its top side, gamma and R; C2 the strip's area
sed -e '/^\[top\]/,/^P2/d' -e '/^gamma/d' -e '/^R = /d' \
    -e 's/^C2 = 3.91$/C2 = 0.91/' data/example-5.1.scene \
  | awk -v g="$geo" '{ print }
      /^C0prime/ { print "[part]"; print "geometry = " g }' > $out/band.scene
printf '%s\n' '[boundary.left]' 'bc = clamped' '[boundary.right]' 'bc = roller' \
  '[boundary.load]' 'bc = traction' 'P2 = -5.75e8' >> $out/band.scene
for k in $levels; do
  "$bin" optimize data/example-5.1.scene -o $out/rect$k -s mesh.refine=$k > $out/rect$k.log
  "$bin" optimize $out/band.scene -o $out/geo$k -s mesh.refine=$k > $out/geo$k.log
  echo "$k $(v energy $out/rect$k) $(v energy $out/geo$k)"
done | awk '
  function abs(x) { return x < 0 ? -x : x }
  function sci(x,  p) { split(sprintf("%.1e", x), p, "e")
    return sprintf("$%s\\cdot10^{%d}$", p[1], p[2]) }
  function order(a, b, c) { return log((a - b) / (b - c)) / log(2) }
  function def(k, v) { printf "\\expandafter\\gdef\\csname parts:%s\\endcsname{%s}\n", k, v }
  BEGIN { n = 0 }
  { k[n] = $1; r[n] = $2; g[n++] = $3 }
  END { print "\\begin{tabular}{@{}rrrrrr@{}}"; print "\\toprule"
    print "refine & $-E^*$ built-in [J/m] & $-E^*$ geometry [J/m]"
    print "& difference & order built-in & order geometry\\\\"
    print "\\midrule"
    for (i = 0; i < n; i++) {
      o1 = i > 1 ? sprintf("%.2f", order(r[i-2], r[i-1], r[i])) : ""
      o2 = i > 1 ? sprintf("%.2f", order(g[i-2], g[i-1], g[i])) : ""
      printf "%d & %.1f & %.1f & %s & %s & %s\\\\\n", k[i], -r[i], -g[i],
        sci(abs(g[i] - r[i]) / abs(r[i])), o1, o2 }
    print "\\bottomrule"; print "\\end{tabular}"
    m = n - 1; qr = order(r[m-2], r[m-1], r[m]); qg = order(g[m-2], g[m-1], g[m])
    lr = r[m] + (r[m] - r[m-1]) / (2^qr - 1); lg = g[m] + (g[m] - g[m-1]) / (2^qg - 1)
    def("order:rect", sprintf("%.2f", qr)); def("order:geo", sprintf("%.2f", qg))
    def("limits", sci(abs(lg - lr) / abs(lr)))
    def("finest", sci(abs(g[m] - r[m]) / abs(r[m]))) }'
