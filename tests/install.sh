# install.sh: make install and make uninstall (paper/install.nw).  The
# package is installed into a temporary DESTDIR under PREFIX=/opt/co; the
# installed program runs from another folder on an installed example
# (solve, optimize, plot); the manual page renders without a warning
# (groff with warnings as errors, lexgrog, mandoc -T lint) and lists
# every command, every key and every exit status the program prints; the
# completion completes a command, an option, a key
# and a key's value; make uninstall leaves the DESTDIR as it found it.
. tests/lib.sh
root=$TMP/root prefix=/opt/co
mkdir -p $root $TMP/work
# the build this suite tests: make SAN=1 check installs the sanitized one
case $BIN in build/san/*) san=1 ;; *) san= ;; esac
MAKEFLAGS= make -s install SAN=$san DESTDIR=$root PREFIX=$prefix > $TMP/install.out 2>&1; rc=$?
check "make install DESTDIR=$root PREFIX=$prefix exits 0$(sed -n 1p $TMP/install.out | sed "s/^./: &/")" [ $rc -eq 0 ]
p=$root$prefix
( cd $root && find . | sort ) > $TMP/installed
expected=$(printf '%s\n' bin/contactopt share/man/man1/contactopt.1 \
  share/bash-completion/completions/contactopt share/contactopt/installed-dirs \
  $(ls data/*.scene data/parts/*.scene data/parts/*.geo | sed 's|^.*/|share/contactopt/examples/|') | sort)
check "the program, the manual page, the completion, the $(ls data/*.scene | wc -l) example scenes and the $(ls data/parts/*.scene | wc -l) parts with their geometries are installed under $prefix, nothing else" \
  [ "$(cd $p && find . -type f | sed 's|^\./||' | sort)" = "$expected" ]
check "the program is executable, the other files are not" \
  sh -c "[ -x $p/bin/contactopt ] && [ -z \"\$(find $p -type f -perm /111 ! -path '*/bin/contactopt')\" ]"

# the installed program, from another folder, on an installed example
co=$p/bin/contactopt ex=$p/share/contactopt/examples/example-5.1.scene
cd $TMP/work
$co solve $ex -o start --plot-files > $TMP/solve.out 2>&1; rc=$?
check "installed: solve of the installed example-5.1.scene from another folder exits 0 and writes start/summary.dat (E = $(value energy start 2>/dev/null))" \
  sh -c "[ $rc -eq 0 ] && [ -s start/summary.dat ] && [ -s start/nodes.dat ]"
$co optimize $ex -o opt --plot-files > $TMP/optimize.out 2>&1; rc=$?
check "installed: optimize converges (exit $rc, $(value stop_reason opt 2>/dev/null), E* = $(value energy opt 2>/dev/null))" \
  sh -c "[ $rc -eq 0 ] && [ \"\$(awk '\$1 == \"stop_reason\" { print \$2 }' opt/summary.dat)\" = converged ]"
$co plot opt --results --start start -o fig > $TMP/plot.out 2>&1; rc=$?
check "installed: plot draws the results (exit $rc, fig.pdf and fig.png)" \
  sh -c "[ $rc -eq 0 ] && [ -s fig.pdf ] && [ -s fig.png ]"
$co optimize $p/share/contactopt/examples/pad.scene -o pad > $TMP/pad.out 2>&1; rc=$?
check "installed: optimize of the installed part pad.scene, its geometry beside it, converges (exit $rc, $(value stop_reason pad 2>/dev/null))" \
  sh -c "[ $rc -eq 0 ] && [ \"\$(awk '\$1 == \"stop_reason\" { print \$2 }' pad/summary.dat)\" = converged ]"
$co solve nosuch.scene > /dev/null 2> $TMP/err; rc=$?
check "installed: a missing scene is one line and exit 2 ($(cat $TMP/err))" \
  clean_failure $rc 2 $TMP/err out/nosuch 'nosuch.scene'
cd - > /dev/null

# the manual page renders without a warning
man1=$p/share/man/man1/contactopt.1
groff -man -ww -z $man1 > $TMP/groff.out 2>&1; rc=$?
check "groff -man -ww -z renders the manual page without a warning (exit $rc$(head -n 3 $TMP/groff.out | tr '\n' ' '))" \
  sh -c "[ $rc -eq 0 ] && [ ! -s $TMP/groff.out ]"
check "lexgrog reads the page's NAME: $(lexgrog $man1 2>&1)" \
  sh -c "lexgrog $man1 | grep -q '\"contactopt - '"
mandoc -T lint $man1 > $TMP/mandoc.out 2>&1; rc=$?
check "mandoc -T lint finds nothing in the page, not even a matter of style (exit $rc$(head -n 3 $TMP/mandoc.out | tr '\n' ' '))" \
  sh -c "[ $rc -eq 0 ] && [ ! -s $TMP/mandoc.out ]"
MANWIDTH=80 man -l $man1 2> $TMP/man.err | col -b > $TMP/man.txt
check "man -l renders the page, with no message on the standard error" \
  sh -c "[ -s $TMP/man.txt ] && [ ! -s $TMP/man.err ]"
sections=$(grep -E '^[A-Z][A-Z ]+$' $TMP/man.txt | grep -v '^CONTACTOPT' | tr '\n' ',')
check "the page has the sections NAME, SYNOPSIS, DESCRIPTION, COMMANDS, SCENE KEYS, FILES, EXIT STATUS, EXAMPLES, SEE ALSO in order ($sections)" \
  [ "$sections" = "NAME,SYNOPSIS,DESCRIPTION,COMMANDS,SCENE KEYS,FILES,EXIT STATUS,EXAMPLES,SEE ALSO," ]
# section NAME: the lines of the rendered page's section NAME
section() { awk -v s="$1" '/^[A-Z][A-Z ]+$/ { on = $0 == s; next } on' $TMP/man.txt; }
section COMMANDS > $TMP/commands.txt
commands=$($BIN --help | awk '/^commands:$/ { on = 1; next } on && NF == 0 { exit } on { print $1 }')
missing=
for c in $commands; do
  grep -q "^   contactopt $c\$" $TMP/commands.txt || missing="$missing $c"
  # every option of the command's help is in its part of the page
  for o in $($BIN $c --help | sed -n 's/^  \(-[^ ]*\).*/\1/p; s/^  -[^ ]*, \(-[^ ]*\).*/\1/p'); do
    awk -v c="   contactopt $c" '$0 == c { on = 1; next } /^   contactopt / { on = 0 } on' $TMP/commands.txt |
      grep -q -- "$o" || missing="$missing $c:$o"
  done
done
check "the page's COMMANDS has each of the $(echo $commands | wc -w) commands ($(echo $commands)) with every option of its help${missing:+; missing:$missing}" \
  sh -c "[ -n '$commands' ] && [ -z '$missing' ]"
section 'SCENE KEYS' > $TMP/keys.txt
$BIN keys | awk 'NR > 1 { print $1 }' > $TMP/names
# a term the page sets on a line of its own, or before its text when short
term() { awk -v t="       $1" 'index($0, t) == 1 && substr($0, length(t) + 1, 1) ~ /^( |)$/ { f = 1 } END { exit !f }' "$2"; }
missing=$(for k in $(cat $TMP/names); do term $k $TMP/keys.txt || echo $k; done | tr '\n' ' ')
check "the page's SCENE KEYS has every one of the $(wc -l < $TMP/names) keys that contactopt keys prints${missing:+; missing: $missing}" \
  sh -c "[ \$(wc -l < $TMP/names) -gt 40 ] && [ -z '$missing' ]"
# every exit status a help text names (Exit status: N meaning, N meaning, ...)
codes=$(for c in $commands; do $BIN $c --help; done |
  awk '/^Exit status:/ { on = 1 } NF == 0 { on = 0 } on' | tr '\n' ' ' |
  grep -o -E '(: |, )[0-9]+ [a-z]' | grep -o -E '[0-9]+' | sort -un)
section 'EXIT STATUS' > $TMP/exit.txt
codes=$(echo $codes)
missing=$(for n in $codes; do term $n $TMP/exit.txt || echo $n; done | tr '\n' ' ')
check "the page's EXIT STATUS has every exit status the help texts name ($codes)${missing:+; missing: $missing}" \
  sh -c "[ $(echo $codes | wc -w) -ge 6 ] && [ -z '$missing' ]"
check "the page's FILES names the installed examples ($prefix/share/contactopt/examples)" \
  grep -q -F "$prefix/share/contactopt/examples/" $TMP/man.txt

# the completion completes a command, an option, a key and a key's value
comp=$p/share/bash-completion/completions/contactopt
complete_line() { bash -c '. "$1"; COMP_LINE=$2; COMP_POINT=${#COMP_LINE}; _contactopt; echo "${COMPREPLY[*]}"' sh $comp "$1"; }
check "completion: contactopt opt completes to optimize ($(complete_line 'contactopt opt'))" \
  [ "$(complete_line 'contactopt opt')" = optimize ]
check "completion: contactopt solve x.scene --plot completes to --plot-files ($(complete_line 'contactopt solve x.scene --plot'))" \
  [ "$(complete_line 'contactopt solve x.scene --plot')" = --plot-files ]
check "completion: -s mesh.ref completes to the key mesh.refine= ($(complete_line 'contactopt optimize x.scene -s mesh.ref'))" \
  [ "$(complete_line 'contactopt optimize x.scene -s mesh.ref')" = mesh.refine= ]
all=$(complete_line 'contactopt solve x.scene -s ' | tr ' ' '\n' | sed 's/=$//')
check "completion: -s offers every key that contactopt keys prints, each with its = ($(echo "$all" | wc -l) keys)" \
  [ "$all" = "$(cat $TMP/names)" ]
check "completion: -s optimizer.method=s completes a value ($(complete_line 'contactopt optimize x.scene -s optimizer.method=s'))" \
  sh -c "case '$(complete_line 'contactopt optimize x.scene -s optimizer.method=s')' in slsqp|optimizer.method=slsqp) ;; *) exit 1 ;; esac"

# make uninstall leaves the DESTDIR as it was before the install: empty
MAKEFLAGS= make -s uninstall SAN=$san DESTDIR=$root PREFIX=$prefix > $TMP/uninstall.out 2>&1; rc=$?
left=$(cd $root && find . -mindepth 1 | head -n 5 | tr '\n' ' ')
check "make uninstall exits 0 and leaves no file and no folder the install created (left: ${left:-nothing})" \
  sh -c "[ $rc -eq 0 ] && [ -z '$left' ]"
# a folder the install found is left, with what else it holds
mkdir -p $root$prefix/bin && touch $root$prefix/bin/other
MAKEFLAGS= make -s install SAN=$san DESTDIR=$root PREFIX=$prefix > /dev/null 2>&1 &&
  MAKEFLAGS= make -s uninstall SAN=$san DESTDIR=$root PREFIX=$prefix > /dev/null 2>&1; rc=$?
left=$(cd $root && find . -mindepth 1 | sort | tr '\n' ' ')
check "install and uninstall over a folder that was there leave it as it was (left: $left)" \
  sh -c "[ $rc -eq 0 ] && [ '$left' = './opt ./opt/co ./opt/co/bin ./opt/co/bin/other ' ]"
finish
