# reproducible.sh: the runs behind the figures give the same bytes twice.
# The runs of the Makefile's out/... rules (solve, optimize, optimize in
# plane strain of the three shipped scenes, and Example 5.1 optimised with
# the C2 of its arc) are made twice, into two fresh folders, and every data
# file of the first is compared with its twin by cmp.  Wall-clock times
# differ by nature and are stripped first: the lines "seconds",
# "metric_seconds", "state_seconds", "model_seconds", "monitor_seconds",
# "subproblem_seconds" and "starts_seconds" of
# summary.dat and the column "seconds" of history.dat (found by the name in
# the header of any .dat file).  So are the lines of summary.dat that say
# how the run computed, which differ between the two sets by design: the
# threads (blas_threads, blas_threads_by_size, threads_chosen_by,
# openmp_threads) and the machine's load.  The second set runs with OpenMP and
# OpenBLAS on one thread, the first with their defaults (one thread per
# core), so a result that depended on how threads split a sum would show
# here.  The printed logs are not compared (they hold times and the output
# folder).
. tests/lib.sh
# runs DIR: the commands of the Makefile's rules for out/..., into DIR
runs() {
  d=$1
  for e in 5.1 5.2 5.2-flat; do
    $BIN solve data/example-$e.scene -o $d/example-$e --plot-files > /dev/null \
      && $BIN optimize data/example-$e.scene -o $d/example-$e-optimize --plot-files > /dev/null \
      && $BIN optimize data/example-$e.scene -o $d/example-$e-strain-optimize \
           -s material.model=plane_strain > /dev/null || return 1
  done
  c2=$(sh src/c2-of-shape.sh 1 $d/example-5.1/shape.dat) \
    && $BIN optimize data/example-5.1.scene -o $d/example-5.1-C2arc-optimize \
         -s design.C2=$c2 > /dev/null
}
runs $TMP/a; rc_a=$?
OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 runs $TMP/b; rc_b=$?
check "the figure runs succeed twice (default threads, then one thread)" \
  [ $rc_a -eq 0 -a $rc_b -eq 0 ]
n=0; same=0; differ=""
for f in $(cd $TMP/a && find . -type f | sort); do
  n=$((n + 1))
  if [ ! -f $TMP/b/$f ]; then differ="$differ $f(missing)"; continue; fi
  case $f in
    *.dat) strip_times $TMP/a/$f > $TMP/x; strip_times $TMP/b/$f > $TMP/y ;;
    *) cp $TMP/a/$f $TMP/x; cp $TMP/b/$f $TMP/y ;;
  esac
  if cmp -s $TMP/x $TMP/y; then same=$((same + 1)); else differ="$differ $f"; fi
done
check "the runs write the same files (found $n)" \
  [ $n -gt 0 -a "$(cd $TMP/a && find . -type f | sort)" = "$(cd $TMP/b && find . -type f | sort)" ]
check "all $n files are bitwise identical, times stripped (differ:${differ:- none})" \
  [ $n -gt 0 -a $same -eq $n ]
check "stripping removes only times and threads: summary.dat loses its seconds line and its 5 of threads and load, history.dat keeps 4 columns" \
  [ $(strip_times $TMP/a/example-5.1/summary.dat | wc -l) -eq $(($(wc -l < $TMP/a/example-5.1/summary.dat) - 6)) \
    -a "$(strip_times $TMP/a/example-5.1-optimize/history.dat | awk '!/^#/ { print NF; exit }')" = 4 ]
finish
