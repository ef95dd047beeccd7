# gradcheck.sh: the gradient (4.8) agrees with finite differences of E at
# the initial designs of the three shipped scenes, both plane models, on
# the article's mesh and on N = 32.
. tests/lib.sh
for scene in data/example-5.1.scene data/example-5.2.scene data/example-5.2-flat.scene; do
  for model in plane_stress plane_strain; do
    for N in 16 32; do
      out=$TMP/g
      if $BIN gradcheck $scene -o $out -s material.model=$model -s design.N=$N \
           -s mesh.M=$((N / 16)) -s mesh.R=$((3 * N / 16)) >/dev/null 2>$TMP/err; then
        e=$(awk '$1 == "max_relative_error" { print $2 }' $out/summary.dat)
        rows=$(grep -vc '^#' $out/gradient.dat)
        check "gradcheck $(basename $scene) $model N=$N: largest relative error $e < 1e-6 over $rows nodes" \
          awk -v e=$e -v r=$rows -v n=$N 'BEGIN { exit !(e < 1e-6 && r == n + 1) }'
      else
        fail "gradcheck $scene $model N=$N: $(cat $TMP/err)"
      fi
    done
  done
done
finish
