#!/bin/sh
# man.sh PROGRAM DATADIR DATE SCENE...: the manual page contactopt(1) on the
# standard output, written from PROGRAM's own texts (paper/install.nw)
set -e
prog=$1 datadir=$2 date=$3; shift 3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$prog" --help > "$tmp/main"
commands=$(awk '/^commands:$/ { on = 1; next } on && NF == 0 { exit } on { print $1 }' "$tmp/main")
for c in $commands; do "$prog" "$c" --help > "$tmp/$c"; done
"$prog" keys > "$tmp/keytable"
version=$("$prog" --version | sed -n 1p)
roff='
function esc(s,   n, w, i, out) {
  gsub(/\\/, "\\e", s)
  n = split(s, w, " ")
  for (i = 1; i <= n; i++) {
    if (w[i] ~ /^[([]*-/) { gsub(/-/, "\\-", w[i]); sub(/^/, "\\%", w[i]) }
    out = out (i > 1 ? " " : "") w[i]
  }
  if (out ~ /^[.\047]/) out = "\\&" out
  return out }
function word(w,   pre, post) {
  gsub(/\\/, "\\e", w)
  while (w ~ /^[[(]/) { pre = pre substr(w, 1, 1); w = substr(w, 2) }
  while (w ~ /[]),]$/) { post = substr(w, length(w)) post; w = substr(w, 1, length(w) - 1) }
  if (w ~ /^-/) { gsub(/-/, "\\-", w); w = "\\fB" w "\\fR"; pre = "\\%" pre }
  else if (w ~ /^[A-Z]+$/ || w ~ /=/) w = "\\fI" w "\\fR"
  return pre w post }
function term(s,   n, w, i, out) {
  n = split(s, w, " ")
  for (i = 1; i <= n; i++)
    out = out (i > 1 ? " " : "") (i == 1 && w[i] ~ /^[a-z]+$/ ? "\\fB" w[i] "\\fR" : word(w[i]))
  return out }
function trim(s) { sub(/^ +/, "", s); sub(/ +$/, "", s); return s }
function wrap(s,   n, w, i, out, line) {
  n = split(s, w, " ")
  for (i = 1; i <= n; i++)
    if (line != "" && length(line) + 1 + length(w[i]) > 78) { out = out line "\n"; line = w[i] }
    else line = line (line == "" ? "" : " ") w[i]
  return out line }'
printf '%s\n' ".\\\" contactopt(1): written by src/man.sh from the texts of $version" \
  ".TH CONTACTOPT 1 \"$date\" \"$version\" \"User Commands\"" ".SH NAME" \
  'contactopt \- shape optimisation of an elastic body on a rigid foundation'
echo ".SH SYNOPSIS"
for f in main $commands; do
  awk "$roff"'
    NR == 1 { sub(/^usage: contactopt */, ""); u = $0; next }
    /^   / { u = u " " trim($0); next }
    { exit }
    END { n = split(u, w, " "); c = w[1] ~ /^[a-z]+$/ ? w[1] : ""
      if (FILENAME !~ /\/main$/) print ".PP"; print ".B contactopt" (c != "" ? " " c : "")
      sub(/^[a-z]+ */, "", u); print wrap(term(u)) }' "$tmp/$f"
done
printf '.PP\n.B contactopt \\-\\-version\n'
help() { awk "$roff"'
  NR == 1 { usage = 1; next }
  usage && /^   / { next }
  { usage = 0 }
  /^Exit status:/ { skip = 1 }
  NF == 0 { skip = 0; brk = 1; next }
  skip { next }
  /^  [^ ]/ { s = substr($0, 3); i = match(s, /  +/)
    if (!i && s !~ /^-/) i = match(s, / +/)
    if (!i && match(s, /^(-[^ ]+,? )*-[^ ]+( [A-Z]+| [^ ]*=[^ ]*)? /)) i = RLENGTH
    print ".TP"; print (i ? term(substr(s, 1, i - 1)) : term(s))
    if (i) print esc(trim(substr(s, i))); interm = 1; brk = 0; next }
  interm && /^   / { print esc(trim($0)); next }
  { if (brk || interm) print ".PP"; brk = interm = 0; print esc($0) }' "$1"; }
echo ".SH DESCRIPTION"
help "$tmp/main"
echo ".SH COMMANDS"
for c in $commands; do
  echo ".SS contactopt $c"
  help "$tmp/$c"
done
echo ".SH SCENE KEYS"
printf '%s\n' 'A scene is an INI file of sections of keys, \fIsection.key\fR below;' \
  '\fB\-s\fR \fIsection.key=value\fR overrides a key. These are the keys that' \
  '\fBcontactopt keys\fR lists, with their units, defaults and accepted values.'
awk "$roff"'
  NR == 1 { next }
  { n = split($0, f, /  +/)
    print ".TP"; print ".B " f[1]; print wrap(esc(f[5]) "."); print ".br"
    print wrap(esc("unit " f[2] "; default " f[3] "; accepted: " f[4])) }' "$tmp/keytable"
echo ".SH FILES"
echo ".TP"
echo ".I $datadir/contactopt/examples/"
echo "the example scenes: $(echo "$@" | sed 's/ /, /g')." | fold -s -w 78 | sed 's/ $//'
echo ".TP"
echo ".I $datadir/bash-completion/completions/contactopt"
echo "the completion of the commands, options and scene keys for bash."
echo ".TP"
printf '%s\n' '.I out/NAME, out/NAME\-gradcheck, out/NAME\-optimize' \
  'the output folders of solve, gradcheck and optimize for a scene NAME.scene' \
  'in the current folder, unless \fB\-o\fR names another.'
echo ".SH EXIT STATUS"
for c in $commands; do
  awk -v c=$c '/^Exit status:/ { on = 1; sub(/^Exit status: */, "") }
    NF == 0 { on = 0 } on { s = s (s == "" ? "" : " ") $0 }
    END { if (s == "") exit; sub(/\.$/, "", s)
      while (match(s, /, [0-9]+ /)) {
        print c, substr(s, 1, RSTART - 1); s = substr(s, RSTART + 2) }
      print c, s }' "$tmp/$c"
done | awk "$roff"'
  { code = $2; c = $1; sub(/^[^ ]+ +[^ ]+ +/, "")
    if (!(code in text)) { order[n++] = code; text[code] = "" }
    text[code] = text[code] (text[code] == "" ? "" : ";\n") wrap(esc(c ": " $0)) }
  END { for (i = 0; i < n; i++) for (j = i + 1; j < n; j++)
          if (order[j] + 0 < order[i] + 0) { t = order[i]; order[i] = order[j]; order[j] = t }
        for (i = 0; i < n; i++) { print ".TP"; print ".B " order[i]; print text[order[i]] "." } }'
ex=$datadir/contactopt/examples/example-5.1.scene
cat << EOF
.SH EXAMPLES
Solve Example 5.1 of the article, optimise its shape, and draw the
optimum beside the start:
.PP
.RS
.nf
contactopt solve $ex \\-o start \\-\\-plot\\-files
contactopt optimize $ex \\-o opt \\-\\-plot\\-files
contactopt plot opt \\-\\-results \\-\\-start start
.fi
.RE
.PP
The same in plane strain, on a mesh four times finer, with the
projected gradient method:
.PP
.RS
.nf
contactopt optimize $ex \\-s material.model=plane_strain \\e
    \\-s mesh.refine=4 \\-s optimizer.method=projgrad \\-s optimizer.max_iter=2000
.fi
.RE
.SH SEE ALSO
.BR gnuplot (1)
.PP
J. Haslinger and P. Neittaanm\\(:aki, Shape optimization in contact
problems. Approximation and numerical realization, M2AN 21(2), 1987,
269\\(en291.
EOF
