#!/bin/sh
# tests/bench/levels.sh: the coarse-to-fine start of optimize
# (optimizer.levels, paper/opt.nw) against a single level.  Example 5.1,
# plane stress, the default Newton method, at N = 16 K for K in
# BENCH_REFINES (default 16 32 64: N = 256, 512, 1024), each with
# optimizer.levels = 1 (one mesh), 2, 3 and 0 (the default schedule).
# For each run: the levels, the evaluations (state solves) of the fine
# level and of the coarse ones, the wall time of the whole command, and
# |E* - E*_1| / |E*_1| and max |X - X_1| / C0 against the single level.
# Writes build/bench/levels.dat and the table, with macros for the prose,
# into paper/bench-levels.tex (TABLE_ONLY=1: the table of the last
# build/bench/levels.dat, no runs).  Not a test.
cd "$(dirname "$0")/../.." || exit 1
refines=${BENCH_REFINES:-16 32 64}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=build/bench/levels.dat
mkdir -p build/bench
[ -n "$TABLE_ONLY" ] || {
make bin/contactopt >/dev/null || exit 1
printf "# N setting levels fine_solves coarse_solves seconds dE_rel dX_C0\n" > $out
for K in $refines; do
  N=$((16 * K))
  for L in 1 2 3 0; do
    d=$tmp/$N-$L
    t0=$(date +%s.%N)
    bin/contactopt optimize data/example-5.1.scene -s mesh.refine=$K \
      -s optimizer.levels=$L -o $d > $tmp/log 2>&1 || { cat $tmp/log; exit 1; }
    t1=$(date +%s.%N)
    coarse=$(sed -n 's/.*coarse to fine: N = \([0-9]*\) .. [0-9]* in \([0-9]*\) evaluations.*/\1 \2/p' $tmp/log)
    levels=1 cs=0
    if [ -n "$coarse" ]; then
      set -- $coarse
      levels=1; n=$1; while [ $n -lt $N ]; do n=$((2 * n)); levels=$((levels + 1)); done
      cs=$2
    fi
    awk -v N=$N -v L=$L -v levels=$levels -v cs=$cs -v t=$(echo "$t1 - $t0" | bc) \
        -v ref=$tmp/$N-1 -v C0=0.05 '
      FNR == 1 { f++ }
      f == 1 && $1 == "energy" { e = $2 } f == 1 && $1 == "evaluations" { ev = $2 }
      f == 2 && $1 == "energy" { e1 = $2 }
      f == 3 && !/^#/ { x[FNR] = $2 } f == 4 && !/^#/ { d = $2 - x[FNR]; if (d < 0) d = -d; if (d > dx) dx = d }
      END { de = (e - e1) / e1; de = de == 0 ? 0 : de < 0 ? -de : de
            printf "%d %d %d %d %d %.2f %.1e %.1e\n", N, L, levels, ev, cs, t, de, dx / C0 }' \
      $d/summary.dat $tmp/$N-1/summary.dat $tmp/$N-1/final/shape.dat $d/final/shape.dat >> $out
    tail -1 $out
  done
done
}
awk -v date="$(date -u +%Y-%m-%d)" -v cpu="$(nproc) cores" \
    -v loadavg="$(cut -d' ' -f1 /proc/loadavg)" '
  function roman(n) { return n == 256 ? "ii" : n == 512 ? "v" : n == 1024 ? "x" : "n" n }
  function name(L) { return L == 0 ? "Default" : L == 1 ? "One" : L == 2 ? "Two" : L == 3 ? "Three" : "Many" }
  !/^#/ { row[++n] = $0; split($0, v); N = v[1]; L = v[2]
          if (L == 1) one[N] = v[6]
          time[N, L] = v[6]; lev[N, L] = v[3]; fine[N, L] = v[4]; coarse[N, L] = v[5]
          de[N, L] = v[7]; dx[N, L] = v[8] }
  END {
    printf "%% written by tests/bench/levels.sh on %s, %s, load %s\n", date, cpu, loadavg
    print "\\begin{center}\\small\\begin{tabular}{rr rr r rr}\\toprule"
    print "$N$ & levels & fine solves & coarse solves & s & $|\\Delta E^*|/|E^*|$ & $\\max|\\Delta X|/C_0$\\\\\\midrule"
    for (k = 1; k <= n; k++) { split(row[k], v)
      printf "%d & %d%s & %d & %d & %.2f & %s & %s\\\\\n", v[1], v[3], v[2] == 0 ? " (default)" : "",
        v[4], v[5], v[6], v[2] == 1 ? "--" : sprintf("%.1e", v[7] == 0 ? 0 : v[7]),
        v[2] == 1 ? "--" : sprintf("%.1e", v[8]) }
    print "\\bottomrule\\end{tabular}\\end{center}"
    for (k = 1; k <= n; k++) { split(row[k], v); N = v[1]; L = v[2]
      printf "\\newcommand{\\levels%s%sSeconds}{%.2f}\n", name(L), roman(N), v[6]
      printf "\\newcommand{\\levels%s%sFine}{%d}\n", name(L), roman(N), v[4]
      printf "\\newcommand{\\levels%s%sCoarse}{%d}\n", name(L), roman(N), v[5]
      printf "\\newcommand{\\levels%s%sSpeedup}{%.2f}\n", name(L), roman(N), one[N] / v[6] }
  }' $out > paper/bench-levels.tex
cat $out
