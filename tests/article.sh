# article.sh: the article (paper/article.tex, built by make paper into
# paper/article.pdf) and the physics it states.
#
# From the runs of make figures, which make check builds: at the start
# and at the optimum of every start of the reproduction, the energy is
# E = -J_c/2 - sum_i T_i alpha_i / 2 (J_c the compliance of summary.dat,
# T_i and alpha_i the columns of contact.dat), and the pressure on the
# free design nodes of Example 5.1's optimum is the area multiplier up to
# the term of the moving mesh; where make figures has run the objectives,
# the energy's optimum is the most compliant of the four.
#
# From the article, where make paper has built it (CI runs make check
# before make paper: then these checks say "# skip" and do not fail;
# make check does not run LaTeX): at most 40 pages; its text (pdftotext)
# holds the reproduction's E* of the run, the bibliography with the
# methods and libraries it relies on, and the section of limits and
# missed targets; its LaTeX log has no overfull box over 5 pt, no float
# too large and no undefined reference (paper/latex-log.sh at 5 pt, which make
# paper also runs).
. tests/lib.sh

# identity RUN WHERE: |E + J_c/2 + sum T alpha/2| / |E| of RUN's WHERE
# (initial or final)
identity() { s=out/$1/summary.dat c=out/$1/$2/contact.dat
  [ -f "$s" ] && [ -f "$c" ] || { echo "# no $s or $c" >&2; echo nan; return; }
  awk -v w="$2" 'FILENAME ~ /summary/ { if ($1 == w "_energy") E = $2
      if ($1 == w "_compliance") J = $2; next }
    !/^#/ { S += $5 * $2 }
    END { d = (E + J / 2 + S / 2) / E; printf "%.3e\n", d < 0 ? -d : d }' "$s" "$c"; }
for e in 5.1 5.2 5.2-flat; do
  for w in initial final; do
    r=$(identity example-$e-optimize $w)
    check "Example $e at the $w design: E = -J_c/2 - sum T_i alpha_i/2 on the files to $r relative (<= 1e-9)" \
      holds 'r <= 1e-9' r="$r"
  done
done

# the flat pressure: on the free nodes of the optimum (no bound of B
# active, multipliers.dat) the pressure of contact.dat is the area
# multiplier mu of summary.dat to within a few per cent
o=out/example-5.1-optimize
dev=$(awk 'FILENAME ~ /summary/ { if ($1 == "area_multiplier") mu = $2; next }
  FILENAME ~ /contact/ { if (!/^#/) p[$1] = $6; next }
  !/^#/ && $5 == 0 && $6 == 0 && $7 == 0 && $8 == 0 && ($2 in p) {
    d = (p[$2] - mu) / mu; if (d < 0) d = -d; if (d > m) m = d; n++ }
  END { if (!n || !mu) print "nan"; else printf "%.4f\n", m }' \
  $o/summary.dat $o/final/contact.dat $o/multipliers.dat)
check "Example 5.1's optimum: the pressure on the free design nodes is the area multiplier to $dev relative (<= 0.05)" \
  holds 'd <= 0.05' d="$dev"

# the energy's optimum is the most compliant of the four objectives
if [ -f out/objectives/N16-energy/summary.dat ]; then
  most=$(for k in energy compliance pressure_spread pressure_peak; do
    awk -v k=$k '$1 == "final_compliance" { print $2, k }' out/objectives/N16-$k/summary.dat; done |
    sort -g | tail -n 1 | cut -d' ' -f2)
  check "of the optima of the four objectives (N = 16) the energy's has the largest compliance (it is: $most)" \
    test "$most" = energy
else
  echo "# skip: out/objectives not there (make figures runs it): the most compliant optimum not checked"
fi

pdf=paper/article.pdf log=build/article/article.log
if [ ! -f "$pdf" ] || [ ! -f "$log" ]; then
  echo "# skip: $pdf or $log not built (make paper builds them): the article's pages, text and log not checked"
  finish; exit $?
fi
if ! command -v pdftotext > /dev/null || ! command -v pdfinfo > /dev/null; then
  fail "pdftotext and pdfinfo (Debian poppler-utils, in the Makefile's PACKAGES) are installed"
  finish; exit $?
fi
pages=$(pdfinfo "$pdf" | awk '$1 == "Pages:" { print $2 }')
check "the article has at most 40 pages ($pages)" holds 'p >= 1 && p <= 40' p="$pages"
pdftotext "$pdf" $TMP/article.txt
# the text as one line, ligatures and the minus sign plain
tr '\n' ' ' < $TMP/article.txt | sed 's/−/-/g; s/ﬁ/fi/g; s/ﬂ/fl/g; s/ﬀ/ff/g' > $TMP/text
estar=$(awk '$1 == "energy" { printf "%.7f\n", $2 / 1e7 }' out/example-5.1-optimize/summary.dat)
check "the article quotes the reproduction's E* of the run ($estar·10^7 J/m)" \
  grep -q -F -- "$estar" $TMP/text
check "the article has a bibliography (References)" grep -q 'References' $TMP/text
for w in Haslinger Hintermüller Dostál Svanberg Kraft CHOLMOD Amestoy Richardson NLopt 'GNU Scientific Library'; do
  check "the bibliography cites $w" sh -c "sed 's/.*References//' $TMP/text | grep -q -F '$w'"
done
check "the article has its section of limits and missed targets, which says what was missed" \
  sh -c "grep -q 'Limits and missed targets' $TMP/text && sed 's/.*Limits and missed targets//' $TMP/text | grep -q missed"
check "the article states that the energy optimum is the most compliant shape" \
  grep -q 'most compliant' $TMP/text
check "the article's LaTeX log: no overfull box over 5 pt, no float too large, no undefined reference" \
  sh paper/latex-log.sh article 5 "$log"

# the log check sees what it should: a planted overfull box of 6 pt, a
# float too large and an undefined reference are each found, a box of
# 4 pt is not
printf '%s\n' 'Overfull \hbox (4.1pt too wide) in paragraph at lines 1--2' > $TMP/ok.log
check "the log check lets a box of 4 pt pass" sh paper/latex-log.sh article 5 $TMP/ok.log
for planted in 'Overfull \hbox (6.2pt too wide) in paragraph at lines 1--2' \
    'LaTeX Warning: Float too large for page by 6.17978pt on input line 482.' \
    "LaTeX Warning: Reference \`P-sec:x' on page 3 undefined on input line 12."; do
  printf '%s\n' "$planted" > $TMP/bad.log
  check "the log check finds: $planted" sh -c "! sh paper/latex-log.sh article 5 $TMP/bad.log > /dev/null"
done
finish
