# figures.sh: the figures of the extensions (src/fig-friction.gp,
# fig-coulomb.gp, fig-objectives.gp) read at the size the paper prints
# them, \textwidth of the article (16.4 cm; issue 35.7): drawn from
# made-up runs, their PDFs' text measured (pdftotext -bbox, DejaVu Sans
# a box 1.164 times its size high) and scaled to that width: every word
# at least 8 pt (a sub- or superscript, two characters at most, 6 pt);
# the keys under the panels, below their x labels, off the data; Coulomb's
# forces, none negative, on an axis that starts at 0; the pressure of the
# objectives cut at 1200 MPa with the peak above written at the top.
. tests/lib.sh
runs=$TMP/runs
# fake DIR [PEAK]: DIR/final/shape.dat and contact.dat, 17 nodes on [0, 4],
# the pressure PEAK Pa at x1 = 2.75 (3 to 4.5e8 elsewhere)
fake() { mkdir -p $1/final
  awk 'BEGIN { for (i = 0; i <= 16; i++) { x = i / 4; print x, 0.05 * (x / 4)^2 } }' > $1/final/shape.dat
  awk -v peak=${2:-3e8} 'BEGIN { print "# x1[m] alpha[m] u2[m] gap[m] T[N/m] pressure[Pa] u1[m] Tt[N/m]"
    for (i = 0; i <= 16; i++) { x = i / 4; p = x == 2.75 ? peak : 3e8 * (1 + x / 8)
      print x, 0, 0, 0, p / 4, p, -0.001 * (1 + x), 2e6 * x } }' > $1/final/contact.dat; }
for g in 0 1e8 5e8 1e9; do fake $runs/friction/g$g; done
printf '# g E\n0 -4.09e7 0 5 6 0 15\n5e8 -3.5e7 1 5 6 3 12\n1e9 -3.4e7 1 5 6 15 0\n' > $runs/friction/energy.dat
for F in 0 0.1 0.2 0.3; do fake $runs/coulomb/N64-F$F; done
for k in energy pressure_spread pressure_peak; do fake $runs/objectives/N64-$k; done
fake $runs/objectives/N64-compliance 2.8e9

# words FIG: each word of FIG.pdf, its size at print (pt), top and bottom
# (cm from the top of the printed page), and its text; a word's size is
# the smaller side of its box (a word of the y axis is turned), a single
# character's the larger
words() { w=$(pdfinfo $1.pdf | awk '/^Page size/ { print $3 }')
  pdftotext -bbox $1.pdf - | awk -v k="$(calc '16.4 / 2.54 * 72 / w' w=$w)" '
    /<word / { for (i = 2; i <= 5; i++) { split($i, a, "\""); v[i] = a[2] }
               t = $0; sub(/.*">/, "", t); sub(/<\/word>.*/, "", t)
               w = v[4] - v[2]; h = v[5] - v[3]
               s = length(t) == 1 ? (w > h ? w : h) : (w < h ? w : h)
               printf "%.2f %.3f %.3f %s\n", s / 1.164 * k,
                      v[3] * k / 72 * 2.54, v[5] * k / 72 * 2.54, t }'; }
for fig in friction coulomb objectives; do
  out=$TMP/fig-$fig
  gnuplot -e "runs='$runs/$fig'; out='$out'" src/fig-$fig.gp 2> $TMP/err
  check "fig-$fig.gp draws the made-up runs ($(head -c 200 $TMP/err))" \
    sh -c "[ -s $out.pdf ] && [ -s $out.png ] && [ ! -s $TMP/err ]"
  words $out > $TMP/words-$fig
  small=$(awk '$1 < 7.95 && length($4) > 2 || $1 < 6 { printf "%s (%s pt) ", $4, $1 }' $TMP/words-$fig)
  check "fig-$fig at print size: no text under 8 pt (sub- and superscripts 6) [$small]" [ -z "$small" ]
done
# below BELOW ABOVE FIG: every word BELOW is under every word ABOVE
below() { awk -v b="$1" -v a="$2" '$4 == a && $3 > lo { lo = $3 } $4 == b && (hi == "" || $2 < hi) { hi = $2 }
  END { exit !(hi != "" && lo != "" && hi > lo) }' $TMP/words-$3; }
check "friction: the keys under the x labels" below sticking '[m]' friction
check "friction: the key of (a) under its x label" below 1e9 '[m]' friction
check "Coulomb: one key (F = 0.3) under the x labels" below 0.3 '[m]' coulomb
check "objectives: one key (pressure peak) under the x labels" below peak '[m]' objectives
check "Coulomb: the forces, none negative, on axes from 0 (no tick below)" \
  sh -c "! grep -q ' −' $TMP/words-coulomb"
check "objectives: the pressure cut at 1200 MPa, the peak of 2800 written at the top" sh -c \
  "grep -q ' 1200$' $TMP/words-objectives && ! grep -q ' 1400$' $TMP/words-objectives &&
   grep -q ' 2800$' $TMP/words-objectives && grep -q ' MPa$' $TMP/words-objectives"
finish
