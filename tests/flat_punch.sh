# flat_punch.sh: the exact uniaxial-strain solution of a flat punch, for
# every state solver and both plane models (see tests/scenes/flat-punch.scene);
# and with the right side free, the exact uniaxial-stress solution.  Both
# are patch tests (the exact displacement is linear), so every quantity of
# summary.dat is known: the peak contact pressure -P2, the contact length
# b - a = 4, the reactions of the rollers (-s11 gamma, s11 gamma; 0 where
# s11 = 0) and the von Mises stress, with s33 = nu (s11 + s22) in plane
# strain:
#   uniaxial strain (rollers): s22 = P2, s11 = nu/(1-nu) P2 (plane strain,
#     s33 = s11: vM = |P2| (1-2nu)/(1-nu)) or nu P2 (plane stress, s33 = 0:
#     vM = |P2| sqrt(1 - nu + nu^2));
#   uniaxial stress (right free): s22 = P2, s11 = 0; vM = |P2| in plane
#     stress, |P2| sqrt(1 - nu + nu^2) in plane strain (s33 = nu P2).
. tests/lib.sh
scene=tests/scenes/flat-punch.scene
E=2.15e11; nu=0.29; P2=-5.75e8
# designer LABEL DIR MODEL strain|stress: the lines of summary.dat that a
# designer reads first against the exact solution (above), to 1e-10
designer() {
  exact=$(awk -v nu=$nu -v P=$P2 -v m=$3 -v k=$4 'BEGIN { a = P < 0 ? -P : P
    s11 = k == "stress" ? 0 : m == "plane_strain" ? nu / (1 - nu) * P : nu * P
    vm = k == "strain" && m == "plane_strain" ? a * (1 - 2 * nu) / (1 - nu) \
       : k == "stress" && m == "plane_stress" ? a : a * sqrt(1 - nu + nu * nu)
    printf "%.17g %.17g\n", s11, vm }')
  s11=${exact% *} vm=${exact#* }
  check "$1: contact_pressure_max = -P2, rel. error $(rel "$(value contact_pressure_max $2)" 5.75e8) <= 1e-10" \
    near_ref 5.75e8 "$(value contact_pressure_max $2)" 1e-10
  check "$1: contact_length = b - a = 4, rel. error $(rel "$(value contact_length $2)" 4) <= 1e-10" \
    near_ref 4 "$(value contact_length $2)" 1e-10
  check "$1: von_mises_max = $(show %.6e $vm) (uniaxial $4), rel. error $(rel "$(value von_mises_max $2)" $vm) <= 1e-10" \
    near_ref $vm "$(value von_mises_max $2)" 1e-10
  # the reaction of a roller on x1 = a is -s11 gamma (gamma = 1), on x1 = b
  # s11 gamma; its tangential component is 0; a free side has none
  check "$1: reaction_left = (-s11, 0) = ($(show %.6e "$(calc -s s=$s11)"), 0) to 1e-10 of |P2|" \
    holds 'abs(x + s) <= 1e-10 * p && y == 0' x="$(value reaction_left_x1 $2)" \
      y="$(value reaction_left_x2 $2)" s=$s11 p=5.75e8
  if [ $4 = strain ]; then
    check "$1: reaction_right = (s11, 0) to 1e-10 of |P2|" \
      holds 'abs(x - s) <= 1e-10 * p && y == 0' x="$(value reaction_right_x1 $2)" \
        y="$(value reaction_right_x2 $2)" s=$s11 p=5.75e8
  else
    check "$1: the free right side has no reaction line" \
      test -z "$(value reaction_right_x1 $2)$(value reaction_right_x2 $2)"
  fi
}

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
      designer "flat punch $model $solver N=$N" $out $model strain
    done
  done
done

# uniaxial stress: the right side free; u2 at the top is P2 / E in plane
# stress, P2 (1 - nu^2) / E in plane strain (s33 = nu s22)
for model in plane_strain plane_stress; do
  want=$(awk -v E=$E -v nu=$nu -v P=$P2 -v m=$model 'BEGIN {
    printf "%.17g", m == "plane_strain" ? P * (1 - nu * nu) / E : P / E }')
  for solver in pdas psor cgssor; do
    N=16 out=$TMP/stress-$model-$solver
    if ! $BIN solve $scene -o $out --plot-files -s material.model=$model -s solver.state=$solver \
         -s right.bc=free -s solver.tol=1e-12 >/dev/null 2>$TMP/err; then
      fail "uniaxial stress $model $solver: $(cat $TMP/err)"; continue
    fi
    top=$(rows_max -w '$3 == row' 'abs(($7 - want) / want)' $out/nodes.dat \
            row="$(calc 'M + R' M="$(value M $out)" R="$(value R $out)")" want="$want")
    check "uniaxial stress $model $solver: top u2 = $want, rel. error $(show %.2e "$top") <= 1e-10" \
      le "$top" 1e-10
    designer "uniaxial stress $model $solver" $out $model stress
  done
done
finish
