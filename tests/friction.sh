# friction.sh: given friction (Tresca) and Coulomb friction from the
# command line (the section "Given friction" of the paper): the files
# carry friction only where a scene asks for it; the friction work of the
# summary is the one the contact file implies; every optimiser reaches
# the same optimum of the friction scene; the gradient agrees with finite
# differences; the Coulomb fixed point meets |Tt| <= F Tn; and what has no
# meaning (the gradient of a Coulomb state, psor with friction) or does not
# converge is refused cleanly.
. tests/lib.sh
ex=data/example-5.1.scene; tr=data/example-5.1-tresca.scene
head6='# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa]'

# ---- frictionless: exactly the files of before ---------------------------
$BIN solve $ex -o $TMP/none >/dev/null 2>$TMP/err || fail "frictionless solve: $(cat $TMP/err)"
check "frictionless: contact.dat has its six columns and header" \
  test "$(head -1 $TMP/none/contact.dat)" = "$head6" -a \
       "$(awk 'NR > 1 && NF != 6' $TMP/none/contact.dat | wc -l)" -eq 0
check "frictionless: no friction line in summary.dat, no tangential force in the VTU" \
  test "$(grep -c -E '^(contact |slip_bound|friction|fixed_point)' $TMP/none/summary.dat)" -eq 0 \
       -a "$(grep -a -c tangential_force $TMP/none/solution.vtu)" -eq 0

# ---- the friction scene at g = 2.5e8 (stick and slip): columns, summary, VTU
$BIN solve $tr -o $TMP/tr -s contact.g=2.5e8 >/dev/null 2>$TMP/err || fail "tresca solve: $(cat $TMP/err)"
check "tresca: contact.dat appends u1 and Tt, eight columns on every row" \
  test "$(head -1 $TMP/tr/contact.dat)" = "$head6 u1[m] Tt[N/m]" -a \
       "$(awk 'NR > 1 && NF != 8' $TMP/tr/contact.dat | wc -l)" -eq 0
check "tresca: summary.dat names the law and its slip bound, as the scene gives it (2.5e8)" \
  test "$(value contact $TMP/tr)" = tresca -a "$(value slip_bound $TMP/tr)" = 2.5e8
check "tresca: at the initial design nodes stick and nodes slip" \
  holds 'stick > 0 && slip > 0' \
    stick=$(awk 'NR > 1 && $7 == 0 && $8 != 0' $TMP/tr/contact.dat | wc -l) \
    slip=$(awk 'NR > 1 && $7 != 0' $TMP/tr/contact.dat | wc -l)
# at a slipping node |Tt| = g omega, at a sticking one u1 = 0: the work
# sum g omega |u1| is sum |Tt u1| over the rows
w=$(rows_sum 'abs($7 * $8)' $TMP/tr/contact.dat)
check "tresca: friction_energy $(value friction_energy $TMP/tr) is sum |Tt u1| of contact.dat ($w)" \
  near_ref "$w" "$(value friction_energy $TMP/tr)" 1e-9
check "tresca: T_t u1 <= 0 at every node (friction opposes the slip)" \
  le "$(rows_max '$7 * $8' $TMP/tr/contact.dat)" 0
# (tests/paraview.sh reads the array back and compares it with contact.dat)
check "tresca: the VTU declares the point array tangential_force" \
  test "$(grep -a -c 'Name="tangential_force"' $TMP/tr/solution.vtu)" -eq 1

# ---- every optimiser reaches one optimum ----------------------------------
for m in newton slsqp projgrad; do
  if $BIN optimize $tr -o $TMP/opt-$m -s optimizer.method=$m -s optimizer.max_iter=2000 \
       >/dev/null 2>$TMP/err; then
    check "tresca optimize $m: converged in $(value iterations $TMP/opt-$m) iterations, E* $(value energy $TMP/opt-$m)" \
      test "$(value stop_reason $TMP/opt-$m)" = converged
    kkt_point "tresca $m" $TMP/opt-$m 0.05 0.00625 0.25
  else fail "tresca optimize $m: $(cat $TMP/err)"; fi
done
# cgssor hands the Newton method the stiffness at the current stick and
# slip, as pdas does: the same iterations (9 when it handed over the
# frictionless one) and the same optimum
if $BIN optimize $tr -o $TMP/opt-cg -s solver.state=cgssor >/dev/null 2>$TMP/err; then
  check "tresca optimize with cgssor: $(value iterations $TMP/opt-cg) Newton iterations as with pdas ($(value iterations $TMP/opt-newton))" \
    test "$(value iterations $TMP/opt-cg)" -eq "$(value iterations $TMP/opt-newton)"
  check "tresca optimize with cgssor: E* agrees with pdas's to 1e-9" \
    near_ref "$(value energy $TMP/opt-newton)" "$(value energy $TMP/opt-cg)" 1e-9
else fail "tresca optimize with cgssor: $(cat $TMP/err)"; fi
for m in slsqp projgrad; do
  check "tresca: $m's E* agrees with the Newton method's to 1e-9" \
    near_ref "$(value energy $TMP/opt-newton)" "$(value energy $TMP/opt-$m)" 1e-9
done
check "tresca: the optimum has both zones: sticking and slipping nodes" \
  holds 'stick > 0 && slip > 0' \
    stick=$(awk 'NR > 1 && $7 == 0 && $8 != 0' $TMP/opt-newton/final/contact.dat | wc -l) \
    slip=$(awk 'NR > 1 && $7 != 0' $TMP/opt-newton/final/contact.dat | wc -l)

# ---- the gradient at three slip bounds ---------------------------------------
for g in 1.5e8 2.5e8 3e8; do
  if $BIN gradcheck $tr -o $TMP/gc$g -s contact.g=$g >/dev/null 2>$TMP/err; then
    check "tresca gradcheck g = $g: largest relative error $(value max_relative_error $TMP/gc$g) <= 1e-6" \
      le "$(value max_relative_error $TMP/gc$g)" 1e-6
  else fail "tresca gradcheck g = $g: $(cat $TMP/err)"; fi
done

# ---- Coulomb ----------------------------------------------------------------
co="-s contact.model=coulomb -s contact.g= -s contact.friction=0.2"
if $BIN solve $tr -o $TMP/co $co >/dev/null 2>$TMP/err; then
  check "coulomb: $(value fixed_point_iterations $TMP/co) fixed-point iterations, the normal forces still move by $(value fixed_point_residual $TMP/co) <= 1e-10" \
    holds 'it >= 1 && r <= 1e-10' it="$(value fixed_point_iterations $TMP/co)" \
      r="$(value fixed_point_residual $TMP/co)"
  Tmax=$(rows_max '$5' $TMP/co/contact.dat)
  check "coulomb: |Tt| <= F Tn at every node, to 1e-8 of max T" \
    le "$(rows_max 'abs($8) - 0.2 * $5' $TMP/co/contact.dat)" "$(calc '1e-8 * t' t=$Tmax)"
else fail "coulomb solve: $(cat $TMP/err)"; fi
$BIN solve $tr -o $TMP/co7 $co -s solver.max_iter=7 >/dev/null 2>$TMP/err
check "coulomb: a fixed point not reached within solver.max_iter = 7: exit 3, one line, no folder" \
  clean_failure $? 3 $TMP/err $TMP/co7 'fixed point did not converge in 7 iterations'
for cmd in optimize gradcheck; do
  $BIN $cmd $tr -o $TMP/co-$cmd $co >/dev/null 2>$TMP/err
  check "coulomb: $cmd refused (no gradient of an energy): exit 2, one line, no folder" \
    clean_failure $? 2 $TMP/err $TMP/co-$cmd "contact.model = coulomb: $cmd needs the gradient"
done
$BIN solve $tr -o $TMP/psor -s solver.state=psor >/dev/null 2>$TMP/err
check "psor with friction: refused, exit 2, one line naming the key" \
  clean_failure $? 2 $TMP/err $TMP/psor 'solver.state = psor: cannot take friction'
finish
