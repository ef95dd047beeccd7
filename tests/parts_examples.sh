# parts_examples.sh: the shipped parts of data/parts/ (paper/parts-examples.nw),
# each solved at its initial shape and optimised by the default method:
# both runs exit 0, the optimisation stops converged and lowers the
# energy, and the global balance of forces holds for each run: the
# reactions of the held sides and curves (summary.dat), the contact forces
# T (contact.dat) and the applied load sum to zero in each component, to
# 1e-10 of the load.  The load is computed here by statics from the
# scene's numbers and the .geo's dimensions, not read from a run: a
# traction times the length of its straight curve; a pressure p on the
# bearing block's seat, the quarter of the bore of radius r from its
# bottom (0.1, c - r) to its side (0.1 - r, c), pushes along the inward
# normal of each straight segment of the mesh, and those forces add up to
# p times the chord turned by a right angle, (-p r, -p r), whatever the
# segments.
. tests/lib.sh
dir=data/parts
# geo NAME VAR: the value of "VAR = number;" in data/parts/NAME.geo
geo() { awk -v k="$2" '{ n = split($0, s, ";"); for (i = 1; i <= n; i++) {
    split(s[i], kv, "="); gsub(/[ \t]/, "", kv[1]); gsub(/[ \t]/, "", kv[2])
    if (kv[1] == k) { print kv[2]; exit } } }' $dir/$1.geo; }
key() { awk -v s="[$1]" -v k="$2" '/^\[/ { in_s = $1 == s; next }
  in_s && $1 == k && $2 == "=" { print $3; exit }' "$3"; }
# the load (N/m) of each part, component 1 and 2
p=$(key boundary.seat p $dir/bearing-block.scene); r=$(geo bearing-block r)
load_bearing_block="$(calc '-p * r' p=$p r=$r) $(calc '-p * r' p=$p r=$r)"
P=$(key boundary.top P2 $dir/machine-foot.scene)
load_machine_foot="0 $(calc 'P * (0.14 - 0.06)' P=$P)"    # the column's top, x1 in (0.06, 0.14)
P=$(key boundary.top P2 $dir/pad.scene)
load_pad="0 $(calc 'P * (b - a)' P=$P a=$(key geometry a $dir/pad.scene) b=$(key geometry b $dir/pad.scene))"

# balanced LABEL SUMMARY CONTACT LX LY
balanced() {
  Rx=$(awk '/^reaction_.*_x1 / { s += $2 } END { printf "%.17g", s }' $2)
  Ry=$(awk '/^reaction_.*_x2 / { s += $2 } END { printf "%.17g", s }' $2)
  T=$(rows_sum '$5' $3)
  s=$(calc 'sqrt(x * x + y * y)' x=$4 y=$5)
  check "$1: x1 balance, |R1 + L1| <= 1e-10 |L| ($Rx + $4)" \
    holds 'abs(R + L) <= 1e-10 * s' R=$Rx L=$4 s=$s
  check "$1: x2 balance, |R2 + T + L2| <= 1e-10 |L| ($Ry + $T + $5)" \
    holds 'abs(R + T + L) <= 1e-10 * s' R=$Ry T=$T L=$5 s=$s; }

for name in bearing-block machine-foot pad; do
  sc=$dir/$name.scene
  eval "set -- \$load_$(echo $name | tr - _)"
  check "$name: the load is read ($1, $2)" test -n "$1" -a -n "$2"
  $BIN solve $sc -o $TMP/$name-solve > $TMP/$name-solve.log 2>&1
  check "$name: solve exits 0" [ $? -eq 0 ]
  $BIN optimize $sc -o $TMP/$name-opt > $TMP/$name-opt.log 2>&1
  check "$name: optimize exits 0" [ $? -eq 0 ]
  check "$name: the initial shape is in U_ad (not moved to B)" \
    test "$(grep -c 'not in B' $TMP/$name-opt.log)" = 0
  check "$name: optimize stops converged ($(value stop_reason $TMP/$name-opt))" \
    [ "$(value stop_reason $TMP/$name-opt)" = converged ]
  check "$name: the optimum's energy is below the start's" \
    lt "$(value energy $TMP/$name-opt)" "$(value energy $TMP/$name-solve)"
  balanced "$name solve" $TMP/$name-solve/summary.dat $TMP/$name-solve/contact.dat $1 $2
  balanced "$name optimum" $TMP/$name-opt/summary.dat $TMP/$name-opt/final/contact.dat $1 $2
done
finish
