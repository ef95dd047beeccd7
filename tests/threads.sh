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
    unset OPENBLAS_NUM_THREADS GOTO_NUM_THREADS OMP_NUM_THREADS
    [ "$_t" = - ] || export OPENBLAS_NUM_THREADS=$_t
    exec timeout 60 $BIN "$@" ) > /dev/null 2> $TMP/err; }
if limits_run; then
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
fi

# ---- what computed a run ---------------------------------------------------------
# summary.dat of each command names the BLAS, its file and kernels, and the
# thread counts; the kernels are those OPENBLAS_CORETYPE selects, the file
# Debian's alternative for libblas.so.3 where there is one, and a user's
# count is the one recorded (16 on two cores too: honoured, not capped)
keys='blas blas_library blas_kernels blas_kernels_advised blas_threads blas_threads_by_size threads_chosen_by openmp_threads cores physical_cores load_average'
has_keys() { for _k in $keys; do [ -n "$(value $_k "$1")" ] || return 1; done; }
unasked $BIN solve $ex -o $TMP/s > /dev/null 2> $TMP/err
unasked $BIN gradcheck $ex -o $TMP/g > /dev/null 2>> $TMP/err
unasked $BIN optimize $ex -o $TMP/o > /dev/null 2>> $TMP/err
for d in s g o; do
  check "summary.dat of $d names $keys" has_keys $TMP/$d
done
check "no line on stderr from a run that is not at a terminal ($(head -c 200 $TMP/err))" test ! -s $TMP/err
alt=/etc/alternatives/libblas.so.3-x86_64-linux-gnu
if [ -e $alt ]; then
  check "blas_library is the file Debian's alternatives choose ($(value blas_library $TMP/s))" \
    test "$(value blas_library $TMP/s)" = "$(readlink -f $alt)"
fi
case $(value blas $TMP/s) in
  OpenBLAS-*)
  # kernels the user chose (no shim of the environment's: see below)
  for k in Prescott Haswell; do
    env -u LD_PRELOAD OPENBLAS_CORETYPE=$k $BIN solve $ex -o $TMP/k$k > /dev/null 2> $TMP/err
    check "OPENBLAS_CORETYPE=$k: blas_kernels $k, no note on stderr" \
      test "$(value blas_kernels $TMP/k$k)" = $k -a ! -s $TMP/err
  done
  check "OPENBLAS_CORETYPE=Prescott, the user's choice: blas_kernels_advised none" \
    test "$(value blas_kernels_advised $TMP/kPrescott)" = none
  # a CPU that OpenBLAS does not know (the shim tests/kernels/unknown_cpu.c:
  # its Prescott kernels, chosen by OpenBLAS): the family that fits this
  # CPU is recorded and in --version, and said on the standard error only
  # at a terminal (script(1) gives the run one), once
  fits=$(awk '/^flags/ { for (i = 2; i <= NF; i++) f[$i] = 1; exit }
    END { print !(f["avx2"] && f["fma"]) ? "none" : \
      f["avx512f"] && f["avx512bw"] && f["avx512vl"] && f["avx512dq"] ? "SkylakeX" : "Haswell" }' /proc/cpuinfo)
  shim=$(pwd)/${UNKNOWN_CPU:-build/kernels/unknown_cpu.so}
  # (under AddressSanitizer a preloaded library must let ASan's runtime
  # come second, as tests/faults.sh does)
  unknown() { env OPENBLAS_CORETYPE=Prescott LD_PRELOAD="$shim" \
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" "$@"; }
  check "the shim of an unknown CPU is built ($shim)" test -f "$shim"
  unknown $BIN solve $ex -o $TMP/unknown > /dev/null 2> $TMP/err
  check "an unknown CPU: blas_kernels Prescott, blas_kernels_advised $fits, nothing on stderr ($(head -c 200 $TMP/err))" \
    test "$(value blas_kernels $TMP/unknown) $(value blas_kernels_advised $TMP/unknown)" = "Prescott $fits" -a ! -s $TMP/err
  unknown $BIN --version > $TMP/version 2>&1
  notes=$(grep -c "^contactopt: note: .* runs its Prescott kernels.*OPENBLAS_CORETYPE=$fits selects" $TMP/version)
  check "an unknown CPU: --version names the family that fits, $([ $fits = none ] && echo 'none due' || echo "$fits"), in $notes note" \
    test "$notes" -eq "$([ $fits = none ] && echo 0 || echo 1)"
  if command -v script > /dev/null; then
    unknown script -qec "$BIN solve $ex -o $TMP/tty" /dev/null > $TMP/tty.out 2>&1; rc=$?
    notes=$(grep -c "^contactopt: note: .*OPENBLAS_CORETYPE=$fits selects" $TMP/tty.out)
    check "an unknown CPU at a terminal: exit $rc, the note once ($notes)" \
      test $rc -eq 0 -a "$notes" -eq "$([ $fits = none ] && echo 0 || echo 1)"
  else
    echo "# script(1) is missing: the note at a terminal is not checked"
  fi
  for t in 1 16; do
    OPENBLAS_NUM_THREADS=$t $BIN solve $ex -o $TMP/t$t > /dev/null 2>&1
    check "OPENBLAS_NUM_THREADS=$t: blas_threads $t, chosen by OPENBLAS_NUM_THREADS, not by size" \
      test "$(value blas_threads $TMP/t$t) $(value threads_chosen_by $TMP/t$t) $(value blas_threads_by_size $TMP/t$t)" \
        = "$t OPENBLAS_NUM_THREADS 0"
  done
  unasked OMP_NUM_THREADS=3 $BIN solve $ex -o $TMP/omp > /dev/null 2>&1
  check "OMP_NUM_THREADS=3 (OpenBLAS reads it): 3 BLAS threads, CHOLMOD's 4 OpenMP threads" \
    test "$(value blas_threads $TMP/omp) $(value openmp_threads $TMP/omp)" = "3 4"
  check "by default CHOLMOD's OpenMP regions run on one thread, the BLAS's calls by size" \
    test "$(value openmp_threads $TMP/s) $(value blas_threads_by_size $TMP/s) $(value threads_chosen_by $TMP/s)" = "1 1 program"
  ;;
  *) echo "# the BLAS is not OpenBLAS: its kernels and threads are not checked" ;;
esac

# ---- results do not depend on the thread count --------------------------------
# optimize of Example 5.1 at N = 256 with one, two and 16 BLAS threads (16
# oversubscribed on a small machine; every call OpenBLAS splits is split)
# and with the program's choice: the same exit status, iterations,
# evaluations and stop reason, E* within 1e-12 of the one-thread run's
for t in 1 2 16 -; do
  ( unset OPENBLAS_NUM_THREADS GOTO_NUM_THREADS OMP_NUM_THREADS
    [ $t = - ] || export OPENBLAS_NUM_THREADS=$t
    exec $BIN optimize $ex -o $TMP/n$t -s mesh.refine=16 ) > /dev/null 2>&1
  echo $? > $TMP/rc$t
done
for t in 2 16 -; do
  check "N = 256, OPENBLAS_NUM_THREADS=$t against 1: exit $(cat $TMP/rc$t), $(value iterations $TMP/n$t) iterations, $(value evaluations $TMP/n$t) evaluations, $(value stop_reason $TMP/n$t)" \
    test "$(cat $TMP/rc$t) $(value iterations $TMP/n$t) $(value evaluations $TMP/n$t) $(value stop_reason $TMP/n$t)" \
       = "$(cat $TMP/rc1) $(value iterations $TMP/n1) $(value evaluations $TMP/n1) $(value stop_reason $TMP/n1)"
  check "N = 256, OPENBLAS_NUM_THREADS=$t: E* within 1e-12 of one thread's ($(value energy $TMP/n$t), $(value energy $TMP/n1))" \
    near_ref "$(value energy $TMP/n1)" "$(value energy $TMP/n$t)" 1e-12
done
check "... and the one-thread run converged (exit 0)" test "$(cat $TMP/rc1) $(value stop_reason $TMP/n1)" = "0 converged"

finish
