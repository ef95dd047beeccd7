# fig-accuracy.gp: the figure of the section "What accuracy costs", the
# error of the optimal energy against the time of the run.
# Tangled from paper/accuracy.nw; do not edit.
# usage: gnuplot -e "sweep='out/accuracy/sweep.dat'; once='data/accuracy-once.dat'; \
#                     out='figures/accuracy-time'" src/fig-accuracy.gp
# reads  sweep (written by src/accuracy.sh) and once (the finer meshes
#        measured once)
# writes out.pdf and out.png
if (!exists("sweep") || !exists("once") || !exists("out")) {
  print "usage: gnuplot -e \"sweep='out/accuracy/sweep.dat'; once='data/accuracy-once.dat'; " . \
        "out='NAME'\" SCRIPT"
  exit error "the variables sweep, once and out are required"
}
families = system("awk '!/^#/ && NF && !seen[$1]++ { printf \"%s \", $1 }' ".sweep)
nmax = system("awk '$2 == \"nmax\" { print $3 }' ".sweep) + 0
ncap = nmax < 128 ? nmax : 128    # the optimiser families stop at N = 128
Einf = real(system("awk '$2 == \"E_inf\" { print $3 }' ".sweep))
onceN = system("awk '!/^#/ && NF { printf \"%s%s\", s, $1; s = \", \" }' ".once)
inf = "\342\210\236"              # the infinity sign, U+221E, in UTF-8
varN = ""; oneN = ""
do for [f in families] {
  if (f eq "mesh" || f eq "projgrad" || f[1:6] eq "slsqp-") { varN = varN." ".f } \
  else { oneN = oneN." ".f }
}
printcm = 16.4; fontpt = 9                # the article's \textwidth, cm; text, pt
dpcm = 1600.0 / printcm
left = 1.7; gap = 1.9; top = 1.5; panelh = 5.0   # cm
Wcm = printcm
panelw = (Wcm - left - gap - 0.6)/2
keytop = top + panelh + 1.3; keyh = 2.8   # the keys under the panels
Hcm = keytop + keyh
sx(cm) = cm / Wcm
sy(cm) = 1.0 - cm / Hcm
fam_rest(f) = f[strstrt(f, "-") + 1:]
fam_first(f) = f[1:strstrt(f, "-") - 1]
fam_title(f) = f eq "mesh" ? sprintf("mesh, {/:Italic N} = 16...%d", nmax) : \
  f eq "projgrad" ? sprintf("Alg. 4.1, {/:Italic N} = 16...%d", ncap) : \
  f[1:6] eq "slsqp-" ? sprintf("SLSQP %s, {/:Italic N} = 16...%d", fam_rest(f), ncap) : \
  f[1:7] eq "opttol-" ? sprintf("optimizer.tol, {/:Italic N} = %s", fam_rest(f)) : \
  sprintf("%s solver.tol, {/:Italic N} = %s", fam_first(f), fam_rest(f))
fam_color(f) = f eq "mesh" ? "black" : f[1:5] eq "pdas-" ? "#1f4e99" : \
  f[1:7] eq "cgssor-" ? "#d95f02" : f eq "projgrad" ? "#1b9e77" : \
  f eq "slsqp-schur" ? "#e7298a" : f[1:6] eq "slsqp-" ? "#7570b3" : "#b00000"
fam_pt(f) = fam_rest(f) eq "128" ? 6 : f eq "projgrad" ? 5 : f eq "slsqp-schur" ? 11 : \
  f[1:6] eq "slsqp-" ? 9 : 7
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
  unset label                      # the labels of N, set for the other format
  set multiplot title sprintf("Example 5.1: accuracy against time (ACCURACY\\_NMAX = %d)", nmax)
  c = 0
  set lmargin at screen sx(left + c*(panelw + gap))
  set rmargin at screen sx(left + c*(panelw + gap) + panelw)
  set tmargin at screen sy(top); set bmargin at screen sy(top + panelh)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xtics out nomirror; set ytics out nomirror; set border 3
  set xlabel "time of the optimisation [s]" offset 0, 0.3
  keyfont = sprintf(",%g", fsz)
  set key at screen sx(left + c*(panelw + gap) - 1.2), sy(keytop) left top vertical \
      spacing 1.1 samplen 2 Left reverse font keyfont
  set ylabel sprintf("|{/:Italic E}^* − {/:Italic E}_%s| / |{/:Italic E}_%s|", inf, inf)
  set title "(a) error against the limit"
  set autoscale y                    # not the range (b) set for the other format
  set xtics 100
  plot for [f in varN] sweep using (strcol(1) eq f ? $13 : NaN):9 \
         with linespoints lw 1.5 pt fam_pt(f) ps 0.9 lc rgb fam_color(f) title fam_title(f), \
       sweep using (strcol(1) eq "mesh" ? $16 : NaN):9:($13 - $16):(0) \
         with vectors nohead dt 3 lw 1 lc rgb "gray50" notitle, \
       sweep using (strcol(1) eq "mesh" ? $16 : NaN):9 \
         with points pt 6 ps 0.9 lc rgb "gray30" title "one factorisation of its mesh", \
       sweep using (strcol(1) eq "mesh" ? $13 : NaN):9:(sprintf("%d", $3)) \
         with labels offset 0, 0.8 font sprintf(",%g", 0.9*fsz) notitle, \
       once using 8:(abs($2 - Einf) / abs(Einf)):($5 - $8):(0) \
         with vectors nohead dt 3 lw 1 lc rgb "gray50" notitle, \
       once using 8:(abs($2 - Einf) / abs(Einf)) with points pt 6 ps 0.9 lc rgb "gray30" notitle, \
       once using 5:(abs($2 - Einf) / abs(Einf)) with points pt 6 ps 0.9 lc rgb "black" \
         title sprintf("mesh, {/:Italic N} = %s, once", onceN), \
       once using 5:(abs($2 - Einf) / abs(Einf)):(sprintf("%d", $1)) \
         with labels offset 0, 0.8 font sprintf(",%g", 0.9*fsz) notitle
  c = 1; eps = 1e-15
  set lmargin at screen sx(left + c*(panelw + gap))
  set rmargin at screen sx(left + c*(panelw + gap) + panelw)
  set tmargin at screen sy(top); set bmargin at screen sy(top + panelh)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xtics out nomirror; set ytics out nomirror; set border 3
  set xlabel "time of the optimisation [s]" offset 0, 0.3
  keyfont = sprintf(",%g", fsz)
  set key at screen sx(left + c*(panelw + gap) - 1.2), sy(keytop) left top vertical \
      spacing 1.1 samplen 2 Left reverse font keyfont
  set ylabel sprintf("|{/:Italic E}^* − {/:Italic E}^*_{(a)}| / |{/:Italic E}_%s|", inf)
  set title "(b) error against (a) on the same mesh"
  set xtics autofreq; set yrange [eps/10:*]   # room for the word under the rounding line
  set arrow 1 from graph 0, first eps to graph 1, first eps nohead dt 2 lc "gray50"
  set label 1 "rounding" at graph 0.02, first 0.3*eps left tc "gray40" font sprintf(",%g", fsz)
  fam_exp(f) = floor(log10(f[1:7] eq "opttol-" ? $7 : $5) + 0.5)
  tol_exp(f) = sprintf("%d", fam_exp(f))
  at64(f) = f[strlen(f)-1:] eq "64"    # a family at N = 64: its labels left
  kinds = "pdas cgssor opttol"
  kind_title(k) = k eq "opttol" ? "optimizer.tol" : k." solver.tol"
  plot for [f in varN." ".oneN] sweep \
         using (strcol(1) eq f && f ne "mesh" ? $13 : NaN):($10 > eps ? $10 : eps) \
         with linespoints lw 1.5 pt fam_pt(f) ps 0.9 lc rgb fam_color(f) notitle, \
       for [f in oneN] sweep \
         using (strcol(1) eq f && at64(f) ? $13 : NaN):($10 > eps ? $10 : NaN):(tol_exp(f)) \
         with labels right offset -0.5, 0 font sprintf(",%g", fsz) tc rgb fam_color(f) notitle, \
       for [f in oneN] sweep \
         using (strcol(1) eq f && !at64(f) ? $13 : NaN):($10 > eps ? $10 : NaN):(tol_exp(f)) \
         with labels left offset 0.5, 0 font sprintf(",%g", fsz) tc rgb fam_color(f) notitle, \
       for [k in kinds] NaN with linespoints lw 1.5 pt 7 ps 0.9 lc rgb fam_color(k."-64") \
         title kind_title(k), \
       NaN with points pt 7 ps 0.9 lc "black" title "{/:Italic N} = 64", \
       NaN with points pt 6 ps 0.9 lc "black" title "{/:Italic N} = 128"
  unset arrow 1; unset label 1
  unset multiplot
  set output
}
