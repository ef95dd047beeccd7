# starts.sh: honest optima of nonconvex objectives (paper/opt.nw,
# "Many starts" and "Progress").  optimizer.starts = K runs the optimiser
# from the scene's start and K - 1 waves in B and goes on from the lowest
# optimum: each start prints its value, summary.dat's starts_min and
# starts_max are the lowest and highest of those printed values, the
# final value is no higher than any start's, the first start is the run
# without starts, the starts find different optima of the compliance of
# Example 5.1 (it is nonconvex), and two runs give the same starts.  A
# stop without progress says what it measured, with the numbers of
# history.dat, and names no cause it did not measure.
. tests/lib.sh
ex=data/example-5.1.scene
cmp_args="-s objective.kind=compliance -s optimizer.method=slsqp"
$BIN optimize $ex -o $TMP/one $cmp_args >/dev/null 2>$TMP/err; rc1=$?
$BIN optimize $ex -o $TMP/k5 $cmp_args -s optimizer.starts=5 >$TMP/out 2>$TMP/err; rc=$?
check "5 starts of slsqp on the compliance of Example 5.1: exit $rc = 0 (the run without starts: $rc1)" \
  holds 'rc == 0 && rc1 == 0' rc=$rc rc1=$rc1
# the starts' values as printed, one line each
sed -n 's/.*: start \([0-9]*\) of 5: compliance = \([^ ]*\) J\/m.*/\1 \2/p' $TMP/out > $TMP/starts
check "a line per start, 1 to 5 ($(cut -d' ' -f1 $TMP/starts | tr '\n' ' '))" \
  test "$(cut -d' ' -f1 $TMP/starts | tr '\n' ' ')" = "1 2 3 4 5 "
lo=$(awk 'NR == 1 || $2 < m { m = $2 } END { printf "%.17g", m }' $TMP/starts)
hi=$(awk 'NR == 1 || $2 > m { m = $2 } END { printf "%.17g", m }' $TMP/starts)
check "summary.dat: starts 5, starts_min $(value starts_min $TMP/k5) the lowest printed ($lo), starts_max $(value starts_max $TMP/k5) the highest ($hi)" \
  holds 'k == 5 && abs(a - lo) <= 1e-11 * abs(lo) && abs(b - hi) <= 1e-11 * abs(hi)' \
  k=$(value starts $TMP/k5) a=$(value starts_min $TMP/k5) lo=$lo b=$(value starts_max $TMP/k5) hi=$hi
J=$(value objective_value $TMP/k5)
check "the final compliance $J is no higher than any start's (the lowest $lo), and the run converged" \
  holds 'J <= lo * (1 + 1e-12) && c == 1' J=$J lo=$lo c=$(grep -c '^stop_reason converged' $TMP/k5/summary.dat)
best=$(value starts_best $TMP/k5)
check "starts_best $best is a start whose printed value is the lowest" \
  holds 'v == lo' v=$(awk -v b=$best '$1 == b { print $2 }' $TMP/starts) lo=$(awk 'NR == 1 || $2 < m { m = $2 } END { print m }' $TMP/starts)
first=$(awk '$1 == 1 { print $2 }' $TMP/starts)
check "start 1 is the scene's: its value $first is the run without starts' ($(value objective_value $TMP/one)) to 1e-11" \
  near_ref "$(value objective_value $TMP/one)" "$first" 1e-11
check "the compliance is nonconvex here: the starts end at optima 1e-3 apart or more (spread $(rel $hi $lo))" \
  holds '(hi - lo) >= 1e-3 * abs(lo)' hi=$hi lo=$lo
check "the spread line names the range and the start the run went on from" \
  grep -q "5 starts: compliance from .* (spread .* relative); the run goes on from start $best" $TMP/out
$BIN optimize $ex -o $TMP/k5b $cmp_args -s optimizer.starts=5 >/dev/null 2>&1
check "the starts are fixed: a second run gives the same starts_min, starts_max and starts_best" \
  test "$(grep -E '^starts_(min|max|best) ' $TMP/k5/summary.dat)" = "$(grep -E '^starts_(min|max|best) ' $TMP/k5b/summary.dat)"
check "without starts summary.dat has no starts line" \
  test "$(grep -c '^starts' $TMP/one/summary.dat)" -eq 0
# bad values: one line naming the key, exit 2
for k in 0 101; do
  $BIN optimize $ex -o $TMP/bad -s optimizer.starts=$k >/dev/null 2>$TMP/err; rc=$?
  check "optimizer.starts = $k: exit $rc = 2, one line naming the key ($(cat $TMP/err))" \
    holds 'rc == 2 && lines == 1 && nm == 1' rc=$rc lines=$(wc -l <$TMP/err) \
    nm=$(grep -c 'optimizer.starts' $TMP/err)
done

# no_progress says what it measured: the Newton method asked for a
# tolerance below the rounding of E on Example 5.1
$BIN optimize $ex -o $TMP/np -s optimizer.tol=1e-15 >/dev/null 2>$TMP/err; rc=$?
msg=$(cat $TMP/err)
check "tol 1e-15: exit $rc = 3, no_progress ($msg)" \
  holds 'rc == 3 && n == 1' rc=$rc n=$(grep -c 'not converged (no_progress)' $TMP/err)
check "the stop names what it measured (the fall of E in all, its rounding, pi) and no cause it guessed" \
  sh -c "grep -q 'the last 3 iterates lowered E by .* J/m in all, none by more than the rounding of E' $TMP/err \
         && ! grep -q 'allows no smaller' $TMP/err"
# its numbers are history.dat's: pi at the last iterate and the smallest of the run
pl=$(sed -n 's/.*none halved pi (\([^ ]*\) at the last, \([^ ]*\) the smallest.*/\1/p' $TMP/err)
pm=$(sed -n 's/.*none halved pi (\([^ ]*\) at the last, \([^ ]*\) the smallest.*/\2/p' $TMP/err)
hl=$(awk '!/^#/ { p = $3 } END { printf "%.2e", p }' $TMP/np/history.dat)
hm=$(awk '!/^#/ && (m == "" || $3 < m) { m = $3 } END { printf "%.2e", m }' $TMP/np/history.dat)
check "its pi at the last ($pl) and smallest ($pm) are history.dat's ($hl, $hm)" \
  test "$pl $pm" = "$hl $hm"
fall=$(sed -n 's/.*lowered E by \([^ ]*\) J\/m in all.*/\1/p' $TMP/err)
hfall=$(awk '!/^#/ { e[$1] = $2; k = $1 } END { print e[k - 3] - e[k] }' $TMP/np/history.dat)
check "its fall of E in all ($fall J/m) is history.dat's over the last 3 iterates ($hfall, printed to 1e-7 J/m)" \
  holds 'abs(a - b) <= 1e-7' a=$fall b=$hfall
finish
