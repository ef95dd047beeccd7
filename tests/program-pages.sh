# program-pages.sh: the pages of the woven program (paper/contactopt.pdf,
# built by make paper) set. Where make paper has built it (CI runs make
# check before make paper: then this says "# skip" and does not fail;
# make check does not run LaTeX), its LaTeX log has no overfull box over
# 20 pt, no float too large, no undefined reference, and its index
# (build/paper/contactopt.nwi) names each identifier once
# (paper/latex-log.sh at 20 pt, which make paper also runs); the contents print
# no section number run into its title. The check of the log is itself
# checked on planted logs either way.
. tests/lib.sh

log=build/paper/contactopt.log
if [ -f "$log" ]; then
  check "the program's LaTeX log: no overfull box over 20 pt, no float too large, no undefined reference; the index names each identifier once" \
    sh paper/latex-log.sh program 20 "$log"
  # the contents as printed: no section number run into its title
  # (19.10What the cases show)
  if [ -f paper/contactopt.pdf ] && command -v pdftotext > /dev/null; then
    pdftotext -f 1 -l 12 paper/contactopt.pdf $TMP/contents.txt
    check "the contents: every number stands apart from its title" \
      sh -c "! grep -E '^ *([A-Z]|[0-9]+)([.][0-9]+)+[A-Z][a-z]' $TMP/contents.txt"
  fi
else
  echo "# skip: $log not built (make paper builds it): the program's pages not checked"
fi

# the check sees what it should: a box of 19 pt passes; one of 21 pt, a
# float too large, an undefined reference and an index entry twice are
# each found
mkdir -p $TMP/ok $TMP/bad
printf '%s\n' 'Overfull \hbox (19.2pt too wide) in paragraph at lines 1--2' > $TMP/ok/p.log
printf '%s\n' '\nwixaddsx{i}{{\nwixident {Design{\_}set}}{Design:unset}}' \
  '\nwixaddsx{i}{{\nwixident {design{\_}set}}{design:unset}}' > $TMP/ok/p.nwi
check "the log check lets a box of 19 pt and two identifiers that differ in case pass" \
  sh paper/latex-log.sh program 20 $TMP/ok/p.log
for planted in 'Overfull \hbox (21.5pt too wide) in paragraph at lines 1--2' \
    'LaTeX Warning: Float too large for page by 118.84398pt on input line 117.' \
    "LaTeX Warning: Reference \`sec:x' on page 3 undefined on input line 12."; do
  printf '%s\n' "$planted" > $TMP/bad/p.log
  check "the log check finds: $planted" sh -c "! sh paper/latex-log.sh program 20 $TMP/bad/p.log > /dev/null"
done
printf '%s\n' 'Overfull \hbox (1.2pt too wide) in paragraph at lines 1--2' > $TMP/bad/p.log
printf '%s\n' '\nwixaddsx{i}{{\nwixident {Design{\_}set}}{Design:unset}}' \
  '\nwixaddsx{i}{{\nwixident {design{\_}set}}{design:unset}}' \
  '\nwixaddsx{i}{{\nwixident {Design{\_}set}}{Design:unset}}' > $TMP/bad/p.nwi
check "the log check finds an index entry twice" sh -c "! sh paper/latex-log.sh program 20 $TMP/bad/p.log > /dev/null"
finish
