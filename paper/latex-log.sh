#!/bin/sh
# latex-log.sh NAME PT LOG: the pages of a document set: no overfull box
# wider than PT points, no float too large, no undefined reference or
# citation, in the LaTeX log LOG of its last pass; and the noweb index
# beside it (LOG's .nwi, where there is one) names each identifier once.
# Prints each offence after NAME and exits 1 if there is one. make paper
# runs it after each build: the article (paper/article.tex) is held to
# 5 pt, the woven program (paper/contactopt.nw and its parts) to 20 pt;
# tests/article.sh and tests/program-pages.sh read the same logs.
name=${1:?usage: latex-log.sh NAME PT LOG} pt=${2:?usage: latex-log.sh NAME PT LOG}
log=${3:?usage: latex-log.sh NAME PT LOG}
[ -f "$log" ] || { echo "latex-log.sh: no log $log"; exit 1; }
bad=0
# LaTeX breaks its log lines at 79 characters: join them first
tr -d '\r' < "$log" | awk '{ line = line $0 } length($0) < 79 { print line; line = "" }
  END { if (line != "") print line }' > "$log.joined"
awk -v name="$name" -v pt="$pt" '/^Overfull \\[hv]box \(/ { w = $3; sub(/^\(/, "", w); sub(/pt$/, "", w)
       if (w + 0 > pt + 0) { print name ": " $0; bad = 1 } }
     END { exit bad }' "$log.joined" || bad=1
if grep -n 'Float too large' "$log.joined"; then bad=1; fi
if grep -n -E "(Reference|Citation) .* undefined|There were undefined references|undefined citations" "$log.joined"; then bad=1; fi
rm -f "$log.joined"
# the index: an entry that noindex wrote twice (the Makefile drops
# repeated entries after noindex, which misses those not next to each other)
nwi=${log%.log}.nwi
if [ -f "$nwi" ] && ! awk -v name="$name" 'seen[$0]++ { print name ": the index repeats " $0; bad = 1 }
                          END { exit bad }' "$nwi"; then bad=1; fi
[ $bad -eq 0 ] || echo "latex-log.sh: $log: the pages do not set (above)"
exit $bad
