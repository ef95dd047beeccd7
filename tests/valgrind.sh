# valgrind.sh: Memcheck on the program, as the figures run it: solve and
# optimize of the three shipped scenes (the article's mesh), gradcheck of
# one, and three failure paths (a malformed scene: exit 2; a state solver
# stopped by its iteration limit: exit 3; an optimiser stopped by its own:
# exit 3 too, its files written).  Each must end with its usual status,
# no memory error and no definite or indirect leak (a leak of either kind
# is an error: --errors-for-leak-kinds).  Valgrind cannot run the
# sanitizer build, so this runs bin/contactopt, the ordinary build, under
# make SAN=1 check too.  Library noise only is suppressed, in
# tests/valgrind.supp, each entry with the reason.  About 15 s.
# Valgrind cannot execute AVX-512 instructions (OpenBLAS's SkylakeX and
# Cooperlake kernels die there with SIGILL), and an OpenBLAS that chooses
# its kernel inside valgrind sees a CPU without them: so the kernel family
# is named, never left to the CPU: every case runs with Haswell's kernels
# (AVX2, the newest valgrind runs), and solve and optimize of Example 5.1
# again with Prescott's (the generic ones), so that memory errors in the
# other code paths of the BLAS and of the solvers they steer are seen too.
. tests/lib.sh
VG_BIN=bin/contactopt
if ! command -v valgrind > /dev/null; then
  fail "valgrind is installed (Debian package valgrind)"
  finish; exit
fi
# vg DESCRIPTION STATUS ARGS...: run ARGS under Memcheck, expect STATUS
vg() {
  desc=$1; want=$2; shift 2
  rm -rf $TMP/run
  OPENBLAS_CORETYPE=${VG_CORE:-Haswell} valgrind -q --error-exitcode=99 --leak-check=full \
    --errors-for-leak-kinds=definite,indirect \
    --suppressions=tests/valgrind.supp --log-file=$TMP/vg.log \
    $VG_BIN "$@" -o $TMP/run > /dev/null 2> $TMP/stderr
  rc=$?
  if [ $rc -eq $want ] && ! grep -q 'lost in' $TMP/vg.log; then
    ok "valgrind: $desc: exit $rc, no memory error, no leak"
  else
    fail "valgrind: $desc: exit $rc (expected $want): $(grep -m3 -E '(Invalid|uninitiali|lost in|Mismatched)' $TMP/vg.log | tr '\n' ' ')"
    sed 's/^/# /' $TMP/vg.log | head -60
  fi
}
for e in 5.1 5.2 5.2-flat; do
  vg "solve example-$e" 0 solve data/example-$e.scene
  vg "optimize example-$e" 0 optimize data/example-$e.scene
done
vg "gradcheck example-5.1" 0 gradcheck data/example-5.1.scene
vg "projgrad (Algorithm 4.1) on example-5.2, 20 iterations" 3 optimize \
  data/example-5.2.scene -s optimizer.method=projgrad -s optimizer.max_iter=20
vg "cgssor state solver" 0 solve data/example-5.1.scene \
  -s solver.state=cgssor
vg "psor state solver" 0 solve data/example-5.1.scene -s solver.state=psor
printf '[geometry]\na = 0\nb = 4\n[design]\nN = 0x\n' > $TMP/bad.scene
vg "a malformed scene" 2 solve $TMP/bad.scene
vg "a state solver at its iteration limit" 3 solve data/example-5.1.scene \
  -s solver.max_iter=1
vg "an optimiser at its iteration limit" 3 optimize data/example-5.1.scene \
  -s optimizer.max_iter=2
vg "SLSQP at its iteration limit" 3 optimize data/example-5.1.scene \
  -s optimizer.method=slsqp -s optimizer.max_iter=2
VG_CORE=Prescott
vg "solve example-5.1, Prescott's kernels" 0 solve data/example-5.1.scene
vg "optimize example-5.1, Prescott's kernels" 0 optimize data/example-5.1.scene
finish
