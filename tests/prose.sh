# prose.sh: the paper, the article and the README describe the program as
# it is; what changed, and when, belongs in git.  A documentation line of a
# paper/*.nw (outside its code chunks: from a line "@" or "@ text" to the
# next "<<name>>=") or of paper/article.tex (not a comment) or of
# README.md must not
# narrate history: no
# issue numbers, no "used to", "no longer", "until November", "was the
# default", "before this module", "this version", "last round" and the
# like (the patterns below, case-insensitive).  Each offending line is
# printed as FILE:LINE: text.
. tests/lib.sh

patterns='until issue|issue[ ~]?[0-9]|issues [0-9]|used to|no longer|until (january|february|march|april|may|june|july|august|september|october|november|december)|was the default|(the )?default (until|before|since)|before this (module|change|version|one)|this version|last round|this session|(was|were) mended|in the run before|the run before this|older versions|(earlier|previous|former|old) version|was the floor of|(stopped|stalled) on before|(slsqp|solvers?|optimi[sz]ers?|pdas) stalled|without the mending'

# the prose (prose_lines of tests/lib.sh), not the tables the bench
# scripts write (paper/bench-*.tex)
prose_lines paper/*.nw paper/article.tex README.md > $TMP/prose.lines
grep -i -E "$patterns" $TMP/prose.lines > $TMP/prose.hits
# a phrase split over two lines ("the residual the solvers stopped on /
# before"): each line joined to the next of its file, reported by its
# first line where neither line matches alone
pairs() { awk '{ i = index($0, ":"); f = substr($0, 1, i - 1); r = substr($0, i + 1)
    j = index(r, ":"); n = substr(r, 1, j - 1); t = substr(r, j + 1)
    if (f == pf) print pf ":" pn ":" pt " " t; pf = f; pn = n; pt = t }' "$1"; }
pairs $TMP/prose.lines | grep -i -E "$patterns" | while IFS= read -r l; do
  f=${l%%:*}; r=${l#*:}; n=${r%%:*}
  grep -q -F -e "$f:$n:" -e "$f:$((n + 1)):" $TMP/prose.hits || echo "$l"
done >> $TMP/prose.hits
cat $TMP/prose.hits
check "the prose of paper/*.nw, paper/article.tex and README.md narrates no history ($(wc -l < $TMP/prose.hits) lines match)" \
  test ! -s $TMP/prose.hits

# the test sees what it should: a line of history in prose is found, the
# same words in a code chunk are not
printf '%s\n' 'Some prose.' '<<chunk>>=' 'x = 1; /* until issue 14 */' '@ Until issue 14 it used to.' > $TMP/probe.nw
check "the check finds history in prose and not in code" \
  test "$(prose $TMP/probe.nw | grep -i -E -c "$patterns")" = 1

# the history of issue 35 (item 4), each typed back into a scratch copy
# of the prose, is found, the last split over two lines as it stood
for phrase in 'for the earlier version of [[pdas]]; Quarteroni and Valli' \
    'This noise was the floor of the optimisers: SLSQP stalled at' \
    'there the residual is the one the solvers stopped on before, and they' \
    'there the residual is the one the solvers stopped on
before, and they take the same steps'; do
  printf '%s\n' 'Some prose.' "$phrase" > $TMP/planted.nw
  prose $TMP/planted.nw > $TMP/planted.lines
  { grep -i -E "$patterns" $TMP/planted.lines; pairs $TMP/planted.lines | grep -i -E "$patterns"; } > $TMP/planted.hits
  check "the check finds the history typed back: $(echo "$phrase" | tr '\n' ' ' | cut -c1-50)" test -s $TMP/planted.hits
done
finish
