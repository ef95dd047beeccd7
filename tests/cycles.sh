# cycles.sh: the files of src/ call one way (paper/overview.nw).  A file A
# depends on a file B when A calls a function that B defines or includes
# B's own header, B.h (src/depends.sh reads both from the code); the test
# fails on any circle among those dependencies, and names it.  A reference
# first: two files that call each other must be found.
. tests/lib.sh

# edges DIR: one line "A B" for each dependency of a file A.c on B.c in
# DIR, read as the paper's table of layers reads it
edges() { sh src/depends.sh edges "$1"; }

# circles: read "A B" edges, print each strongly connected set of more
# than one file (Tarjan's algorithm in awk), one per line
circles() {
  awk '{ n[$1]; n[$2]; out[$1] = out[$1] " " $2 }
    function visit(v,   k, ws, w, c, line) {
      idx[v] = low[v] = ++t; st[++sp] = v; on[v] = 1
      k = split(out[v], ws, " ")
      for (; k > 0; k--) { w = ws[k]
        if (!(w in idx)) { visit(w); if (low[w] < low[v]) low[v] = low[w] }
        else if (on[w] && idx[w] < low[v]) low[v] = idx[w] }
      if (low[v] == idx[v]) { c = 0; line = ""
        do { w = st[sp--]; on[w] = 0; c++; line = line " " w } while (w != v)
        if (c > 1) print line }
    }
    END { for (v in n) if (!(v in idx)) visit(v) }'
}

mkdir -p "$TMP/ref"
printf 'int b(void);\nint a(void) { return b(); }\n' > "$TMP/ref/a.c"
printf 'int a(void);\nint b(void) { return 1; }\nint c(void) { return a(); }\n' > "$TMP/ref/b.c"
printf 'int d(void) { return 0; }\n' > "$TMP/ref/d.c"
edges "$TMP/ref" | circles > "$TMP/ref.out"
check "the paper's table of layers refuses a tree with a circle" \
  sh -c '! sh src/depends.sh layers "$1" > /dev/null 2>&1' - "$TMP/ref"
check "a reference circle (a.c calls b.c, b.c calls a.c) is found" \
  grep -qx ' [ab]\.c [ab]\.c' "$TMP/ref.out"

edges src > "$TMP/src.edges"
check "the files of src/ have dependencies to read ($(wc -l < "$TMP/src.edges") found)" \
  test "$(wc -l < "$TMP/src.edges")" -gt 50
circles < "$TMP/src.edges" > "$TMP/src.out"
while read -r c; do echo "# circle:$c" >&2; done < "$TMP/src.out"
check "no circle among the files of src/ ($(wc -l < "$TMP/src.out") found)" \
  test ! -s "$TMP/src.out"
finish
