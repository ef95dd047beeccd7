# fig-body.gp: Fig. 5.1 / 5.3 of Haslinger & Neittaanmaki (1987), the
# initial body Omega(alpha0) and the parts of its boundary.
# Tangled from paper/figures.nw; do not edit.
# usage: gnuplot -e "solve='out/example-5.1'; out='figures/fig-5.1'; \
#                    example='5.1'" src/fig-body.gp
# reads  solve/shape.dat (x1 alpha)
# writes out.pdf and out.png
if (!exists("solve") || !exists("out")) {
  print "usage: gnuplot -e \"solve='DIR'; out='NAME'; example='5.1'\" SCRIPT"
  exit error "the variables solve and out are required"
}
if (!exists("example")) { example = "" }
xlo = -0.45; xhi = 4.55               # room for the clamp and the rollers
ylo = -0.2;  yhi = 1.5                # the foundation and the load arrows
slo = -0.01; shi = 0.07; exag = 10    # the bottom strip, x2 times exag
ucm = 4.4                             # cm per metre
left = 2.6; top = 1.4; gap = 2.2      # margins (cm)
Wcm = left + (xhi - xlo)*ucm + 0.6
Hcm = top + (yhi - ylo)*ucm + gap + (shi - slo)*exag*ucm + 1.6
dpcm = 1600.0 / Wcm; fontpt = 12
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
shape = solve."/shape.dat"
stats shape using 2 nooutput
nshape = STATS_records
stats shape using 2 every ::0::0 nooutput
a_left = STATS_min
stats shape using 2 every ::(nshape-1)::(nshape-1) nooutput
a_right = STATS_min
stats shape using 1:2 nooutput
x_gap = STATS_pos_max_y; a_max = STATS_max_y
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
  set multiplot title sprintf("Example %s: Ω({/:Italic α}^0) and the parts of its boundary", example)
  set lmargin at screen sx(left); set rmargin at screen sx(left + (xhi-xlo)*ucm)
  set tmargin at screen sy(top);  set bmargin at screen sy(top + (yhi-ylo)*ucm)
  set xrange [xlo:xhi]; set yrange [ylo:yhi]
  set xtics 0, 1, 4 out nomirror; set ytics 0, 0.5, 1 out nomirror
  set format y "%.1f"; set ylabel "{/:Italic x}_2 [m]"
  set border 3
  set object 1 rect from xlo, ylo to xhi, 0 fs pattern 5 noborder fc "gray40" back
  set arrow 1 from xlo, 0 to xhi, 0 nohead lw 2 lc "gray30" back
  set object 2 rect from -0.12, a_left to 0, 1 fs pattern 4 noborder fc "gray40" back
  r = 0.035
  do for [k=1:4] {
    set object 2+k circle at 4+r, 0.2*k size r fs empty border lc "black" lw 1.5 front
  }
  set object 7 rect from 4+2*r, a_right to 4+2*r+0.08, 1 fs pattern 4 noborder fc "gray40" back
  set arrow 2 from 4+2*r, a_right to 4+2*r, 1 nohead lw 1.5 lc "black" back
  do for [k=0:8] {
    set arrow 10+k from 2+0.25*k, 1.3 to 2+0.25*k, 1.02 head filled size 0.06,25 lw 1.5 lc "#b00000"
  }
  set arrow 19 from 2, 1.3 to 4, 1.3 nohead lw 1.5 lc "#b00000"
  set label 1 "{/:Italic P}_2 = −5.75·10^8 N/m^2" at 3, 1.41 center tc "#b00000"
  set label 2 "Ω({/:Italic α}^0)" at 1.1, 0.6 center front font sprintf(",%g", 1.4*fsz)
  set label 3 "Γ_D" at -0.17, 0.6 right
  set label 4 "Γ@^{/*0.7 1}_{/*0.7 P}" at 4.2, 0.6 left
  set label 5 "Γ@^{/*0.7 2}_{/*0.7 P}" at 1.0, 1.09 center
  set label 6 "Γ_C({/:Italic α}^0)" at 0.75, 0.14 center front
  set label 7 "rigid foundation  {/:Italic x}_2 ≤ 0" at 2, -0.1 center boxed
  set style textbox opaque noborder
  set arrow 3 from 0, a_left to 0, 1 nohead lw 2 lc "black" front
  set arrow 4 from 0, 1 to 4, 1 nohead lw 2 lc "black" front
  set arrow 5 from 4, 1 to 4, a_right nohead lw 2 lc "black" front
  plot shape using 1:2 with filledcurves y=1 fc "#dce6f2" notitle, \
       shape using 1:2 with lines lw 2 lc "black" notitle
  unset object; unset arrow; unset label
  stop = top + (yhi-ylo)*ucm + gap
  set tmargin at screen sy(stop); set bmargin at screen sy(stop + (shi-slo)*exag*ucm)
  set yrange [slo:shi]; set ytics 0, 0.02, 0.06 out nomirror format "%.2f"
  set xlabel "{/:Italic x}_1 [m]" offset 0, 0.5
  set title sprintf("the bottom strip −%g ≤ {/:Italic x}_2 ≤ %g, vertical scale exaggerated ×%g", \
                    -slo, shi, exag) offset 0, -0.3
  set object 1 rect from xlo, slo to xhi, 0 fs pattern 5 noborder fc "gray40" back
  set arrow 1 from xlo, 0 to xhi, 0 nohead lw 2 lc "gray30" back
  set object 2 rect from -0.12, a_left to 0, shi fs pattern 4 noborder fc "gray40" back
  set arrow 3 from 0, a_left to 0, shi nohead lw 2 lc "black" front
  set arrow 4 from 4, a_right to 4, shi nohead lw 2 lc "black" front
  set label 1 "Γ_C({/:Italic α}^0)" at 1.0, 0.045 center front
  set label 2 "gap" at (x_gap < 2 ? x_gap + 0.3 : x_gap - 0.3), 0.4*a_max center front \
      font sprintf(",%g", 0.9*fsz)
  plot shape using 1:2 with filledcurves y=shi fc "#dce6f2" notitle, \
       shape using 1:2 with linespoints lw 2 pt 7 ps 0.5 lc "black" notitle
  unset object; unset arrow; unset label
  unset title
  unset multiplot
  set output
}
