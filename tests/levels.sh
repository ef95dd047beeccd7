# levels.sh: the coarse-to-fine start of optimize (optimizer.levels,
# paper/opt.nw).  At N = 256 and 512 (Example 5.1, plane stress, Newton)
# the default levels reach the single level's E* to 1e-9 relative and its
# design to 1e-7 C0, and say so in one line; converged to optimizer.tol =
# 1e-9 (N = 256) to 1e-12 and 1e-9 C0; optimizer.levels = 1 runs no
# coarse level; at the article's N = 16 the default is one level, the same
# run, bit for bit, as optimizer.levels = 1.
. tests/lib.sh
ex=data/example-5.1.scene
# same_data A B: the data files of two runs without times are the same
# (fewer than lib.sh's same_run compares)
same_data() {
  for f in final/shape.dat final/contact.dat iterates.dat multipliers.dat; do
    cmp -s "$1/$f" "$2/$f" || return 1
  done
}
# agree TOLE TOLX A B: E* to TOLE relative, the final design to TOLX in
# metres (C0 = 0.05)
agree() {
  awk -v tolE=$1 -v tolX=$2 'FNR == 1 { f++ }
    f == 1 && $1 == "energy" { e1 = $2 } f == 2 && $1 == "energy" { e2 = $2 }
    f == 3 && !/^#/ { x[FNR] = $2 }
    f == 4 && !/^#/ { d = $2 - x[FNR]; if (d < 0) d = -d; if (d > dx) dx = d }
    END { de = (e2 - e1) / e1; if (de < 0) de = -de; exit !(de <= tolE && dx <= tolX) }' \
    "$3/summary.dat" "$4/summary.dat" "$3/final/shape.dat" "$4/final/shape.dat"
}
for K in 16 32; do
  N=$((16 * K))
  $BIN optimize $ex -s mesh.refine=$K -s optimizer.levels=1 -o $TMP/one-$N > $TMP/one.log
  $BIN optimize $ex -s mesh.refine=$K -o $TMP/lev-$N > $TMP/lev.log
  check "N = $N: the default runs coarse levels and says so in one line" \
    grep -q "coarse to fine: N = 64 \.\. $((N / 2)) in [0-9]* evaluations" $TMP/lev.log
  check "N = $N: optimizer.levels = 1 runs no coarse level" \
    sh -c "! grep -q 'coarse to fine' $TMP/one.log"
  check "N = $N: the levels reach the single level's E* to 1e-9 relative and its design to 1e-7 C0" \
    agree 1e-9 5e-9 $TMP/one-$N $TMP/lev-$N
  c=$(sed -n 's/.*coarse to fine: N = [0-9]* \.\. [0-9]* in \([0-9]*\) evaluations, \([0-9.]*\) s.*/\1 \2/p' $TMP/lev.log)
  check "N = $N: summary.dat counts the coarse levels: levels $(value levels $TMP/lev-$N), coarse_evaluations $(value coarse_evaluations $TMP/lev-$N) and coarse_seconds $(value coarse_seconds $TMP/lev-$N) as printed ($c), within seconds $(value seconds $TMP/lev-$N)" \
    holds 'l >= 2 && ce == c1 && cs > 0 && cs <= s && (cs - c2 <= 0.01 && c2 - cs <= 0.01)' \
      l="$(value levels $TMP/lev-$N)" ce="$(value coarse_evaluations $TMP/lev-$N)" c1="${c% *}" \
      cs="$(value coarse_seconds $TMP/lev-$N)" c2="${c#* }" s="$(value seconds $TMP/lev-$N)"
  check "N = $N: one level writes no levels line" sh -c "! grep -q '^levels ' $TMP/one-$N/summary.dat"
done
# At the default tol each run stops a few 1e-8 C0 from its mesh's optimum,
# which is what separates the two designs above; both converged to
# optimizer.tol = 1e-9 are one design to 1e-9 C0 and one E* to 1e-12
for L in 1 0; do
  $BIN optimize $ex -s mesh.refine=16 -s optimizer.tol=1e-9 -s optimizer.levels=$L -o $TMP/tight-$L > /dev/null
done
check "N = 256, optimizer.tol = 1e-9: the levels reach the single level's E* to 1e-12 relative and its design to 1e-9 C0" \
  agree 1e-12 5e-11 $TMP/tight-1 $TMP/tight-0
$BIN optimize $ex -s optimizer.levels=1 -o $TMP/one-16 > /dev/null
$BIN optimize $ex -o $TMP/lev-16 > $TMP/lev.log
check "N = 16: the default is one level, bit for bit the run of optimizer.levels = 1" \
  same_data $TMP/one-16 $TMP/lev-16
$BIN optimize $ex -s optimizer.levels=-1 -o $TMP/bad > /dev/null 2> $TMP/err
check "optimizer.levels = -1 is refused (exit 2)" test $? -eq 2
finish
