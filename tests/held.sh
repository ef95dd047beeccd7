#!/bin/sh
# tests/held.sh: a body that nothing holds is refused before any solve,
# whatever the solver and the command (paper/model.nw, "Bodies that
# nothing holds", the test (H)): exit 2, one line naming the free motion,
# nothing written.  The thresholds come from statics, not from the
# program: a flat block (alpha = 0) on [0, 4] x [0, 1], its top loaded on
# [2, 4] with (P1, P2), P2 = -5.75e8 Pa, tips about the left end when its
# moment about (0, 0), P2 (4^2 - 2^2)/2 - 1 * P1 * 2, turns it
# anticlockwise (P1 < -1.725e9 Pa), and about the right end when its
# moment about (4, 0), P2 * 2 + 1 * P1 * 2 (clockwise), is positive
# (P1 > 5.75e8 Pa).  Coulomb friction with F = 5 holds the slide
# (F W = 5.75e9 N/m > |L1| = 2 |P1|) and does no work on a tip.
. tests/lib.sh
ex=data/example-5.1.scene
# the pad of issue 34: rubber, rollers on both sides, the top pulled up
pad="-s geometry.b=0.04 -s geometry.gamma=0.01 -s design.N=32 -s design.C0=0.001
  -s design.C1=0.1 -s design.C2=0.000395 -s design.initial=constant
  -s design.constant=0 -s design.arc_x1= -s design.arc_x2= -s design.arc_radius=
  -s mesh.C0prime=0.002 -s material.E=6e6 -s material.nu=0.49
  -s material.model=plane_strain -s left.bc=roller -s right.bc=roller
  -s top.from=0.01 -s top.to=0.03 -s top.P2=2e6"
# refused NAME CODE PATTERN COMMAND...: exit CODE, one line matching
# PATTERN, no output folder
refused() { _n=$1 _code=$2 _pat=$3; shift 3
  "$@" -o $TMP/$_n >/dev/null 2>$TMP/err; _rc=$?
  check "$_n: exit $_rc, '$(head -1 $TMP/err)'" clean_failure $_rc $_code $TMP/err $TMP/$_n "$_pat"; }
# solved NAME COMMAND...: exit 0
solved() { _n=$1; shift
  "$@" -o $TMP/$_n >/dev/null 2>$TMP/err; _rc=$?
  check "$_n: exit $_rc $(head -1 $TMP/err)" [ $_rc -eq 0 ]; }

lift="not held: the loads do not press it onto the foundation \(their vertical resultant is 40000 N/m.*no side holds u2 \(left.bc = roller, right.bc = roller, top.bc = traction\): nothing stops it lifting off"
for solver in pdas cgssor psor; do
  refused pad-$solver 2 "$lift" $BIN solve $ex $pad -s solver.state=$solver
done
for method in newton slsqp mma projgrad; do
  refused pad-optimize-$method 2 "$lift" $BIN optimize $ex $pad -s optimizer.method=$method
done
refused pad-gradcheck 2 "$lift" $BIN gradcheck $ex $pad --components 0-32/8

# a gravity that points up, Coulomb friction, no side holding anything:
# the body floats off, said as such (not as friction too weak)
up="-s left.bc=free -s right.bc=free -s top.bc=free -s top.from= -s top.to=
  -s top.P1= -s top.P2= -s contact.model=coulomb -s contact.friction=0.5
  -s body_force.F2=1e8"
refused gravity-up-coulomb 2 "not held: the loads do not press it onto the foundation.*lifting off" \
  $BIN solve $ex $up
refused gravity-up-tresca 2 "not held: the loads do not press it onto the foundation.*lifting off" \
  $BIN solve $ex $up -s contact.model=tresca -s contact.friction= -s contact.g=1e8

# the tips of a flat block, at the thresholds of statics
block="-s design.initial=constant -s design.constant=0 -s design.arc_x1=
  -s design.arc_x2= -s design.arc_radius= -s left.bc=free -s right.bc=free
  -s contact.model=coulomb -s contact.friction=5"
# (pdas: cgssor and psor take no Coulomb friction on a body that the sides
# do not hold)
for solver in pdas; do
  solved block-left-held-$solver $BIN solve $ex $block -s top.P1=-1.7249e9 -s solver.state=$solver
  refused block-left-tips-$solver 2 "tip it about the left end of its contact \(x1 = 0\).*with 200000 N m/m" \
    $BIN solve $ex $block -s top.P1=-1.7251e9 -s solver.state=$solver
  solved block-right-held-$solver $BIN solve $ex $block -s top.P1=5.749e8 -s solver.state=$solver
  refused block-right-tips-$solver 2 "tip it about the right end of its contact \(x1 = 4\).*with 200000 N m/m" \
    $BIN solve $ex $block -s top.P1=5.751e8 -s solver.state=$solver
done

# given friction on the flat block: every contact node is at height 0, so
# a tip slides none of them and friction does no work on it: the same
# thresholds (g = 1e9 Pa holds the slide, g (b - a) = 4e9 > 2 |P1|)
tresca="-s contact.model=tresca -s contact.friction= -s contact.g=1e9"
solved block-left-held-tresca $BIN solve $ex $block $tresca -s top.P1=-1.7249e9
refused block-left-tips-tresca 2 "tip it about the left end of its contact \(x1 = 0\): their moment about it, less what friction resists, turns the body off the foundation with 200000 N m/m" \
  $BIN solve $ex $block $tresca -s top.P1=-1.7251e9

# held by the sides: the same loads are no trouble with a clamped side
solved clamped-pulled $BIN solve $ex -s top.P2=5.75e8
finish
