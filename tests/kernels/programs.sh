# tests/kernels/programs.sh: the test programs (TESTS, default build/tests)
# under every kernel family of the OpenBLAS in use that this CPU can
# execute (make check-kernels). OpenBLAS names its x86-64 families in
# OPENBLAS_CORETYPE; several names fall back to one family (Athlon, Katmai,
# Northwood and Banias to Prescott), which OPENBLAS_VERBOSE=2 tells, so each
# family runs once, under the first name that selects it. A family whose
# instructions this CPU lacks dies with SIGILL (exit 132) and is listed as
# not run. One line a family, "ok - ..." or "FAIL - ..." with the failing
# checks; with TABLE=FILE also the macros \kernelsmachine and \kernelrows
# (the rows "family & passed & failed \\") of the paper's table.
. tests/lib.sh
TESTS=${TESTS:-build/tests}
NAMES="Prescott Core2 Penryn Dunnington Nehalem Atom Opteron Barcelona Bobcat
       Bulldozer Piledriver Steamroller Excavator Sandybridge Haswell Zen
       SkylakeX Cooperlake Athlon Katmai Northwood Banias"
probe=$(ls $TESTS/test_* | grep -v '\.d$' | head -n 1)
seen=" "; skipped=""; rows=""
[ -n "${TABLE:-}" ] && printf '%% written by tests/kernels/programs.sh (make kernels-table)\n\\newcommand{\\kernelsmachine}{%s, %s}\n' \
  "$(sed -n 's/^model name[^:]*: *//p' /proc/cpuinfo | head -n 1)" "$(date +%Y-%m-%d)" > "$TABLE"
for name in $NAMES; do
  core=$(OPENBLAS_VERBOSE=2 OPENBLAS_CORETYPE=$name $probe 2>&1 >/dev/null | sed -n 's/^Core: //p' | head -n 1)
  [ -n "$core" ] || core=$name
  case "$seen" in *" $core "*) continue ;; esac
  seen="$seen$core "
  passed=0; failed=0; which=""
  for t in $TESTS/test_*; do
    case $t in *.d) continue ;; esac
    [ -f "tests/$(basename $t).c" ] || continue      # left from a source that is gone
    OPENBLAS_CORETYPE=$name $t > $TMP/out 2>&1; rc=$?
    if [ $rc -eq 132 ]; then passed=-1; break; fi
    passed=$((passed + $(grep -c '^ok - ' $TMP/out)))
    failed=$((failed + $(grep -c '^FAIL - ' $TMP/out)))
    which="$which$(grep '^FAIL - ' $TMP/out | sed "s|^FAIL - |; $(basename $t): |" | tr -d '\n')"
    if [ $rc -ne 0 ] && ! grep -q '^FAIL - ' $TMP/out; then
      failed=$((failed + 1)); which="$which; $(basename $t) exited with status $rc"
    fi
  done
  if [ $passed -lt 0 ]; then
    skipped="$skipped $core"
    [ -n "${TABLE:-}" ] && rows="$rows$core & \\multicolumn{2}{l}{illegal instruction} \\\\ "
    continue
  fi
  rows="$rows$core & $passed & $failed \\\\ "
  check "the test programs under OpenBLAS's $core kernels: $passed passed, $failed failed$which" \
    test $failed -eq 0 -a $passed -gt 0
done
[ -n "${TABLE:-}" ] && printf '\\newcommand{\\kernelrows}{%s}\n' "$rows" >> "$TABLE"
[ -n "$skipped" ] && echo "# not executable on this CPU (SIGILL):$skipped"
finish
