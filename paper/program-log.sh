#!/bin/sh
# program-log.sh LOG: the pages of the woven program (paper/contactopt.nw
# and its parts) set: no overfull box wider than 20 pt, no float too
# large, no undefined reference, in the LaTeX log LOG of its last pass;
# and the index beside it (LOG's .nwi, where there is one) names each
# identifier once. Prints each offence and exits 1 if there is one; make
# paper runs it after the program's build, and tests/program-pages.sh on
# the same log. (paper/article-log.sh holds the article to 5 pt.)
log=${1:?usage: program-log.sh LOG}
[ -f "$log" ] || { echo "program-log.sh: no log $log"; exit 1; }
bad=0
# LaTeX breaks its log lines at 79 characters: join them first
tr -d '\r' < "$log" | awk '{ line = line $0 } length($0) < 79 { print line; line = "" }
  END { if (line != "") print line }' > "$log.joined"
awk '/^Overfull \\[hv]box \(/ { w = $3; sub(/^\(/, "", w); sub(/pt$/, "", w)
       if (w + 0 > 20) { print "program: " $0; bad = 1 } }
     END { exit bad }' "$log.joined" || bad=1
if grep -n 'Float too large' "$log.joined"; then bad=1; fi
if grep -n -E "(Reference|Citation) .* undefined|There were undefined references|undefined citations" "$log.joined"; then bad=1; fi
rm -f "$log.joined"
# the index: an entry that noindex wrote twice (the Makefile drops
# repeated entries after noindex, which misses those not next to each other)
nwi=${log%.log}.nwi
if [ -f "$nwi" ] && ! awk 'seen[$0]++ { print "program: the index repeats " $0; bad = 1 }
                          END { exit bad }' "$nwi"; then bad=1; fi
[ $bad -eq 0 ] || echo "program-log.sh: $log: the pages do not set (above)"
exit $bad
