#!/bin/sh
# parts-table.sh OUT: the shipped parts of data/parts/*.scene, each solved
# at its initial shape and optimised by the default method, and beside
# each the rectangle of the same N (the part's a, b, N, M, C0prime, design,
# [material] and sides; its top gamma the part's highest point; R rows of
# cells as near square as N makes them; the part's vertical load spread
# evenly over its top), each run seven times into OUT/<name>-<run>, the
# least of the seven times kept (the seconds of summary.dat).  The table
# of the section "Parts a designer knows" (LaTeX, on standard output) and
# its macros \partsitsmax, \partsoptratiomin, \partsoptratiomax.  Timed,
# so rebuilt and not tracked.  Tangled from paper/parts-examples.nw; do
# not edit.
set -e
bin=${BIN:-bin/contactopt}
out=$1
mkdir -p "$out"; rm -f "$out/macros.dat"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
ini() { awk -v s="[$1]" -v k="$2" '/^\[/ { in_s = $1 == s; next }
  in_s && $1 == k && $2 == "=" { print $3; exit }' "$3/effective.scene"; }
points() { python3 - "$1" <<'PY'
import re, struct, sys
d = open(sys.argv[1], 'rb').read()
head, _, body = d.partition(b'<AppendedData encoding="raw">')
body = body[body.index(b'_') + 1:]
n = int(re.search(rb'NumberOfPoints="(\d+)"', head).group(1))
off = int(re.search(rb'<Points>\s*<DataArray[^>]*offset="(\d+)"', head).group(1))
size, = struct.unpack_from('<Q', body, off)
x = struct.unpack_from('<%dd' % (size // 8), body, off + 8)
print(n, repr(max(x[1::3])))
PY
}
# best COMMAND SCENE DIR [ARGS]: seven runs of COMMAND into DIR, the least
# of their seconds
best() { c=$1 s=$2 d=$3 t=; shift 3
  for i in 1 2 3 4 5 6 7; do
    "$bin" $c "$s" -o "$d" "$@" > "$d.log" 2>&1 || { cat "$d.log" >&2; return 1; }
    t="$t $(v seconds "$d")"
  done
  printf '%s\n' $t | sort -g | head -n 1; }
# sci X: X in LaTeX, four digits
sci() { awk -v x="$1" 'BEGIN { a = x < 0 ? -x : x
  e = int(log(a) / log(10)); if (a < 1) e--
  printf "$%.4f\\cdot10^{%d}$", x / 10 ^ e, e }'; }
# rectangle SCENE SOLVEDIR: the rectangle's scene, on standard output
rectangle() {
  a=$(ini geometry a "$2"); b=$(ini geometry b "$2"); N=$(ini design N "$2")
  c=$(ini mesh C0prime "$2"); set -- "$1" "$2" $(points "$2/solution.vtu")
  load=$(awk '/^reaction_.*_x2 / { s += $2 } END { printf "%.17g", s }' \
    "$2/summary.dat")
  T=$(awk '!/^#/ { s += $5 } END { printf "%.17g", s }' "$2/contact.dat")
  awk '/^\[/ { skip = $1 ~ /^\[(part|boundary\.|material\.)/; s = $1 }
    !skip && !(s == "[design]" && $1 == "C2")' "$1"
  awk -v a="$a" -v b="$b" -v N="$N" -v c="$c" -v g="$4" -v R="$load" -v T="$T" \
      -v C2="$(ini design C2 "$2")" 'BEGIN {
    r = int((g - c) * N / (b - a) + 0.5); if (r < 1) r = 1
    printf "[geometry]\ngamma = %.17g\n", g
    printf "[design]\nC2 = %.17g\n", C2 + (g - c) * (b - a)
    printf "[mesh]\nR = %d\n", r
    printf "[top]\nbc = traction\nfrom = %.17g\nto = %.17g\n", a, b
    printf "P1 = 0\nP2 = %.17g\n", -(R + T) / (b - a) }'; }
echo "% written by src/parts-table.sh; do not edit"
printf '%s\n' '\begin{tabular}{@{}lrrrrrrlrrrr@{}}\toprule' \
  'part & \multicolumn{2}{c}{triangles} & nodes & $E(\alpha^0)$ & $E^*$ & its.' \
  '  & status & solve & $\times$ & optimize & $\times$\\' \
  '  & part & rect. & & [J/m] & [J/m] & & & [ms] & & [ms] &\\\midrule'
m=$out/macros.dat
for sc in data/parts/*.scene; do
  n=$(basename "$sc" .scene); d=$out/$n
  ts=$(best solve "$sc" $d-solve); to=$(best optimize "$sc" $d-optimize)
  rectangle "$sc" $d-solve > $d-rectangle.scene
  rs=$(best solve $d-rectangle.scene $d-rectangle-solve)
  ro=$(best optimize $d-rectangle.scene $d-rectangle-optimize)
  set -- $(points $d-solve/solution.vtu)
  E0=$(sci "$(v energy $d-solve)") E=$(sci "$(v energy $d-optimize)") \
  awk -v n="$n" -v t="$(v triangles $d-solve)" -v nodes="$1" \
      -v rt="$(v triangles $d-rectangle-solve)" -v it="$(v iterations $d-optimize)" \
      -v st="$(v stop_reason $d-optimize)" -v ts="$ts" -v rs="$rs" \
      -v to="$to" -v ro="$ro" -v m="$m" 'BEGIN {
    gsub("_", "\\_", st)
    printf "%s & %d & %d & %d & %s & %s & %d & %s", n, t, rt, nodes,
           ENVIRON["E0"], ENVIRON["E"], it, st
    printf " & %.3g & %.2g & %.3g & %.2g\\\\\n", 1000 * ts, ts / rs, 1000 * to, to / ro
    print it, to / ro >> m }'
done
printf '%s\n' '\bottomrule\end{tabular}'
printf '%s %s, %s cores, load %s.}\n' \
  '\par\smallskip{\footnotesize Measured by \texttt{make figures} on' \
  "$(date -u +%F)" "$(v cores $d-optimize)" "$(v load_average $d-optimize)"
awk 'NR == 1 || $1 > i { i = $1 }
  NR == 1 || $2 < lo { lo = $2 } NR == 1 || $2 > hi { hi = $2 } END {
  printf "\\gdef\\partsitsmax{%d}\n", i
  printf "\\gdef\\partsoptratiomin{%.2g}\n\\gdef\\partsoptratiomax{%.2g}\n", lo, hi }' $m
rm -f $m
