# coulomb.sh: shape optimisation with Coulomb friction from the command
# line (the section "Shape optimisation with Coulomb friction"): gradcheck
# of J_F at the initial design of Example 5.1 and at the optimum SLSQP
# finds, for F = 0.1, 0.2, 0.3; the optimum a KKT point with every iterate
# in B; projgrad to the same optimum; the other objectives of a Coulomb
# state; an optimisation that cannot converge stops without progress,
# exit 3, every file written.
. tests/lib.sh
tr=data/example-5.1-tresca.scene
co="-s contact.model=coulomb -s contact.g="
for F in 0.1 0.2 0.3; do
  if $BIN gradcheck $tr -o $TMP/g$F $co -s contact.friction=$F >/dev/null 2>$TMP/err; then
    check "F = $F: gradcheck of J_F at the initial design: largest relative error $(value max_relative_error $TMP/g$F) < 1e-6" \
      lt "$(value max_relative_error $TMP/g$F)" 1e-6
  else fail "F = $F: gradcheck: $(cat $TMP/err)"; fi
  o=$TMP/o$F
  if ! $BIN optimize $tr -o $o $co -s contact.friction=$F -s optimizer.method=slsqp \
       >/dev/null 2>$TMP/err; then fail "F = $F: optimize: $(cat $TMP/err)"; continue; fi
  check "F = $F: slsqp converges ($(value stop_reason $o), $(value iterations $o) iterations)" \
    [ "$(value stop_reason $o)" = converged ]
  in_B "F = $F slsqp" $o 1e-12 $B_article
  kkt_point "F = $F slsqp" $o 0.05 0.00625 0.25
  if $BIN gradcheck $tr -o $TMP/go$F $co -s contact.friction=$F -s design.initial=file \
       -s design.file=$o/final/shape.dat >/dev/null 2>$TMP/err; then
    check "F = $F: gradcheck of J_F at the optimum: largest relative error $(value max_relative_error $TMP/go$F) < 1e-6" \
      lt "$(value max_relative_error $TMP/go$F)" 1e-6
  else fail "F = $F: gradcheck at the optimum: $(cat $TMP/err)"; fi
done
# Algorithm 4.1 reaches the optimum SLSQP found
if $BIN optimize $tr -o $TMP/pg $co -s contact.friction=0.2 -s optimizer.method=projgrad \
     >/dev/null 2>$TMP/err; then
  check "F = 0.2: projgrad reaches slsqp's J_F* to 1e-7 ($(value energy $TMP/pg) against $(value energy $TMP/o0.2))" \
    near_ref "$(value energy $TMP/o0.2)" "$(value energy $TMP/pg)" 1e-7
else fail "F = 0.2 projgrad: $(cat $TMP/err)"; fi
# the other objectives of a Coulomb state
for kind in compliance pressure_spread pressure_peak; do
  if $BIN gradcheck $tr -o $TMP/k $co -s contact.friction=0.2 -s objective.kind=$kind \
       >/dev/null 2>$TMP/err; then
    check "F = 0.2 $kind: largest relative error $(value max_relative_error $TMP/k) < 1e-6" \
      lt "$(value max_relative_error $TMP/k)" 1e-6
  else fail "F = 0.2 $kind: $(cat $TMP/err)"; fi
done
# below the rounding of J_F (optimizer.tol = 1e-14) the optimiser cannot
# make progress: it stops so, long before max_iter, with exit 3 and the
# files of the last design it accepted
for m in slsqp projgrad; do
  rm -rf $TMP/np
  $BIN optimize $tr -o $TMP/np $co -s contact.friction=0.3 -s optimizer.method=$m \
    -s optimizer.tol=1e-14 -s optimizer.max_iter=1000 >/dev/null 2>$TMP/err; rc=$?
  check "$m at optimizer.tol = 1e-14: exit $rc, one line, no_progress after $(value iterations $TMP/np) < 1000 iterations" \
    holds 'rc == 3 && lines == 1 && ok && its < 1000' rc=$rc lines=$(wc -l < $TMP/err) \
      its="$(value iterations $TMP/np)" \
      ok=$(grep -q "not converged (no_progress)" $TMP/err && [ "$(value stop_reason $TMP/np)" = no_progress ] && echo 1 || echo 0)
  check "$m without progress: every file written (summary, history, iterates, multipliers, initial/, final/)" \
    sh -c "cd $TMP/np && test -s summary.dat -a -s history.dat -a -s iterates.dat -a -s multipliers.dat -a -s initial/shape.dat -a -s final/shape.dat"
  in_B "$m without progress" $TMP/np 1e-12 $B_article
done
finish
