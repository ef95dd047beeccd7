#!/bin/sh
# article-log.sh LOG: the pages of the article set (paper/article.tex):
# no overfull box wider than 5 pt, no float too large, no undefined
# reference or citation, in the LaTeX log LOG of its last pass. Prints
# each offence and exits 1 if there is one; make paper runs it after
# the article's build, and tests/article.sh on the same log.
log=${1:?usage: article-log.sh LOG}
[ -f "$log" ] || { echo "article-log.sh: no log $log"; exit 1; }
bad=0
# LaTeX breaks its log lines at 79 characters: join them first
tr -d '\r' < "$log" | awk '{ line = line $0 } length($0) < 79 { print line; line = "" }
  END { if (line != "") print line }' > "$log.joined"
awk '/^Overfull \\[hv]box \(/ { w = $3; sub(/^\(/, "", w); sub(/pt$/, "", w)
       if (w + 0 > 5) { print "article: " $0; bad = 1 } }
     END { exit bad }' "$log.joined" || bad=1
if grep -n 'Float too large' "$log.joined"; then bad=1; fi
if grep -n -E "(Reference|Citation) .* undefined|There were undefined references|undefined citations" "$log.joined"; then bad=1; fi
rm -f "$log.joined"
[ $bad -eq 0 ] || echo "article-log.sh: $log: the pages do not set (above)"
exit $bad
