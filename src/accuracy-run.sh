#!/bin/sh
# accuracy-run.sh PROGRAM SCENE POINT DIR: one point of the accuracy sweep,
# PROGRAM optimize SCENE with the settings that POINT names,
# N<N>_<state>_<solver.tol>_<method>[-<metric>]_<optimizer.tol>, into DIR;
# its log to DIR.log, the wall time of the run to DIR/wall.dat (added to
# the run's folder once it is in place).  Exit 1 if the run fails,
# unless it stopped at its iteration limit.
# Tangled from paper/accuracy.nw; do not edit.
prog=$1 scene=$2 point=$3 dir=$4
case $point in
  N[0-9]*_*_*_*_*) ;;
  *) echo "accuracy-run.sh: $point: not N<N>_<state>_<tol>_<method>_<tol>" >&2; exit 2 ;;
esac
set -- $(echo "$point" | tr _ ' ')
n=${1#N} state=$2 tol=$3 method=$4 otol=$5
case $n in
  *[!0-9]*) n=0 ;;
esac
if [ $((n % 16)) -ne 0 ] || [ $n -eq 0 ]; then
  echo "accuracy-run.sh: $point: N must be a positive multiple of 16" >&2; exit 2
fi
metric=
case $method in
  *-*) metric="-s optimizer.metric=${method#*-}"; method=${method%%-*} ;;
esac
rm -rf "$dir" "$dir.log" && mkdir -p "$(dirname "$dir")" || exit 1
t0=$(date +%s.%N)
"$prog" optimize "$scene" -o "$dir" -s mesh.refine=$((n / 16)) \
  -s solver.state=$state -s solver.tol=$tol \
  -s optimizer.method=$method $metric -s optimizer.tol=$otol \
  > "$dir.log" 2>&1
rc=$?
t1=$(date +%s.%N)
wall=$(awk -v a=$t0 -v b=$t1 'BEGIN { printf "%.3f", b - a }')
mkdir -p "$dir" && printf '# name value\nwall_seconds %s\n' $wall > "$dir/wall.dat"
stop=$(awk '$1 == "stop_reason" { print $2 }' "$dir/summary.dat" 2>/dev/null)
case $rc:$stop in
  0:*|3:max_iter|3:no_progress) ;;
  *) echo "accuracy: $point FAILED (exit $rc); the end of $dir.log:" >&2
     tail -n 5 "$dir.log" >&2
     rm -f "$dir/summary.dat"
     exit 1 ;;
esac
echo "accuracy: $point: $stop in $wall s"
