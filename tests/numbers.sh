# numbers.sh: the prose quotes no measured number by hand.  A time, a
# memory, a count of iterations, solves, steps, calls, checks, pages or
# evaluations, a ratio ("1.6 times") or a percentage that a run measured
# belongs in the table of the script that measured it, which also writes
# it as a macro for the prose (paper/bench-*.tex, figures/*.tex); README.md,
# which cannot cite a macro, points to the paper's tables.  A
# documentation line of a paper/*.nw (outside its code chunks, as in
# tests/prose.sh), a line of the article paper/article.tex (not a
# comment; its numbers are macros of paper/article-numbers.sh) or of
# README.md fails when it holds a number followed, past LaTeX
# spacing (\, \  ~ $ }), by such a unit, or a percentage.  What matches
# and is no measurement (a constant of the article, a default of a key, a
# target or a threshold that is a setting) is taken out first by the
# regular expressions of tests/numbers.allow, each with its reason.
# Each offending line is printed as FILE:LINE: text.
. tests/lib.sh

# a number (not part of a word, a name or an exponent; thousands may be
# set apart by \,), the spacing, the unit
num='(^|[^A-Za-z0-9_.^{=/\\])[0-9]+([.][0-9]+)?'
sep='(\\[,;: ]|\\thinspace|~|[$}]| )'
unit='(s|ms|min|minutes?|seconds?|hours?|B|kB|MB|GB|KiB|MiB|GiB|times|iterations?|solves?|steps?|calls?|checks?|pages?|evaluations?)'
pattern="$num$sep+$unit([^A-Za-z0-9]|\$)|$num$sep*\\\\?%"

# prose FILE: the documentation lines of the noweb file FILE, as FILE:LINE:text
prose() { awk '/^<<.*>>=[ \t]*$/ { code = 1; next }
  /^@( |$)/ { code = 0; sub(/^@ ?/, "") }
  !code { print FILENAME ":" FNR ":" $0 }' "$1"; }
# lines FILE...: the lines of the prose of each FILE, as FILE:LINE:text
lines() { for f; do
  case $f in
    *.nw) prose "$f" ;;
    *.tex) awk -v F="$f" '!/^%/ { print F ":" FNR ":" $0 }' "$f" ;;
    *) awk '{ print FILENAME ":" FNR ":" $0 }' "$f" ;;
  esac
done; }
# allowed: standard input with what tests/numbers.allow allows taken out
allowed() { awk 'NR == FNR { if (!/^#/ && NF) re[++n] = $0; next }
  { for (i = 1; i <= n; i++) gsub(re[i], "(allowed)"); print }' tests/numbers.allow -; }

# pending: standard input (FILE:LINE:text) less the lines that
# tests/numbers.pending lists (FILE, a tab, the text): the measured
# numbers still typed by hand, each to become a macro of its script or
# to go; the list may only shrink
pending() { awk -F '\t' 'FILENAME != "-" { if (!/^#/ && NF) p[$1 "\t" $2] = 1; next }
  { i = index($0, ":"); f = substr($0, 1, i - 1); r = substr($0, i + 1); t = substr(r, index(r, ":") + 1)
    if ((f "\t" t) in p) { print > "/dev/stderr"; next } print }' tests/numbers.pending -; }

lines paper/*.nw paper/article.tex README.md | allowed | grep -E "$pattern" | pending > $TMP/numbers.hits 2> $TMP/numbers.pending
cat $TMP/numbers.hits
check "the prose of paper/*.nw, paper/article.tex and README.md quotes no measured number by hand ($(wc -l < $TMP/numbers.hits) lines do; $(wc -l < $TMP/numbers.pending) listed as pending in tests/numbers.pending)" \
  test ! -s $TMP/numbers.hits

# the test sees what it should: a planted time, percentage, count and
# ratio in prose are found, the same in a code chunk, a macro of a table
# and an allowed constant are not
printf '%s\n' 'It takes 0.53\,s and 12\,\% of the time.' 'A run of 489 checks,' 'and 1.6~times as long.' \
  '<<chunk>>=' 'x = 1; /* 0.53 s, 489 checks, 12 % */' \
  '@ The macro \outputwhole\,s, and $10^{10}$ times.' 'SLSQP stops after 200 iterations.' > $TMP/probe.nw
lines $TMP/probe.nw | allowed | grep -E "$pattern" > $TMP/probe.hits
check "the check finds the planted numbers in prose (lines 1 to 3) and nothing else" \
  test "$(cut -d: -f2 $TMP/probe.hits | tr '\n' ' ')" = "1 2 3 "
finish
