#!/bin/sh
# tests/bench/cholmod_long.sh: what CHOLMOD's interface of long integers
# (cholmod_l_*, src/sparse.h) costs against its interface of ints.  Builds
# the program of INT_REF (default: the last commit that called the int
# interface) into build/bench/int, then solves Example 5.1 at N = 16 K
# (K = BENCH_REFINE, default 64: N = 1024) with both programs, alternately,
# RUNS times each (default 5), and compares their results (shape.dat,
# contact.dat, solution.vtu: byte for byte) and their times (the least and
# the median of summary.dat's seconds, the whole solve).  Writes the
# table and its macros into paper/cholmod-long.tex.  Not a test.
cd "$(dirname "$0")/../.." || exit 1
ref=${INT_REF:-3439607}
K=${BENCH_REFINE:-64}
runs=${RUNS:-5}
new=bin/contactopt
old=build/bench/int/bin/contactopt
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ ! -x $old ]; then
  rm -rf build/bench/int && mkdir -p build/bench/int
  git archive "$ref" | tar -x -C build/bench/int || exit 1
  make -C build/bench/int bin/contactopt >/dev/null || exit 1
fi
make bin/contactopt >/dev/null || exit 1
same=yes
for r in $(seq $runs); do
  for v in int long; do
    b=$new; [ $v = int ] && b=$old
    d=$tmp/$v
    rm -rf $d
    $b solve data/example-5.1.scene -s mesh.refine=$K -o $d >/dev/null 2>&1 || exit 1
    awk -v v=$v '$1 == "seconds" { print v, $2 }' $d/summary.dat >> $tmp/times
  done
  for f in shape.dat contact.dat solution.vtu; do
    cmp -s $tmp/int/$f $tmp/long/$f || same=no
  done
done
N=$((16 * K))
awk -v N=$N -v runs=$runs -v same=$same -v date="$(date -u +%Y-%m-%d)" \
    -v cpu="$(nproc) cores" -v loadavg="$(cut -d' ' -f1 /proc/loadavg)" '
  { t[$1, ++n[$1]] = $2 }
  function sorted(v,   i, j, x) {
    for (i = 1; i <= n[v]; i++) s[i] = t[v, i]
    for (i = 2; i <= n[v]; i++) { x = s[i]; for (j = i - 1; j >= 1 && s[j] > x; j--) s[j + 1] = s[j]; s[j + 1] = x }
  }
  function least(v) { sorted(v); return s[1] }
  function median(v) { sorted(v); return s[int((n[v] + 1) / 2)] }
  END {
    li = least("int"); ll = least("long"); mi = median("int"); ml = median("long")
    printf "%% written by tests/bench/cholmod_long.sh on %s, %s, load %s\n", date, cpu, loadavg
    printf "\\newcommand{\\cholmodLongN}{%d}\n", N
    printf "\\newcommand{\\cholmodLongRuns}{%d}\n", runs
    printf "\\newcommand{\\cholmodIntLeast}{%.2f}\n", li
    printf "\\newcommand{\\cholmodLongLeast}{%.2f}\n", ll
    printf "\\newcommand{\\cholmodIntMedian}{%.2f}\n", mi
    printf "\\newcommand{\\cholmodLongMedian}{%.2f}\n", ml
    printf "\\newcommand{\\cholmodLongCost}{%+.1f\\,\\%%}\n", 100 * (ll / li - 1)
    printf "\\newcommand{\\cholmodLongSame}{%s}\n", same == "yes" ? "the same, byte for byte" : "not the same"
    printf "\\newcommand{\\cholmodLongSentence}{at $N = %d$, %d solves of each: least %.2f\\,s with the long integers against %.2f\\,s with the ints (%+.1f\\,\\%%), medians %.2f\\,s and %.2f\\,s; the results %s}\n",
      N, runs, ll, li, 100 * (ll / li - 1), ml, mi, same == "yes" ? "the same, byte for byte" : "not the same"
  }' $tmp/times > paper/cholmod-long.tex
cat paper/cholmod-long.tex
