# fig-friction.gp: the figure of the section "Given friction".
# Tangled from paper/friction.nw; do not edit.
# usage: gnuplot -e "runs='out/friction'; out='figures/fig-friction'" src/fig-friction.gp
# reads  runs/energy.dat, runs/g<g>/final/{shape,contact}.dat (src/friction.sh)
# writes out.pdf and out.png
if (!exists("runs") || !exists("out")) {
  exit error "the variables runs and out are required"
}
printcm = 16.4; fontpt = 9                # the article's \textwidth, cm; text, pt
dpcm = 1600.0 / printcm
left = 1.4; gap = 1.9; top = 1.5; panelh = 4.2   # cm
Wcm = printcm                             # 1.9 cm on the right for (c)'s slip axis
panelw = (Wcm - left - 2*gap - 1.9)/3
Hcm = top + panelh + 3.3                  # the keys under (a) and (c)
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
x0(c) = left + c*(panelw + gap)           # the left edge of panel c, cm
keyat(c) = sprintf("set key at screen %g, %g left top vertical maxrows 4 Left reverse " \
                   ."samplen 2 spacing 1.1 font ',%g'", \
                   sx(x0(c) - 1.0), sy(top + panelh + 1.35), fsz)
place(c) = sprintf("set lmargin at screen %g; set rmargin at screen %g; " \
                   ."set tmargin at screen %g; set bmargin at screen %g", \
                   sx(x0(c)), sx(x0(c) + panelw), sy(top), sy(top + panelh))
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
  set multiplot title "Example 5.1 with given friction (Tresca)"
  eval place(0)
  unset y2tics; unset y2label; set ytics mirror   # left over from panel (c)
  set xlabel "{/:Italic x}_1 [m]"; set ylabel "α* [mm]"
  set title "(a) optimal contact surface"
  set xtics 1; eval keyat(0)                # the key under the panel, off the curves
  plot for [g in "0 1e8 5e8 1e9"] runs."/g".g."/final/shape.dat" \
         using 1:($2*1000) with linespoints pt 7 ps 0.5 lw 1.5 title "g = ".g." Pa"
  eval place(1)
  set xtics autofreq
  set xlabel "g [10^8 Pa]"; set ylabel "E* [10^7 J/m]"
  set title "(b) optimal energy"
  plot runs."/energy.dat" using ($1/1e8):($2/1e7) with linespoints pt 7 ps 0.7 lw 1.5 notitle
  eval place(2)
  set xlabel "{/:Italic x}_1 [m]"; set ylabel "force [10^7 N/m]"
  set y2label "slip {/:Italic u}_1 [mm]"; set y2tics; set ytics nomirror
  set title "(c) optimum for g = 5·10^8 Pa"
  set xtics 1; eval keyat(2)
  c = runs."/g5e8/final/contact.dat"
  plot c using 1:($5/1e7) with linespoints pt 7 ps 0.5 lw 1.5 title "normal {/:Italic T}", \
       c using 1:($8/1e7) with linespoints pt 5 ps 0.5 lw 1.5 title "tangential {/:Italic T}_t", \
       c using 1:($7 == 0 && $8 != 0 ? $8/1e7 : NaN) \
         with points pt 6 ps 1.6 lc "gray30" title "sticking", \
       c using 1:($7*1000) axes x1y2 \
         with linespoints pt 9 ps 0.5 lw 1.5 dt 2 title "slip {/:Italic u}_1"
  unset multiplot
  set output
}
