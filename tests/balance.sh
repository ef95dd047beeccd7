# balance.sh: the global balance of forces from the files of a run (the
# paper's section "What a designer reads first"): the reactions of the held
# sides (summary.dat), the contact forces T and, with friction, Tt
# (contact.dat) and the applied loads sum to zero in each component, to
# 1e-10 of the load, on scenes with every kind of side (clamped, roller
# on the left, right and top, traction on each, free), frictionless, with
# Tresca and with Coulomb friction, with and without a body force, in both
# plane models, for solve and for optimize at its optimum.  The loads are
# computed here from the scene's numbers: a traction times the loaded
# length of its side, a body force times the area of the body, gamma (b -
# a) less the integral of the piecewise linear alpha of shape.dat.  Also:
# a roller's tangential reaction is 0 exactly, a side that holds nothing
# has no reaction line, and contact_length is the tributary lengths of
# the nodes of contact.dat at gap 0, recomputed from shape.dat.
. tests/lib.sh
ex=data/example-5.1.scene         # a = 0, b = 4, gamma = 1

# side_args SIDE SPEC: the overrides of a side: clamped, roller, free, or
# traction:FROM:TO:P1:P2
side_args() {
  case $2 in
    traction:*) IFS=: read -r _ f t p1 p2 <<EOF
$2
EOF
      echo "-s $1.bc=traction -s $1.from=$f -s $1.to=$t -s $1.P1=$p1 -s $1.P2=$p2" ;;
    *) echo "-s $1.bc=$2" ;;
  esac; }
# contact_args SPEC: frictionless, tresca:G or coulomb:F
contact_args() {
  case $1 in
    tresca:*) echo "-s contact.model=tresca -s contact.g=${1#tresca:}" ;;
    coulomb:*) echo "-s contact.model=coulomb -s contact.friction=${1#coulomb:}" ;;
    *) echo "-s contact.model=frictionless" ;;
  esac; }

# load DIR LEFT RIGHT TOP F1 F2 COMPONENT: the applied load (N/m) in
# component 1 or 2: each traction times the length of its side that it
# covers (left and right: x2 from alpha_0, alpha_N to gamma = 1; top: x1
# from a = 0 to b = 4), the body force times the area of the body
load() {
  awk -v L="$2" -v R="$3" -v T="$4" -v F1="$5" -v F2="$6" -v c="$7" "$awk_lib"'
    function part(spec, lo, hi,   s, n, f, t) {
      n = split(spec, s, ":"); if (s[1] != "traction") return 0
      f = s[2] > lo ? s[2] : lo; t = s[3] < hi ? s[3] : hi
      return (t > f ? t - f : 0) * s[3 + c] }
    /^#/ { next }
    { if (!number($1) || !number($2)) { bad = 1; exit }
      x[n] = $1; al[n++] = $2 }
    END { if (bad || n < 2) exit 2
      for (i = 1; i < n; i++) under += (x[i] - x[i-1]) * (al[i] + al[i-1]) / 2
      area = 1 * (x[n-1] - x[0]) - under
      printf "%.17g\n", part(L, al[0], 1) + part(R, al[n-1], 1) + part(T, 0, 4) \
                        + (c == 1 ? F1 : F2) * area }' "$1/shape.dat"; }

# balanced LABEL DIR SUMMARY LEFT RIGHT TOP F1 F2: the checks of one state:
# its files in DIR, its summary SUMMARY
balanced() {
  _d=$2 _s=$3
  Lx=$(load $_d "$4" "$5" "$6" "$7" "$8" 1); Ly=$(load $_d "$4" "$5" "$6" "$7" "$8" 2)
  scale=$(calc 'sqrt(x * x + y * y)' x="$Lx" y="$Ly")
  Tx=0; if [ "$(head -1 $_d/contact.dat | wc -w)" -gt 7 ]; then Tx=$(rows_sum '$8' $_d/contact.dat); fi
  Ty=$(rows_sum '$5' $_d/contact.dat)
  Rx=0 Ry=0 lines=0 tangential=0
  for side in left right top; do
    x=$(value reaction_${side}_x1 $_s); y=$(value reaction_${side}_x2 $_s)
    [ -n "$x$y" ] || continue
    lines=$((lines + 1))
    Rx=$(calc 'a + b' a="$Rx" b="$x"); Ry=$(calc 'a + b' a="$Ry" b="$y")
    eval spec=\$side_$side
    case $side:$spec in
      left:roller|right:roller) [ "$y" = 0 ] || tangential=1 ;;
      top:roller) [ "$x" = 0 ] || tangential=1 ;;
    esac
  done
  held=$(for s in "$4" "$5" "$6"; do echo $s; done | grep -c -E '^(clamped|roller)$')
  check "$1: a reaction line pair for each of its $held held sides and no other ($lines)" \
    [ "$lines" -eq "$held" ]
  check "$1: a roller's tangential reaction is 0" [ $tangential -eq 0 ]
  for c in 1 2; do
    if [ $c = 1 ]; then r=$(calc 'abs(R + T + L) / s' R="$Rx" T="$Tx" L="$Lx" s="$scale")
    else r=$(calc 'abs(R + T + L) / s' R="$Ry" T="$Ty" L="$Ly" s="$scale"); fi
    check "$1: x$c: reactions + contact forces + loads = 0, $(show %.1e "$r") of the load <= 1e-10" \
      le "$r" 1e-10
  done
  # the contact length: the tributary lengths (half of each contact edge
  # next to a node, along alpha) of the nodes at gap 0
  len=$(awk "$awk_lib"'
    FILENAME ~ /shape/ { if (!/^#/) { x[n] = $1; al[n++] = $2 }; next }
    /^#/ { next }
    $4 == 0 { for (i = 0; i < n; i++) if (x[i] == $1) break
              if (i == n) { bad = 1; exit }
              if (i > 0) s += sqrt((x[i] - x[i-1])^2 + (al[i] - al[i-1])^2) / 2
              if (i < n - 1) s += sqrt((x[i+1] - x[i])^2 + (al[i+1] - al[i])^2) / 2 }
    END { if (bad) exit 2; printf "%.17g\n", s }' $_d/shape.dat $_d/contact.dat)
  want=$(value contact_length $_s)
  check "$1: contact_length $want = the tributary lengths of the nodes at gap 0 ($len)" \
    holds 'abs(a - b) <= 1e-12 * (b > 1 ? b : 1)' a="$want" b="$len"
  peak=$(rows_max -w '$4 == 0' '$6' $_d/contact.dat 2>/dev/null || echo 0)
  check "$1: contact_pressure_max is the largest pressure at gap 0 of contact.dat" \
    holds 'abs(a - b) <= 1e-12 * abs(b)' a="$(value contact_pressure_max $_s)" b="$peak"
}

# case NAME MODEL LEFT RIGHT TOP F1 F2 CONTACT [COMMAND [OVERRIDE...]]:
# solve (or optimize) Example 5.1 with these sides, loads and contact
# law, and check
case_() {
  name=$1 model=$2 side_left=$3 side_right=$4 side_top=$5 F1=$6 F2=$7 law=$8 cmd=${9:-solve}
  out=$TMP/$name more=
  if [ $# -gt 9 ]; then shift 9; for o; do more="$more -s $o"; done; fi
  if ! $BIN $cmd $ex -o $out -s material.model=$model $(side_args left $side_left) \
       $(side_args right $side_right) $(side_args top $side_top) -s body_force.F1=$F1 \
       -s body_force.F2=$F2 $(contact_args $law) $more > /dev/null 2> $TMP/err; then
    fail "$name: $cmd: $(cat $TMP/err)"; return
  fi
  if [ $cmd = solve ]; then balanced "$name" $out $out "$side_left" "$side_right" "$side_top" $F1 $F2
  else balanced "$name (optimum)" $out/final $out "$side_left" "$side_right" "$side_top" $F1 $F2; fi
}

P=-5.75e8
#     name             model         left       right      top                        F1    F2     contact
case_ example-5.1      plane_stress  clamped    roller     traction:2:4:0:$P          0     0      frictionless
case_ tresca           plane_stress  clamped    roller     traction:2:4:0:$P          0     0      tresca:5e8
case_ coulomb          plane_strain  clamped    roller     traction:2:4:0:$P          0     0      coulomb:0.3
case_ gravity          plane_strain  clamped    roller     traction:2:4:0:$P          5e7   -2e8   frictionless
case_ punch            plane_stress  roller     roller     traction:0:4:0:$P          0     -1e8   frictionless
case_ punch-shear      plane_strain  roller     roller     traction:0:4:2e8:$P        0     0      coulomb:0.3
case_ one-roller       plane_stress  roller     free       traction:0.5:3.5:0:$P      0     0      tresca:2e8
case_ top-roller       plane_stress  clamped    traction:0.3:0.9:-3e8:-1e8 roller     0     -3e8   tresca:2e8
case_ top-clamped      plane_strain  traction:0.3:0.8:2e8:-1e8 free clamped           1e8   -2e8   coulomb:0.2
case_ right-clamped    plane_stress  free       clamped    traction:0:3:1e8:-4e8      0     0      frictionless
case_ friction-holds   plane_stress  free       free       traction:0:4:1e7:-5e8      0     0      tresca:1e8
case_ left-load        plane_strain  traction:0.3:0.9:1e8:0 roller roller             -4e7  -1e8   frictionless
case_ corner-load      plane_stress  clamped    clamped    traction:0:4:1e8:$P        0     0      frictionless
case_ opt-5.1          plane_stress  clamped    roller     traction:2:4:0:$P          0     0      frictionless optimize
case_ opt-gravity      plane_strain  clamped    roller     traction:2:4:0:$P          5e7   -2e8   tresca:5e8   optimize
case_ opt-coulomb      plane_stress  roller     roller     traction:1:4:1e8:$P        0     -1e8   coulomb:0.3  optimize optimizer.method=slsqp
finish
