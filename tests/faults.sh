#!/bin/sh
# faults.sh: every allocation and every write may fail (issue 19).
# The shim tests/faults/inject.c (make builds it, build/faults/inject.so),
# preloaded, makes the k-th allocation (FAULT_ALLOC=k) or the k-th write
# to a file the program creates (FAULT_WRITE=k: fopen, fprintf, fputs,
# fputc, fwrite, fflush, fclose, mkdir, rename) of a run fail, counting
# from main on.  For every k of each leg, the run into a folder that holds
# a previous run must end
#   - allocation: exit 5 with one line on stderr, the folder byte for byte
#     as it was, nothing beside it (no staging folder, no old run); or
#     exit 0, no line and the same files as an unfaulted run (times
#     aside), where the C library absorbs the failure (a stream's buffer:
#     it writes unbuffered) or the failure is that of a clean-up the run
#     may skip (the staging folders of dead runs);
#   - write: exit 4 with one line, the folder as it was, nothing beside it.
# A crash, a signal, a sanitizer's report (make SAN=1: the leaks of every
# run, by LeakSanitizer) or any other exit fails the leg.  Each leg prints
# the operations it made fail and their distinct call sites.
#
# A run that a failed write of the matrix file (--matrix-market, written
# after the commit) ends may leave the new run's complete folder instead.
#
# make check runs the legs of a solve (FAULTS=quick); make faults runs
# every leg (FAULTS=all): the solve, the Newton method's and SLSQP's
# optimisations of Example 5.1 at N = 4, and the solve with
# --matrix-market (FAULTS="newton slsqp" runs those legs only).
# FAULTS_VALGRIND=n also runs every n-th k under Memcheck (leaks and
# invalid accesses), which must end as the run did or with exit 0
# (Memcheck's allocator takes the place of the C library's, so the k-th
# allocation there is not always the same one).
cd "$(dirname "$0")/.." || exit 1
. tests/lib.sh
SHIM=${FAULT_SHIM:-build/faults/inject.so}
MODE=${FAULTS:-quick}
# one thread: the k-th operation is then the same one in every run
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0:detect_leaks=1
export FAULT_PROGRAM=$(basename "$BIN")
ex=data/example-5.1.scene
if [ ! -f "$SHIM" ]; then
  fail "faults: the shim $SHIM is missing (make $SHIM)"; finish; exit 1
fi
case $SHIM in /*) ;; *) SHIM=$(pwd)/$SHIM ;; esac
start=$(date +%s)


# shim KIND K CMD...: CMD with the shim, the K-th operation of KIND failing
# (K = 0: none), its report in $TMP/report
shim() { _kind=$1 _k=$2; shift 2; rm -f $TMP/report
  if [ "$_kind" = alloc ]; then set -- env FAULT_ALLOC=$_k "$@"; else set -- env FAULT_WRITE=$_k "$@"; fi
  FAULT_REPORT=$TMP/report LD_PRELOAD=$SHIM "$@"; }

# as_it_was D: the folder D/out is D/before byte for byte, nothing is beside
# it, and the matrix D/A.mtx (if any) is D/before.mtx; with a matrix, whose
# file is written after the commit, a complete new run in D/out is as good
as_it_was() {
  nothing_beside $1 || return 1
  [ ! -e $1/before.mtx ] || cmp -s $1/before.mtx $1/A.mtx || return 1
  diff -r $1/before $1/out > /dev/null 2>&1 && return 0
  [ -e $1/before.mtx ] && same_run $1/before $1/out; }
# nothing_beside D: no staging folder, old run or partial matrix in D
nothing_beside() {
  for _f in $1/out.* $1/A.mtx.*; do [ -e "$_f" ] && return 1; done; return 0; }
# lines F: the number of lines of F (the shell's read: no process per k)
lines() { _n=0; while IFS= read -r _l || [ -n "$_l" ]; do _n=$((_n + 1)); done < "$1"; echo $_n; }

# symbolic: the lines of stdin with the program's frames (NAME+0xOFFSET)
# named by addr2line, where binutils is installed
symbolic() { _p=$(basename "$BIN")
  while IFS= read -r _l; do
    for _a in $(echo "$_l" | grep -o "$_p+0x[0-9a-f]*" | sort -u); do
      _f=$(addr2line -f -e "$BIN" "${_a#*+}" 2>/dev/null | head -1)
      [ -n "$_f" ] && _l=$(echo "$_l" | sed "s|$_a|$_f|g")
    done
    echo "$_l"
  done; }

# restore D: D/out and D/A.mtx as before, nothing beside
restore() { rm -rf $1/out $1/out.* $1/A.mtx.*; cp -R $1/before $1/out
  [ ! -e $1/before.mtx ] || cp $1/before.mtx $1/A.mtx; }

# leg NAME KIND CODE ARGS...: every k of KIND in "$BIN ARGS -o DIR"; with
# matrix=1, also --matrix-market DIR/A.mtx
leg() { name=$1 kind=$2 code=$3; shift 3
  d=$TMP/$name-$kind; rm -rf $d; mkdir -p $d
  [ "$matrix" = 1 ] && set -- "$@" --matrix-market $d/A.mtx
  total=
  $BIN "$@" -o $d/out > /dev/null 2>&1 \
    && shim $kind 0 $BIN "$@" -o $d/out > /dev/null 2>&1 \
    && total=$(awk -v kind=$kind '{ print kind == "alloc" ? $2 : $4 }' $TMP/report) \
    && cp -R $d/out $d/before && { [ "$matrix" != 1 ] || cp $d/A.mtx $d/before.mtx; }
  if [ -z "$total" ] || [ "$total" -lt 1 ]; then
    fail "$name: the run without faults, or its count of operations, failed"; return
  fi
  : > $d/sites; : > $d/bad; refused=0 absorbed=0 k=1
  while [ $k -le "$total" ]; do
    shim $kind $k $BIN "$@" -o $d/out > /dev/null 2> $d/err; rc=$?
    site=; read -r _ _ _ _ _ site < $TMP/report
    lines=$(lines $d/err)
    if [ $rc -eq $code ] && [ "$lines" -eq 1 ] && as_it_was $d; then
      refused=$((refused + 1))
    elif [ $rc -eq 0 ] && [ "$lines" -eq 0 ] && nothing_beside $d \
         && same_run $d/before $d/out; then
      absorbed=$((absorbed + 1)); echo "$site" >> $d/absorbed
    else
      printf '%s\t%s\t%s\t%s\t%s%s\n' $k $rc "$lines" "$site" "$(head -c 200 $d/err | tr '\n' ' ' | sed "s|$d/||g; s|partial-[0-9]*|partial-PID|g")" \
        "$(ls -d $d/out.* 2>/dev/null | sed 's|.*/| left: |' | tr '\n' ' ')" >> $d/bad
    fi
    [ -n "$site" ] && echo "$site" >> $d/sites
    if [ $rc -ne $code ] || [ "$matrix" = 1 ]; then restore $d; fi
    if [ -n "$FAULTS_VALGRIND" ] && [ $((k % FAULTS_VALGRIND)) -eq 0 ]; then
      shim $kind $k valgrind -q --soname-synonyms=somalloc=nouserintercepts \
        --leak-check=full --errors-for-leak-kinds=definite \
        --error-exitcode=99 --suppressions=tests/valgrind.supp $BIN "$@" -o $d/out > /dev/null 2> $d/vg
      vrc=$?
      [ $vrc -eq $code ] || [ $vrc -eq 0 ] \
        || printf '%s\t%s\t-\t-\tunder valgrind: %s\n' $k $vrc "$(grep -m1 '==' $d/vg)" >> $d/bad
      restore $d
    fi
    k=$((k + 1))
  done
  sites=$(sort -u $d/sites | wc -l)
  echo "$name $kind $total $sites" >> $TMP/counts
  cat $d/sites >> $TMP/sites.$kind
  what="exit $code, one line, the folder as it was"
  # an allocation with a fallback, or a write that is retried (the move
  # back of the folder that output_check moved aside to prove it movable)
  what="$what; or exit 0 with the same files where the failure is absorbed ($absorbed)"
  check "$name: every $kind fails once, k = 1..$total at $sites distinct sites: $what ($refused)" test ! -s $d/bad
  # the failures, one line per kind: exit status, lines, message
  awk -F'\t' '{ key = "exit " $2 ", " $3 " lines: " $5
    if (!(key in n)) { order[++m] = key; first[key] = $1; site[key] = $4 }
    n[key]++; last[key] = $1 }
    END { for (i = 1; i <= m && i <= 8; i++) { k = order[i]
      printf "# %d runs, k = %d..%d (first at %s): %s\n", n[k], first[k], last[k], site[k], k } }' $d/bad | symbolic
}

case $MODE in quick) legs=solve ;; all) legs="solve newton slsqp matrix" ;; *) legs=$MODE ;; esac
solve="solve $ex -s design.N=4"
for l in $legs; do
  case $l in
    solve) leg solve alloc 5 $solve; leg solve write 4 $solve ;;
    newton) leg newton alloc 5 optimize $ex -s design.N=4
            leg newton write 4 optimize $ex -s design.N=4 ;;
    slsqp) leg slsqp alloc 5 optimize $ex -s design.N=4 -s optimizer.method=slsqp
           leg slsqp write 4 optimize $ex -s design.N=4 -s optimizer.method=slsqp ;;
    matrix) matrix=1; leg matrix alloc 5 $solve; leg matrix write 4 $solve; matrix= ;;
    *) fail "faults: no leg $l (solve, newton, slsqp, matrix)" ;;
  esac
done
touch $TMP/counts $TMP/sites.alloc $TMP/sites.write
awk -v t=$(( $(date +%s) - start )) -v sa=$(sort -u $TMP/sites.alloc | wc -l) \
    -v sw=$(sort -u $TMP/sites.write | wc -l) '{ n[$2] += $3 }
  END { printf "# faults: %d allocations (%d distinct sites) and %d writes (%d sites) made to fail, %d s\n",
        n["alloc"], sa, n["write"], sw, t }' $TMP/counts
finish
