# fig-coulomb.gp: the figure of the section "Shape optimisation with
# Coulomb friction".  Tangled from paper/coulomb.nw; do not edit.
# usage: gnuplot -e "runs='out/coulomb'; out='figures/fig-coulomb'" src/fig-coulomb.gp
# reads  runs/N64-F<F>/final/{shape,contact}.dat (src/coulomb.sh)
# writes out.pdf and out.png
if (!exists("runs") || !exists("out")) {
  exit error "the variables runs and out are required"
}
printcm = 16.4; fontpt = 9                # the article's \textwidth, cm; text, pt
dpcm = 1600.0 / printcm
left = 1.4; gap = 1.75; top = 1.5; panelh = 4.2   # cm
Wcm = printcm
panelw = (Wcm - left - 2*gap - 0.45)/3
Hcm = top + panelh + 2.0                  # one key under the three panels
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
x0(c) = left + c*(panelw + gap)           # the left edge of panel c, cm
place(c) = sprintf("set lmargin at screen %g; set rmargin at screen %g; " \
                   ."set tmargin at screen %g; set bmargin at screen %g", \
                   sx(x0(c)), sx(x0(c) + panelw), sy(top), sy(top + panelh))
Fs = "0 0.1 0.2 0.3"
keys = words(Fs); keyy = top + panelh + 1.25
keytitle(i) = "{/:Italic F} = ".word(Fs, i)
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
  set multiplot title "Example 5.1 with Coulomb friction, optimised by SLSQP (N = 64)"
  set xlabel "{/:Italic x}_1 [m]"; set xtics 1
  eval place(0)
  unset key
  set ylabel "α* [mm]"; set title "(a) optimal contact surface"
  plot for [F in Fs] runs."/N64-F".F."/final/shape.dat" \
         using 1:($2*1000) with lines lw 1.5 notitle
  eval place(1)
  set autoscale yfixmin                   # the forces from the least one, not a tick below
  set ylabel "{/:Italic T} [10^7 N/m]"; set title "(b) normal force"; set ytics 1
  plot for [F in Fs] runs."/N64-F".F."/final/contact.dat" \
         using 1:($5/1e7) with lines lw 1.5 notitle
  eval place(2)
  set ylabel "{/:Italic T}_t [10^6 N/m]"; set title "(c) tangential force"; set ytics autofreq
  plot for [F in Fs] runs."/N64-F".F."/final/contact.dat" \
         using 1:($4 == 0 ? $8/1e6 : NaN) with lines lw 1.5 notitle
  set autoscale y; set ytics autofreq
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
