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
# spacing (\, \  ~ $ }), by such a unit, a percentage, or a quantity
# (a physical unit, a mantissa times a power of ten; below).  What matches
# and is no measurement (a constant of the article, a default of a key, a
# target or a threshold that is a setting) is taken out first by the
# regular expressions of tests/numbers.allow, each with its reason.
# Each offending line is printed as FILE:LINE: text.
. tests/lib.sh

# a number (not part of a word, a name, a macro's key such as
# \acc{sec:1024} or an exponent; thousands may be set apart by \,), the
# spacing, the unit
num='(^|[^A-Za-z0-9_.^{=/:\\])[0-9]+([.][0-9]+)?'
sep='(\\[,;: ]|\\thinspace|~|[$}]| )'
unit='(s|ms|min|minutes?|seconds?|hours?|B|kB|MB|GB|KiB|MiB|GiB|times|iterations?|solves?|steps?|calls?|checks?|pages?|evaluations?|sweeps?|allocations?|sites|writes)'
pattern="$num$sep+$unit([^A-Za-z0-9]|\$)|$num$sep*\\\\?%"

# and the phrases that quote a measurement without such a unit, matched
# without regard to case, one extended regular expression a line: a
# ratio or a count in words ("some thirty times", "five to seven state
# solves"), a time in words ("a quarter of a second", "under a second"),
# a count of runs or rounds ("143 runs", "67 rounds"), a rate of
# convergence ("rate 2", "above the 1.81"), a KKT residual, and a cell of
# a hand-typed table that holds a number alone ("& 13 &", "& 3.2 / 8.2 &"),
# the tables that a script writes being paper/bench-*.tex and
# figures/*.tex, not the prose
cat > $TMP/phrases <<'PHRASES'
(^|[^a-z])(some|about|roughly|nearly|almost|over|under|at most|at least) (two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|a hundred|hundred) times
(^|[^a-z])(one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve) (to|or) (two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty)( state| fine| coarse)? (solves|steps|iterations|rounds|runs)
(a|one) (quarter|half|third|tenth|hundredth) of a (second|minute)|under (a|one) (second|minute)
(^|[^A-Za-z0-9_.^{=/:\\])[0-9]+(\\[,;: ]|~| )+(runs|rounds)([^A-Za-z0-9]|$)
rates? (of |is )?\$?[0-9]+\.[0-9]+|rate \$?2\$?([ ,.;)]|$)|(above|below) the [0-9]+\.[0-9]+
KKT( residual)?( of| at| to| is)? \$?[0-9.]+\\cdot ?10
&[ ]*\$?-?[0-9][0-9., \\]*(\\cdot ?10\^\{?-?[0-9]+\}?)?\$?[ ]*(/[ ]*[0-9.]+[ ]*)?(&|\\\\)
PHRASES
# and the quantities, which a run measures as often as a setting gives
# them: a number followed by a physical unit (J/m, Pa, MPa, N/m, mm, cm,
# m, ...), and a number in scientific notation with its mantissa
# ("2.6\cdot10^{-14}", "4·10^-9"), each in prose; a power of ten alone
# ("$10^{-10}$", a tolerance or an order of magnitude) is left alone: an
# exponent is read as no number.  What is a setting (a key's value, the
# article's constants and E* as the article gives it, a target, a bound
# of a test, a size on the page) is taken out by tests/numbers.allow
phys='(J/m|J|MJ/m|kJ/m|Pa|mPa|kPa|MPa|GPa|N/m|N|mm|cm|m|N\\,m)'
sci='(^|[^A-Za-z0-9_.^{=/:\\])[0-9]+([.][0-9]+)?(\\,|~| )*(\\cdot|·|\\times) ?10\^'
QPATTERN="$num$sep+$phys([^A-Za-z0-9]|\$)|$sci"
export QPATTERN
# hits: standard input (FILE:LINE:text) reduced to the lines that quote a
# measurement, each once
hits() { tee $TMP/numbers.in | grep -E "$pattern" > $TMP/numbers.a
  grep -i -E -f $TMP/phrases $TMP/numbers.in > $TMP/numbers.b
  awk '{ t = $0; gsub(/\^\{?-?[0-9]+\}?/, "^{e}", t); if (t ~ ENVIRON["QPATTERN"]) print }' \
    $TMP/numbers.in > $TMP/numbers.c
  cat $TMP/numbers.a $TMP/numbers.b $TMP/numbers.c | awk '!seen[$0]++'; }

# allowed: standard input with what tests/numbers.allow allows taken out;
# an entry "FILE<tab>regex" applies to the lines of FILE only
allowed() { awk 'NR == FNR { if (!/^#/ && NF) { n++; f[n] = ""; re[n] = $0
      if ((t = index($0, "\t")) > 0) { f[n] = substr($0, 1, t - 1) ":"; re[n] = substr($0, t + 1) } }
    next }
  { for (i = 1; i <= n; i++) if (f[i] == "" || index($0, f[i]) == 1) gsub(re[i], "(allowed)"); print }' \
    tests/numbers.allow -; }

# pending: standard input (FILE:LINE:text) less the lines that
# tests/numbers.pending lists (FILE, a tab, the text): the measured
# numbers still typed by hand, each to become a macro of its script or
# to go; the list may only shrink
pending() { awk -F '\t' 'FILENAME != "-" { if (!/^#/ && NF) p[$1 "\t" $2] = 1; next }
  { i = index($0, ":"); f = substr($0, 1, i - 1); r = substr($0, i + 1); t = substr(r, index(r, ":") + 1)
    if ((f "\t" t) in p) { print > "/dev/stderr"; next } print }' tests/numbers.pending -; }

prose_lines paper/*.nw paper/article.tex README.md | allowed | hits | pending > $TMP/numbers.hits 2> $TMP/numbers.pending
cat $TMP/numbers.hits
check "the prose of paper/*.nw, paper/article.tex and README.md quotes no measured number by hand ($(wc -l < $TMP/numbers.hits) lines do; $(wc -l < $TMP/numbers.pending) listed as pending in tests/numbers.pending)" \
  test ! -s $TMP/numbers.hits

# the test sees what it should: a planted time, percentage, count and
# ratio in prose are found, the same in a code chunk, a macro of a table
# and an allowed constant are not
printf '%s\n' 'It takes 0.53\,s and 12\,\% of the time.' 'A run of 489 checks,' 'and 1.6~times as long.' \
  '<<chunk>>=' 'x = 1; /* 0.53 s, 489 checks, 12 % */' \
  '@ The macro \outputwhole\,s, and $10^{10}$ times.' 'SLSQP stops after 200 iterations.' > $TMP/probe.nw
prose_lines $TMP/probe.nw | allowed | hits > $TMP/probe.hits
check "the check finds the planted numbers in prose (lines 1 to 3) and nothing else" \
  test "$(cut -d: -f2 $TMP/probe.hits | tr '\n' ' ')" = "1 2 3 "

# a documentation line may not mark a measurement as typed by hand: the
# comment "% NUMBERS:" let such lines pass once; no line of paper/*.nw or
# paper/article.tex carries it
check "no line of paper/*.nw or paper/article.tex carries a % NUMBERS: exemption" \
  sh -c '! grep -n "^%[ ]*NUMBERS:" paper/*.nw paper/article.tex'

# the stale numbers of issue 35 (item 4) and the quantities its item 3
# found typed by hand (a residual in scientific notation, a sinking in
# mm, an energy in J/m, a gap in cm (allowed in paper/figures.nw only,
# as a size on the page), a pressure in MPa), each typed back by hand
# into a scratch copy of the prose where it stood, are found: each phrase
# below is appended, as a documentation line, to a copy of its file, and
# the check must report that line
while IFS='|' read -r file phrase; do
  cp "$file" $TMP/planted.nw
  printf '@ %s\n' "$phrase" >> $TMP/planted.nw
  n=$(wc -l < $TMP/planted.nw)
  prose_lines $TMP/planted.nw | allowed | hits | grep -c "^$TMP/planted.nw:$n:" > $TMP/planted.count || true
  label=$(printf '%s' "$phrase" | tr -d '\\$' | cut -c1-60)
  check "the check finds a stale number typed back into $file: $label" test "$(cat $TMP/planted.count)" = 1
done <<'STALE'
paper/accuracy.nw|one state solve takes it some thirty times as long as [[pdas]] on $N = 64$
paper/opt.nw|Example~5.1 takes five to seven state solves from $N = 16$ to 1024
paper/stability.nw|plane stress & 13 & $2.7\cdot10^{-12}$ & $-4\,573\,711.03$ & 1.848 & 3.2 / 8.2 & 812\\
paper/stability.nw|the solve took 13 steps, a KKT residual of $2.7\cdot10^{-12}$, 8.2\,s and 812\,MB at $N = 1024$
paper/accuracy.nw|from $32$, $64$, $128$ for five in a quarter of a second
paper/accuracy.nw|from $64$, $128$, $256$ for six in under a second
paper/friction.nw|at $\mathcal F$ from $0.05$ to $100$ (143 runs, the limit raised to 1000)
paper/friction.nw|the 137 that converged took at most 67 rounds
paper/accuracy.nw|The rate is a little above the 1.81 of the state at the fixed initial shape
paper/fem.nw|converges at the rate 2 of $P_1$ elements
paper/stability.nw|The displacements agree to $2.6\cdot10^{-14}$ relative, the energies
paper/stability.nw|of the loaded half onto the foundation (6 to 8\,mm at $x_1 = 2$, largely
paper/stability.nw|design (the energy, $-1.429\cdot10^{8}$\,J/m, here depends on $\alpha$ only
paper/stability.nw|the smallest gap is $5.3$\,cm, and the largest contact force is
paper/stability.nw|$E^* = -40\,897\,325.0546$\,J/m, to $5\cdot10^{-13}$ relative
paper/stability.nw|cut at 2800\,MPa, a spike of 1.2\,GPa and 3\,kPa
README.md|and the same shape to `4·10^-9 m`; sticks from about `8·10^8 Pa`
STALE
finish
