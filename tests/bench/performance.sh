#!/bin/sh
# make bench, part 2: the performance targets of issue 5, measured on this
# machine, wall-clock (CLOCK_MONOTONIC), on Example 5.1 (at large N one run
# of each; bench_cholmod.c says how it repeats the short ones):
#   1. a state solve against one CHOLMOD factorisation and solve of the same
#      stiffness matrix, and its peak memory, N = 16 .. 1024;
#   2. the gradient (4.8), and the adjoint gradients of the other
#      objectives, against a warm state solve, at the same N;
#   3. the whole `contactopt optimize` at the article's mesh (N = 16), best of 5;
#   4. the whole `contactopt optimize` at N = 256, best of 3.
# Writes the four tables into paper/bench-performance.tex (only when every
# measurement succeeded), the raw numbers into build/bench/performance-*.dat,
# and prints a summary.  A measurement that fails stops the benchmark with
# exit status 1 and its message; a missed target is a result, not a failure.
#   BENCH_NMAX  largest N (default 1024); BENCH_NMAX=128 for a short run
#   BENCH_RUNS  runs of item 3 (default 5)
#   BENCH_RUNS4 runs of item 4 (default 3)
#   BIN, BENCH_BIN  the program and the folder of bench_cholmod and walltime
#               (default bin/contactopt and build/bench, as make builds them)
cd "$(dirname "$0")/../.." || exit 1
bin=${BIN:-bin/contactopt}
bb=${BENCH_BIN:-build/bench}
nmax=${BENCH_NMAX:-1024}
runs=${BENCH_RUNS:-5}
runs4=${BENCH_RUNS4:-3}
scene=data/example-5.1.scene
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "performance: FAILED: $*" >&2; exit 1; }
# mesh N: the setting of Example 5.1 refined to N, as in state.sh
mesh() { echo "mesh.refine=$(($1 / 16))"; }
[ "$nmax" -ge 16 ] 2>/dev/null || fail "BENCH_NMAX=$nmax: must be a number >= 16"
[ "$runs" -ge 1 ] 2>/dev/null || fail "BENCH_RUNS=$runs: must be a number >= 1"
[ "$runs4" -ge 1 ] 2>/dev/null || fail "BENCH_RUNS4=$runs4: must be a number >= 1"
for p in "$bin" "$bb/bench_cholmod" "$bb/walltime"; do
  [ -x "$p" ] || fail "$p is missing (make bench builds it)"
done
mkdir -p build/bench
state=build/bench/performance-state.dat
whole=build/bench/performance-optimize.dat

# ---- 1 and 2: one process per N, so that its peak memory is that N's ------
echo "# bench_cholmod on $scene: N dofs setup[s] cold[s] cold_steps analyse[s]" \
     "factor_solve[s] ratio maxrss[MiB] warm[s] warm_steps grad[s] grad/warm residual" \
     "adjoint_compliance[s] adjoint_spread[s] adjoint_peak[s]" > $state
echo "performance: state solve vs CHOLMOD, gradient vs warm solve (Example 5.1, N <= $nmax)"
N=16
while [ $N -le "$nmax" ]; do
  "$bb/bench_cholmod" $scene $(mesh $N) >> $state 2> "$tmp/err" \
    || fail "bench_cholmod at N = $N, exit status $?: $(cat "$tmp/err")"
  tail -n 1 $state
  [ $N -le 256 ] && N4=$N        # item 4's N: 256, or less under BENCH_NMAX
  N=$((N * 2))
done

# ---- 3 and 4: the whole program, timed from outside ----------------------
# optimize DIR N [-s key=value ...]: one timed run into DIR, one line of $whole
optimize() {
  d=$1 n=$2; shift 2
  "$bb/walltime" "$tmp/t" "$bin" optimize $scene -o "$d" "$@" > "$tmp/log" 2>&1 \
    || fail "optimize at N = $n (into $d), exit status $?: $(tail -n 3 "$tmp/log")"
  awk -v N=$n -v t="$(cat "$tmp/t")" '{ v[$1] = $2 } END {
      if (!("iterations" in v && "evaluations" in v && "stop_reason" in v)) exit 1
      print N, t, v["iterations"], v["evaluations"], v["stop_reason"], v["projected_gradient"] }' \
    "$d/summary.dat" >> $whole || fail "optimize at N = $n: no iterations, evaluations, stop_reason in $d/summary.dat"
  tail -n 1 $whole
}
echo "# contactopt optimize $scene: N wall[s] maxrss[MiB] iterations evaluations stop_reason projected_gradient" > $whole
echo "performance: contactopt optimize, N = 16 ($runs runs) and N = $N4 ($runs4 runs)"
k=1
# the scene as it is: the article's mesh, N = 16
while [ $k -le "$runs" ]; do optimize "$tmp/opt16-$k" 16; k=$((k + 1)); done
k=1
while [ $k -le "$runs4" ]; do
  optimize "$tmp/opt$N4-$k" $N4 -s $(mesh $N4)
  k=$((k + 1))
done

# ---- the tables and the summary ---------------------------------------------
tex=$tmp/bench-performance.tex
awk -v date="$(date -u +%Y-%m-%d)" -v cores="$(nproc)" -v nmax="$nmax" -v runs="$runs" -v runs4="$runs4" \
    -v sum="$tmp/summary" '
  # 3 significant digits, no exponent (times from microseconds to minutes)
  function fmt(x,   l, f) {
    if (x <= 0) return "0"
    l = log(x) / log(10); f = int(l); if (f > l) f--
    return sprintf("%." (f < 2 ? 2 - f : 0) "f", x) }
  # a target is judged only at the N it names (not under a smaller BENCH_NMAX)
  function verdict(ok, at) { return !at ? "not judged" : ok ? "met" : "missed" }
  # x as m.m\cdot10^{e}, for LaTeX
  function sci(x,   e, p) {
    if (x == "") return "--"
    e = sprintf("%.1e", x); split(e, p, "e")
    return "$" p[1] "\\cdot10^{" (p[2] + 0) "}$" }
  function title(s) { print "\\begin{center}\\small\\textit{" s "}\\\\[3pt]" }
  function foot(s) { print "\\bottomrule\\end{tabular}\\par\\smallskip\\parbox{.92\\linewidth}{\\footnotesize " s "}\\end{center}" }
  FNR == 1 { file++ }
  /^#/ { next }
  file == 1 { n++; for (i = 1; i <= NF; i++) S[n, i] = $i + 0 }
  file == 2 && FNR > 1 && FNR <= runs + 1 { w++; t16 = t16 (w > 1 ? ", " : "") fmt($2)
    if (w == 1 || $2 + 0 < best) { best = $2; for (i = 1; i <= NF; i++) O16[i] = $i } }
  file == 2 && FNR > runs + 1 { w4++; t4 = t4 (w4 > 1 ? ", " : "") fmt($2)
    if (w4 == 1 || $2 + 0 < best4) { best4 = $2; for (i = 1; i <= NF; i++) O4[i] = $i } }
  END {
    print "% written by make bench (tests/bench/performance.sh) on " date ", " cores " cores"
    # 1. state solve against CHOLMOD; the targets are at the largest N
    title("1. A state solve against one Cholesky factorisation of its matrix")
    print "\\begin{tabular}{rr rrr rr rr}\\toprule"
    print "& & \\multicolumn{3}{c}{state solve} & \\multicolumn{2}{c}{CHOLMOD} & & peak\\\\"
    print "$N$ & unknowns & setup & solve & steps & analyse & factor, solve & ratio & [MiB]\\\\\\midrule"
    for (k = 1; k <= n; k++)
      printf "%d & %d & %s & %s & %d & %s & %s & %.2f & %.0f\\\\\n", S[k,1], S[k,2],
        fmt(1e3 * S[k,3]), fmt(1e3 * S[k,4]), S[k,5], fmt(1e3 * S[k,6]), fmt(1e3 * S[k,7]), S[k,8], S[k,9]
    big = S[n,1] == 1024
    at = big ? "at $N = 1024$" : "$N = 1024$ not measured (BENCH\\_NMAX $=" nmax "$); at $N = " S[n,1] "$"
    foot("Times in ms; ratio $=$ (setup $+$ solve) / (analyse $+$ factor, solve); peak: the resident set after the state solve. " \
      "Targets at $N = 1024$: ratio $\\le 3$, peak $\\le 1024$\\,MiB; " at ": ratio " sprintf("%.2f", S[n,8]) \
      " (" verdict(S[n,8] <= 3, big) "), peak " sprintf("%.0f", S[n,9]) "\\,MiB (" verdict(S[n,9] <= 1024, big) "). " \
      "Measured by make bench on " date ", " cores " cores, one run each, wall-clock.")
    printf "1. state solve / CHOLMOD at N = %d: %.2f (target <= 3 at N = 1024): %s\n", S[n,1], S[n,8], verdict(S[n,8] <= 3, big) > sum
    printf "   peak memory at N = %d: %.0f MiB (target <= 1024 MiB at N = 1024): %s\n", S[n,1], S[n,9], verdict(S[n,9] <= 1024, big) > sum
    # 2. the gradient against a warm solve; the target holds at every N
    title("2. The gradient (4.8) and the adjoint gradients against a warm state solve")
    print "\\begin{tabular}{rr rrr rr rr}\\toprule"
    print "$N$ & unknowns & cold solve & warm solve & steps & gradient & gradient / warm & adjoint & adjoint / warm\\\\\\midrule"
    for (k = 1; k <= n; k++) {
      A[k] = S[k,15]; if (S[k,16] > A[k]) A[k] = S[k,16]; if (S[k,17] > A[k]) A[k] = S[k,17]
      print S[k,1] " & " S[k,2] " & " fmt(1e3 * S[k,4]) " & " fmt(1e3 * S[k,10]) " & " S[k,11] " & " \
        fmt(1e3 * S[k,12]) " & " sprintf("%.1f", 100 * S[k,13]) "\\,\\% & " fmt(1e3 * A[k]) " & " \
        sprintf("%.2f", A[k] / S[k,10]) "\\\\"
      if (k == 1 || S[k,13] > S[worst,13]) worst = k
      if (k == 1 || A[k] / S[k,10] > A[aworst] / S[aworst,10]) aworst = k }
    foot("Times in ms. Warm: from the state of a design one step ($10^{-3}C_0$ against the gradient, projected on $B$) away. " \
      "Target: gradient $\\le 20$\\,\\% of a warm solve at every $N$; largest " sprintf("%.1f", 100 * S[worst,13]) \
      "\\,\\% at $N = " S[worst,1] "$ (" verdict(S[worst,13] <= 0.2, 1) "). " \
      "Adjoint: the slowest of the adjoint gradients of the compliance, the pressure spread and the pressure peak " \
      "(\\texttt{objective\\_gradient}) after the same warm solves; target: at most 1.3 warm solves at $N = 1024$, " \
      sprintf("%.2f", A[n] / S[n,10]) " at $N = " S[n,1] "$ (" verdict(A[n] / S[n,10] <= 1.3, big) ").")
    printf "2. gradient / warm solve, largest over N = 16..%d: %.1f %% at N = %d (target <= 20 %%): %s\n",
      S[n,1], 100 * S[worst,13], S[worst,1], verdict(S[worst,13] <= 0.2, 1) > sum
    printf "   adjoint gradient / warm solve at N = %d: %.2f (target <= 1.3 at N = 1024): %s; largest over N: %.2f at N = %d\n",
      S[n,1], A[n] / S[n,10], verdict(A[n] / S[n,10] <= 1.3, big), A[aworst] / S[aworst,10], S[aworst,1] > sum
    # 3 and 4. the whole optimisation
    title("3. The whole optimisation of Example 5.1 on the mesh of the article")
    whole(O16, "$< 0.1$", verdict(O16[2] + 0 < 0.1, 1))
    foot("Wall time of \\texttt{contactopt optimize data/example-5.1.scene}, process and output files included, the best of " runs " runs: " t16 "\\,s.")
    printf "3. optimize Example 5.1, N = 16: %s s, best of %d (target < 0.1 s): %s\n", fmt(O16[2]), runs, verdict(O16[2] + 0 < 0.1, 1) > sum
    title("4. The whole optimisation of Example 5.1 at $N = " O4[1] "$")
    whole(O4, "$< 10$", verdict(O4[2] + 0 < 10, O4[1] == 256))
    foot("The best of " runs4 " runs: " t4 "\\,s; $M = " (O4[1] / 16) "$, $R = " (3 * O4[1] / 16) "$" (O4[1] == 256 ? "" : "; the target is at $N = 256$, not measured (BENCH\\_NMAX $=" nmax "$)") ".")
    printf "4. optimize Example 5.1, N = %d: %s s, best of %d (%s s), %d iterations, %d evaluations, %s (target < 10 s at N = 256): %s\n",
      O4[1], fmt(O4[2]), runs4, t4, O4[4], O4[5], O4[6], verdict(O4[2] + 0 < 10, O4[1] == 256) > sum
  }
  function whole(O, target, judged,   stop) {
    stop = O[6]; gsub(/_/, "\\_", stop)
    if (judged == "not judged") judged = "--"
    print "\\begin{tabular}{r rrlr r rrl}\\toprule"
    print "$N$ & iterations & evaluations & stop & proj.\\ gradient & peak [MiB] & wall [s] & target [s] &\\\\\\midrule"
    print O[1] " & " O[4] " & " O[5] " & " stop " & " sci(O[7]) " & " sprintf("%.0f", O[3]) " & " fmt(O[2]) " & " target " & " judged "\\\\" }
' $state $whole > "$tex" || fail "writing the tables"
mv "$tex" paper/bench-performance.tex
echo "performance: tables written to paper/bench-performance.tex ($(date -u +%Y-%m-%d), $(nproc) cores)"
cat "$tmp/summary"
