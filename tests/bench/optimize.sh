#!/bin/sh
# make bench, part 3: what an optimisation costs against the physics
# (issue 12), on Example 5.1 refined to N = 64, 256, 512, 1024:
#   the whole `contactopt optimize` process, timed from outside, with the
#   default (Newton) and with SLSQP, its iterations and state solves, the
#   seconds of its state solves and gradients (summary.dat), and the
#   reference of the same N measured in the same run: one CHOLMOD analyse +
#   factorise + solve of the initial stiffness (bench_cholmod).
# Writes the table paper/bench-optimize.tex (only when every measurement
# succeeded), the raw numbers into build/bench/optimize.dat, and prints them.
# A missed target is a result, not a failure.
#   BENCH_NMAX        largest N (default 1024)
#   BENCH_SLSQP_NMAX  largest N of the SLSQP runs (default BENCH_NMAX)
cd "$(dirname "$0")/../.." || exit 1
bin=${BIN:-bin/contactopt}
bb=${BENCH_BIN:-build/bench}
nmax=${BENCH_NMAX:-1024}
snmax=${BENCH_SLSQP_NMAX:-$nmax}
scene=data/example-5.1.scene
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "optimize bench: FAILED: $*" >&2; exit 1; }
for p in "$bin" "$bb/bench_cholmod" "$bb/walltime"; do
  [ -x "$p" ] || fail "$p is missing (make bench builds it)"
done
raw=build/bench/optimize.dat
mkdir -p build/bench
echo "# N method wall[s] iterations evaluations seconds[s] state_seconds[s] stop_reason cholmod[s] monitor_seconds[s]" > $raw
for N in 64 256 512 1024; do
  [ $N -le "$nmax" ] || break
  "$bb/bench_cholmod" $scene mesh.refine=$((N / 16)) > "$tmp/ref" 2> "$tmp/err" \
    || fail "bench_cholmod at N = $N: $(cat "$tmp/err")"
  ref=$(awk '!/^#/ { printf "%.6f", $6 + $7 }' "$tmp/ref")
  for method in newton slsqp; do
    [ $method = slsqp ] && [ $N -gt "$snmax" ] && continue
    d=$tmp/$method-$N
    "$bb/walltime" "$tmp/t" "$bin" optimize $scene -o "$d" -s mesh.refine=$((N / 16)) \
      -s optimizer.method=$method > "$tmp/log" 2>&1 \
      || fail "optimize $method at N = $N, exit status $?: $(tail -n 2 "$tmp/log")"
    awk -v N=$N -v m=$method -v t="$(cut -d' ' -f1 "$tmp/t")" -v ref=$ref '{ v[$1] = $2 } END {
        if (!("iterations" in v && "state_seconds" in v && "seconds" in v)) exit 1
        print N, m, t, v["iterations"], v["evaluations"] + v["coarse_evaluations"], v["seconds"],
              v["state_seconds"] + v["coarse_seconds"], v["stop_reason"], ref,
              v["monitor_seconds"] + 0 }' \
      "$d/summary.dat" >> $raw || fail "optimize $method at N = $N: no summary"
    tail -n 1 $raw
  done
done
awk -v date="$(date -u +%Y-%m-%d)" -v cores="$(nproc)" '
  !/^#/ { n++; N[n] = $1; m[n] = $2; wall[n] = $3; it[n] = $4; ev[n] = $5
          sec[n] = $6 - $10; st[n] = $7; stop[n] = $8; ref[n] = $9; mon[n] = $10 }
  END {
    # the numbers the prose quotes: \optimizebench{METHOD}{N}{COLUMN}, a cell
    # of the table below (iterations, solves, whole, state, outside,
    # monitor, cholmod, ratio; an unknown one stops LaTeX)
    print "% written by make bench (tests/bench/optimize.sh) on " date ", " cores " cores"
    print "\\providecommand{\\optimizebench}[3]{\\ifcsname optimize:#1:#2:#3\\endcsname\\csname optimize:#1:#2:#3\\endcsname\\else\\errmessage{paper/bench-optimize.tex has no #1 #2 #3}\\fi}"
    for (i = 1; i <= n; i++) {
      k = "\\expandafter\\def\\csname optimize:" m[i] ":" N[i] ":"
      printf "%siterations\\endcsname{%d}%ssolves\\endcsname{%d}%swhole\\endcsname{%.3g}%sstate\\endcsname{%.3g}\n", k, it[i], k, ev[i], k, wall[i], k, st[i]
      printf "%soutside\\endcsname{%.1f}%smonitor\\endcsname{%.2g}%scholmod\\endcsname{%.3g}%sratio\\endcsname{%.1f}\n", k, 100 * (sec[i] - st[i]) / sec[i], k, mon[i], k, ref[i], k, wall[i] / ref[i] }
    print "\\begin{center}\\small\\setlength{\\tabcolsep}{4pt}"
    print "\\begin{tabular}{@{}rlrrrrrrrl@{}}\\toprule"
    print "$N$ & method & iterations & solves & whole [s] & state [s] & outside [\\%] & monitor [s] & CHOLMOD [s] & ratio\\\\\\midrule"
    for (i = 1; i <= n; i++)
      printf "%d & %s & %d & %d & %.3g & %.3g & %.1f & %.2g & %.3g & %.1f%s\\\\\n", N[i], m[i], it[i], ev[i],
        wall[i], st[i], 100 * (sec[i] - st[i]) / sec[i], mon[i], ref[i], wall[i] / ref[i],
        stop[i] == "converged" ? "" : " (" stop[i] ")"
    print "\\bottomrule\\end{tabular}\\\\[2pt]"
    printf "{\\footnotesize Measured by \\texttt{make bench} on %s, %d cores. ", date, cores
    print "\\emph{solves}: every state solve, those of the coarse meshes of a coarse-to-fine start included;"
    print "\\emph{whole}: the process, files included; \\emph{state}: its state solves and gradients, and the whole time of the coarse meshes;"
    print "\\emph{outside}: the share of the optimisation (\\texttt{seconds} less the monitor) not in them;"
    print "\\emph{monitor}: the output of the command line at each iterate (its line, \\texttt{iterates/*.vtu});"
    print "\\emph{ratio}: whole over one CHOLMOD analyse, factorise and solve of the same $N$.}"
    print "\\end{center}"
  }' $raw > "$tmp/bench-optimize.tex" || fail "the table"
cp "$tmp/bench-optimize.tex" paper/bench-optimize.tex
echo "optimize bench: paper/bench-optimize.tex written"
