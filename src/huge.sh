#!/bin/sh
# huge.sh OUT: Example 5.1 solved by pdas on N = 128 .. 1024 in both
# plane models into OUT/<model>-<N>, the run on N = 1024 timed by
# /usr/bin/time -v; the table of the section "A mesh of half a million
# unknowns" and its macros \hugeN{KEY} (LaTeX, on standard output).
# Tangled from paper/stability.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
out=$1; ex=data/example-5.1.scene
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
# thousands N: N with its thousands set apart by \, (from 10 000 on)
thousands() { awk -v n="$1" 'BEGIN { s = ""; if (n < 10000) { print n; exit }
  while (n >= 1000) { s = sprintf("\\,%03d", n % 1000) s; n = int(n / 1000) }
  print n s }'; }
timer=; /usr/bin/time -v true > /dev/null 2>&1 && timer=/usr/bin/time
for m in plane_stress plane_strain; do
  for N in 128 256 512 1024; do
    d=$out/$m-$N; t=
    [ $N = 1024 ] && [ -n "$timer" ] && t="$timer -v -o $d.time"
    $t "$bin" solve $ex -o "$d" -s material.model=$m \
      -s mesh.refine=$((N / 16)) > "$d.log"
  done
done
d=$out/plane_stress-1024
echo "% written by src/huge.sh; do not edit"
printf '%s\n' '\gdef\hugeN#1{\csname huge:#1\endcsname}'
for k in triangles dofs contact_nodes; do
  printf '\\expandafter\\gdef\\csname huge:%s\\endcsname{%s}\n' \
    "${k%_nodes}" "$(thousands "$(v $k $d)")"
done
printf '%s\n' '\begin{tabular}{@{}lrrrlrr@{}}\toprule' \
  'model & steps & KKT & $E_h$ [J/m] & rate & solve / run [s]' \
  '  & max RSS [MiB]\\\midrule'
for m in plane_stress plane_strain; do
  d=$out/$m-1024
  rss=-- run=--
  if [ -f $d.time ]; then
    rss=$(awk -F': ' '/Maximum resident/ { printf "%d", $2 / 1024 }' \
      $d.time)
    run=$(awk -F': ' '/Elapsed/ { n = split($2, t, ":"); s = 0
      for (i = 1; i <= n; i++) s = s * 60 + t[i]; printf "%.1f", s }' \
      $d.time)
  fi
  e=$(v energy $d)
  awk -v m="$m" -v it="$(v iterations $d)" -v kkt="$(v kkt_residual $d)" \
      -v e1="$(v energy $out/$m-128)" -v e2="$(v energy $out/$m-256)" \
      -v e3="$(v energy $out/$m-512)" -v e4="$e" \
      -v s="$(v seconds $d)" -v run="$run" -v rss="$rss" 'BEGIN {
    r1 = log((e1 - e2) / (e2 - e3)) / log(2)
    r2 = log((e2 - e3) / (e3 - e4)) / log(2)
    sub(/_/, " ", m); x = kkt + 0; k = "0"
    if (x > 0) { ex = int(log(x) / log(10) - (x < 1))
      k = sprintf("%.1f\\cdot10^{%d}", x / 10^ex, ex) }
    printf "%s & %d & $%s$ & ", m, it, k
    printf "%.3f (%.3f) & %.1f / %s & %s\\\\\n", r2, r1, s, run, rss }' |
  awk -v e="$(printf '%.2f' "$e" | sed 's/^-//')" -F'& ' '{
    i = index(e, "."); w = substr(e, 1, i - 1); g = ""
    while (length(w) > 3) { g = "\\," substr(w, length(w) - 2) g
      w = substr(w, 1, length(w) - 3) }
    print $1 "& " $2 "& " $3 "& $-" w g substr(e, i) "$ & " $4 "& " $5 "& " $6 }'
done
printf '%s\n' '\bottomrule\end{tabular}'
printf '%s %s %s, %s cores, load %s.\n' \
  '\par\smallskip\footnotesize Measured by \texttt{make figures}' \
  '(\texttt{src/huge.sh}) on' "$(date -u +%F)" "$(v cores $d)" \
  "$(v load_average $d)"
