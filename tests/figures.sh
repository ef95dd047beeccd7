# figures.sh: the figures of the extensions (src/fig-friction.gp,
# fig-coulomb.gp, fig-objectives.gp) read at the size the paper prints
# them, \textwidth of the article (16.4 cm; issue 35.7): drawn from
# made-up runs, their PDFs' text measured (pdftotext -bbox, DejaVu Sans
# a box 1.164 times its size high) and scaled to that width: every word
# at least 8 pt (a sub- or superscript, three characters at most, 6 pt);
# the keys under the panels, below their x labels, off the data; Coulomb's
# forces, none negative, on an axis that starts at 0; the pressure of the
# objectives cut at 1200 MPa with the peak above written at the top;
# no two words of a figure on each other; the results figures of
# Section 5 (contactopt plot --results) at the same size, and the
# article's own figures where make paper has drawn them; the accuracy figure
# (src/fig-accuracy.gp, drawn from a made-up sweep) with a key under
# each panel, for what that panel draws.
. tests/lib.sh
runs=$TMP/runs
# fake DIR [PEAK]: DIR/final/shape.dat and contact.dat, 17 nodes on [0, 4],
# the pressure PEAK Pa at x1 = 2.75 (3 to 4.5e8 elsewhere), the forces
# at x1 = 0 a rounding below zero (-1 N/m)
fake() { mkdir -p $1/final
  awk 'BEGIN { for (i = 0; i <= 16; i++) { x = i / 4; print x, 0.05 * (x / 4)^2 } }' > $1/final/shape.dat
  awk -v peak=${2:-3e8} 'BEGIN { print "# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa] u1[m] Tt[N/m]"
    for (i = 0; i <= 16; i++) { x = i / 4; p = x == 2.75 ? peak : 3e8 * (1 + x / 8)
      print x, 0, 0, 0, x ? p / 4 : -1, p, -0.001 * (1 + x), x ? 2e6 * x : -1 } }' > $1/final/contact.dat; }
for g in 0 1e8 5e8 1e9; do fake $runs/friction/g$g; done
printf '# g E\n0 -4.09e7 0 5 6 0 15\n5e8 -3.5e7 1 5 6 3 12\n1e9 -3.4e7 1 5 6 15 0\n' > $runs/friction/energy.dat
for F in 0 0.1 0.2 0.3; do fake $runs/coulomb/N64-F$F; done
for k in energy pressure_spread pressure_peak; do fake $runs/objectives/N64-$k; done
fake $runs/objectives/N64-compliance 2.8e9
# a sweep of accuracy.sh's columns: each family on its meshes (N), its
# tolerances (the exponents e), its error falling with both
mkdir -p $runs/accuracy
awk 'BEGIN { print "# nmax 128"; print "# E_inf -4.19e7"
  split("mesh projgrad slsqp-schur slsqp-euclidean", v, " ")
  for (i = 1; i <= 4; i++) for (N = 16; N <= 128; N *= 2)
    row(v[i], N, "pdas", -10, "newton", -6, 0.0003 * 16 / N, i == 1 ? 0 : 1e-14 * i * N, N^2 / 1000 * i)
  split("pdas-64 cgssor-64 pdas-128 cgssor-128 opttol-64 opttol-128", f, " ")
  for (i = 1; i <= 6; i++) for (e = -4; e >= -12; e -= 2) {
    N = f[i] ~ /128/ ? 128 : 64; o = f[i] ~ /opttol/
    row(f[i], N, f[i] ~ /cgssor/ ? "cgssor" : "pdas", o ? -10 : e, "newton", o ? e / 2 : -6,
        0.0003 * 16 / N, 10^(e - 1), 10^(i - 3) * (1 - e / 10)) } }
  function row(fam, N, st, t, m, o, err, same, sec) {
    printf "%s N%d %d %s 1e%d %s 1e%d %.9g %.3e %.3e 0 6 %g 5 converged %g\n", fam, N, N, st, t, m, o,
           -4.19e7 * (1 - err), err, same, sec, sec / 20 }' > $runs/accuracy/sweep.dat

# words FIG [CM]: each word of FIG.pdf, its size at print (pt), top and
# bottom (cm from the top of the printed page), and its text, printed CM
# wide (16.4 unless given); a word's size is the smaller side of its box
# (a word of the y axis is turned), a single character's the larger
words() { w=$(pdfinfo $1.pdf | awk '/^Page size/ { print $3 }')
  pdftotext -bbox $1.pdf - | awk -v k="$(calc 'cm / 2.54 * 72 / w' cm=${2:-16.4} w=$w)" '
    /<word / { for (i = 2; i <= 5; i++) { split($i, a, "\""); v[i] = a[2] }
               t = $0; sub(/.*">/, "", t); sub(/<\/word>.*/, "", t)
               w = v[4] - v[2]; h = v[5] - v[3]
               s = length(t) == 1 ? (w > h ? w : h) : (w < h ? w : h)
               printf "%.2f %.3f %.3f %s %.3f %.3f\n", s / 1.164 * k,
                      v[3] * k / 72 * 2.54, v[5] * k / 72 * 2.54, t,
                      v[2] * k / 72 * 2.54, v[4] * k / 72 * 2.54 }'; }
# off_page FIG: the words of FIG.pdf whose box passes an edge of the page
# by more than 1 pt (a clipped label), "WORD" each
off_page() { pdftotext -bbox $1.pdf - | awk -v W="$(pdfinfo $1.pdf | awk '/^Page size/ { print $3 }')" \
    -v H="$(pdfinfo $1.pdf | awk '/^Page size/ { print $5 }')" '
  /<word / { split($0, a, "\""); t = $0; sub(/.*">/, "", t); sub(/<\/word>.*/, "", t)
             if (a[2] < -1 || a[4] < -1 || a[6] > W + 1 || a[8] > H + 1) printf "%s ", t }'; }
# small NAME MIN: the words of $TMP/words-NAME printed under 8 pt (a
# sub- or superscript of at most 3 characters under 6), "WORD (SIZE pt)"
# each, or a note when it read fewer than MIN words
small() { LC_ALL=C awk -v min=$2 '{ t = $4; gsub(/[\200-\277]/, "", t) }  # characters, not bytes
    $1 < 7.95 && length(t) > 3 || $1 < 6 { printf "%s (%s pt) ", $4, $1 }
    END { if (NR < min) print "(only", NR, "words)" }' $TMP/words-$1 || echo "(awk failed)"; }
# overlaps FIG: the pairs of words of FIG whose boxes overlap by more than
# 0.03 cm either way
overlaps() { awk '{ t[NR] = $2; b[NR] = $3; w[NR] = $4; l[NR] = $5; r[NR] = $6 }
  END { for (i = 1; i <= NR; i++) for (j = i + 1; j <= NR; j++)
          if ((r[i] < r[j] ? r[i] : r[j]) - (l[i] > l[j] ? l[i] : l[j]) > 0.03 &&
              (b[i] < b[j] ? b[i] : b[j]) - (t[i] > t[j] ? t[i] : t[j]) > 0.03)
            printf "%s/%s ", w[i], w[j] }' $TMP/words-$1; }
for fig in friction coulomb objectives accuracy; do
  out=$TMP/fig-$fig
  if [ $fig = accuracy ]; then
    gnuplot -e "sweep='$runs/accuracy/sweep.dat'; once='data/accuracy-once.dat'; out='$out'" \
      src/fig-accuracy.gp 2> $TMP/err
  else gnuplot -e "runs='$runs/$fig'; out='$out'" src/fig-$fig.gp 2> $TMP/err; fi
  check "fig-$fig.gp draws the made-up runs ($(head -c 200 $TMP/err))" \
    sh -c "[ -s $out.pdf ] && [ -s $out.png ] && [ ! -s $TMP/err ]"
  words $out > $TMP/words-$fig
  small=$(small $fig 20)
  check "fig-$fig at print size: no text under 8 pt (sub- and superscripts 6) [$small]" [ -z "$small" ]
  on=$(overlaps $fig)
  check "fig-$fig: no word on another [$on]" [ -z "$on" ]
  off=$(off_page $out)
  check "fig-$fig: every word on the page [$off]" [ -z "$off" ]
done
# the results figures of Section 5 (Figs. 5.2 and 5.4: contactopt plot
# --results, the gnuplot text of paper/figures.nw), drawn from a run of
# Example 5.1 and read the same way at the 16.4 cm they print at: no
# text under 8 pt (sub- and superscripts 6), no word on another (the
# marks of the points, which data may put on each other, left out)
$BIN solve data/example-5.1.scene -o $runs/results-start > /dev/null 2>&1 &&
  $BIN optimize data/example-5.1.scene -o $runs/results > /dev/null 2>&1 &&
  $BIN plot $runs/results --results --start $runs/results-start --title 'Example 5.1' \
    -o $TMP/fig-results > /dev/null 2> $TMP/err
check "contactopt plot --results draws Example 5.1 ($(head -c 200 $TMP/err))" \
  sh -c "[ -s $TMP/fig-results.pdf ] && [ -s $TMP/fig-results.png ]"
words $TMP/fig-results | awk '$4 !~ /^(▷|◁|○|●|□|■|△|▽)$/' > $TMP/words-results
small=$(small results 20)
check "the results figure at print size: no text under 8 pt (sub- and superscripts 6) [$small]" [ -z "$small" ]
on=$(overlaps results)
check "the results figure: no word on another [$on]" [ -z "$on" ]
off=$(off_page $TMP/fig-results)
check "the results figure: every word on the page [$off]" [ -z "$off" ]
# the body figure (Figs. 5.1 and 5.3: contactopt plot --body) of the
# same start, read the same way: the sides' names and their stacked
# scripts (Gamma_P^1) too at 8 pt (scripts 6) or more, no word on another
# (but the two scripts of a Gamma_P^k, stacked at the same place)
$BIN plot $runs/results-start --body --title 'Example 5.1' -o $TMP/fig-body > /dev/null 2> $TMP/err
check "contactopt plot --body draws Example 5.1 ($(head -c 200 $TMP/err))" \
  sh -c "[ -s $TMP/fig-body.pdf ] && [ -s $TMP/fig-body.png ]"
# (a stacked pair, "1P", is read as its digit: its width over a digit's
# advance in DejaVu Sans, 0.636 of the font's size)
words $TMP/fig-body | awk '$4 ~ /^[0-9]P$/ { $1 = sprintf("%.2f", ($6 - $5) / 0.636 / 2.54 * 72) } 1' \
  > $TMP/words-body
small=$(small body 20)
check "the body figure at print size: no text under 8 pt (sub- and superscripts 6) [$small]" [ -z "$small" ]
on=$(overlaps body | tr ' ' '\n' | grep -v -E '^[0-9]+/P$' | tr '\n' ' ' | sed 's/ *$//')
check "the body figure: no word on another [$on]" [ -z "$on" ]
off=$(off_page $TMP/fig-body)
check "the body figure: every word on the page [$off]" [ -z "$off" ]

# the article's own figures (paper/article-*.gp), where make paper has
# drawn them: the article includes them at their own size (16 cm wide)
for f in figures/article-*.pdf; do
  [ -f "$f" ] || { echo "# skip: no figures/article-*.pdf (make paper draws them)"; break; }
  n=$(basename $f .pdf)
  words ${f%.pdf} 16 | awk '$4 !~ /^(▷|◁|○|●|□|■|△|▽)$/' > $TMP/words-$n
  small=$(small $n 10)
  check "$n at print size: no text under 8 pt (sub- and superscripts 6) [$small]" [ -z "$small" ]
  on=$(overlaps $n)
  check "$n: no word on another [$on]" [ -z "$on" ]
  off=$(off_page ${f%.pdf})
  check "$n: every word on the page [$off]" [ -z "$off" ]
done

# below BELOW ABOVE FIG: every word BELOW is under every word ABOVE
below() { awk -v b="$1" -v a="$2" '$4 == a && $3 > lo { lo = $3 } $4 == b && (hi == "" || $2 < hi) { hi = $2 }
  END { exit !(hi != "" && lo != "" && hi > lo) }' $TMP/words-$3; }
check "friction: the keys under the x labels" below sticking '[m]' friction
check "friction: the key of (a) under its x label" below 1e9 '[m]' friction
check "Coulomb: one key (F = 0.3) under the x labels" below 0.3 '[m]' coulomb
check "objectives: one key (pressure peak) under the x labels" below peak '[m]' objectives
# beside FIG WORD SIDE: WORD (in a key) lies wholly on SIDE (left, right)
# of the middle of the page, and below the x labels (under the panels)
beside() { awk -v w="$2" -v s=$3 '$4 == "[s]" && $3 > lo { lo = $3 } $4 == w { n++
    if ((s == "left" ? $6 < 8.2 : $5 > 8.2) && $2 > top) top = $2; else bad = 1 }
  END { exit !(n && !bad && top > lo) }' $TMP/words-$1; }
check "accuracy: (a)'s key (SLSQP euclidean) under (a)" beside accuracy euclidean, left
key_b() { [ "$(awk '$4 == "optimizer.tol" { n++ } END { print n }' $TMP/words-accuracy)" = 1 ] &&
  beside accuracy optimizer.tol right && beside accuracy cgssor right; }
check "accuracy: (b)'s key (optimizer.tol, cgssor) under (b), one entry for both meshes" key_b
has() { awk -v w="$2" '$4 == w { n++ } END { exit !n }' $TMP/words-$1; }
no_minus() { awk '$4 ~ /^−/ { bad = 1 } END { exit bad }' $TMP/words-$1; }
check "Coulomb: the forces, none negative, on axes from 0 (no tick below)" no_minus coulomb
cut() { has objectives 1200 && ! has objectives 1400 && has objectives 2800 && has objectives MPa; }
check "objectives: the pressure cut at 1200 MPa, the peak of 2800 written at the top" cut
finish
