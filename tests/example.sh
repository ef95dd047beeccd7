# example.sh: the client program of the overview (src/example.c, built as
# build/example) ends where contactopt optimize ends on every shipped scene:
# the same stop reason, the same number of iterations, the same E* to 1e-12
# relative (the pipeline is the same; the program adds only its files, its
# threads and its interrupts, which change no result).
. tests/lib.sh
TESTS=${TESTS:-build/tests}
EXAMPLE=${EXAMPLE:-${TESTS%/tests}/example}
for sc in data/*.scene; do
  n=$(basename $sc .scene)
  if ! $EXAMPLE $sc > $TMP/$n.out 2> $TMP/$n.err; then
    check "$n: the example runs ($(head -1 $TMP/$n.err))" false; continue
  fi
  $BIN optimize $sc -o $TMP/$n > /dev/null 2>&1
  set -- $(cat $TMP/$n.out)
  e=$1 it=$4 why=$6
  check "$n: the example reaches optimize's E* to 1e-12 ($e, $(value energy $TMP/$n))" \
    near_ref "$(value energy $TMP/$n)" "$e" 1e-12
  check "$n: in as many iterations ($it, $(value iterations $TMP/$n)) and for the same reason ($why, $(value stop_reason $TMP/$n))" \
    [ "$it" = "$(value iterations $TMP/$n)" -a "$why" = "$(value stop_reason $TMP/$n)" ]
done
$EXAMPLE > /dev/null 2> $TMP/usage.err; rc=$?
check "without a scene: exit 2 and its usage ($rc, '$(cat $TMP/usage.err)')" [ $rc -eq 2 ]
$EXAMPLE $TMP/none.scene > /dev/null 2> $TMP/none.err; rc=$?
check "a missing scene: exit 2 and one line naming it ($rc, '$(cat $TMP/none.err)')" \
  [ $rc -eq 2 -a "$(wc -l < $TMP/none.err)" -eq 1 ] && grep -q none.scene $TMP/none.err
finish
