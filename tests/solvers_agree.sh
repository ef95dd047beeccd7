# solvers_agree.sh: pdas, psor and cgssor agree on the energy E and the
# displacements Q, and each meets its KKT tolerance, for the three shipped
# scenes, both plane models, on the article's mesh and on N = 64.
. tests/lib.sh
tol=1e-11
value() { awk -v k=$1 '$1 == k { print $2 }' $2/summary.dat; }
for scene in data/example-5.1.scene data/example-5.2.scene data/example-5.2-flat.scene; do
  name=$(basename $scene .scene)
  for model in plane_stress plane_strain; do
    for N in 16 64; do
      M=$((N / 16)); R=$((3 * N / 16)); tag="$name $model N=$N"
      for solver in pdas psor cgssor; do
        out=$TMP/$name-$model-$N-$solver
        if $BIN solve $scene -o $out -s material.model=$model -s solver.state=$solver \
             -s design.N=$N -s mesh.M=$M -s mesh.R=$R -s solver.tol=$tol >/dev/null 2>$TMP/err; then
          kkt=$(value kkt_residual $out)
          check "$tag $solver: KKT residual $kkt <= $tol" awk -v r=$kkt -v t=$tol 'BEGIN { exit !(r <= t) }'
        else
          fail "$tag $solver: $(cat $TMP/err)"
        fi
      done
      ref=$TMP/$name-$model-$N-pdas
      [ -f $ref/summary.dat ] || continue
      umax=$(awk '!/^#/ { for (c = 6; c <= 7; c++) { v = $c < 0 ? -$c : $c; if (v > m) m = v } }
                  END { printf "%.3e", m }' $ref/nodes.dat)
      for solver in psor cgssor; do
        out=$TMP/$name-$model-$N-$solver
        [ -f $out/summary.dat ] || continue
        e1=$(value energy $ref); e2=$(value energy $out)
        check "$tag $solver: E = $e2 agrees with pdas $e1 to 1e-9" \
          awk -v a=$e1 -v b=$e2 'BEGIN { d = (a - b) / a; exit !(d < 1e-9 && d > -1e-9) }'
        abs=$(awk -v u=$umax 'BEGIN { printf "%.3e", 1e-6 * u }')
        check "$tag $solver: displacements agree with pdas to 1e-6 max|u| = $abs" \
          numdiff -q -a $abs -r 0 $ref/nodes.dat $out/nodes.dat
      done
    done
  done
done
finish
