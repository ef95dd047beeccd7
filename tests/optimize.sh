# optimize.sh: the shape optimisation (Section 4.4, Algorithm 4.1) from the
# starts of Examples 5.1, 5.2 and the flat variant, with both optimisers.
. tests/lib.sh
value() { awk -v k=$1 '$1 == k { print $2 }' $2/summary.dat; }
# near A B TOL: |A - B| <= TOL |A|
near() { awk -v a=$1 -v b=$2 -v t=$3 'BEGIN { d = (a - b) / a; exit !(d <= t && d >= -t) }'; }
# every iterate in B: 0 <= X <= C0, |X_{i+1} - X_i| <= C1 h, h sum trapezoids = S,
# each to 1e-12 (relative to C0, and to C0 (b - a) for the area)
in_B() { awk -v C0=0.05 -v d=0.025*0.25 -v S=0.09 -v L=4 -v h=0.25 '
  BEGIN { d = 0.025 * 0.25 }
  /^#/ { next }
  NF == 0 { if (n) done(); next }
  { if ($2 == 0) { n = 0; area = 0 } x[n++] = $4 }
  function done(  i, v) {
    for (i = 0; i < n; i++) {
      if (x[i] < -1e-12 * C0 || x[i] > C0 * (1 + 1e-12)) bad = 1
      if (i > 0 && (x[i] - x[i-1] > d + 1e-12 * C0 || x[i-1] - x[i] > d + 1e-12 * C0)) bad = 1
      if (i > 0) area += h * (x[i] + x[i-1]) / 2
    }
    v = (area - S) / (C0 * L); if (v < 0) v = -v; if (v > 1e-12) bad = 1
    n = 0 }
  END { if (n) done(); exit bad }' $1; }
for model in plane_stress plane_strain; do
for scene in data/example-5.1.scene data/example-5.2.scene data/example-5.2-flat.scene; do
  name=$(basename $scene .scene)-$model
  for method in slsqp projgrad; do
    out=$TMP/$name-$method
    if ! $BIN optimize $scene -o $out -s optimizer.method=$method -s material.model=$model \
         >$TMP/log 2>$TMP/err; then
      fail "$name $method: $(cat $TMP/err)"; continue
    fi
    check "$name $method: stops converged ($(value stop_reason $out), pg $(value projected_gradient $out))" \
      [ "$(value stop_reason $out)" = converged ]
    check "$name $method: every iterate lies in B to 1e-12" in_B $out/iterates.dat
    r=$(kkt $out/multipliers.dat 0.05 0.00625 0.25); rc=$?
    # the optimiser stops at pi <= optimizer.tol = 1e-6, pi measured with the
    # step of the start gradient, some 50 times smaller than the final one:
    # the stationarity relative to the final gradient is then about 1e-5
    check "$name $method: the final design is a KKT point (signs, complementarity; stationarity $r <= 1e-4)" \
      awk -v r=$r -v rc=$rc 'BEGIN { exit !(rc == 0 && r <= 1e-4) }' 
    check "$name $method: E decreases, $(value initial_energy $out) -> $(value energy $out)" \
      awk -v a=$(value initial_energy $out) -v b=$(value energy $out) 'BEGIN { exit !(b < a) }'
    check "$name $method: the contact pressure is more even at the optimum (cv $(value contact_pressure_cv_initial $out) -> $(value contact_pressure_cv_final $out))" \
      awk -v a=$(value contact_pressure_cv_initial $out) -v b=$(value contact_pressure_cv_final $out) 'BEGIN { exit !(b < a) }'
  done
  check "$name projgrad: E never increases along Algorithm 4.1" \
    awk '!/^#/ { if (n++ && $2 > prev) bad = 1; prev = $2 } END { exit bad }' $TMP/$name-projgrad/history.dat
  a=$TMP/$name-slsqp; b=$TMP/$name-projgrad
  [ -f $a/summary.dat ] && [ -f $b/summary.dat ] || continue
  check "$name: both optimisers reach the same E to 1e-6 ($(value energy $a), $(value energy $b))" \
    near $(value energy $a) $(value energy $b) 1e-6
  check "$name: both optimisers reach the same shape to 1e-4 C0" \
    numdiff -q -a 5e-6 -r 0 $a/final/shape.dat $b/final/shape.dat
  echo "# $name: E0 $(value initial_energy $a) -> slsqp $(value energy $a) ($(value iterations $a) it, $(value evaluations $a) solves), projgrad $(value energy $b) ($(value iterations $b) it, $(value evaluations $b) solves)"
done
done
# SLSQP in the metric of the contact stiffness (optimizer.metric = schur,
# the default) against the euclidean one, N = 16, 32, 64 (M = N/16,
# R = 3N/16): the same E* to 1e-9 and the same shape to 1e-4 C0; the
# iterations must not grow with N more than by half from N = 16 to 64 (they
# were 22, 24, 28), while the euclidean metric's grow about linearly (26,
# 46, 75), so that at N = 64 it needs more than twice the schur iterations.
for N in 16 32 64; do
  for metric in schur euclidean; do
    $BIN optimize data/example-5.1.scene -o $TMP/m$N-$metric -s design.N=$N -s mesh.M=$((N / 16)) \
      -s mesh.R=$((3 * N / 16)) -s optimizer.metric=$metric >/dev/null 2>$TMP/err \
      || fail "N = $N, metric $metric: $(cat $TMP/err)"
  done
  a=$TMP/m$N-schur; b=$TMP/m$N-euclidean
  check "N = $N: both metrics converge ($(value stop_reason $a), $(value stop_reason $b))" \
    [ "$(value stop_reason $a) $(value stop_reason $b)" = "converged converged" ]
  check "N = $N: both metrics reach the same E* to 1e-9 ($(value energy $a), $(value energy $b))" \
    near $(value energy $a) $(value energy $b) 1e-9
  check "N = $N: both metrics reach the same shape to 1e-4 C0" \
    numdiff -q -a 5e-6 -r 0 $a/final/shape.dat $b/final/shape.dat
  echo "# N = $N: schur $(value iterations $a) it / $(value evaluations $a) solves, euclidean $(value iterations $b) it / $(value evaluations $b) solves"
done
check "schur iterations grow by at most half from N = 16 to 64 ($(value iterations $TMP/m16-schur) -> $(value iterations $TMP/m64-schur))" \
  [ $((2 * $(value iterations $TMP/m64-schur))) -le $((3 * $(value iterations $TMP/m16-schur))) ]
check "at N = 64 the euclidean metric needs more than twice the schur iterations ($(value iterations $TMP/m64-euclidean) vs $(value iterations $TMP/m64-schur))" \
  [ $(value iterations $TMP/m64-euclidean) -gt $((2 * $(value iterations $TMP/m64-schur))) ]
# a state solve that fails inside the optimisation stops it: exit 3, a
# message naming the solver, nothing written
rm -rf $TMP/fail
$BIN optimize data/example-5.1.scene -o $TMP/fail -s solver.state=psor -s solver.max_iter=5 \
  >/dev/null 2>$TMP/err; rc=$?
check "a failed state solve stops the optimisation: exit $rc, $(cat $TMP/err)" \
  sh -c "[ $rc -eq 3 ] && grep -q psor $TMP/err && [ ! -e $TMP/fail ]"
finish
