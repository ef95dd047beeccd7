# suite.sh: the robustness suite of the optimiser (data/suite/,
# the section "The Newton method" of the paper): scenes unlike the
# article's (both ends clamped, plane strain with nu = 0.45, a body force
# only, free sides, a thin body, a tangential traction, a start at a
# vertex of B, a load that lifts, a plate on an arc pushed sideways, also
# at N = 256 and 512) and Example 5.1 at N = 512.  The Newton
# method must converge within 100 iterations, keep every iterate in B to
# 1e-12, and end at a KKT point of the programme; SLSQP, the reference,
# runs too and must end as documented below: where it converges, the two
# energies agree to 1e-9, and where it does not, the Newton method's
# energy is not above its own.
. tests/lib.sh
# What SLSQP (schur metric, optimizer.max_iter = 200) does on each scene:
# "STOP EXIT [ITERATIONS]", the same under the OpenBLAS kernels Haswell,
# Sandybridge, Prescott, SkylakeX and with one thread (paper/opt.nw,
# "SQP: NLopt's SLSQP").  On the cantilever and the clamped strip its
# quasi-Newton model does not learn the flat directions of E (the nodes
# out of contact) and it uses every iteration, restarted where it breaks
# down; on the others it converges.
slsqp_outcome() {
  case $1 in
    cantilever-gravity|clamped-strip) echo "max_iter 3 200" ;;
    *) echo "converged 0" ;;
  esac
}
for sc in data/suite/*.scene; do
  n=$(basename $sc .scene); c=$TMP/$n-newton; r=$TMP/$n-slsqp
  if ! $BIN optimize $sc -o $c -s optimizer.method=newton >/dev/null 2>$TMP/err; then
    fail "$n: newton: $(cat $TMP/err)"; continue
  fi
  check "$n: the Newton method converges within 100 iterations ($(value stop_reason $c), $(value iterations $c) it, pi $(value projected_gradient $c))" \
    holds 'ok && it <= 100' ok=$([ "$(value stop_reason $c)" = converged ] && echo 1 || echo 0) it="$(value iterations $c)"
  read -r C0 d S L h <<B
$(scene_B $sc)
B
  in_B "$n newton" $c 1e-12 $C0 $d $S $L $h
  kkt_point "$n newton" $c $C0 $d $h
  $BIN optimize $sc -o $r -s optimizer.method=slsqp >/dev/null 2>$TMP/err; rc=$?
  set -- $(slsqp_outcome $n)
  if [ ! -f $r/summary.dat ]; then fail "$n: slsqp: exit $rc, $(cat $TMP/err)"; continue; fi
  check "$n: SLSQP stops $1, exit $2${3:+, after $3 iterations} as documented (exit $rc, $(value stop_reason $r), $(value iterations $r) it, pi $(value projected_gradient $r))" \
    holds "ok && rc == $2 && ($# < 3 || it == ${3:-0})" ok=$([ "$(value stop_reason $r)" = $1 ] && echo 1 || echo 0) \
      rc=$rc it="$(value iterations $r)"
  if [ "$(value stop_reason $r)" = converged ]; then
    check "$n: Newton and SLSQP reach the same E* to 1e-9 ($(value energy $c), $(value energy $r))" \
      near_ref "$(value energy $r)" "$(value energy $c)" 1e-9
  else
    check "$n: SLSQP stops unconverged ($(value stop_reason $r), pi $(value projected_gradient $r)); the Newton method's E* $(value energy $c) is not above its $(value energy $r)" \
      holds 'e <= f + 1e-12 * (f < 0 ? -f : f)' e="$(value energy $c)" f="$(value energy $r)"
  fi
  echo "# $n: newton $(value iterations $c) it / $(value evaluations $c) solves, slsqp $(value iterations $r) it / $(value evaluations $r) solves ($(value stop_reason $r))"
done
# the aluminium plate refined 8 and 16 times (N = 256, 512), where its
# projected gradient stalled while the model problems failed (paper/opt.nw,
# "The end without progress"); make check-fine adds refine 32 (N = 1024)
sc=data/suite/aluminium-arc.scene
for r in ${ALUMINIUM_REFINES:-8 16}; do
  c=$TMP/aluminium-$r-newton
  if ! $BIN optimize $sc -o $c -s mesh.refine=$r >/dev/null 2>$TMP/err; then
    fail "aluminium-arc refine $r: newton: $(cat $TMP/err)"; continue
  fi
  check "aluminium-arc refine $r: the Newton method converges within 100 iterations ($(value stop_reason $c), $(value iterations $c) it, pi $(value projected_gradient $c))" \
    holds 'ok && it <= 100' ok=$([ "$(value stop_reason $c)" = converged ] && echo 1 || echo 0) it="$(value iterations $c)"
  h=$(calc '2 / (32 * r)' r=$r)
  in_B "aluminium-arc refine $r newton" $c 1e-12 0.02 "$(calc '0.05 * h' h=$h)" 0.01 2 $h
  kkt_point "aluminium-arc refine $r newton" $c 0.02 "$(calc '0.05 * h' h=$h)" $h
  echo "# aluminium-arc refine $r: newton $(value iterations $c) it / $(value evaluations $c) solves, E* $(value energy $c), $(value seconds $c) s"
done
# one scene at N = 512: Example 5.1 refined 32 times
c=$TMP/N512-newton
if $BIN optimize data/example-5.1.scene -o $c -s mesh.refine=32 -s optimizer.method=newton \
     >/dev/null 2>$TMP/err; then
  check "N = 512: the Newton method converges within 100 iterations ($(value stop_reason $c), $(value iterations $c) it)" \
    holds 'ok && it <= 100' ok=$([ "$(value stop_reason $c)" = converged ] && echo 1 || echo 0) it="$(value iterations $c)"
  in_B "N = 512 newton" $c 1e-12 0.05 0.0001953125 0.09 4 0.0078125
  kkt_point "N = 512 newton" $c 0.05 0.0001953125 0.0078125
else
  fail "N = 512: newton: $(cat $TMP/err)"
fi
finish
