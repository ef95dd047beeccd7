#!/bin/sh
# make bench: the state solvers on Example 5.1's initial shape for
# N = 16 .. 512 (mesh.refine = N/16), all at the same relative KKT
# tolerance.  Prints a table and writes it as LaTeX into
# paper/bench-state.tex, which the woven document shows.  Not a test.
cd "$(dirname "$0")/../.." || exit 1
tol=${BENCH_TOL:-1e-8}
# the relaxation methods get at most this many iterations: PSOR needs
# O(N^2) sweeps and would run for hours at N = 512
cap=${BENCH_MAX_ITER:-20000}
tmp=$(mktemp -d)
out=build/bench/state.dat
mkdir -p build/bench
printf "# N dofs solver iterations seconds kkt\n" > $out
for N in 16 32 64 128 256 512; do
  for solver in pdas cgssor psor; do
    d=$tmp/$N-$solver
    t0=$(date +%s.%N)
    if bin/contactopt solve data/example-5.1.scene -o $d -s mesh.refine=$((N / 16)) \
         -s solver.state=$solver -s solver.tol=$tol -s solver.max_iter=$cap >/dev/null 2>$tmp/err; then
      awk -v N=$N -v s=$solver '{ v[$1] = $2 } END {
        printf "%d %d %s %d %.4f %.1e\n", N, v["dofs"], s, v["iterations"], v["seconds"], v["kkt_residual"] }' \
        $d/summary.dat >> $out
    else
      # not converged within the cap: record the cap and the time spent
      awk -v N=$N -v s=$solver -v c=$cap -v t0=$t0 -v t1=$(date +%s.%N) 'BEGIN {
        printf "%d - %s >%d %.4f -\n", N, s, c, t1 - t0 }' >> $out
    fi
    tail -1 $out
  done
done
rm -rf $tmp
awk -v tol=$tol -v date="$(date -u +%Y-%m-%d)" -v cpu="$(nproc) cores" '
  !/^#/ { key = $1; if ($2 != "-") dofs[key] = $2; it[key, $3] = $4; sec[key, $3] = $5; if (!(key in seen)) { order[++n] = key; seen[key] = 1 } }
  END {
    print "% written by make bench (tests/bench/state.sh) on " date ", " cpu
    print "\\begin{tabular}{rr rr rr rr}\\toprule"
    print "& & \\multicolumn{2}{c}{pdas} & \\multicolumn{2}{c}{cgssor} & \\multicolumn{2}{c}{psor}\\\\"
    print "$N$ & DOFs & it. & s & it. & s & it. & s\\\\\\midrule"
    for (k = 1; k <= n; k++) { N = order[k]
      printf "%d & %d & %s & %s & %s & %s & %s & %s\\\\\n", N, dofs[N],
        it[N, "pdas"], sec[N, "pdas"], it[N, "cgssor"], sec[N, "cgssor"], it[N, "psor"], sec[N, "psor"] }
    print "\\bottomrule\\end{tabular}"
    print "\\par\\smallskip\\footnotesize Relative KKT tolerance " tol "; wall seconds of one state solve, assembly included."
  }' $out > paper/bench-state.tex
echo "table written to paper/bench-state.tex"
