# solvers_agree.sh: pdas, psor and cgssor agree on the energy E and the
# displacements Q, and each meets its KKT tolerance, for the three shipped
# scenes, both plane models, on the article's mesh and on N = 64.
. tests/lib.sh
tol=1e-11
for scene in data/example-5.1.scene data/example-5.2.scene data/example-5.2-flat.scene; do
  name=$(basename $scene .scene)
  for model in plane_stress plane_strain; do
    for N in 16 64; do
      tag="$name $model N=$N"
      for solver in pdas psor cgssor; do
        out=$TMP/$name-$model-$N-$solver
        if $BIN solve $scene -o $out --plot-files -s material.model=$model -s solver.state=$solver \
             -s mesh.refine=$((N / 16)) -s solver.tol=$tol >/dev/null 2>$TMP/err; then
          kkt=$(value kkt_residual $out)
          check "$tag $solver: KKT residual $kkt <= $tol" le "$kkt" $tol
        else
          fail "$tag $solver: $(cat $TMP/err)"
        fi
      done
      ref=$TMP/$name-$model-$N-pdas
      [ -f $ref/summary.dat ] || continue
      # numdiff's absolute tolerance: 1e-6 of max |u|, both to 4 digits
      abs=$(calc '1e-6 * u' u="$(show %.3e "$(umax $ref)")") && abs=$(show %.3e "$abs")
      for solver in psor cgssor; do
        out=$TMP/$name-$model-$N-$solver
        [ -f $out/summary.dat ] || continue
        e1=$(value energy $ref); e2=$(value energy $out)
        check "$tag $solver: E = $e2 agrees with pdas $e1 to 1e-9" near_ref "$e1" "$e2" 1e-9
        check "$tag $solver: displacements agree with pdas to 1e-6 max|u| = $abs" \
          numdiff -q -a "$abs" -r 0 $ref/nodes.dat $out/nodes.dat
      done
    done
  done
done
finish
