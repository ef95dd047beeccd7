# guard.sh: the numeric guard of tests/lib.sh fails on what is not a
# finite number (an empty value, NaN, Inf, a word, a value without its
# name) and on a maximum, minimum or sum over no rows, each with a line
# naming the value; it passes on good values and computes the right ones.
# And clean_failure, the test of a refused command, fails on each of its
# conditions.
. tests/lib.sh
# refuses DESCRIPTION PATTERN COMMAND...: COMMAND fails, prints nothing on
# standard output, and says PATTERN (a fixed string) on standard error
refuses() { _d=$1 _p=$2; shift 2
  if "$@" >$TMP/out 2>$TMP/msg; then fail "$_d: passed ($(cat $TMP/out))"
  elif [ -s $TMP/out ]; then fail "$_d: failed, but printed $(cat $TMP/out)"
  elif grep -q -F -- "$_p" $TMP/msg; then ok "$_d: fails, $(grep -F -- "$_p" $TMP/msg | head -1)"
  else fail "$_d: failed without saying \"$_p\": $(cat $TMP/msg)"; fi; }
# gives DESCRIPTION WANT COMMAND...: COMMAND succeeds and prints WANT
gives() { _d=$1 _w=$2; shift 2
  _g=$("$@" 2>$TMP/msg); _rc=$?
  check "$_d: $_g" sh -c "[ $_rc -eq 0 ] && [ '$_g' = '$_w' ] && [ ! -s $TMP/msg ]"; }
not() { ! "$@"; }

# ---- a missing value, NaN, Inf or a word fails, and the message names it --
empty=
for bad in "" nan NaN -nan +nan inf -inf Infinity 1e400 word 1.2.3 1e 0x10 "1 2" 3m; do
  refuses "holds with e = '$bad'" "e = '$bad' is not a finite number" holds 'e < 1e-6' e="$bad"
done
refuses "the empty value that passed before: awk -v e= 'BEGIN { exit !(e < 1e-6) }' exits 0" \
  "e = '' is not a finite number" holds 'e < 1e-6' e=$empty
refuses "a value without its name" "'1e-7' is not NAME=VALUE" holds 'e < 1e-6' 1e-7
refuses "le, the first value empty" "value = '' is not a finite number" le "" 1e-6
refuses "le, the bound NaN" "bound = 'nan' is not a finite number" le 1 nan
refuses "le, an empty value unquoted (one argument left)" "le: 2 values expected, got 1: '1e-6'" le $empty 1e-6
refuses "lt, a word" "value = 'converged' is not a finite number" lt converged 1
refuses "near_ref, the reference empty" "ref = '' is not a finite number" near_ref "" 1 1e-9
refuses "near_ref, the tolerance a word" "tol = 'tight' is not a finite number" near_ref 1 1 tight
refuses "calc, an empty value" "a = '' is not a finite number" calc 'a * 2' a=
refuses "calc, a result that is NaN" "is not a finite number" calc 'log(a)' a=-1
refuses "rate, a missing energy" "c = '' is not a finite number" rate 3 2 ""
refuses "a syntax error in EXPR" "syntax error" holds 'e <' e=1

# ---- rows: no rows, or a field that is not a number, fails -------------------
printf '# x y\n' > $TMP/none.dat
printf '# x y\n0 1\n1 -2\n2 nan\n3 4\n' > $TMP/nan.dat
printf '# x y\n0 1\n\n1 -2\n2 word\n' > $TMP/word.dat
printf '# x y\n0 1.5\n1 -2\n2 4e-1\n' > $TMP/good.dat
for how in max min sum; do
  refuses "rows_$how over zero rows (a comment only)" "no rows" rows_$how '$2' $TMP/none.dat
  refuses "rows_$how over an empty file" "no rows" rows_$how '$2' /dev/null
  refuses "rows_$how where no row qualifies" "no rows" rows_$how -w '$1 > 5' '$2' $TMP/good.dat
  refuses "rows_$how over a NaN field" "field 2 of line 4, 'nan', is not a finite number" rows_$how '$2' $TMP/nan.dat
  refuses "rows_$how over a word" "field 2 of line 5, 'word', is not a finite number" rows_$how '$2' $TMP/word.dat
  refuses "rows_$how, a NAME empty" "p = '' is not a finite number" rows_$how '$2 - p' $TMP/good.dat p=
done
refuses "rows_max, a field named only in WHERE is checked too" "field 2 of line 4, 'nan'" \
  rows_max -w '$2 > 0' '$1' $TMP/nan.dat
refuses "a missing file" "missing.dat" rows_max '$1' $TMP/missing.dat
refuses "kkt over an empty multipliers.dat" "has no rows" kkt /dev/null 0.05 0.00625 0.25
refuses "violation over an empty iterates.dat" "no iterate" violation /dev/null $B_article
refuses "value of a missing key, compared" "E = '' is not a finite number" \
  holds 'E < 0' E="$(value no_such_key $TMP/good.dat)"

# ---- good values pass, and the helpers compute what they say -------------------
check "holds 'e < 1e-6' with e = 1e-7" holds 'e < 1e-6' e=1e-7
check "holds 'e < 1e-6' with e = 1e-5 is false" not holds 'e < 1e-6' e=1e-5
check "holds with several values and awk_lib" holds 'abs(a) == max(b, c) && n == N + 1' a=-3 b=3 c=-1 n=17 N=16
check "holds accepts 0, -0, +1.5, .5, 5., 1E+3, -2.5e-07" \
  holds 'a == 0 && b == 0 && c == 1.5 && d == 0.5 && e == 5 && f == 1000 && g == -2.5e-7' \
  a=0 b=-0 c=+1.5 d=.5 e=5. f=1E+3 g=-2.5e-07
check "le 1 2" le 1 2
check "le 2 2" le 2 2
check "le 2 1 is false" not le 2 1
check "lt 1 2" lt 1 2
check "lt 2 2 is false" not lt 2 2
check "near_ref -4e6 -4.000000001e6 1e-9 (relative to the reference)" near_ref -4e6 -4.000000001e6 1e-9
check "near_ref -4e6 -4.00001e6 1e-9 is false" not near_ref -4e6 -4.00001e6 1e-9
check "near_ref 0 0 0" near_ref 0 0 0
gives "calc 'f * v' f=2 v=-5.75e8" -1150000000 calc 'f * v' f=2 v=-5.75e8
gives "rate 4 3 2.75 = log2 4" 2 rate 4 3 2.75
gives "rows_max '\$2'" 1.5 rows_max '$2' $TMP/good.dat
gives "rows_min '\$2'" -2 rows_min '$2' $TMP/good.dat
gives "rows_sum '\$2'" -0.099999999999999978 rows_sum '$2' $TMP/good.dat
gives "rows_max 'abs(\$2 - p)' p=1" 3 rows_max 'abs($2 - p)' $TMP/good.dat p=1
gives "rows_max -w '\$1 > 0'" 0.40000000000000002 rows_max -w '$1 > 0' '$2' $TMP/good.dat
gives "rows_max -w '_row > 1' '\$2 - prev(2)' (the largest rise)" 2.3999999999999999 \
  rows_max -w '_row > 1' '$2 - prev(2)' $TMP/good.dat
gives "rows_max from standard input" 4 sh -c ". tests/lib.sh; printf '1 4\n2 3\n' | rows_max '\$2' -; finish"
printf '# name value\nenergy -4.5e6\nstop_reason converged\n' > $TMP/summary.dat
gives "value of a summary file" -4.5e6 value energy $TMP/summary.dat
gives "value of a folder's summary.dat" converged value stop_reason $TMP
gives "show %.1e of a number" 1.2e-07 show %.1e 1.2345e-7
gives "show %.1e of an empty value" "''" show %.1e ""

# ---- clean_failure: exit status, one line, every pattern, nothing written ------
echo "contactopt: x.scene: line 3: bad value" > $TMP/one.err
printf 'contactopt: x.scene\nline 3\n' > $TMP/two.err
mkdir -p $TMP/written
check "clean_failure on a clean refusal" clean_failure 2 2 $TMP/one.err $TMP/none x.scene 'line [0-9]'
check "clean_failure: another exit status fails" not clean_failure 3 2 $TMP/one.err $TMP/none x.scene
check "clean_failure: two lines fail" not clean_failure 2 2 $TMP/two.err $TMP/none x.scene
check "clean_failure: a pattern not said fails" not clean_failure 2 2 $TMP/one.err $TMP/none x.scene psor
check "clean_failure: an output folder written fails" not clean_failure 2 2 $TMP/one.err $TMP/written x.scene
finish
