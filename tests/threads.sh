# threads.sh: the threads of the BLAS and of CHOLMOD (paper/threads.nw).
# A memory limit never makes the program hang nor end with another status
# than 0 or 5 and its own line; summary.dat names the BLAS, its kernels
# and the thread counts; the results do not depend on the thread count.
. tests/lib.sh
ex=data/example-5.1.scene

# ---- memory limits -----------------------------------------------------------
# ulimit -v of 100 to 400 MB, the BLAS's threads asked for by the user (1,
# 2, 16) or left to the program (-), N = 16 and N = 1024.  timeout turns a
# hang into exit 124; every run must end in 60 s with exit 0 (the program's
# notes only on stderr) or 5 (one line of its own).
ends_cleanly() { _rc=$1 _err=$2
  [ "$_rc" -eq 0 ] && ! grep -q -v '^contactopt: ' "$_err" && return 0
  [ "$_rc" -eq 5 ] && [ "$(wc -l < "$_err")" -eq 1 ] && grep -q '^contactopt: ' "$_err"; }
limited() { _mb=$1 _t=$2; shift 2
  ( ulimit -v $((_mb * 1000))
    if [ "$_t" = - ]; then unset OPENBLAS_NUM_THREADS; else export OPENBLAS_NUM_THREADS=$_t; fi
    exec timeout 60 $BIN "$@" ) > /dev/null 2> $TMP/err; }
case $BIN in
  */san/*) echo "# skipped under AddressSanitizer: the ulimit -v runs (its shadow memory cannot be reserved under an address-space limit)" ;;
  *)
  for N in 16 1024; do
    refine=$((N / 16))
    for t in 1 2 16 -; do
      for mb in 100 150 250 400; do
        limited $mb $t solve $ex -o $TMP/lim -s mesh.refine=$refine; rc=$?
        check "N = $N, ulimit -v $mb MB, OPENBLAS_NUM_THREADS=$t: exit $rc, $(head -c 160 $TMP/err | tr '\n' ' ')" \
          ends_cleanly $rc $TMP/err
      done
    done
  done
  # what fits runs: one BLAS thread at 250 MB, two at 400 (16 asked: lowered, said once)
  limited 250 1 solve $ex -o $TMP/fit1; rc=$?
  check "N = 16 at 250 MB with one BLAS thread runs (exit $rc)" test $rc -eq 0
  limited 400 16 solve $ex -o $TMP/fit16; rc=$?
  check "N = 16 at 400 MB with 16 asked: exit 0, 2 threads recorded, chosen by the memory, one note" \
    holds 'rc == 0 && t == 2 && notes == 1' rc=$rc t="$(value blas_threads $TMP/fit16)" \
      notes="$(grep -c 'OPENBLAS_NUM_THREADS=16: 2 BLAS threads fit' $TMP/err)"
  check "... threads_chosen_by memory" test "$(value threads_chosen_by $TMP/fit16)" = memory
  # a limit under which OpenBLAS could not even create its worker as it
  # loads (it raised SIGINT: exit 130): the program starts it alone
  limited 60 2 solve $ex -o $TMP/tiny; rc=$?
  check "ulimit -v 60 MB, 2 threads asked: exit 5 with the program's line, never 130 ($(cat $TMP/err))" \
    clean_failure $rc 5 $TMP/err $TMP/tiny 'the BLAS .* reserves'
  ;;
esac

finish
