# fig-coulomb.gp: the figure of the section "Shape optimisation with
# Coulomb friction".  Tangled from paper/coulomb.nw; do not edit.
# usage: gnuplot -e "runs='out/coulomb'; out='figures/fig-coulomb'" src/fig-coulomb.gp
# reads  runs/N64-F<F>/final/{shape,contact}.dat (src/coulomb.sh)
# writes out.pdf and out.png
if (!exists("runs") || !exists("out")) {
  exit error "the variables runs and out are required"
}
left = 2.6; panelw = 7.2; gap = 2.9; top = 1.9; panelh = 6.6   # cm
Wcm = left + 3*panelw + 2*gap + 1.0
Hcm = top + panelh + 2.2
dpcm = 1600.0 / Wcm; fontpt = 12
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
x0(c) = left + c*(panelw + gap)           # the left edge of panel c, cm
place(c) = sprintf("set lmargin at screen %g; set rmargin at screen %g; " \
                   ."set tmargin at screen %g; set bmargin at screen %g", \
                   sx(x0(c)), sx(x0(c) + panelw), sy(top), sy(top + panelh))
Fs = "0 0.1 0.2 0.3"
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
  set multiplot title "Example 5.1 with Coulomb friction, optimised by SLSQP (N = 64)"
  keyfont = sprintf(",%g", 0.85*fsz)
  set key inside bottom right Left reverse samplen 2 font keyfont
  set xlabel "{/:Italic x}_1 [m]"
  eval place(0)
  set ylabel "α* [mm]"; set title "(a) optimal contact surface"
  plot for [F in Fs] runs."/N64-F".F."/final/shape.dat" \
         using 1:($2*1000) with lines lw 1.5 title "F = ".F
  eval place(1)
  set key inside top left
  set ylabel "{/:Italic T} [10^7 N/m]"; set title "(b) normal nodal force"
  plot for [F in Fs] runs."/N64-F".F."/final/contact.dat" \
         using 1:($5/1e7) with lines lw 1.5 title "F = ".F
  eval place(2)
  set ylabel "{/:Italic T}_t [10^6 N/m]"; set title "(c) tangential nodal force"
  plot for [F in Fs] runs."/N64-F".F."/final/contact.dat" \
         using 1:($4 == 0 ? $8/1e6 : NaN) with lines lw 1.5 title "F = ".F
  unset multiplot
  set output
}
