# friction.sh: given friction (Tresca) and Coulomb friction from the
# command line (the section "Given friction" of the paper): the files
# carry friction only where a scene asks for it; the friction work of the
# summary is the one the contact file implies; every optimiser reaches
# the same optimum of the friction scene; the gradient agrees with finite
# differences; the Coulomb fixed point meets |Tt| <= F Tn, and stops at its
# own limit or when it stalls; a body that only friction holds sideways is
# solved when friction can hold it (|Tt| <= g omega, the forces carry the
# loads) and refused with the numbers when it cannot; and what has no
# meaning (the Newton method on a Coulomb state, psor with friction) or
# does not converge is refused cleanly.
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
$BIN solve $tr -o $TMP/co7 $co -s contact.max_fixed_point=7 >/dev/null 2>$TMP/err
check "coulomb: a fixed point not reached within contact.max_fixed_point = 7: exit 3, one line, no folder" \
  clean_failure $? 3 $TMP/err $TMP/co7 'fixed point did not converge in 7 iterations \(contact.max_fixed_point\)'
if $BIN solve $tr -o $TMP/co-mi7 $co -s solver.max_iter=7 >/dev/null 2>$TMP/err; then
  check "coulomb: solver.max_iter = 7 bounds the state solver's steps, not the fixed point's $(value fixed_point_iterations $TMP/co-mi7) rounds" \
    test "$(value fixed_point_iterations $TMP/co-mi7)" -gt 7
else fail "coulomb with solver.max_iter = 7: $(cat $TMP/err)"; fi
# Example 5.2 at F = 100: the fixed point alternates between two states
# from its fourth round; it stops when the change has not halved in 10
for m in pdas cgssor; do
  $BIN solve data/example-5.2.scene -o $TMP/co-cycle-$m -s contact.model=coulomb \
    -s contact.friction=100 -s solver.state=$m >/dev/null 2>$TMP/err
  check "coulomb, a fixed point that cycles ($m): stops on the stall within 20 rounds: exit 3, one line, no folder: $(cat $TMP/err)" \
    clean_failure $? 3 $TMP/err $TMP/co-cycle-$m 'stopped converging: the change of the normal forces did not halve in its last 10 of 1[0-9] iterations'
done
$BIN optimize $tr -o $TMP/co-newton $co -s optimizer.method=newton >/dev/null 2>$TMP/err
check "coulomb: the Newton method refused (its model is a Tresca energy's): exit 2, one line, no folder" \
  clean_failure $? 2 $TMP/err $TMP/co-newton "contact.model = coulomb: optimizer.method = newton models"
$BIN solve $tr -o $TMP/psor -s solver.state=psor >/dev/null 2>$TMP/err
check "psor with friction: refused, exit 2, one line naming the key" \
  clean_failure $? 2 $TMP/err $TMP/psor 'solver.state = psor: cannot take friction'

# ---- a body that friction alone holds sideways (the section "Bodies that
# friction alone holds sideways"): the friction scene with free sides and
# 1e7 Pa sideways on [2, 4], a horizontal load L1 = 2e7 N/m, and the
# vertical one W = 5.75e8 * 2 = 1.15e9 N/m
held="-s left.bc=free -s right.bc=free -s top.P1=1e7"
# omega FILE: contact.dat's rows as x1 omega T u1 Tt, omega half the
# contact edges next to the node, from the columns x1 and alpha
omega() { awk 'NR > 1 && !/^#/ { n++; x[n] = $1; a[n] = $2; T[n] = $5; u[n] = $7; t[n] = $8 }
  function len(i) { return sqrt((x[i + 1] - x[i])^2 + (a[i + 1] - a[i])^2) }
  END { for (i = 1; i <= n; i++)
          printf "%s %.17g %s %s %s\n", x[i], ((i > 1 ? len(i - 1) : 0) + (i < n ? len(i) : 0)) / 2, T[i], u[i], t[i] }' "$1"; }
if $BIN solve $tr -o $TMP/held $held -s contact.g=2e8 >/dev/null 2>$TMP/err; then
  omega $TMP/held/contact.dat > $TMP/held.rows
  check "held by friction, g = 2e8 Pa: |Tt| <= g omega at every node, to 1e-8 of g omega" \
    le "$(rows_max 'abs($5) / (2e8 * $2) - 1' $TMP/held.rows)" 1e-8
  check "held by friction: the tangential forces carry the horizontal load, sum Tt = -2e7 N/m ($(rows_sum '$5' $TMP/held.rows))" \
    near_ref -2e7 "$(rows_sum '$5' $TMP/held.rows)" 1e-9
  check "held by friction: the normal forces carry the vertical load, sum T = 1.15e9 N/m" \
    near_ref 1.15e9 "$(rows_sum '$3' $TMP/held.rows)" 1e-9
  check "held by friction: the nodes in contact stick (u1 = 0 under a tangential force)" \
    test "$(awk 'NR > 1 && $4 == 0 && ($7 != 0 || $8 == 0)' $TMP/held/contact.dat | wc -l)" -eq 0 -a \
         "$(awk 'NR > 1 && $4 == 0' $TMP/held/contact.dat | wc -l)" -gt 0
else fail "held by friction, g = 2e8 Pa: $(cat $TMP/err)"; fi
$BIN solve $tr -o $TMP/held-small $held -s contact.g=4e6 >/dev/null 2>$TMP/err
check "held by friction, g = 4e6 Pa: refused with the capacity and the load: exit 2, one line, no folder" \
  clean_failure $? 2 $TMP/err $TMP/held-small 'no side holds u1, and friction cannot hold the body' \
  'g \(b - a\) = 1.6e\+07 N/m' 'horizontal load of 2e\+07 N/m'
$BIN solve $tr -o $TMP/held-cg $held -s contact.g=2e8 -s solver.state=cgssor >/dev/null 2>$TMP/err
check "held by friction: cgssor refused (its dual needs S positive definite): exit 2, one line, no folder" \
  clean_failure $? 2 $TMP/err $TMP/held-cg 'solver.state = cgssor: cannot take friction' 'use pdas'
for m in newton slsqp; do
  $BIN optimize $tr -o $TMP/held-$m $held -s contact.g=2e8 -s optimizer.method=$m >/dev/null 2>$TMP/err \
    || fail "held by friction, optimize $m: $(cat $TMP/err)"
done
check "held by friction: optimize newton converges ($(value iterations $TMP/held-newton) iterations)" \
  test "$(value stop_reason $TMP/held-newton)" = converged
check "held by friction: slsqp's E* agrees with the Newton method's to 1e-9" \
  near_ref "$(value energy $TMP/held-newton)" "$(value energy $TMP/held-slsqp)" 1e-9
# tresca_kkt FILE G: the Tresca conditions at slip bound G, read from
# contact.dat alone (omega from the columns x1 and alpha, as omega() does):
# prints the largest violation of T >= 0, gap >= 0, min(|T|, |gap|) = 0,
# |Tt| <= G omega (relative to G omega) and G omega |u1| + Tt u1 = 0 (stick
# where |Tt| < G omega, slide against Tt), each force relative to max T and
# each displacement to max |u|, as in the solver's residual; then sum T and
# sum Tt
tresca_kkt() { awk -v g="$2" '
  function abs(v) { return v < 0 ? -v : v }
  function max(p, q) { return p > q ? p : q }
  function min(p, q) { return p < q ? p : q }
  function len(i) { return sqrt((x[i + 1] - x[i])^2 + (a[i + 1] - a[i])^2) }
  NR > 1 && !/^#/ { n++; x[n] = $1; a[n] = $2; gap[n] = $4; T[n] = $5; u[n] = $7; t[n] = $8
    Tm = max(Tm, T[n]); um = max(um, max(abs($3), abs($7))) }
  END { for (i = 1; i <= n; i++) {
      s = g * ((i > 1 ? len(i - 1) : 0) + (i < n ? len(i) : 0)) / 2
      v = max(v, max(-T[i] / Tm, -gap[i] / um))
      v = max(v, min(abs(T[i]) / Tm, abs(gap[i]) / um))
      v = max(v, abs(t[i]) / s - 1)
      v = max(v, (s * abs(u[i]) + t[i] * u[i]) / (Tm * um))
      sn += T[i]; st += t[i] }
    printf "%.3g %.17g %.17g\n", v, sn, st }' "$1"; }
# N = 16 to 256 and g = 6e6 to 1e9 Pa (capacity 2.4e7 to 4e9 N/m against
# the load of 2e7): every solve converges and carries the loads, sum T =
# 1.15e9 and sum Tt = -2e7 N/m, to 1e-9. The default tolerance (1e-10, in
# the norms of the whole state) lets a node at its threshold slide the
# wrong way by up to 1.8e-8 m at N = 256, 3e-8 of the largest force times
# displacement; so Tresca's conditions are checked, to 1e-8, on the same
# solve at a tolerance of 1e-14, which only the exact set meets
bad= worst=0 most=0
for N in 16 32 64 128 256; do
  for g in 6e6 1e7 2e7 5e7 1e8 5e8 1e9; do
    d=$TMP/held-$N-$g
    if $BIN solve $tr -o $d $held -s contact.g=$g -s design.N=$N >/dev/null 2>$TMP/err; then
      set -- $(tresca_kkt $d/contact.dat $g)
      holds 'abs(n - 1.15e9) <= 1.15 && abs(t + 2e7) <= 2e-2' n=$2 t=$3 \
        || bad="$bad N=$N,g=$g(sums $2 $3)"
      most=$(calc 'max(a, b)' a=$most b="$(value iterations $d)")
    else bad="$bad N=$N,g=$g(exit $?)"; fi
    if $BIN solve $tr -o $d-exact $held -s contact.g=$g -s design.N=$N -s solver.tol=1e-14 \
         >/dev/null 2>$TMP/err; then
      set -- $(tresca_kkt $d-exact/contact.dat $g)
      le "$1" 1e-8 || bad="$bad N=$N,g=$g(conditions $1)"
      worst=$(calc 'max(a, b)' a=$worst b=$1)
      most=$(calc 'max(a, b)' a=$most b="$(value iterations $d-exact)")
    else bad="$bad N=$N,g=$g(tol 1e-14: exit $?)"; fi
    rm -rf $d $d-exact
  done
done
check "held by friction, N = 16..256, g = 6e6..1e9 Pa (35 solves): each converges, sum T and sum Tt carry the loads to 1e-9, Tresca's conditions at tol 1e-14 to $(show %.1e $worst) <= 1e-8, at most $(show %d $most) pdas steps${bad:+; failed:$bad}" \
  test -z "$bad"
co_held="$held -s contact.model=coulomb -s contact.g= -s contact.friction=0.2"
if $BIN solve $tr -o $TMP/held-co $co_held >/dev/null 2>$TMP/err; then
  omega $TMP/held-co/contact.dat > $TMP/held-co.rows
  Tmax=$(rows_max '$3' $TMP/held-co.rows)
  check "held by Coulomb friction, F = 0.2: |Tt| <= F T at every node, to 1e-8 of max T; $(value fixed_point_iterations $TMP/held-co) rounds" \
    le "$(rows_max 'abs($5) - 0.2 * $3' $TMP/held-co.rows)" "$(calc '1e-8 * t' t=$Tmax)"
  check "held by Coulomb friction: sum Tt = -2e7 N/m, sum T = 1.15e9 N/m" \
    holds 'abs(t + 2e7) <= 2e-2 && abs(n - 1.15e9) <= 1.15' \
      t="$(rows_sum '$5' $TMP/held-co.rows)" n="$(rows_sum '$3' $TMP/held-co.rows)"
else fail "held by Coulomb friction, F = 0.2: $(cat $TMP/err)"; fi
$BIN solve $tr -o $TMP/held-co-small $co_held -s contact.friction=0.01 >/dev/null 2>$TMP/err
check "held by Coulomb friction, F = 0.01: refused with F W and the load: exit 2, one line, no folder" \
  clean_failure $? 2 $TMP/err $TMP/held-co-small 'vertical load 1.15e\+09 N/m holds at most 1.15e\+07 N/m' \
  'horizontal load of 2e\+07 N/m'
# pressed flat and symmetrically (L1 = 0) at g = 1e5 Pa, N = 15: no node at
# the middle, the two halves slide apart, and every position by less than
# the innermost slide is a state; pdas holds the first of the two
# innermost nodes (x1 = 1.8666666667, the 8th), whatever the rounding
flat="-s left.bc=free -s right.bc=free -s top.from=0 -s design.initial=constant -s design.constant=0 -s design.arc_x1= -s design.arc_x2= -s design.arc_radius= -s design.N=15 -s contact.g=1e5"
if $BIN solve $tr -o $TMP/flat $flat >/dev/null 2>$TMP/err; then
  omega $TMP/flat/contact.dat > $TMP/flat.rows
  check "flat and symmetric, every node but one sliding: |Tt| <= g omega, to 1e-8 of g omega" \
    le "$(rows_max 'abs($5) / (1e5 * $2) - 1' $TMP/flat.rows)" 1e-8
  check "flat and symmetric: sum Tt = 0 to 1e-9 of g (b - a)" \
    holds 'abs(t) <= 4e-4' t="$(rows_sum '$5' $TMP/flat.rows)"
  check "flat and symmetric: one node at rest, the 8th (x1 = 1.8666666667)" \
    test "$(awk '$4 == 0 { print NR }' $TMP/flat.rows | tr '\n' ' ')" = "8 "
else fail "flat and symmetric: $(cat $TMP/err)"; fi
finish
