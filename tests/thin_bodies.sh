# thin_bodies.sh: the state solvers on thin bodies clamped at both ends
# (paper/pdas.nw, "Where the active set crawls"), with and without contact:
# the steel strip of tests/scenes/strip.scene (10 m by 5 cm) and strips of
# aspect 1:10 to 1:500 made here.  Every solve must end with exit 0 and
# its state must be the physics':
# - at rest (no load): u = 0, E = 0 and every contact force 0, exactly;
# - no contact: no node active, every contact force zero against the
#   load (1e-6 of it: the residual Ax - b at a free node, which the
#   solver's tolerance bounds relative to the internal forces, up to 1e8
#   times the load on these strips), and the displacement that of the linear elastic
#   body without a foundation.  That reference is another solve: the same
#   load upwards lifts the body away from the foundation, so that no bound
#   can act there, and linear elasticity gives u(-P) = -u(P), E(-P) = E(P);
#   a node held wrongly on either side breaks both;
# - contact: the Signorini conditions read from contact.dat (gaps >= 0,
#   forces >= 0 to 1e-6 of the largest, and no force without contact:
#   the work sum |T| gap at most 1e-5 of |E|; a free node's force is the
#   rounding of internal forces up to 1e8 times the load, which on the
#   1:500 strip leaves 1e-8 (pdas) to 1e-7 (cgssor) of the largest force
#   and 6e-8 to 7e-7 of |E| in that work), E equal to the work of the loads and the contact forces
#   (Clapeyron; both are sums in which those internal forces cancel, so
#   to 1e-6 here), and cgssor (psor on the 1:10 strip) agreeing with
#   pdas;
# - part of the body lifted: the same, with some nodes in contact and some
#   lifted.
# psor runs where it converges within its default 1e5 sweeps: the strip
# at rest, and the 1:10 strip (its rate falls with the conditioning of a
# thin body, paper/psor.nw).
# The optimisation of the strips (paper/newton.nw, "A soft face"; at the
# end): the Newton method, the default, converges on the strip of
# tests/scenes/strip.scene and on its kin of aspect 1:50 and 1:100; on
# the 1:500 strip it ends without progress at the rounding of E, pi below
# 1e-2, and no model problem of its run fails; SLSQP started from each
# Newton optimum finds no lower energy, and SLSQP from the line start
# ends max_iter above it on all four (paper/opt.nw, "SLSQP on a thin
# strip").  Under the Prescott and the Sandybridge kernels of OpenBLAS,
# one thread, the Newton method's runs at 1:50, 1:200 and 1:500 end with
# the same stop reason, E and shape; at the end of the 1:500 run the
# gradient's own rounding, measured by the two kernels at the same
# design, is of the order of pi and above tol: no method that reads the
# gradient can converge there (paper/newton.nw, "The end on the 1:500
# strip").
. tests/lib.sh
strip=tests/scenes/strip.scene

# thin R KIND: $TMP/thin-R-KIND.scene, a steel strip 10 m long and 10/R
# thick (E = 2e11 Pa, nu = 0.3, plane stress), clamped at both ends,
# N = 100 columns of 10 cm and 1 + 2 rows; KIND gap: alpha = gamma/20
# everywhere, a gap of gamma/20 at rest; KIND rest: alpha = 0, resting on
# the foundation.  The whole top is loaded with P2 = 0 (changed by -s).
thin() { awk -v r=$1 -v kind=$2 'BEGIN { b = 10; g = b / r; C0 = g / 10
  c = kind == "gap" ? g / 20 : 0
  printf "[geometry]\na = 0\nb = %.17g\ngamma = %.17g\n", b, g
  printf "[design]\nN = 100\nC0 = %.17g\nC1 = 0\nC2 = %.17g\n", C0, g * b - c * b
  printf "initial = constant\nconstant = %.17g\n", c
  printf "[mesh]\nM = 1\nR = 2\nC0prime = %.17g\n", g / 5
  printf "[material]\nE = 2e11\nnu = 0.3\n[left]\nbc = clamped\n[right]\nbc = clamped\n"
  printf "[top]\nbc = traction\nfrom = 0\nto = 10\nP2 = -1\n" }' > $TMP/thin-$1-$2.scene; }
# load R FACTOR: the traction P2 (negative: down) under which an
# Euler-Bernoulli beam of the strip's section, clamped at both ends,
# would bend by FACTOR times the gap gamma/20 at its middle:
# w = q L^4 / (384 E I), I = gamma^3 / 12.  Shear makes the body softer
# than the beam by 12 % at 1:10 and less beyond, and the finite elements
# (three rows of linear triangles, which lock in bending) stiffer, by a
# factor of about 30 at 1:500: FACTOR 1/20 leaves the gap open, FACTOR
# 1000 closes it (the checks below say whether a node touches)
load() { calc '-f * (g / 20) * 384 * 2e11 * g * g * g / 12 / 1e4' f="$2" g="$(calc '10 / r' r="$1")"; }

# run NAME SCENE ARGS...: solve into $TMP/NAME (with nodes.dat); a check
# that it ends with exit 0
run() { _n=$1 _sc=$2; shift 2; rm -rf $TMP/$_n
  $BIN solve $_sc -o $TMP/$_n --plot-files "$@" >/dev/null 2>$TMP/err; _rc=$?
  check "$_n: exit 0 (exit $_rc$([ $_rc -eq 0 ] || echo ": $(head -1 $TMP/err)"))" test $_rc -eq 0; }
# solved NAME: converged, KKT residual <= 1e-10, no NaN or Inf (state_ok)
solved() { [ -f $TMP/$1/summary.dat ] || return 1; state_ok $1 1e-10; }
# at_rest NAME: no load: u = 0, E = 0, every contact force 0, exactly
at_rest() { solved $1 || return
  _u=$(umax $TMP/$1) _t=$(rows_max 'abs($5)' $TMP/$1/contact.dat) _e=$(value energy $TMP/$1)
  check "$1: at rest: max |u| = $_u, max |T| = $_t, E = $_e, all 0" holds 'u == 0 && t == 0 && e == 0' u="$_u" t="$_t" e="$_e"; }
# no_contact NAME LOAD: no node active, every |T| <= 1e-6 |LOAD|
no_contact() { solved $1 || return
  _a=$(value active_contact_nodes $TMP/$1) _t=$(rows_max 'abs($5)' $TMP/$1/contact.dat)
  check "$1: no contact: $_a nodes active, max |T| = $(show %.1e "$_t") <= 1e-6 of the load $(show %.3g "$2") N/m" \
    holds 'a == 0 && t <= 1e-6 * abs(l)' a="$_a" t="$_t" l="$2"; }
# opposite DOWN UP: u(DOWN) = -u(UP) to 1e-9 of the largest, E equal to 1e-12
opposite() { [ -f $TMP/$1/summary.dat ] && [ -f $TMP/$2/summary.dat ] || return
  _d=$(udiff $TMP/$1 $TMP/$2 -1) _a=$(value energy $TMP/$1) _b=$(value energy $TMP/$2)
  check "$1: the elastic body's state, u = -u($2) (rel. $(show %.1e "$_d") <= 1e-9), E = $_a = E($2) (rel. $(rel "$_b" "$_a") <= 1e-12)" \
    holds 'd <= 1e-9 && abs(b - a) <= 1e-12 * abs(a)' d="$_d" a="$_a" b="$_b"; }
# signorini NAME: from contact.dat, with F the largest force: gaps >= 0,
# forces >= -1e-6 F, and sum |T| gap <= 1e-5 |E| (no force without
# contact)
signorini() {
  _e=$(value energy $TMP/$1) _f=$(rows_max 'abs($5)' $TMP/$1/contact.dat)
  _gmin=$(rows_min '$4' $TMP/$1/contact.dat) _fmin=$(rows_min '$5' $TMP/$1/contact.dat)
  _c=$(rows_sum 'abs($5) * $4' $TMP/$1/contact.dat)
  check "$1: Signorini: gaps >= 0 (min $_gmin), forces >= 0 (min $(show %.1e "$_fmin") of max $(show %.3g "$_f")), sum |T| gap = $(show %.1e "$_c") <= 1e-5 |E|" \
    holds 'gmin >= 0 && fmin >= -1e-6 * f && c <= 1e-5 * abs(e)' gmin="$_gmin" fmin="$_fmin" f="$_f" e="$_e" c="$_c"; }
# contact NAME GAMMA P2 [F2]: some node in contact, the Signorini
# conditions, and E the work of the loads (the whole top loaded)
contact() { solved $1 || return
  _a=$(value active_contact_nodes $TMP/$1)
  check "$1: $_a nodes in contact" holds 'a > 0' a="$_a"
  signorini $1; WTOL=1e-6; energy_is_work $1 $2 0 10 0 $3 0 ${4:-0}; WTOL=; }

# ---- the strip of the issue: 10 m by 5 cm, N = 200 -----------------------
# Under 1 kPa it touches (beam theory: 12.5 mm at the middle against a gap
# of at most 5 mm); with no load, or 1 mPa down or up, it does not.
run strip-pdas $strip && contact strip-pdas 0.05 -1e3
run strip-cgssor $strip -s solver.state=cgssor && solved strip-cgssor && agrees strip-cgssor strip-pdas
run strip-pdas-iter1000 $strip -s solver.max_iter=1000 && solved strip-pdas-iter1000 && agrees strip-pdas-iter1000 strip-pdas
for s in pdas cgssor psor; do run strip-rest-$s $strip -s top.bc=free -s solver.state=$s && at_rest strip-rest-$s; done
for s in pdas cgssor; do run strip-down-$s $strip -s top.P2=-1e-3 -s solver.state=$s && no_contact strip-down-$s 1e-2; done
run strip-up-pdas $strip -s top.P2=1e-3 && no_contact strip-up-pdas 1e-2
opposite strip-down-pdas strip-up-pdas
[ -f $TMP/strip-down-cgssor/summary.dat ] && agrees strip-down-cgssor strip-down-pdas

# ---- strips of aspect 1:10 to 1:500 --------------------------------------
for r in 10 50 100 200 500; do
  thin $r gap; thin $r rest; sc=$TMP/thin-$r-gap.scene
  g=$(calc '10 / r' r=$r) p0=$(load $r 0.05) p1=$(load $r 1000)
  solvers="pdas cgssor"; [ $r -eq 10 ] && solvers="pdas cgssor psor"
  # at rest, above the foundation and on it
  for s in pdas cgssor psor; do
    for k in gap rest; do
      run thin$r-rest-$k-$s $TMP/thin-$r-$k.scene -s top.bc=free -s solver.state=$s && at_rest thin$r-rest-$k-$s
    done
  done
  # no contact: the load down, and up
  for s in $solvers; do
    run thin$r-down-$s $sc -s top.P2=$p0 -s solver.state=$s && no_contact thin$r-down-$s "$(calc '10 * p' p=$p0)"
  done
  run thin$r-up-pdas $sc -s top.P2=$(calc '-p' p=$p0) && no_contact thin$r-up-pdas "$(calc '10 * p' p=$p0)"
  opposite thin$r-down-pdas thin$r-up-pdas
  for s in $solvers; do [ $s = pdas ] || { [ -f $TMP/thin$r-down-$s/summary.dat ] && agrees thin$r-down-$s thin$r-down-pdas; }; done
  # contact: the gap closed
  for s in $solvers; do
    run thin$r-press-$s $sc -s top.P2=$p1 -s solver.state=$s && contact thin$r-press-$s $g $p1
  done
  for s in $solvers; do [ $s = pdas ] || { [ -f $TMP/thin$r-press-$s/summary.dat ] && agrees thin$r-press-$s thin$r-press-pdas; }; done
  # part lifted: resting on the foundation under its weight (steel,
  # 7.85e4 N/m^3), the right half pulled up by twice its weight: the
  # left half pressed, the right half lifted by the same net load
  up=$(calc '2 * 7.85e4 * g' g=$g)
  lift="-s top.from=5 -s top.P2=$up -s body_force.F2=-7.85e4"
  for s in $solvers; do
    run thin$r-lift-$s $TMP/thin-$r-rest.scene $lift -s solver.state=$s || continue
    solved thin$r-lift-$s || continue
    a=$(value active_contact_nodes $TMP/thin$r-lift-$s) n=$(value contact_nodes $TMP/thin$r-lift-$s)
    check "thin$r-lift-$s: part lifted: $a of $n nodes in contact" holds 'a > 0 && a < n' a="$a" n="$n"
    signorini thin$r-lift-$s
    [ $s = pdas ] && { WTOL=1e-6; energy_is_work thin$r-lift-$s $g 5 10 0 $up 0 -7.85e4; WTOL=; }
    [ $s = pdas ] || agrees thin$r-lift-$s thin$r-lift-pdas
  done
done

# ---- optimisations of the strips (paper/newton.nw, "A soft face") -------
# strip R: $TMP/strip-R.scene, tests/scenes/strip.scene at aspect 1:R:
# gamma = 10/R, the design box and the moving rows scaled with it (C0 =
# gamma/10, C0prime = gamma/5, the slope bound C1 = 2 C0 per metre, the
# area under alpha half of C0 (b - a)), N = 200, M + R = 1 + 2 rows, and
# the load that bends it as much against C0 as 1 kPa bends the 1:200
# strip (beam theory: the deflection goes as P / gamma^3), 1e3 (200/R)^4
# Pa.  R = 200 is tests/scenes/strip.scene itself.
strip() { awk -v r=$1 'BEGIN { b = 10; g = b / r; C0 = g / 10
  printf "[geometry]\na = 0\nb = %.17g\ngamma = %.17g\n", b, g
  printf "[design]\nN = 200\nC0 = %.17g\nC1 = %.17g\nC2 = %.17g\n", C0, 2 * C0, g * b - C0 * b / 2
  printf "initial = line\nline_start = 0\nline_end = %.17g\n", C0
  printf "[mesh]\nM = 1\nR = 2\nC0prime = %.17g\n", g / 5
  printf "[material]\nE = 2e11\nnu = 0.3\n[left]\nbc = clamped\n[right]\nbc = clamped\n"
  printf "[top]\nbc = traction\nfrom = 0\nto = 10\nP2 = %.17g\n", -1e3 * (200 / r) ^ 4 }' > $TMP/strip-$1.scene; }
# optimize NAME SCENE ARGS...: $BIN optimize SCENE into $TMP/NAME (its
# final files too); its exit status in _rc, its message in $TMP/NAME.err
optimize() { _n=$1 _sc=$2; shift 2; rm -rf $TMP/$_n
  $BIN optimize $_sc -o $TMP/$_n --plot-files "$@" >/dev/null 2>$TMP/$_n.err; _rc=$?; }
# converged NAME: exit 0, stop_reason converged, pi <= optimizer.tol
converged() { _s=$(value stop_reason $TMP/$1) _p=$(value projected_gradient $TMP/$1)
  check "$1: converged (exit $_rc, $_s, pi = $_p after $(value iterations $TMP/$1) iterations, E* = $(value energy $TMP/$1) J/m$([ $_rc -eq 0 ] || echo ": $(grep -v warning $TMP/$1.err | head -1 | cut -c1-300)"))" \
    holds 'rc == 0 && c == 1 && p <= 1e-6' rc="$_rc" c="$([ "$_s" = converged ] && echo 1 || echo 0)" p="$_p"; }
# no_lower NAME SCENE: SLSQP started from the final shape of the run NAME
# ends at no lower energy than NAME's, to 1e-12 of it: the start is that
# shape to the 15 digits of shape.dat, whose change of E is of the order
# of its rounding, 1e-15 |E| (a lower minimum near it, which SLSQP's
# own steps would find, lies below by more)
no_lower() { optimize $1-slsqp $2 -s optimizer.method=slsqp -s design.initial=file \
    -s design.file=$TMP/$1/final/shape.dat
  _a=$(value energy $TMP/$1) _b=$(value energy $TMP/$1-slsqp)
  check "$1: SLSQP from its optimum ends at no lower energy: E = $_b ($(value stop_reason $TMP/$1-slsqp) after $(value iterations $TMP/$1-slsqp) iterations) >= E* - 1e-12 |E*| (rel. $(rel "$_b" "$_a"))" \
    holds 'b >= a - 1e-12 * abs(a)' a="$_a" b="$_b"; }

# slsqp NAME SCENE: SLSQP from the scene's start, at its default limit,
# ends max_iter above the Newton method's E* of the run NAME (the metric
# of the contact stiffness fits a thin body's pressed nodes, not the ones
# that float: paper/opt.nw, "SLSQP on a thin strip"); its E must not be
# lower than E* (to 1e-12 of it, the comparison of no_lower)
slsqp() { optimize $1-slsqp0 $2 -s optimizer.method=slsqp
  _a=$(value energy $TMP/$1) _b=$(value energy $TMP/$1-slsqp0) _s=$(value stop_reason $TMP/$1-slsqp0)
  check "$1: SLSQP from the start: $_s after $(value iterations $TMP/$1-slsqp0) iterations, pi = $(value projected_gradient $TMP/$1-slsqp0), E = $_b, above E* by $(rel "$_b" "$_a") of it" \
    holds 's == 1 && b >= a - 1e-12 * abs(a)' s="$([ "$_s" = max_iter ] && echo 1 || echo 0)" a="$_a" b="$_b"; }

# 1:50, 1:100, 1:200 (tests/scenes/strip.scene itself): converged
optimize strip-newton $strip && converged strip-newton
[ -f $TMP/strip-newton/final/shape.dat ] && no_lower strip-newton $strip
[ -f $TMP/strip-newton/summary.dat ] && slsqp strip-newton $strip
for r in 50 100; do
  strip $r
  optimize strip$r-newton $TMP/strip-$r.scene && converged strip$r-newton
  [ -f $TMP/strip$r-newton/final/shape.dat ] && no_lower strip$r-newton $TMP/strip-$r.scene
done
for r in 50 100; do [ -f $TMP/strip$r-newton/summary.dat ] && slsqp strip$r-newton $TMP/strip-$r.scene; done
# 1:500: the run ends without progress, and says why: three iterates in a
# row changed E by no more than its rounding and did not halve pi, which
# stays below 1e-2 (from states whose contact forces are those of their
# own active set: 6.7e-2 before, paper/pdas.nw); what is left of pi is
# the gradient at three pressed nodes next to the ends of the contact
# zone, where the stiffness under a node makes the decrease it offers
# some 1e-20 J/m, below the rounding of E (paper/newton.nw, "A soft
# face"); no model problem fails on the way, and SLSQP from its end finds
# no lower energy
strip 500
optimize strip500-newton $TMP/strip-500.scene
_p=$(value projected_gradient $TMP/strip500-newton)
_ok=$([ -f $TMP/strip500-newton/summary.dat ] && ! grep -q 'model problem failed' $TMP/strip500-newton.err \
  && grep -q 'none by more than the rounding of E' $TMP/strip500-newton.err && echo 1 || echo 0)
check "strip500-newton: no_progress at the rounding of E, pi <= 1e-2, no model problem failed ($(value stop_reason $TMP/strip500-newton) after $(value iterations $TMP/strip500-newton) iterations, pi = $_p: $(grep -o '(.*' $TMP/strip500-newton.err | head -1 | cut -c1-200))" \
  holds 'ok == 1 && p <= 1e-2' ok="$_ok" p="${_p:-1}"
[ -f $TMP/strip500-newton/final/shape.dat ] && no_lower strip500-newton $TMP/strip-500.scene
[ -f $TMP/strip500-newton/summary.dat ] && slsqp strip500-newton $TMP/strip-500.scene

# ---- the optimisations under other BLAS kernels (OpenBLAS only) ----------
# The Newton method on the strips of 1:50, 1:200 and 1:500 again under the
# Prescott and the Sandybridge kernels, one thread: each run ends as the
# one under the default kernels did (converged, converged, no_progress),
# at its E to 1e-12 of it (the comparison of no_lower) and at its shape to
# 1e-4 C0 (the comparison of converged runs in paper/opt.nw, "How it is
# checked"); the paths differ, since the last bits of every state do.
# kernel NAME SCENE K: the run NAME again under the kernels K, as NAME-K
kernel() { _k=$3; env -u LD_PRELOAD OPENBLAS_CORETYPE=$_k OPENBLAS_NUM_THREADS=1 \
    $BIN optimize $2 -o $TMP/$1-$_k --plot-files >/dev/null 2>$TMP/$1-$_k.err
  [ -f $TMP/$1-$_k/summary.dat ] || { fail "$1-$_k: no summary.dat ($(head -c 200 $TMP/$1-$_k.err))"; return; }
  _s=$(value stop_reason $TMP/$1) _t=$(value stop_reason $TMP/$1-$_k)
  _a=$(value energy $TMP/$1) _b=$(value energy $TMP/$1-$_k) _c=$(awk '$1 == "C0" { print $3 }' $TMP/$1/effective.scene)
  _d=$(paste $TMP/$1/final/shape.dat $TMP/$1-$_k/final/shape.dat | rows_max 'abs($2 - $4)' -)
  check "$1 under $_k: $_t (as $_s) after $(value iterations $TMP/$1-$_k) iterations (against $(value iterations $TMP/$1)), E = $_b (rel. $(rel "$_b" "$_a") <= 1e-12), shape to $(show %.1e "$(calc 'd / c' d="$_d" c="$_c")") C0 <= 1e-4" \
    holds 'same == 1 && abs(b - a) <= 1e-12 * abs(a) && d <= 1e-4 * c' \
    same="$([ "$_s" = "$_t" ] && echo 1 || echo 0)" a="$_a" b="$_b" d="$_d" c="$_c"; }
# gradient NAME SCENE K: dE/dX at the final shape of the run NAME under the
# kernels K, in $TMP/NAME-grad-K (a run that converges at its start,
# optimizer.tol = 0.99: one state solve, the gradient in multipliers.dat)
gradient() { env -u LD_PRELOAD OPENBLAS_CORETYPE=$3 OPENBLAS_NUM_THREADS=1 $BIN optimize $2 \
    -o $TMP/$1-grad-$3 -s optimizer.tol=0.99 -s design.initial=file \
    -s design.file=$TMP/$1/final/shape.dat >/dev/null 2>&1; }
# spread NAME SCENE: max_i |dE/dX_i(Prescott) - dE/dX_i(Sandybridge)| at
# the final shape of NAME over |grad E(X0)|_inf at the scene's start: the
# rounding of the gradient (a lower bound of it) in the units of pi, which
# weighs the gradient with the step tau = C0 / |grad E(X0)|_inf
spread() { gradient $1 $2 Prescott; gradient $1 $2 Sandybridge
  $BIN optimize $2 -o $TMP/$1-grad0 -s optimizer.tol=0.99 >/dev/null 2>&1
  _g=$(rows_max 'abs($4)' $TMP/$1-grad0/multipliers.dat)
  _d=$(paste $TMP/$1-grad-Prescott/multipliers.dat $TMP/$1-grad-Sandybridge/multipliers.dat | rows_max 'abs($4 - $12)' -)
  calc 'd / g' d="$_d" g="$_g"; }
case $(value blas $TMP/strip-newton) in
  OpenBLAS-*)
  strip 50
  for k in Prescott Sandybridge; do
    [ -f $TMP/strip50-newton/summary.dat ] && kernel strip50-newton $TMP/strip-50.scene $k
    [ -f $TMP/strip-newton/summary.dat ] && kernel strip-newton $strip $k
    [ -f $TMP/strip500-newton/summary.dat ] && kernel strip500-newton $TMP/strip-500.scene $k
  done
  # Why the 1:500 strip does not converge: at the end of its run the
  # gradient's rounding in pi's units is above ten times optimizer.tol and
  # at least a fortieth of the pi it ended at (the kernels give the
  # gradient at the same design two values whose difference is of the
  # order of pi there: a tenth to a third of it under the default,
  # Prescott and Sandybridge kernels), so that no step can take pi to
  # tol; on the 1:200 strip the
  # same measure lies below a hundredth of tol, and the run converges
  # (paper/newton.nw, "The end on the 1:500 strip")
  if [ -f $TMP/strip500-newton/final/shape.dat ] && [ -f $TMP/strip-newton/final/shape.dat ]; then
    s5=$(spread strip500-newton $TMP/strip-500.scene) p5=$(value projected_gradient $TMP/strip500-newton)
    s2=$(spread strip-newton $strip)
    check "strip500-newton: the gradient's rounding at its end, $(show %.1e "$s5") in pi's units, is above 10 tol = 1e-5 and at least a fortieth of its final pi = $p5" \
      holds 's >= 1e-5 && s >= 0.025 * p' s="$s5" p="$p5"
    check "strip-newton: the gradient's rounding at its end, $(show %.1e "$s2") in pi's units, is below tol / 100 = 1e-8" \
      holds 's <= 1e-8' s="$s2"
  fi
  ;;
esac
finish
