# tests/kernels/fine.sh: the robustness suite's aluminium plate
# (data/suite/aluminium-arc.scene) at mesh.refine 32, N = 1024, where the
# Newton method's projected gradient stalled while its model problems
# failed (paper/opt.nw, "The end without progress"); tests/suite.sh runs it
# at refine 8 and 16.  Under each kernel family in KERNELS the Newton
# method must converge within 100 iterations, in the same number of
# iterations under each, with every iterate in B to 1e-12, at a KKT point,
# and at the energy of SLSQP (run once, under the first kernel) to 1e-9.
# Slow: some 20 s a Newton run and several minutes for SLSQP on two loaded
# cores; make check-fine runs it, and make check-kernels-full with it.
. tests/lib.sh
KERNELS=${KERNELS:-Haswell Sandybridge Prescott}
REFINE=${REFINE:-32}
sc=data/suite/aluminium-arc.scene
h=$(calc '2 / (32 * r)' r=$REFINE); d=$(calc '0.05 * h' h=$h)
start=$(date +%s)
first= iters=
for k in $KERNELS; do
  c=$TMP/newton-$k
  if ! OPENBLAS_CORETYPE=$k $BIN optimize $sc -o $c -s mesh.refine=$REFINE >/dev/null 2>$TMP/err; then
    fail "aluminium-arc refine $REFINE, $k: newton: $(cat $TMP/err)"; continue
  fi
  check "aluminium-arc refine $REFINE, $k: the Newton method converges within 100 iterations ($(value stop_reason $c), $(value iterations $c) it, pi $(value projected_gradient $c), $(value seconds $c) s)" \
    holds 'ok && it <= 100' ok=$([ "$(value stop_reason $c)" = converged ] && echo 1 || echo 0) it="$(value iterations $c)"
  in_B "aluminium-arc refine $REFINE, $k, newton" $c 1e-12 0.02 $d 0.01 2 $h
  kkt_point "aluminium-arc refine $REFINE, $k, newton" $c 0.02 $d $h
  first=${first:-$k} iters="$iters $(value iterations $c)"
done
set -- $iters
check "aluminium-arc refine $REFINE: the same iterations under every kernel ($KERNELS:$iters)" \
  [ "$(printf '%s\n' "$@" | sort -u | wc -l)" -eq 1 ]
r=$TMP/slsqp
OPENBLAS_CORETYPE=${first:-Haswell} $BIN optimize $sc -o $r -s mesh.refine=$REFINE \
  -s optimizer.method=slsqp >/dev/null 2>$TMP/err
c=$TMP/newton-${first:-Haswell}
if [ "$(value stop_reason $r)" = converged ] && [ -f $c/summary.dat ]; then
  check "aluminium-arc refine $REFINE: Newton and SLSQP reach the same E* to 1e-9 ($(value energy $c), $(value energy $r); SLSQP $(value iterations $r) it, $(value seconds $r) s)" \
    near_ref "$(value energy $r)" "$(value energy $c)" 1e-9
else
  fail "aluminium-arc refine $REFINE: SLSQP, the reference, did not converge: $(cat $TMP/err)"
fi
echo "# kernels/fine.sh: $(($(date +%s) - start)) s"
finish
