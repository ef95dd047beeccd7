# fig-results.gp: Fig. 5.2 / 5.4 of Haslinger & Neittaanmaki (1987), the
# initial and final states, E_h against iteration, and the contact stress.
# Tangled from paper/figures.nw; do not edit.
# usage: gnuplot -e "solve='out/example-5.1'; opt='out/example-5.1-optimize'; \
#                    out='figures/fig-5.2'; example='5.1'" src/fig-results.gp
# reads  solve/{triangles,nodes,contact,summary}.dat (the article's alpha0),
#        opt/history.dat, opt/final/{triangles,nodes,contact}.dat
# writes out.pdf and out.png
if (!exists("solve") || !exists("out")) {
  print "usage: gnuplot -e \"solve='DIR'; out='NAME'; example='5.1'\" SCRIPT"
  exit error "the variables solve and out are required"
}
if (!exists("example")) { example = "" }
if (!exists("opt")) {
  exit error "the variable opt (the folder of contactopt optimize) is required"
}
bxlo = -0.1; bxhi = 4.1; bylo = -0.25; byhi = 1.1
left = 2.8; colw = 10.8; colgap = 2.4    # cm
top = 2.4; rowgap = 2.3; graphh = 5.0     # cm
ucm = colw / (bxhi - bxlo)                # cm per metre in the body panels
bodyh = (byhi - bylo) * ucm
Wcm = left + 2*colw + colgap + 0.5
Hcm = top + 3*bodyh + 3*rowgap + graphh + 1.6
dpcm = 1600.0 / Wcm; fontpt = 12
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
colx(c) = left + c*(colw + colgap)        # left edge of column c = 0, 1
rowy(r) = top + r*(bodyh + rowgap)        # top edge of body row r = 0, 1, 2
umax = 0.2      # the largest scaled displacement, as a fraction of the height 1
round_down(x) = (p = 10**floor(log10(x)), m = x/p, (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p)
stats solve."/nodes.dat" using (sqrt($6**2 + $7**2)) nooutput
S0 = round_down(umax / STATS_max)
stats opt."/final/nodes.dat" using (sqrt($6**2 + $7**2)) nooutput
S1 = round_down(umax / STATS_max)
do for [fmt in "pdf png"] {
  set encoding utf8; set minussign
  dpi = dpcm * 2.54
  kfont = fmt eq "pdf" ? 1.5 : dpi/96.0     # nominal font size per point
  klw = fmt eq "pdf" ? 1.0 : 0.5*dpi/72.0   # nominal line width per half point
  fsz = kfont * fontpt
  if (fmt eq "pdf") {
    set terminal pdfcairo enhanced color size Wcm/2.54, Hcm/2.54 \
        font sprintf("DejaVu Sans,%.2f", fsz) linewidth klw
  } else {
    set terminal pngcairo enhanced color size int(Wcm*dpcm), int(Hcm*dpcm) \
        font sprintf("DejaVu Sans,%.2f", fsz) linewidth klw background "white"
  }
  set output out.".".fmt
  unset xlabel; unset ylabel; unset title   # left over from the other format
  set multiplot title sprintf("Example %s: numerical results", example)
  do for [c=0:1] {
    dir = c == 0 ? solve : opt."/final"
    S = c == 0 ? S0 : S1
    name = c == 0 ? "Ω({/:Italic α}^0)" : "Ω({/:Italic α}^*)"
    do for [r=0:2] {
      set lmargin at screen sx(colx(c)); set rmargin at screen sx(colx(c) + colw)
      set tmargin at screen sy(rowy(r)); set bmargin at screen sy(rowy(r) + bodyh)
      set xrange [bxlo:bxhi]; set yrange [bylo:byhi]
      set xtics 0, 1, 4 out nomirror; set ytics 0, 0.5, 1 out nomirror
      set border 3
      letter = "abcdefg"[c*4 + r + 1 : c*4 + r + 1]
      if (r == 0) {
        set title sprintf("(%s) triangulation of %s", letter, name)
        set object 1 rect from bxlo, bylo to bxhi, 0 fs pattern 5 noborder fc "gray50" back
        plot dir."/triangles.dat" using 1:2 with lines lw 1 lc "black" notitle
        unset object 1
      }
      if (r == 1) {
        set title sprintf("(%s) %s after deformation, displacements × %g", letter, name, S)
        plot dir."/triangles.dat" using 1:2 with lines lw 0.5 lc "gray75" notitle, \
             dir."/triangles.dat" using ($1 + S*$3):($2 + S*$4) with lines lw 1 lc "#1f4e99" notitle
      }
      if (r == 2) {
        set title sprintf("(%s) displacement field ({/:Italic u}_1, {/:Italic u}_2) × %g", letter, S)
        plot dir."/triangles.dat" using 1:2 with lines lw 0.5 lc "gray75" notitle, \
             dir."/nodes.dat" using 4:5:(S*$6):(S*$7) with vectors head filled size 0.04,20 \
                 lw 1.2 lc "#b00000" notitle
      }
    }
  }
  unset title; set border 3; set ytics autofreq; set xtics autofreq
  set lmargin at screen sx(colx(0)); set rmargin at screen sx(colx(0) + colw)
  set tmargin at screen sy(rowy(3)); set bmargin at screen sy(rowy(3) + graphh)
  set title "(d) {/:Italic E_h} against iteration"
  set xlabel "iteration" offset 0, 0.4
  set ylabel "{/:Italic E_h} [10^7 J/m]"
  set xrange [*:*]; set autoscale xfix; set yrange [*:*]; set offsets 0.5, 0.5, 0, 0
  set xtics 0, 5 out nomirror; set ytics autofreq out nomirror
  set key top right spacing 1.2
  plot opt."/history.dat" using 1:($2/1e7) with linespoints pt 7 ps 0.6 lw 1.5 \
           lc "#1f4e99" title "iterates, from {/:Italic α}^0 projected onto {/:Italic B}", \
       solve."/summary.dat" using (0):(strcol(1) eq "energy" ? $2/1e7 : NaN) \
           with points pt 6 ps 1.2 lc "black" title "{/:Italic α}^0 as given, outside {/:Italic B}"
  set offsets 0, 0, 0, 0
  set lmargin at screen sx(colx(1)); set rmargin at screen sx(colx(1) + colw)
  set title "(h) contact pressure along Γ_C"
  set xlabel "{/:Italic x}_1 [m]" offset 0, 0.4
  set ylabel "−{/:Italic T}_2 [10^8 N/m^2]"
  set xrange [0:4]; set yrange [-0.5:*]; set xtics 0, 1, 4 out nomirror
  set key top left
  plot solve."/contact.dat" using 1:($6/1e8) with linespoints pt "▷" ps 1.3 lw 1.2 \
           lc "#b00000" title "initial {/:Italic α}^0", \
       opt."/final/contact.dat" using 1:($6/1e8) with linespoints pt "◁" ps 1.3 lw 1.2 \
           lc "#1f4e99" title "final {/:Italic α}^*"
  unset multiplot
  set output
}
