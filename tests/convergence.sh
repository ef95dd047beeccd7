# convergence.sh: E_h at Example 5.1's initial shape converges as the mesh is
# refined (N = 16, 32, 64, 128; M = N/16, R = 3N/16).  For P1 elements the
# energy error is O(h^2) on a smooth solution, so the ratio of successive
# differences should be near 4 (the observed rate, log2 of it, near 2).
# The corners of the clamped side, the jump of the traction at x1 = 2 and
# the end of the contact zone are not smooth: they pull the rate a little
# below 2 (about 1.8 here, 1.86 on finer meshes), hence the window.
. tests/lib.sh
for model in plane_stress plane_strain; do
  for N in 16 32 64 128; do
    $BIN solve data/example-5.1.scene -o $TMP/$model-$N -s material.model=$model \
      -s design.N=$N -s mesh.M=$((N / 16)) -s mesh.R=$((3 * N / 16)) >/dev/null 2>&1 \
      || fail "convergence $model N=$N: solve failed"
    awk '$1 == "energy" { print $2 }' $TMP/$model-$N/summary.dat >> $TMP/$model.E
  done
  rates=$(awk '{ E[NR] = $1 } END {
      for (k = 1; k + 2 <= NR; k++) printf "%.3f ", log((E[k] - E[k+1]) / (E[k+1] - E[k+2])) / log(2) }' $TMP/$model.E)
  echo "# $model: E_h = $(tr '\n' ' ' < $TMP/$model.E); observed rates $rates"
  last=$(echo $rates | awk '{ print $NF }')
  check "$model: observed convergence rate of E_h $last is near 2 (1.7 .. 2.3)" \
    awk -v r=$last 'BEGIN { exit !(r >= 1.7 && r <= 2.3) }'
done
finish
