# lib.sh: shell helpers for the tests; every check prints one line,
# "ok - what" or "FAIL - what", and tests/run counts them.
BIN=${BIN:-bin/contactopt}
TMP=${TMP:-$(mktemp -d)}
failures=0
ok()   { echo "ok - $*"; }
fail() { echo "FAIL - $*"; failures=$((failures + 1)); }
# expect COND-COMMAND... -- description
check() { desc=$1; shift; if "$@"; then ok "$desc"; else fail "$desc"; fi; }
finish() { rm -rf "$TMP"; [ "$failures" -eq 0 ]; }
