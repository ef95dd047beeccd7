# magnitudes.sh: the window of magnitudes of the scene appendix (paper/
# scene.nw, "Magnitudes"): at its eight corners, E and b - a at 1e-30 and
# 1e30 and the load at 1.001e-30 and 0.999e30 times E (just inside: the
# ratio |P2| / E is rounded; Example 5.1 scaled to the width), solve and gradcheck exit 0 and optimize 0 or 3, and no file they
# write holds a NaN or an infinity; outside it, and for numbers that are
# not decimal, the program refuses the scene before solving: exit 2, one
# line naming the key, nothing written.
. tests/lib.sh
ex=data/example-5.1.scene
# finite_all DIR: DIR exists, and no NaN or Inf (any case, any sign) among
# the words of any of its files, the binary ones too (lib.sh's finite
# skips them)
finite_all() { [ -d "$1" ] && ! grep -r -q -i -E "(^|[[:space:]\"'>=])[-+]?(nan|inf)" "$1"; }
# scaled E L R: the overrides of Example 5.1 with Young's modulus E, the
# width L (every length scaled by L / 4) and the load R E
scaled() { awk -v E=$1 -v L=$2 -v R=$3 'BEGIN { s = L / 4
  printf "-s material.E=%.17g -s geometry.b=%.17g -s geometry.gamma=%.17g", E, L, s
  printf " -s design.C0=%.17g -s design.C2=%.17g -s mesh.C0prime=%.17g", 0.05 * s, 3.91 * s * s, 0.25 * s
  printf " -s design.arc_x1=%.17g -s design.arc_x2=%.17g -s design.arc_radius=%.17g", L, 160.025 * s, 160.025 * s
  printf " -s top.from=%.17g -s top.to=%.17g -s top.P2=%.17g\n", L / 2, L, -R * E }'; }
for E in 1e-30 1e30; do
  for L in 1e-30 1e30; do
    for R in 1.001e-30 0.999e30; do
      over=$(scaled $E $L $R)
      for cmd in solve gradcheck optimize; do
        n=corner-E$E-L$L-R$R-$cmd
        $BIN $cmd $ex -o $TMP/$n $over > /dev/null 2> $TMP/err; rc=$?
        ok_rc=0; [ $cmd = optimize ] && [ $rc -eq 3 ] && ok_rc=3
        check "E = $E, b - a = $L, |P2| = $R E: $cmd exits $rc, every file finite $(cat $TMP/err | cut -c1-100)" \
          sh -c "[ $rc -eq $ok_rc ] && [ -s $TMP/$n/summary.dat ]" && check "$n: no NaN or Inf in any file" finite_all $TMP/$n
        rm -rf $TMP/$n
      done
    done
  done
done

# refused: status 2, one line naming the key and the reason, nothing written
refused() { # description key pattern -- overrides
  desc=$1 key=$2 pat=$3; shift 4
  rm -rf $TMP/bad
  $BIN solve $ex -o $TMP/bad "$@" > /dev/null 2> $TMP/err; rc=$?
  check "$desc: exit $rc, $(cat $TMP/err)" clean_failure $rc 2 $TMP/err $TMP/bad "$key" "$pat"; }
refused "E = 1e308" material.E '\[1e-30, 1e30\]' -- -s material.E=1e308
refused "E = 1e-300" material.E '\[1e-30, 1e30\]' -- -s material.E=1e-300
refused "a traction of -1e300 Pa" top.P2 'a load must be 0 or lie within' -- -s top.P2=-1e300
refused "a traction of -1e-300 Pa" top.P2 'a load must be 0 or lie within' -- -s top.P2=-1e-300
refused "a body force of 1e300 N/m^3" body_force.F1 'a load must be 0' -- -s body_force.F1=1e300
refused "E = 0x10, hexadecimal" material.E 'hexadecimal' -- -s material.E=0x10
refused "M = 0x2, hexadecimal" mesh.M 'hexadecimal' -- -s mesh.M=0x2
refused "E = inf" material.E 'not a finite number' -- -s material.E=inf
# on the bound as the user writes it: |P2| / E = 2e-19 / 2e11 = 1e-30 in
# decimal, whose doubles' quotient is 9.9999999999999992e-31, is accepted;
# just outside, the message shows the ratio with the digits that put it
# outside, not 1e-30
$BIN solve $ex -o $TMP/bound -s material.E=2e11 -s top.P2=-2e-19 > /dev/null 2> $TMP/err; rc=$?
check "|P2| / E = 2e-19 / 2e11, on the bound 1e-30 in decimal: accepted (exit $rc $(cat $TMP/err))" \
  test $rc -eq 0 -a -s $TMP/bound/summary.dat
$BIN solve $ex -o $TMP/bound -s material.E=4.9e10 -s top.P2=-4.9e40 > /dev/null 2> $TMP/err; rc=$?
check "|P2| / E = 4.9e40 / 4.9e10, on the bound 1e30 in decimal (the doubles' quotient 1.0000000000000002e30): accepted (exit $rc)" \
  test $rc -eq 0
refused "|P2| / E = 1.99999e-19 / 2e11, just below 1e-30" top.P2 '\|P2\| / E = 9\.9999e-31: a load must be 0 or lie within \[1e-30, 1e30\]' -- \
  -s material.E=2e11 -s top.P2=-1.99999e-19
finish
