#!/bin/sh
# tests/bench/orderings.sh: the fill of the factor of Example 5.1's
# stiffness under four orderings (tests/bench/orderings.c: the state
# solver's CAMD with the contact last, METIS of the interior with the
# contact last, and unconstrained AMD and METIS), analysis only, at
# N = 256 .. BENCH_ORDER_NMAX (default 2048; 4096 needs some 5 GB and
# minutes).  Writes build/bench/orderings.dat and the table, with a macro
# per cell for the prose (\orderingsbench{ordering}{N}{lnz|flops|seconds}),
# into paper/bench-orderings.tex.  Not a test.
cd "$(dirname "$0")/../.." || exit 1
nmax=${BENCH_ORDER_NMAX:-2048}
bb=${BENCH_BIN:-build/bench}
out=build/bench/orderings.dat
[ -x $bb/orderings ] || { echo "orderings: $bb/orderings is missing (make bench builds it)" >&2; exit 1; }
mkdir -p build/bench
echo "# N ordering lnz flops seconds" > $out
N=256
while [ $N -le $nmax ]; do
  $bb/orderings data/example-5.1.scene mesh.refine=$((N / 16)) >> $out || exit 1
  N=$((N * 2))
done
tex=paper/bench-orderings.tex
awk -v date="$(date -u +%Y-%m-%d)" -v cores="$(nproc)" '
  /^#/ { next }
  { n[$1] = 1; lnz[$1, $2] = $3; fl[$1, $2] = $4; t[$1, $2] = $5 }
  function sci(x,   e, p) { e = sprintf("%.2e", x); split(e, p, "e")
    return "$" p[1] "\\cdot10^{" (p[2] + 0) "}$" }
  END {
    print "% written by tests/bench/orderings.sh on " date ", " cores " cores"
    print "\\providecommand{\\orderingsbench}[3]{\\csname orderings:#1:#2:#3\\endcsname}"
    split("camd-last metis-last amd metis", o, " ")
    print "\\begin{center}\\small\\begin{tabular}{r rrr rrr}\\toprule"
    print "& \\multicolumn{3}{c}{the contact last} & \\multicolumn{3}{c}{unconstrained}\\\\"
    print "$N$ & CAMD & METIS & METIS/CAMD & AMD & METIS & CAMD/AMD\\\\\\midrule"
    for (N = 256; (N in n); N *= 2) {
      printf "%d & %s & %s & %.3f & %s & %s & %.3f\\\\\n", N, sci(lnz[N, "camd-last"]),
        sci(lnz[N, "metis-last"]), lnz[N, "metis-last"] / lnz[N, "camd-last"],
        sci(lnz[N, "amd"]), sci(lnz[N, "metis"]), lnz[N, "camd-last"] / lnz[N, "amd"]
      for (k = 1; k <= 4; k++)
        printf "\\expandafter\\def\\csname orderings:%s:%d:lnz\\endcsname{%s}" \
               "\\expandafter\\def\\csname orderings:%s:%d:flops\\endcsname{%s}" \
               "\\expandafter\\def\\csname orderings:%s:%d:seconds\\endcsname{%.2f}\n",
               o[k], N, sci(lnz[N, o[k]]), o[k], N, sci(fl[N, o[k]]), o[k], N, t[N, o[k]] > "/dev/stderr"
    }
    print "\\bottomrule\\end{tabular}\\par\\smallskip\\parbox{.92\\linewidth}{\\footnotesize Entries of the factor $L$ of the"
    print "stiffness of Example~5.1 at its initial shape under each ordering, CHOLMOD'"'"'s estimates from"
    print "its symbolic analysis (\\texttt{tests/bench/orderings.sh}, " date ", " cores " cores).}\\end{center}"
  }' $out > $tex.table 2> $tex.macros || exit 1
cat $tex.macros $tex.table > $tex && rm -f $tex.macros $tex.table
cat $out
