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
# kkt FILE C0 d h: the KKT conditions of min E over B from multipliers.dat
# (C0, d = C1 h and h are the scene's constants): prints
# the stationarity relative to max |dE/dX|, fails on a sign or a
# complementarity violated
kkt() { awk -v C0=$2 -v d=$3 -v h=$4 '
  /^#/ { split($0, a, "mu = "); mu = a[2]; next }
  { i = $1; x[i] = $3; G[i] = $4; lo[i] = $5; up[i] = $6; ri[i] = $7; fa[i] = $8; n = i + 1 }
  END {
    for (i = 0; i < n; i++) {
      if (lo[i] < 0 || up[i] < 0 || ri[i] < 0 || fa[i] < 0) bad = 1
      if (lo[i] > 0 && x[i] > 1e-9 * C0) bad = 1
      if (up[i] > 0 && x[i] < C0 * (1 - 1e-9)) bad = 1
      if (i + 1 < n && ri[i] > 0 && x[i+1] - x[i] < d - 1e-9 * C0) bad = 1
      if (i + 1 < n && fa[i] > 0 && x[i] - x[i+1] < d - 1e-9 * C0) bad = 1
      w = (i == 0 || i == n - 1) ? h / 2 : h
      r = G[i] - lo[i] + up[i] + (i > 0 ? ri[i-1] - fa[i-1] : 0) - ri[i] + fa[i] + mu * w
      if (r < 0) r = -r; if (r > rmax) rmax = r
      g = G[i] < 0 ? -G[i] : G[i]; if (g > gmax) gmax = g
    }
    printf "%.1e\n", (gmax > 0 ? rmax / gmax : rmax); exit bad }' $1; }
