# fig-objectives.gp: the figure of the section "Designing for the
# pressure".  Tangled from paper/objective.nw; do not edit.
# usage: gnuplot -e "runs='out/objectives'; out='figures/fig-objectives'" src/fig-objectives.gp
# reads  runs/N64-<kind>/final/{shape,contact}.dat (src/objectives.sh)
# writes out.pdf and out.png
if (!exists("runs") || !exists("out")) {
  exit error "the variables runs and out are required"
}
printcm = 16.4; fontpt = 9                # the article's \textwidth, cm; text, pt
dpcm = 1600.0 / printcm
left = 1.4; gap = 2.0; top = 1.5; panelh = 4.6   # cm
Wcm = printcm
panelw = (Wcm - left - gap - 0.45)/2
Hcm = top + panelh + 2.2                  # one key under the two panels
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
x0(c) = left + c*(panelw + gap)           # the left edge of panel c, cm
place(c) = sprintf("set lmargin at screen %g; set rmargin at screen %g; " \
                   ."set tmargin at screen %g; set bmargin at screen %g", \
                   sx(x0(c)), sx(x0(c) + panelw), sy(top), sy(top + panelh))
kinds = "energy compliance pressure_spread pressure_peak"
keys = words(kinds); keyy = top + panelh + 1.25
keytitle(i) = word("energy compliance 'pressure spread' 'pressure peak'", i)
pclip = 1200                              # MPa: the top of (b)
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
    set terminal pngcairo enhanced color size int(Wcm*dpcm + 0.5), int(Hcm*dpcm) \
        font sprintf("DejaVu Sans,%.2f", fsz) linewidth klw background "white"
  }
  set output out.".".fmt
  unset xlabel; unset ylabel; unset title   # left over from the other format
  set multiplot title "Example 5.1 optimised for each objective by SLSQP (N = 64)"
  unset key
  set xlabel "{/:Italic x}_1 [m]"; set xtics 1
  eval place(0)
  set ylabel "α* [mm]"; set title "(a) optimal contact surface"
  plot for [k in kinds] runs."/N64-".k."/final/shape.dat" \
         using 1:($2*1000) with lines lw 1.5 notitle
  eval place(1)
  set ylabel "{/:Italic p} [MPa]"; set title "(b) contact pressure"
  do for [i = 1:keys] {
    stats runs."/N64-".word(kinds, i)."/final/contact.dat" \
          using 1:($4 == 0 ? $6/1e6 : 0) nooutput
    if (STATS_max_y > pclip) {
      set label i sprintf("%.0f MPa ↑", STATS_max_y) at STATS_pos_max_y, pclip \
          right offset -0.5, -0.8 tc lt i font sprintf(",%g", fsz)
    }
  }
  set yrange [0:pclip]
  plot for [k in kinds] runs."/N64-".k."/final/contact.dat" \
         using 1:($4 == 0 ? $6/1e6 : 0) with lines lw 1.5 notitle
  unset label; set autoscale y
  set lmargin at screen sx(left); set rmargin at screen sx(Wcm - 0.45)
  unset border; unset tics; unset xlabel; unset ylabel; unset title
  set xrange [0:1]; set yrange [0:1]
  keyfont = sprintf(",%g", fsz)
  set key at screen 0.5, sy(keyy) center top horizontal maxrows 1 \
      Left reverse samplen 2 width 1 font keyfont
  plot for [i = 1:keys] NaN with lines lw 1.5 title keytitle(i)
  set border; set tics; set autoscale xy; unset key
  unset multiplot
  set output
}
