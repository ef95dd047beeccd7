# lib.sh: shell helpers for the tests (sourced by every tests/*.sh, and by
# tests/reference/generate.sh for value); every check prints one line,
# "ok - what" or "FAIL - what", and tests/run counts them.  The helpers'
# own variables begin with _l, so that they leave the caller's alone.
BIN=${BIN:-bin/contactopt}
TMP=${TMP:-$(mktemp -d)}
failures=0
ok()   { echo "ok - $*"; }
fail() { echo "FAIL - $*"; failures=$((failures + 1)); }
# check DESCRIPTION COMMAND...: one line, ok if COMMAND succeeds
check() { desc=$1; shift; if "$@"; then ok "$desc"; else fail "$desc"; fi; }
finish() { rm -rf "$TMP"; [ "$failures" -eq 0 ]; }

# unasked CMD...: CMD with no thread count of the user's in its
# environment (the variables OpenBLAS and OpenMP read), for the checks of
# what the program chooses when nobody asks; make check-kernels runs the
# whole suite with OPENBLAS_NUM_THREADS=16 too
unasked() { env -u OPENBLAS_NUM_THREADS -u GOTO_NUM_THREADS -u OMP_NUM_THREADS "$@"; }

# limits_run: the runs under ulimit -v can be made; under AddressSanitizer
# (make SAN=1), which reserves terabytes of shadow address space at start
# that no ulimit -v admits, they cannot: a comment says so, status 1
# (tests/runs.sh, tests/threads.sh)
limits_run() { case $BIN in
  */san/*) echo "# skipped under AddressSanitizer: the ulimit -v runs (its shadow memory cannot be reserved under an address-space limit)"; return 1 ;;
esac; }

# ---- the numeric guard ------------------------------------------------------
# A check compares numbers only: every value it compares must be a finite
# decimal number (number() below: not empty, not NaN or Inf, not a word),
# or the check fails with a line on stderr, "# WHAT: NAME = 'VALUE' is not
# a finite number", where plain awk would read the empty value or the word
# as 0 and pass.  A maximum, minimum or sum over no rows fails likewise.
# Numbers pass between the helpers with 17 digits; show rounds them for
# the descriptions only.
#
# awk_lib: the awk functions of the guard, for the helpers and for the
# tests' own awk: number(s), 1 if the string s is a finite decimal number;
# abs, max, min; named(i, what), the value of ARGV[i] = "NAME=VALUE"
# (removed from ARGV), with a message and _bad = 1 unless it is a number.
awk_lib='
function number(s) {
  return s ~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/ &&
         abs(s + 0) <= 1.7976931348623157e308 }
function abs(x) { return x < 0 ? -x : x }
function max(a, b) { return a > b ? a : b }
function min(a, b) { return a < b ? a : b }
function named(i, what,   k, s) {
  k = index(ARGV[i], "="); s = substr(ARGV[i], k + 1)
  if (k < 2) { _bad = 1
    printf "# %s: \047%s\047 is not NAME=VALUE\n", what, ARGV[i] > "/dev/stderr" }
  else if (!number(s)) { _bad = 1
    printf "# %s: %s = \047%s\047 is not a finite number\n", what, substr(ARGV[i], 1, k - 1), s > "/dev/stderr" }
  delete ARGV[i]; return s + 0 }'
# _lset FIRST NAME=VALUE...: the awk statements that set each NAME from
# ARGV[FIRST], ARGV[FIRST + 1], ... by named()
_lset() { _li=$1; shift; _lc=
  for _la; do
    case $_la in [A-Za-z_]*=*) _ln=${_la%%=*} ;; *) _ln=_noname ;; esac
    case $_ln in *[!A-Za-z0-9_]*) _ln=_noname ;; esac
    _lc="$_lc $_ln = named($_li, _what);"; _li=$((_li + 1))
  done
  echo "$_lc"; }
# _leval holds|calc EXPR NAME=VALUE...: the awk expression EXPR of the NAMEs
_leval() { _lm=$1 _lx=$2; shift 2
  awk -v _what="$_lx" "$awk_lib
    BEGIN { $(_lset 1 "$@") if (_bad) exit 2
      if (\"$_lm\" == \"holds\") exit !($_lx)
      _s = sprintf(\"%.17g\", $_lx)
      if (!number(_s)) { printf \"# %s = %s is not a finite number\\n\", _what, _s > \"/dev/stderr\"; exit 2 }
      print _s }" "$@"; }

# holds EXPR NAME=VALUE...: the awk expression EXPR (of the NAMEs and the
# functions of awk_lib) is true, and every VALUE is a finite number
holds() { _leval holds "$@"; }
# calc EXPR NAME=VALUE...: prints EXPR to 17 digits; fails on a VALUE or a
# result that is not a finite number
calc() { _leval calc "$@"; }
# le A B: A <= B;  lt A B: A < B;  both finite numbers (quote them: "$x")
le() { _larity le 2 "$@" && holds 'value <= bound' value="$1" bound="$2"; }
lt() { _larity lt 2 "$@" && holds 'value < bound' value="$1" bound="$2"; }
# near_ref REF X TOL: |X - REF| <= TOL |REF|, X within TOL of the reference
# REF relative to it
near_ref() { _larity near_ref 3 "$@" && holds 'abs(value - ref) <= tol * abs(ref)' ref="$1" value="$2" tol="$3"; }
_larity() { [ $# -eq $(($2 + 2)) ] && return 0
  echo "# $1: $2 values expected, got $(($# - 2)):$(shift 2; printf " '%s'" "$@")" >&2; return 2; }
# rate E1 E2 E3: the observed order log2((E1 - E2) / (E2 - E3)) of three
# successive halvings of h
rate() { calc 'log((a - b) / (b - c)) / log(2)' a="$1" b="$2" c="$3"; }
# show FORMAT X: X by the printf FORMAT if a finite number, else 'X'
show() { awk -v f="$1" -v x="$2" "$awk_lib"'
  BEGIN { if (number(x)) printf f "\n", x; else printf "\047%s\047\n", x }'; }

# rows_max [-w WHERE] EXPR FILE [NAME=VALUE...]: the largest value of the
# awk expression EXPR (of the fields $1, $2, ..., the NAMEs, prev(K), field
# K of the data row before, and _row, the count of data rows so far) over
# the data rows of FILE (- for standard input; lines starting with # and
# blank lines are no data) where WHERE holds; rows_min the smallest,
# rows_sum the sum; 17 digits.  Fails, printing nothing, when no row is
# left, when a field that EXPR or WHERE names as $K is not a finite number
# in any data row, or when EXPR, a VALUE or the result is not.
rows_max() { _lrows max "$@"; }
rows_min() { _lrows min "$@"; }
rows_sum() { _lrows sum "$@"; }
_lrows() { _lh=$1 _lw=1; shift
  if [ "$1" = -w ]; then _lw=$2; shift 2; fi
  _lx=$1 _lf=$2; shift 2
  _lk=$(printf '%s %s\n' "$_lx" "$_lw" | grep -o '\$[0-9][0-9]*' | tr -d '$' | sort -un | tr '\n' ' ')
  awk -v _what="rows_$_lh $_lx over $_lf" -v _how=$_lh -v _fields="$_lk" "$awk_lib
    function prev(k) { return _p[k] }
    BEGIN { $(_lset 2 "$@") _nk = split(_fields, _k, \" \") }
    _bad { exit }
    /^#/ || NF == 0 { next }
    { _row++; for (_i = 1; _i <= _nk; _i++) if (!number(\$_k[_i])) { _bad = 1
        printf \"# %s: field %d of line %d, \\047%s\\047, is not a finite number\\n\", _what, _k[_i], FNR, \$_k[_i] > \"/dev/stderr\"; exit } }
    $_lw { _v = $_lx; _s = sprintf(\"%.17g\", _v)
        if (!number(_s)) { _bad = 1; printf \"# %s: %s at line %d\\n\", _what, _s, FNR > \"/dev/stderr\"; exit }
        if (!_n++) _r = _v; else if (_how == \"max\") _r = max(_r, _v); else if (_how == \"min\") _r = min(_r, _v); else _r += _v }
    { for (_i = 1; _i <= NF; _i++) _p[_i] = \$_i }
    END { if (_bad) exit 2
      if (!_n) { printf \"# %s: no rows\\n\", _what > \"/dev/stderr\"; exit 1 }
      _s = sprintf(\"%.17g\", _r)
      if (!number(_s)) { printf \"# %s: the result %s is not a finite number\\n\", _what, _s > \"/dev/stderr\"; exit 1 }
      print _s }" "$_lf" "$@"; }

# ---- a clean failure ------------------------------------------------------------
# clean_failure RC CODE ERR DIR PATTERN...: a command was refused cleanly:
# its exit status RC is CODE, its standard error (the file ERR) is one line
# that matches every PATTERN (grep -E), and it wrote nothing (no DIR)
clean_failure() { _lrc=$1 _lcode=$2 _lerr=$3 _ldir=$4; shift 4
  [ "$_lrc" -eq "$_lcode" ] && [ "$(wc -l < "$_lerr")" -eq 1 ] && [ ! -e "$_ldir" ] || return 1
  for _lp; do grep -q -E -- "$_lp" "$_lerr" || return 1; done; }

# ---- reading the program's files ---------------------------------------------
# value KEY PATH: the value of the line "KEY value" of PATH/summary.dat (of
# PATH itself if it is a file); nothing if there is none
value() { if [ -d "$2" ]; then _lf=$2/summary.dat; else _lf=$2; fi
  awk -v k="$1" '$1 == k { print $2 }' "$_lf"; }
# umax DIR: max |u1|, |u2| over DIR/nodes.dat
umax() { rows_max 'max(abs($6), abs($7))' "$1/nodes.dat"; }
# uncomment FILE: FILE without its comments (from #) and blank lines
uncomment() { sed 's/#.*//; /^ *$/d' "$1"; }
# numbers ABS REL A B [COLUMN]: the files A and B agree (comments dropped,
# one column if given) within absolute ABS or relative REL (numdiff)
numbers() {
  uncomment "$3" > $TMP/numbers.a; uncomment "$4" > $TMP/numbers.b
  if [ -n "$5" ]; then
    awk -v c=$5 '{ print $c }' $TMP/numbers.a > $TMP/numbers.c; mv $TMP/numbers.c $TMP/numbers.a
    awk -v c=$5 '{ print $c }' $TMP/numbers.b > $TMP/numbers.c; mv $TMP/numbers.c $TMP/numbers.b
  fi
  numdiff -q -a $1 -r $2 $TMP/numbers.a $TMP/numbers.b; }


# ---- the prose of the paper (tests/numbers.sh, tests/prose.sh) ----------------
# prose FILE: the documentation lines of the noweb file FILE (outside its
# code chunks: from a line "@" or "@ text" to the next "<<name>>="), as
# FILE:LINE:text
prose() { awk '/^<<.*>>=[ \t]*$/ { code = 1; next }
  /^@( |$)/ { code = 0; sub(/^@ ?/, "") }
  !code { print FILENAME ":" FNR ":" $0 }' "$1"; }
# prose_lines FILE...: the lines of the prose of each FILE, as
# FILE:LINE:text: of a paper/*.nw its documentation lines (prose), of a
# .tex file its lines that are not comments, of any other file (README.md)
# every line
prose_lines() { for _lp; do
  case $_lp in
    *.nw) prose "$_lp" ;;
    *.tex) awk -v F="$_lp" '!/^%/ { print F ":" FNR ":" $0 }' "$_lp" ;;
    *) awk '{ print FILENAME ":" FNR ":" $0 }' "$_lp" ;;
  esac
done; }

# ---- the design set B and the optimality of a design --------------------------
# B of the three shipped scenes on the article's mesh: C0, d = C1 h, the
# area S = gamma (b - a) - C2, b - a and h, as in_B takes them
B_article="0.05 0.00625 0.09 4 0.25"
# scene_key KEY SCENE: the value of the first line "KEY = value" of the
# scene file SCENE, in whatever section (the scenes of tests/converged.sh
# and tests/suite.sh give their constants once, each in full)
scene_key() { awk -v k="$1" '$1 == k && $2 == "=" { print $3; exit }' "$2"; }
# scene_B SCENE: B of the scene file SCENE on its own mesh, as in_B takes
# it: "C0 d S L h", with L = b - a, h = L / N, d = C1 h, S = gamma L - C2
scene_B() {
  _lbL=$(calc 'b - a' a="$(scene_key a "$1")" b="$(scene_key b "$1")")
  _lbh=$(calc 'L / N' L="$_lbL" N="$(scene_key N "$1")")
  echo "$(scene_key C0 "$1")" "$(calc 'C1 * h' C1="$(scene_key C1 "$1")" h="$_lbh")" \
    "$(calc 'g * L - C2' g="$(scene_key gamma "$1")" L="$_lbL" C2="$(scene_key C2 "$1")")" "$_lbL" "$_lbh"; }
# violation FILE C0 d S L h: the largest violation of B (4.4) by an iterate
# of FILE (iterates.dat: one block per iteration, two blank lines apart,
# alpha in column 4),
# relative to C0 (to C0 L for the area); fails on no iterate or a value
# that is not a finite number
violation() { awk -v C0=$2 -v d=$3 -v S=$4 -v L=$5 -v h=$6 "$awk_lib"'
  function up(v) { if (v > w) w = v }
  function done(  i) {
    for (i = 0; i < n; i++) {
      up(-x[i] / C0); up(x[i] / C0 - 1)
      if (i > 0) { up((x[i] - x[i-1] - d) / C0); up((x[i-1] - x[i] - d) / C0)
                   area += h * (x[i] + x[i-1]) / 2 }
    }
    up((area - S) / (C0 * L)); up((S - area) / (C0 * L))
    n = 0; blocks++ }
  /^#/ { next }
  NF == 0 { if (n) done(); next }
  !number($2) || !number($4) { printf "# violation: line %d of %s is not numbers: %s\n", FNR, FILENAME, $0 > "/dev/stderr"; bad = 1; exit }
  { if ($2 == 0) { n = 0; area = 0 } x[n++] = $4 }
  END { if (bad) exit 2; if (n) done()
    if (!blocks) { printf "# violation: no iterate in %s\n", FILENAME > "/dev/stderr"; exit 1 }
    printf "%.17g\n", w }' "$1"; }
# in_B LABEL DIR TOL C0 d S L h: a check: every iterate of DIR/iterates.dat
# lies in B, its largest violation at most TOL
in_B() { _lv=$(violation "$2/iterates.dat" $4 $5 $6 $7 $8)
  check "$1: every iterate lies in B (largest violation $(show %.1e "$_lv") <= $3)" le "$_lv" "$3"; }
# kkt FILE C0 d h: the KKT conditions of min E over B from multipliers.dat
# (C0, d = C1 h and h are the scene's constants): prints the stationarity
# relative to max |dE/dX|; fails on a sign or a complementarity violated,
# on no row, or on a value that is not a finite number
kkt() { awk -v C0=$2 -v d=$3 -v h=$4 "$awk_lib"'
  /^#/ { split($0, a, "mu = "); mu = a[2]; next }
  NF == 0 { next }
  { for (k = 1; k <= 8; k++) if (!number($k)) { printf "# kkt: line %d of %s: field %d, \047%s\047, is not a finite number\n", FNR, FILENAME, k, $k > "/dev/stderr"; broken = 1; exit }
    i = $1; x[i] = $3; G[i] = $4; lo[i] = $5; up[i] = $6; ri[i] = $7; fa[i] = $8; n = i + 1 }
  END {
    if (broken) exit 2
    if (!n || !number(mu)) { printf "# kkt: %s has no rows or no mu = (\047%s\047)\n", FILENAME, mu > "/dev/stderr"; exit 2 }
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
    printf "%.17g\n", (gmax > 0 ? rmax / gmax : rmax); exit bad }' "$1"; }
# kkt_point LABEL DIR C0 d h: a check: the final design of DIR is a KKT
# point (kkt above), with the stationarity at most 1e-4
kkt_point() { _lr=$(kkt "$2/multipliers.dat" $3 $4 $5); _lrc=$?
  check "$1: the final design is a KKT point (signs, complementarity; stationarity $(show %.1e "$_lr") <= 1e-4)" \
    holds 'rc == 0 && r <= 1e-4' rc=$_lrc r="$_lr"; }

# strip_times FILE: the file without its wall-clock times and the lines that say
# how the run computed (its thread counts, the machine's load), which differ by design
strip_times() {
  awk 'NR == 1 && /^#/ { for (i = 2; i <= NF; i++) if ($i == "seconds") col = i - 1 }
       ($1 == "seconds" || $1 ~ /^(metric|state|model|monitor|subproblem|starts)_seconds$/) && NF == 2 { next }
       $1 ~ /^(blas_threads|blas_threads_by_size|threads_chosen_by|openmp_threads|load_average)$/ && NF == 2 { next }
       col && !/^#/ { $col = ""; print; next }
       { print }' "$1"
}
# same_run A B: the output folders A and B hold the same files with the same contents,
# their times and thread counts aside (strip_times)
same_run() {
  ( cd "$1" && find . -type f | sort ) > $TMP/same.a
  ( cd "$2" && find . -type f | sort ) > $TMP/same.b
  cmp -s $TMP/same.a $TMP/same.b || return 1
  while read -r f; do
    case $f in
      *.dat) strip_times "$1/$f" > $TMP/same.c; strip_times "$2/$f" > $TMP/same.d ;;
      *) cmp -s "$1/$f" "$2/$f" || return 1; continue ;;
    esac
    cmp -s $TMP/same.c $TMP/same.d || return 1
  done < $TMP/same.a; }

# ---- a state: the physics of a solution (tests/hard_cases.sh, tests/thin_bodies.sh)
# rel A REF: |A - REF| / |REF|, for the descriptions
rel() { show %.1e "$(calc 'abs(a - ref) / abs(ref)' a="$1" ref="$2")"; }
# finite DIR: no NaN or Inf (any case, any sign) among the words of any text
# file; the binary VTU files are skipped (grep -I: their bytes may spell
# "nan"), their values are those of nodes.dat and contact.dat and the
# stress from them, which tests/paraview.sh finds finite
finite() { ! grep -r -q -I -i -E "(^|[[:space:]\"'>=])[-+]?(nan|inf)" "$1"; }
# state_ok NAME TOL: the solve into $TMP/NAME converged to a KKT residual
# at most TOL, and wrote no NaN or Inf (two checks)
state_ok() {
  _lsk=$(value kkt_residual $TMP/$1)
  check "$1: KKT residual $_lsk <= $2 after $(value iterations $TMP/$1) $(value state_solver $TMP/$1) iterations" le "$_lsk" $2
  check "$1: no NaN or Inf in any output file" finite $TMP/$1; }
# udiff DIR1 DIR2 [FACTOR]: max |u - u'/FACTOR| over the nodes (same mesh),
# relative to umax DIR1 (absolute if that is 0)
udiff() { paste $1/nodes.dat $2/nodes.dat | rows_max 'max(abs($6 - $13 / f), abs($7 - $14 / f)) / (u > 0 ? u : 1)' - \
  f=${3:-1} u="$(umax $1)"; }
# work DIR GAMMA FROM TO P1 P2 [F1 F2]: -1/2 <L, u> + 1/2 sum_i T_i u2_i,
# from the files alone: at a solution of (4.3), Q'AQ = b'Q + sum T_i Q_i,
# so that E = 1/2 Q'AQ - b'Q is this (Clapeyron's theorem with the contact
# forces).  <L, u>: the traction (P1, P2) on [FROM, TO] of the top x2 =
# GAMMA against the piecewise linear u there, and the body force F against
# u on every triangle (area/3 times the sum of its vertex values).
work() {
  tri=/dev/null; [ "${7:-0}${8:-0}" != 00 ] && tri=$1/triangles.dat
  awk -v g=$2 -v from=$3 -v to=$4 -v P1=$5 -v P2=$6 -v F1=${7:-0} -v F2=${8:-0} '
  FILENAME ~ /nodes.dat$/ { if (!/^#/ && $5 == g) { n++; X[n] = $4; U1[n] = $6; U2[n] = $7 }; next }
  FILENAME ~ /contact.dat$/ { if (!/^#/) tu += $5 * $3; next }
  /^#/ { next }
  NF == 0 { k = 0; next }
  { if (k < 3) { x[k] = $1; y[k] = $2; v1[k] = $3; v2[k] = $4 }
    if (++k == 3) { A = ((x[1]-x[0]) * (y[2]-y[0]) - (x[2]-x[0]) * (y[1]-y[0])) / 2
      if (A < 0) A = -A
      body += A / 3 * (F1 * (v1[0] + v1[1] + v1[2]) + F2 * (v2[0] + v2[1] + v2[2])) } }
  END {
    if (n < 2) { print "# work: no nodes on the top x2 = " g > "/dev/stderr"; exit 1 }
    for (i = 1; i < n; i++) {
      lo = X[i] > from ? X[i] : from; hi = X[i+1] < to ? X[i+1] : to
      if (hi <= lo) continue
      s = (lo - X[i]) / (X[i+1] - X[i]); t = (hi - X[i]) / (X[i+1] - X[i])
      top += (hi - lo) / 2 * P1 * (2 * U1[i] + (s + t) * (U1[i+1] - U1[i]))
      top += (hi - lo) / 2 * P2 * (2 * U2[i] + (s + t) * (U2[i+1] - U2[i])) }
    printf "%.15g\n", -(top + body) / 2 + tu / 2 }' $1/nodes.dat $1/contact.dat $tri; }
# energy_is_work NAME GAMMA FROM TO P1 P2 [F1 F2]: the summary's E agrees,
# to WTOL (1e-9 unless set): the identity holds to the residual of the state
energy_is_work() {
  _n=$1; shift; _w=$(work $TMP/$_n "$@"); _e=$(value energy $TMP/$_n)
  check "$_n: E = $_e is the work of the loads and the contact forces, $_w (rel. $(rel "$_w" "$_e") <= ${WTOL:-1e-9})" \
    near_ref "$_e" "$_w" ${WTOL:-1e-9}; }
# agrees NAME REF: another solver's state agrees with REF's: E to 1e-9,
# the displacements to 1e-6 of their largest
agrees() {
  _a=$(value energy $TMP/$2); _b=$(value energy $TMP/$1); _d=$(udiff $TMP/$2 $TMP/$1)
  check "$1: agrees with $2: E $_b (rel. $(rel "$_b" "$_a") <= 1e-9), u (rel. $(show %.1e "$_d") <= 1e-6)" \
    holds 'abs(b - a) <= 1e-9 * abs(a) && d <= 1e-6' a="$_a" b="$_b" d="$_d"; }

# part_scene GEO: Example 5.1's strip and design (N = 16, M = 1, C0prime =
# 0.25) under the part of the geometry file GEO, steel, clamped on the
# left, on rollers on the right, its curve top under P2 = -5.75e8 Pa (the
# article's load, over the whole top); a test appends its own sections
part_scene() {
  cat <<END
[geometry]
a = 0
b = 4
[design]
N = 16
C0 = 0.05
C1 = 0.025
C2 = 0.91
initial = arc
arc_x1 = 4
arc_x2 = 160.025
arc_radius = 160.025
[mesh]
M = 1
C0prime = 0.25
[part]
geometry = $1
[material]
E = 2.15e11
nu = 0.29
[left]
bc = clamped
[right]
bc = roller
[boundary.top]
bc = traction
P2 = -5.75e8
END
}
