#!/bin/sh
# tangle.sh DIR FILE.nw...: write every root chunk named like a C file
# (foo.c, foo.h) of the given noweb files into DIR, with #line directives
# pointing into the .nw, and every root chunk named like a gnuplot script
# (foo.gp) or a shell script (foo.sh) as plain text (#line is C).  cpif leaves an unchanged file (and
# its time) alone, so a prose-only edit rebuilds nothing.  A gnuplot root
# also sees the chunks of paper/figures.nw, the page and terminal of every
# figure, so that another part's figure uses them instead of a copy.
set -e
dir=$1; shift
mkdir -p "$dir"
for nw in "$@"; do
  for root in $(noroots "$nw" | sed -n 's/^<<\(.*\.[ch]\)>>$/\1/p'); do
    notangle -L'#line %L "%F"%N' -R"$root" "$nw" | cpif "$dir/$root"
  done
  style=paper/figures.nw
  [ "$nw" = $style ] && style=
  for root in $(noroots "$nw" | sed -n 's/^<<\(.*\.gp\)>>$/\1/p'); do
    notangle -R"$root" $style "$nw" | cpif "$dir/$root"
  done
  for root in $(noroots "$nw" | sed -n 's/^<<\(.*\.sh\)>>$/\1/p'); do
    notangle -R"$root" "$nw" | cpif "$dir/$root"
  done
done
