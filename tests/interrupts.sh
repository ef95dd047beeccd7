#!/bin/sh
# interrupts.sh: SIGINT at twenty random moments of an optimisation and of a
# solve (issue 19), and twice at twenty moments of an optimisation, the
# second soon after the first (issue 20).  Each run must end with exit 130,
# or 0 if it had finished; leave the output folder complete (a new run's,
# every file of it) or as it was (absent, or the previous run's byte for
# byte), never half written; and leave nothing beside it (no staging folder
# DIR.partial-PID, no old run DIR.old-PID).  Its standard error holds at
# most the line the first signal writes at once and, last, the line of a
# run stopped at an iterate.  Odd runs write into a new
# folder, even ones into a folder that holds a previous run.  The moments
# are drawn uniformly from [0, 1.1 T], T the time of an uninterrupted run
# measured first, by awk's generator from INTERRUPT_SEED (default 19):
# the seed is printed, and the same seed draws the same moments.  A solve
# stages its folder only when its computation is done, so every other
# moment of the solve is drawn from [0, 1.1 W] after its staging folder
# appears, W the time it existed in the uninterrupted run: the moments
# where the program, not the default action, must handle the signal.
#
# The program runs as from a terminal, with SIGINT's default action: a
# command a script starts in the background ignores SIGINT (POSIX), so
# env --default-signal gives it back.  The shell reports a run killed by
# the signal as exit 130 too, without a line; the signals are caught while
# a staging folder exists, so such a run was killed before it staged its
# folder (which is as it was) or after the commit (the new run's folder
# complete), which the folder checks confirm. With two signals, the first
# may come after the last iterate and the second after the commit: the
# first's line, then the default action, and the new run's folder
# complete.
cd "$(dirname "$0")/.." || exit 1
. tests/lib.sh
SEED=${INTERRUPT_SEED:-19}
RUNS=${INTERRUPT_RUNS:-20}
ex=data/example-5.1.scene
echo "# interrupts: seed $SEED (INTERRUPT_SEED=$SEED reproduces the moments)"
dflt=
env --default-signal=INT true 2>/dev/null && dflt="env --default-signal=INT"
[ -n "$dflt" ] || echo "# env --default-signal is missing: SIGINT stays ignored outside the program's window"

now() { date +%s.%N; }
# stopped D REF: D is a complete optimisation stopped at an accepted
# iterate: the start as REF's, every file of REF's list but the iterates,
# a row of history.dat per iteration from 0, as many data sets in
# iterates.pvd and files in iterates/,
# and the final design the last block of iterates.dat
stopped() {
  [ -s $1/summary.dat ] && [ "$(value stop_reason $1)" = interrupted ] || return 1
  same_run $2/initial $1/initial || return 1
  for f in $( cd $2 && find . -type f ! -path './iterates/*' ); do [ -s $1/$f ] || return 1; done
  rows=$(grep -vc '^#' $1/history.dat); sets=$(grep -c '<DataSet' $1/iterates.pvd)
  vtus=$(ls $1/iterates | wc -l)
  [ "$rows" -eq $(( $(value iterations $1) + 1 )) ] && [ "$rows" -eq "$sets" ] && [ "$rows" -eq "$vtus" ] || return 1
  # shape.dat has 15 digits, iterates.dat 17: equal to 1e-14 of C0
  awk 'FNR == NR && NF == 4 { x[$2] = $4; next } FNR == NR { next }
       FNR > 1 { d = $2 - x[FNR - 2]; if (d < 0) d = -d; if (d > 5e-16 || !((FNR - 2) in x)) bad = 1; n++ }
       END { exit bad || n != length(x) }' $1/iterates.dat $1/final/shape.dat; }

# untouched PREV D: D is absent (PREV empty: it was new) or PREV byte for byte
untouched() { if [ -z "$1" ]; then [ ! -e "$2" ]; else diff -r "$1" "$2" > /dev/null 2>&1; fi; }

# staged DIR: a staging folder of DIR exists
staged() { for _f in $1.partial-*; do [ -e "$_f" ] && return 0; done; return 1; }
# start DIR ARGS...: "$BIN ARGS -o DIR" in the background as from a terminal, its pid in $pid
start() { _o=$1; shift; $dflt $BIN "$@" -o $_o > $d/out 2> $d/err & pid=$!; }
# until_staged DIR: wait (polling) until DIR is staged or the run $pid has ended
until_staged() { while ! staged $1 && kill -0 $pid 2>/dev/null; do sleep 0.005; done; }

# said FILE: FILE (a run's standard error) holds nothing but, at most once
# each and in this order, the line of the first signal and the line of a run
# stopped at an iterate; says=N: it has N lines
said() { awk 'NR == 1 && /^contactopt: .*: interrupted: .*; interrupt again to stop at once without them$/ { next }
  /^contactopt: .*: interrupted by signal [0-9]+ at iteration [0-9]+: the files of the best design so far are in / && !last++ { next }
  { bad = 1 } END { exit bad }' "$1"; }
# the line of the first signal, and that of a stopped run, in FILE
first_line() { grep -c 'interrupted: .*interrupt again to stop at once' "$1"; }
final_line() { grep -c 'interrupted by signal' "$1"; }

# leg NAME ARGS...: RUNS runs of "$BIN ARGS", each interrupted at a moment
# from its start; with window=1, every other moment is counted from the
# moment the staging folder appears instead, drawn from the time it exists;
# with twice=1, a second SIGINT follows the first after a moment drawn
# from [0, 0.2] s
leg() { name=$1; shift
  d=$TMP/$name; mkdir -p $d
  t0=$(now); start $d/ref "$@"; until_staged $d/ref; ts=$(now); wait $pid; rc=$?; t1=$(now)
  if [ $rc -ne 0 ]; then fail "$name: the uninterrupted run failed (exit $rc)"; return; fi
  T=$(calc 't1 - t0' t0=$t0 t1=$t1) W=$(calc 't1 - ts' ts=$ts t1=$t1)
  awk -v seed=$SEED -v name=$name -v T=$T -v W=$W -v w=${window:-0} -v n=$RUNS 'BEGIN {
    srand(seed + length(name))
    for (i = 1; i <= n; i++) if (w && i % 2) printf "staged %.3f %.3f\n", 1.1 * W * rand(), 0.2 * rand()
                             else printf "start %.3f %.3f\n", 1.1 * T * rand(), 0.2 * rand() }' > $d/moments
  : > $d/bad; before=0 after=0 stopped=0 finished=0 killed=0 i=0
  while read -r from t t2; do
    i=$((i + 1)); out=$d/run$i; prev=
    if [ $((i % 2)) -eq 0 ]; then cp -R $d/ref $out; prev=$d/prev$i; cp -R $d/ref $prev; fi
    start $out "$@"
    [ $from = staged ] && until_staged $out
    sleep $t; kill -INT $pid 2>/dev/null
    [ "${twice:-0}" = 1 ] && { sleep $t2; kill -INT $pid 2>/dev/null; }
    wait $pid; rc=$?
    first=$(first_line $d/err) final=$(final_line $d/err)
    left=$(ls -d $out.* 2>/dev/null | wc -l)
    if ! said $d/err; then how=
    elif [ $rc -eq 0 ] && [ $final -eq 0 ] && same_run $d/ref $out; then how=finished
    elif [ $rc -eq 130 ] && [ $first -eq 1 ] && [ $final -eq 1 -o "${twice:-0}" = 1 ] && stopped $out $d/ref; then how=stopped
    elif [ $rc -eq 130 ] && [ $first -eq 0 ] && untouched "$prev" $out; then how=before
    elif [ $rc -eq 130 ] && [ $first -eq 0 -o "${twice:-0}" = 1 ] && same_run $d/ref $out; then how=after
    elif [ $rc -eq 130 ] && [ "${twice:-0}" = 1 ] && [ $final -eq 0 ] && untouched "$prev" $out; then how=killed
    else how=; fi
    if [ -z "$how" ] || [ $left -ne 0 ]; then
      echo "run $i at $t s from the $from: exit $rc, $(wc -l < $d/err) lines ($(head -c 150 $d/err | tr '\n' ' ')), $left beside the folder, folder $(ls $out 2>/dev/null | wc -l) entries" >> $d/bad
    else eval "$how=\$(($how + 1))"; fi
    rm -rf $out $out.* $prev
  done < $d/moments
  span="in [0, $(show %.2f $(calc '1.1 * T' T=$T))] s"
  [ "${window:-0}" = 1 ] && span="$span, every other in [0, $(show %.2f $(calc '1.1 * W' W=$W))] s after the staging folder appeared"
  again=; [ "${twice:-0}" = 1 ] && again=", again after [0, 0.2] s,"
  check "$name: SIGINT at $RUNS moments $span$again: exit 130 or 0, the folder complete or as it was, nothing beside it ($before killed before staging, $stopped stopped with their files, $finished finished, $after killed after the commit, $killed killed by the second with the folder as it was)" \
    test ! -s $d/bad
  head -5 $d/bad | sed 's/^/# /'
}

leg optimize optimize $ex -s mesh.refine=8
twice=1
leg twice optimize $ex -s mesh.refine=8
twice=0 window=1
leg solve solve $ex -s mesh.refine=16 --plot-files
finish
