# convergence.sh: E_h at Example 5.1's initial shape converges as the mesh is
# refined (N = 16, 32, 64, 128: mesh.refine = N/16).  For P1 elements the
# energy error is O(h^2) on a smooth solution, so the ratio of successive
# differences should be near 4 (the observed rate, log2 of it, near 2).
# The corners of the clamped side, the jump of the traction at x1 = 2 and
# the end of the contact zone are not smooth: they pull the rate a little
# below 2 (about 1.8 here, 1.86 on finer meshes), hence the window.
. tests/lib.sh
# E N: E_h of the current model on the mesh of N
E() { value energy $TMP/$model-$1; }
for model in plane_stress plane_strain; do
  for N in 16 32 64 128; do
    $BIN solve data/example-5.1.scene -o $TMP/$model-$N -s material.model=$model \
      -s mesh.refine=$((N / 16)) >/dev/null 2>&1 \
      || fail "convergence $model N=$N: solve failed"
  done
  rates=
  for N in 16 32; do
    r=$(rate "$(E $N)" "$(E $((2 * N)))" "$(E $((4 * N)))")
    rates="$rates $(show %.3f "$r")"
  done
  echo "# $model: E_h = $(E 16) $(E 32) $(E 64) $(E 128); observed rates$rates"
  check "$model: observed convergence rate of E_h $(show %.3f "$r") is near 2 (1.7 .. 2.3)" \
    holds 'r >= 1.7 && r <= 2.3' r="$r"
done
finish
