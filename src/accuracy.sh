#!/bin/sh
# accuracy.sh OUT: the table of the accuracy sweep from the runs in OUT
# (written by make accuracy, listed in OUT/plan.dat), on standard output.
# Tangled from paper/accuracy.nw; do not edit.
out=${1:-out/accuracy}
acc_val() { awk -v k=$1 '$1 == k { print $2; exit }' $out/$2/summary.dat; }
acc_limit() { if [ -f $out/limit/N$1.dat ]; then
  awk '{ printf "%.6f", $3 + $4; exit }' $out/limit/N$1.dat; else echo NaN; fi; }
acc_seconds() { s=$(acc_val seconds $1)
  [ -n "$s" ] || s=$(awk '$1 == "wall_seconds" { print $2 }' $out/$1/wall.dat)
  echo $s; }
mesh=$(awk '$1 == "mesh" { $1 = ""; print }' $out/plan.dat)
finest=$(echo $mesh | awk '{ print $NF }')
levels=$(echo $mesh | awk '{ print $(NF-2), $(NF-1), $NF }')
set -- $(for p in $levels; do acc_val energy $p; done)
limit=$(awk -v a=$1 -v b=$2 -v c=$3 'BEGIN { r = (a - b) / (b - c)
  if (!(r > 1)) exit 1; p = log(r) / log(2)
  printf "%.15g %.4f\n", c + (c - b) / (2^p - 1), p }') || {
  echo "accuracy.sh: the energies $* of $levels do not converge" >&2; exit 1; }
set -- $limit
Einf=$1 p=$2
acc_shape_error() { awk 'FNR == 1 { f++ } /^#/ { next }
  f == 1 { x[n] = $1; a[n++] = $2; next }
  { while (i < n - 2 && x[i+1] < $1) i++
    d = $2 - a[i] - ($1 - x[i]) / (x[i+1] - x[i]) * (a[i+1] - a[i])
    if (d < 0) d = -d; if (d > m) m = d }
  END { printf "%.3e\n", m }' $out/$finest/final/shape.dat $out/$1/final/shape.dat; }
echo "# the accuracy sweep of Example 5.1 (make accuracy); one line per family and point"
echo "# nmax $(echo $finest | sed 's/^N\([0-9]*\)_.*/\1/')"
echo "# levels $levels"
echo "# E_inf $Einf"
echo "# p $p"
echo "# family point N state solver_tol method optimizer_tol energy[J/m] rel_error" \
     "same_mesh_error shape_error[m] state_solves seconds iterations stop_reason" \
     "limit_seconds"
grep -v '^#' $out/plan.dat | while read -r family points; do
  for pt in $points; do
    set -- $(echo "$pt" | tr _ ' ')
    n=$1 state=$2 tol=$3 method=$4 otol=$5
    E=$(acc_val energy $pt)
    Eref=$(for q in $mesh; do case $q in ${n}_*) acc_val energy $q;; esac; done)
    set -- $(awk -v E=$E -v r=$Eref -v i=$Einf 'function abs(x) { return x < 0 ? -x : x }
      BEGIN { printf "%.3e %.3e", abs(E - i) / abs(i), abs(E - r) / abs(i) }')
    echo $family $pt ${n#N} $state $tol $method $otol $E $1 $2 \
      $(acc_shape_error $pt) $(acc_val evaluations $pt) $(acc_seconds $pt) \
      $(acc_val iterations $pt) $(acc_val stop_reason $pt) $(acc_limit ${n#N})
  done
done
