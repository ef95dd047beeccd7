#!/bin/sh
# depends.sh edges DIR: "A B" for each file A.c of DIR that depends on
#   B.c (calls a function B.c defines, found by universal-ctags, or
#   includes B.h itself), one line each, sorted
# depends.sh layers DIR: the LaTeX table of the files of DIR, their layer
#   and the files they call; fails on a circle, which has no layers
# Comments and strings are removed (cc's preprocessor on the file alone)
# before the calls are read; a call through a field (->f(, .f() is not.
mode=$1 dir=$2
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
calls() {  # calls FILE: the names FILE calls, once each
  cc -fpreprocessed -dD -E -P "$1" 2>/dev/null |
    sed 's/"\([^"\\]\|\\.\)*"/""/g' |
    grep -o '[^A-Za-z0-9_.>][A-Za-z_][A-Za-z0-9_]*[[:space:]]*(' |
    sed 's/^.//; s/[[:space:]]*($//' | sort -u
}
edges() {
  ctags -x --c-kinds=f --language-force=C "$dir"/*.c |
    awk '$1 != "main" { print $1, $4 }' > "$tmp/defs"
  for f in "$dir"/*.c; do
    calls "$f" | awk -v f="$f" 'NR == FNR { def[$1] = $2; next }
      ($1 in def) && def[$1] != f { print f, def[$1] }' "$tmp/defs" -
    sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\(.*\)\.h".*/\1/p' \
        "$f" | while read -r h; do
      [ -f "$dir/$h.c" ] && [ "$dir/$h.c" != "$f" ] && echo "$f $dir/$h.c"
    done
  done | sed "s#$dir/##g" | sort -u
}
layers() {  # layers FILES EDGES
  awk 'NR == FNR { file[$1]; next } { out[$1] = out[$1] " " $2 }
    function mod(f) { sub(/\.c$/, "", f); sub(/_.*/, "", f); return f }
    function layer(v,   k, ws, l, top) {
      if (v in lay) return lay[v]
      if (v in path) { print "depends.sh: a circle through " v > "/dev/stderr"
                       bad = 1; return 0 }
      path[v] = 1; top = 0
      for (k = split(out[v], ws, " "); k > 0; k--)
        if ((l = layer(ws[k])) > top) top = l
      delete path[v]
      return lay[v] = top + 1
    }
    function tt(f) { gsub(/_/, "\\_", f); return "\\texttt{" f "}" }
    function row(v,   k, ws, own, others) {
      own = ""; others = 0
      for (k = split(out[v], ws, " "); k > 0; k--)
        if (mod(ws[k]) == mod(v)) own = tt(ws[k]) (own == "" ? "" : ", ") own
        else others++
      if (others) own = own (own == "" ? "" : "; ") others " of other modules"
      printf "%03d %s\t%s & %d & %s\\\\\n", lay[v], v, tt(v), lay[v], own
    }
    END {
      for (v in file) layer(v)
      if (bad) exit 1
      for (v in file) row(v)
    }' "$@" > "$tmp/rows" || return 1
  printf '%s\n' '% written by src/depends.sh from the files of src/' \
    '\begin{longtable}{@{}llp{0.55\textwidth}@{}}\toprule' \
    'file & layer & the files of its module it calls; of others, how many\\' \
    '\midrule\endhead'
  sort "$tmp/rows" | cut -f2-
  printf '%s\n' '\bottomrule\end{longtable}'
}
case $mode in
  edges) edges ;;
  layers) edges > "$tmp/edges" && ls "$dir"/*.c | sed "s#$dir/##" |
            layers - "$tmp/edges" ;;
  *) echo "usage: depends.sh edges|layers DIR" >&2; exit 2 ;;
esac
