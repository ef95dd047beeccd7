# fig-objectives.gp: the figure of the section "Designing for the
# pressure".  Tangled from paper/objective.nw; do not edit.
# usage: gnuplot -e "runs='out/objectives'; out='figures/fig-objectives'" src/fig-objectives.gp
# reads  runs/N64-<kind>/final/{shape,contact}.dat (src/objectives.sh)
# writes out.pdf and out.png
if (!exists("runs") || !exists("out")) {
  exit error "the variables runs and out are required"
}
left = 2.6; panelw = 9.0; gap = 2.9; top = 1.9; panelh = 6.6   # cm
Wcm = left + 2*panelw + gap + 1.0
Hcm = top + panelh + 2.2
dpcm = 1600.0 / Wcm; fontpt = 12
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
x0(c) = left + c*(panelw + gap)           # the left edge of panel c, cm
place(c) = sprintf("set lmargin at screen %g; set rmargin at screen %g; " \
                   ."set tmargin at screen %g; set bmargin at screen %g", \
                   sx(x0(c)), sx(x0(c) + panelw), sy(top), sy(top + panelh))
kinds = "energy compliance pressure_spread pressure_peak"
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
  set multiplot title "Example 5.1 optimised for each objective by SLSQP (N = 64)"
  keyfont = sprintf(",%g", 0.85*fsz)
  set key inside top right Left reverse samplen 2 font keyfont noenhanced
  set xlabel "{/:Italic x}_1 [m]"
  eval place(0)
  set ylabel "α* [mm]"; set title "(a) optimal contact surface"
  plot for [k in kinds] runs."/N64-".k."/final/shape.dat" \
         using 1:($2*1000) with lines lw 1.5 title k
  eval place(1)
  set key inside top left
  set ylabel "{/:Italic p} [MPa]"; set title "(b) contact pressure"
  plot for [k in kinds] runs."/N64-".k."/final/contact.dat" \
         using 1:($4 == 0 ? $6/1e6 : 0) with lines lw 1.5 title k
  unset multiplot
  set output
}
