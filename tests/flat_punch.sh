# flat_punch.sh: the exact uniaxial-strain solution of a flat punch, for
# every state solver and both plane models (see tests/scenes/flat-punch.scene).
. tests/lib.sh
scene=tests/scenes/flat-punch.scene
E=2.15e11; nu=0.29; P2=-5.75e8
for model in plane_strain plane_stress; do
  # u2 at the top (gamma = 1): P2 / (lambda + 2 mu) or P2 (1 - nu^2) / E
  want=$(awk -v E=$E -v nu=$nu -v P=$P2 -v m=$model 'BEGIN {
    l = E * nu / ((1 + nu) * (1 - 2 * nu)); mu = E / (2 * (1 + nu));
    printf "%.17g", m == "plane_strain" ? P / (l + 2 * mu) : P * (1 - nu * nu) / E }')
  for solver in pdas psor cgssor; do
    for N in 16 64; do
      out=$TMP/$model-$solver-$N
      if ! $BIN solve $scene -o $out --plot-files -s material.model=$model -s solver.state=$solver \
           -s mesh.refine=$((N / 16)) -s solver.tol=1e-12 >/dev/null 2>$TMP/err; then
        fail "flat punch $model $solver N=$N: $(cat $TMP/err)"; continue
      fi
      worst=$(rows_max 'abs(($6 - p) / p)' $out/contact.dat p=5.75e8)
      check "flat punch $model $solver N=$N: contact pressure = applied, rel. error $(show %.2e "$worst") <= 1e-10" \
        le "$worst" 1e-10
      # the top is the row M + R of the mesh
      top=$(rows_max -w '$3 == row' 'abs(($7 - want) / want)' $out/nodes.dat \
              row="$(calc 'M + R' M="$(value M $out)" R="$(value R $out)")" want="$want")
      check "flat punch $model $solver N=$N: top u2 = $want, rel. error $(show %.2e "$top") <= 1e-10" \
        le "$top" 1e-10
    done
  done
done
finish
