#!/bin/sh
# make bench, the frontier: Example 5.1 (plane stress, the default Newton
# method and coarse-to-fine start) at N = 256 ... BENCH_FRONTIER_NMAX
# (default 4096), each point against the physical limit of its mesh, one
# CHOLMOD analyse + factorise + solve of the same stiffness
# (bench_cholmod --limit), measured in the same run just before it.
# For each N: the whole `contactopt solve` process at the initial design
# (files included), the levels, the fine and the coarse state solves, the
# whole `contactopt optimize` process and its peak resident set, the limit
# and its peak, their ratios, E*, and where the time of `optimize` went
# (summary.dat: the optimisation's seconds, of them the coarse levels', the
# fine state solves', the Newton models' and the monitor's; the rest of
# the process is before and after the optimisation).  A point the machine
# cannot hold (the program's own estimate refuses it, exit 5) ends the
# sweep.  Writes build/bench/frontier.dat and, with macros for the prose
# (\frontierbench{N}{COLUMN}), paper/bench-frontier.tex; TABLE_ONLY=1
# writes the table of the last build/bench/frontier.dat without runs.
# At N = 4096 the run takes minutes and about 20 GiB.  Not a test.
cd "$(dirname "$0")/../.." || exit 1
bin=${BIN:-bin/contactopt}
bb=${BENCH_BIN:-build/bench}
nmax=${BENCH_FRONTIER_NMAX:-4096}
scene=data/example-5.1.scene
out=build/bench/frontier.dat
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "frontier bench: FAILED: $*" >&2; exit 1; }
mkdir -p build/bench
[ -n "$TABLE_ONLY" ] || {
for p in "$bin" "$bb/bench_cholmod" "$bb/walltime"; do
  [ -x "$p" ] || fail "$p is missing (make bench builds it)"
done
echo "# N levels fine_solves coarse_solves whole[s] peak[MiB] limit[s] limit_peak[MiB] energy[J/m] stop_reason solve[s] seconds coarse_seconds state_seconds model_seconds monitor_seconds" > $out
for N in 256 512 1024 2048 4096; do
  [ $N -le "$nmax" ] || break
  K=$((N / 16))
  "$bb/walltime" "$tmp/tl" "$bb/bench_cholmod" --limit $scene mesh.refine=$K > "$tmp/limit" 2> "$tmp/err" \
    || { grep -q 'memory' "$tmp/err" && break; fail "bench_cholmod at N = $N: $(cat "$tmp/err")"; }
  "$bb/walltime" "$tmp/ts" "$bin" solve $scene -o "$tmp/run" -s mesh.refine=$K > "$tmp/log" 2>&1
  rc=$?
  [ $rc -eq 5 ] && break                       # refused by the memory estimate
  [ $rc -eq 0 ] || fail "solve at N = $N, exit status $rc: $(tail -n 2 "$tmp/log")"
  rm -rf "$tmp/run"
  "$bb/walltime" "$tmp/t" "$bin" optimize $scene -o "$tmp/run" -s mesh.refine=$K > "$tmp/log" 2>&1
  rc=$?
  [ $rc -eq 5 ] && break                       # refused by the memory estimate
  [ $rc -eq 0 ] || fail "optimize at N = $N, exit status $rc: $(tail -n 2 "$tmp/log")"
  awk -v N=$N -v t="$(cat "$tmp/t")" -v tl="$(cat "$tmp/tl")" -v ts="$(cut -d' ' -f1 "$tmp/ts")" -v lim="$(awk '!/^#/ { print $3 + $4 }' "$tmp/limit")" '
    { v[$1] = $2 }
    END { split(t, w, " "); split(tl, l, " ")
          if (!("evaluations" in v)) exit 1
          print N, v["levels"] + 0 ? v["levels"] : 1, v["evaluations"], v["coarse_evaluations"] + 0,
                w[1], w[2], lim, l[2], v["energy"], v["stop_reason"], ts,
                v["seconds"], v["coarse_seconds"] + 0, v["state_seconds"], v["model_seconds"],
                v["monitor_seconds"] }' \
    "$tmp/run/summary.dat" >> $out || fail "optimize at N = $N: no summary"
  tail -n 1 $out
  rm -rf "$tmp/run"
done
}
awk -v date="$(date -u +%Y-%m-%d)" -v cores="$(nproc)" '
  !/^#/ { n++; for (k = 1; k <= NF; k++) v[n, k] = $k }
  END {
    print "% written by make bench (tests/bench/frontier.sh) on " date ", " cores " cores"
    print "\\providecommand{\\frontierbench}[2]{\\ifcsname frontier:#1:#2\\endcsname\\csname frontier:#1:#2\\endcsname\\else\\errmessage{paper/bench-frontier.tex has no #1 #2}\\fi}"
    for (i = 1; i <= n; i++) {
      k = "\\expandafter\\def\\csname frontier:" v[i, 1] ":"
      printf "%slevels\\endcsname{%d}%sfine\\endcsname{%d}%scoarse\\endcsname{%d}%swhole\\endcsname{%.3g}\n",
        k, v[i, 2], k, v[i, 3], k, v[i, 4], k, v[i, 5]
      printf "%ssolve\\endcsname{%.3g}%ssolveratio\\endcsname{%.2f}\n", k, v[i, 11], k, v[i, 11] / v[i, 7]
      printf "%slimit\\endcsname{%.3g}%sratio\\endcsname{%.1f}%speak\\endcsname{%.2g}%slimitpeak\\endcsname{%.2g}%speakratio\\endcsname{%.2f}\n",
        k, v[i, 7], k, v[i, 5] / v[i, 7], k, v[i, 6] / 1024, k, v[i, 8] / 1024, k, v[i, 6] / v[i, 8]
      printf "%scoarsesec\\endcsname{%.2g}%sstatesec\\endcsname{%.2g}%smodelsec\\endcsname{%.2g}%smonitorsec\\endcsname{%.2g}%saround\\endcsname{%.2g}\n",
        k, v[i, 13], k, v[i, 14], k, v[i, 15], k, v[i, 16], k, v[i, 5] - v[i, 12] }
    print "\\begin{center}\\small\\setlength{\\tabcolsep}{4pt}"
    print "\\begin{tabular}{@{}rrrrrrrrrrrr@{}}\\toprule"
    # the header on two lines, so that the twelve columns fit the page
    print "& limit & solve & & & fine & coarse & optimize & & peak & limit peak &\\\\"
    print "$N$ & [s] & [s] & ratio & levels & solves & solves & [s] & ratio & [GiB] & [GiB] & ratio\\\\\\midrule"
    for (i = 1; i <= n; i++)
      printf "%d & %.3g & %.3g & %.2f & %d & %d & %d & %.3g & %.1f & %.2g & %.2g & %.2f%s\\\\\n", v[i, 1], v[i, 7], v[i, 11],
        v[i, 11] / v[i, 7], v[i, 2], v[i, 3], v[i, 4],
        v[i, 5], v[i, 5] / v[i, 7], v[i, 6] / 1024, v[i, 8] / 1024, v[i, 6] / v[i, 8],
        v[i, 10] == "converged" ? "" : " (" v[i, 10] ")"
    print "\\bottomrule\\end{tabular}\\\\[2pt]"
    printf "{\\footnotesize Measured by \\texttt{make bench} on %s, %d cores. ", date, cores
    print "Example 5.1, the default Newton method and coarse-to-fine start. \\emph{limit}: one CHOLMOD"
    print "analyse, factorise and solve of the same stiffness, measured just before; \\emph{solve},"
    print "\\emph{optimize}: the whole process of the command, its files included, and its ratio to the limit;"
    print "\\emph{peak}: the largest resident set of \\texttt{optimize} and of the limit.}"
    print "\\end{center}"
  }' $out > "$tmp/bench-frontier.tex" || fail "the table"
cp "$tmp/bench-frontier.tex" paper/bench-frontier.tex
echo "frontier bench: paper/bench-frontier.tex written"
