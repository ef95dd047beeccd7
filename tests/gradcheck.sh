# gradcheck.sh: the gradient (4.8) agrees with finite differences of E at
# the initial designs of the three shipped scenes, both plane models, on
# the article's mesh and on N = 32.
. tests/lib.sh
for scene in data/example-5.1.scene data/example-5.2.scene data/example-5.2-flat.scene; do
  for model in plane_stress plane_strain; do
    for N in 16 32; do
      out=$TMP/g
      if $BIN gradcheck $scene -o $out -s material.model=$model -s mesh.refine=$((N / 16)) \
           >/dev/null 2>$TMP/err; then
        e=$(value max_relative_error $out)
        rows=$(grep -vc '^#' $out/gradient.dat)
        check "gradcheck $(basename $scene) $model N=$N: largest relative error $e < 1e-6 over $rows nodes" \
          holds 'e < 1e-6 && rows == N + 1' e="$e" rows="$rows" N=$N
      else
        fail "gradcheck $scene $model N=$N: $(cat $TMP/err)"
      fi
    done
  done
done
# a body force (and no traction) makes the F'(X) term of (4.8) the main
# one: without it the error is about 0.45
nolo="-s top.bc=free -s top.from= -s top.to= -s top.P1= -s top.P2="
for scene in data/example-5.1.scene data/example-5.2.scene; do
  for model in plane_stress plane_strain; do
    if $BIN gradcheck $scene -o $TMP/g -s material.model=$model $nolo \
         -s body_force.F1=1e6 -s body_force.F2=-7.65e6 >/dev/null 2>$TMP/err; then
      e=$(value max_relative_error $TMP/g)
      check "gradcheck $(basename $scene) $model with a body force only: largest relative error $e < 1e-6" \
        lt "$e" 1e-6
    else
      fail "gradcheck $scene $model with a body force: $(cat $TMP/err)"
    fi
  done
done
finish
