#!/bin/sh
# make bench, part 5: the threads (paper/threads.nw, issue 26).  `optimize`
# of Example 5.1 at N = 256 and 1024 with the program's own choice of
# threads and with each setting a user might make, in the same run and
# interleaved: each repetition runs every setting once, so that a change of
# the machine's load falls on all of them.  Each run's wall-clock time
# (walltime), its CPU time (user + system, from the shell's times) and its
# summary.dat (iterations, energy, the BLAS threads it used) are kept.
# Writes the table paper/bench-threads.tex (only when every run succeeded
# and every setting gave the same iterations), the raw numbers into
# build/bench/threads.dat, and prints them.
#   BENCH_NS     the N measured (default "256 1024")
#   BENCH_REPS   repetitions (default 3)
#   BASE_BIN     another build of the program, timed beside with its
#                defaults (the row "before"), e.g. one of the last release
cd "$(dirname "$0")/../.." || exit 1
bin=${BIN:-bin/contactopt}
bb=${BENCH_BIN:-build/bench}
ns=${BENCH_NS:-256 1024}
reps=${BENCH_REPS:-3}
scene=data/example-5.1.scene
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "threads bench: FAILED: $*" >&2; exit 1; }
for p in "$bin" "$bb/walltime"; do
  [ -x "$p" ] || fail "$p is missing (make bench builds it)"
done
# the settings: a name (no blanks) and the environment it sets; every run
# starts from an environment without the libraries' thread variables
settings='defaults:
OPENBLAS_NUM_THREADS=1:OPENBLAS_NUM_THREADS=1
OPENBLAS_NUM_THREADS=2:OPENBLAS_NUM_THREADS=2
OPENBLAS_NUM_THREADS=16:OPENBLAS_NUM_THREADS=16
OMP_WAIT_POLICY=passive:OMP_WAIT_POLICY=passive
OMP_WAIT_POLICY=active:OMP_WAIT_POLICY=active
16+CHOLMOD-OpenMP:OMP_NUM_THREADS=16 OPENBLAS_NUM_THREADS=16'
[ -n "$BASE_BIN" ] && settings="$settings
before:BASE"
clean="env -u OPENBLAS_NUM_THREADS -u GOTO_NUM_THREADS -u OMP_NUM_THREADS -u OMP_WAIT_POLICY -u OMP_THREAD_LIMIT"
raw=build/bench/threads.dat
mkdir -p build/bench
echo "# N setting repetition wall[s] cpu[s] iterations energy stop_reason blas_threads" > $raw
# cpu FILE: the children's user + system seconds in FILE, the output of
# times (its second line; times runs in this shell, not in a $(...), whose
# children are not these)
cpu() { awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, p, "m"); s += 60 * p[1] + p[2] } printf "%.3f", s }' "$1"; }
r=1
while [ $r -le "$reps" ]; do
  for N in $ns; do
    echo "$settings" | while IFS=: read -r name envs; do
      run=$bin; [ "$envs" = BASE ] && run=$BASE_BIN envs=
      d=$tmp/$N-$r
      times > "$tmp/c0"
      $clean $envs "$bb/walltime" "$tmp/t" "$run" optimize $scene -o "$d" -s mesh.refine=$((N / 16)) \
        > "$tmp/log" 2>&1 || fail "$name at N = $N, exit status $?: $(tail -n 2 "$tmp/log")"
      times > "$tmp/c1"
      awk -v N=$N -v s=$name -v r=$r -v t="$(cut -d' ' -f1 "$tmp/t")" -v c0="$(cpu "$tmp/c0")" -v c1="$(cpu "$tmp/c1")" '
        { v[$1] = $2 } END {
          if (!("iterations" in v && "energy" in v)) exit 1
          print N, s, r, t, c1 - c0, v["iterations"], v["energy"], v["stop_reason"], ("blas_threads" in v ? v["blas_threads"] : "-") }' \
        "$d/summary.dat" >> $raw || fail "$name at N = $N: no summary"
      tail -n 1 $raw
    done || exit 1
  done
  r=$((r + 1))
done
# every setting, every repetition: the same iterations at each N
awk '!/^#/ { k = $1; if (k in it && it[k] != $6) bad = 1; it[k] = $6 }
     END { exit bad }' $raw || fail "the iterations differ between settings"
blas=$($clean "$bin" --version | sed -n 's/^BLAS: \([^ ]*\) .*, \([A-Za-z0-9]*\) kernels$/\1, \2 kernels/p')
awk -v date="$(date -u +%Y-%m-%d)" -v cores="$(nproc)" -v blas="$blas" \
    -v lavg="$(cut -d' ' -f3 /proc/loadavg)" -v ns="$ns" '
  function median(a, n,   i, j, x) { for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j-1] > a[j]; j--) { x = a[j]; a[j] = a[j-1]; a[j-1] = x }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
  !/^#/ { if (!(($2) in seen)) { seen[$2] = 1; order[++ns_] = $2 }
          k = $1 SUBSEP $2; n[k]++; w[k, n[k]] = $4; c[k, n[k]] = $5
          if (!(k in lo) || $4 < lo[k]) lo[k] = $4; if (!(k in hi) || $4 > hi[k]) hi[k] = $4
          thr[k] = $9 }
  END {
    nn = split(ns, N, " ")
    for (i = 1; i <= nn; i++) { best[N[i]] = 1e300
      for (s = 1; s <= ns_; s++) { k = N[i] SUBSEP order[s]; m = 0
        for (j = 1; j <= n[k]; j++) x[j] = w[k, j]
        med[k] = median(x, n[k]); for (j = 1; j <= n[k]; j++) x[j] = c[k, j]; cmed[k] = median(x, n[k])
        if (med[k] < best[N[i]]) best[N[i]] = med[k] } }
    # the numbers the prose quotes: \threadsbench{SETTING}{N}{wall|low|high|cpu|ratio},
    # a cell of the table below (an unknown one stops LaTeX)
    print "% written by tests/bench/threads.sh on " date ", " cores " cores"
    print "\\providecommand{\\threadsbench}[3]{\\ifcsname threads:\\detokenize{#1}:#2:#3\\endcsname\\csname threads:\\detokenize{#1}:#2:#3\\endcsname\\else\\errmessage{paper/bench-threads.tex has no #1 #2 #3}\\fi}"
    for (i = 1; i <= nn; i++) for (s = 1; s <= ns_; s++) { k = N[i] SUBSEP order[s]
      printf "\\expandafter\\def\\csname threads:\\detokenize{%s}:%d:wall\\endcsname{%.3g}\\expandafter\\def\\csname threads:\\detokenize{%s}:%d:low\\endcsname{%.3g}\\expandafter\\def\\csname threads:\\detokenize{%s}:%d:high\\endcsname{%.3g}\n", order[s], N[i], med[k], order[s], N[i], lo[k], order[s], N[i], hi[k]
      printf "\\expandafter\\def\\csname threads:\\detokenize{%s}:%d:cpu\\endcsname{%.3g}\\expandafter\\def\\csname threads:\\detokenize{%s}:%d:ratio\\endcsname{%.2f}\n", order[s], N[i], cmed[k], order[s], N[i], med[k] / best[N[i]] }
    print "\\begin{center}\\small"
    print "\\begin{tabular}{@{}lrrrrr@{}}\\toprule"
    print "setting & $N$ & threads & wall [s] & CPU [s] & ratio\\\\\\midrule"
    for (i = 1; i <= nn; i++) {
      if (i > 1) print "\\addlinespace"
      for (s = 1; s <= ns_; s++) { name = order[s]; gsub(/_/, "\\_", name); k = N[i] SUBSEP order[s]
        printf "\\texttt{%s} & %d & %s & %.3g (%.3g--%.3g) & %.3g & %.2f\\\\\n", name, N[i], thr[k],
          med[k], lo[k], hi[k], cmed[k], med[k] / best[N[i]] } }
    print "\\bottomrule\\end{tabular}\\\\[2pt]"
    printf "{\\footnotesize Measured by \\texttt{tests/bench/threads.sh} on %s, %d cores, %s, 15-minute load %s at the end. ", date, cores, blas, lavg
    print "\\emph{threads}: the most BLAS threads a call may use (\\texttt{blas\\_threads} of \\texttt{summary.dat});"
    print "\\emph{wall}: the median of the repetitions (their range); \\emph{CPU}: user and system, median;"
    print "\\emph{ratio}: the median over the fastest setting'"'"'s at the same $N$.}"
    print "\\end{center}"
  }' $raw > "$tmp/bench-threads.tex" || fail "the table"
cp "$tmp/bench-threads.tex" paper/bench-threads.tex
echo "threads bench: paper/bench-threads.tex written"
