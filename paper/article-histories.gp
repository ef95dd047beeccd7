# article-histories.gp: the article's figure of the optimisation histories
# of Examples 5.1 and 5.2 on the article's mesh: the Newton method (the
# runs of make figures), SLSQP and Algorithm 4.1 (projgrad), each from
# history.dat (iteration E state_solves ...): the distance to the optimal
# energy, (E - E*)/|E*|, against the iteration (a) and against the state
# solves (b). E* is the least energy any of the six runs reached; a value
# below 1e-15 (the rounding of E) is not drawn.
# usage: gnuplot -e "out='figures/article-histories.pdf'" paper/article-histories.gp
if (!exists("out")) { exit error "the variable out is required" }
if (!exists("runs")) { runs = "out" }
set encoding utf8; set minussign
set terminal pdfcairo enhanced color size 16cm, 9cm font "DejaVu Sans,12.5" linewidth 1
set output out
ex = "5.1 5.2"
meth = "optimize slsqp projgrad"
label = "'Newton' 'SLSQP' 'Algorithm 4.1'"
file(e, m) = runs."/example-".e."-".m."/history.dat"
Estar = 0
do for [e in ex] { do for [m in meth] {
  stats file(e, m) using 2 nooutput
  if (STATS_min < Estar) { Estar = STATS_min }
} }
gap(E) = (E - Estar) / abs(Estar) > 1e-15 ? (E - Estar) / abs(Estar) : NaN
set multiplot layout 1,2 margins 0.11, 0.985, 0.33, 0.9 spacing 0.1, 0
set logscale y; set format y "10^{%T}"; set yrange [1e-15:3]
set ylabel "(E_h − E_h^*) / |E_h^*|" offset 0.6, 0
set grid lc rgb "#dddddd"
unset key
set xlabel "1 + iteration"; set title "(a) against the iteration"
set logscale x 2; set xrange [1:128]; set format x "%g"
plot for [j=1:3] for [i=1:2] file(word(ex, i), word(meth, j)) using ($1 + 1):(gap($2)) \
       with linespoints lc j dt i pt (i == 1 ? 7 : 6) ps 0.55 lw 1.3 \
       title word(label, j).", Ex. ".word(ex, i)
set xlabel "state solves"; set title "(b) against the state solves"
set xrange [1:256]
plot for [j=1:3] for [i=1:2] file(word(ex, i), word(meth, j)) using 4:(gap($2)) \
       with linespoints lc j dt i pt (i == 1 ? 7 : 6) ps 0.55 lw 1.3 \
       title word(label, j).", Ex. ".word(ex, i)
# the key, below both panels: a plot of nothing across the whole width
set key at screen 0.5, 0.15 center top vertical maxrows 2 font ",12.5" samplen 2.5 spacing 1.1 width 1
unset logscale; unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set lmargin at screen 0.02; set rmargin at screen 0.98; set tmargin at screen 0.16; set bmargin at screen 0.01
set xrange [0:1]; set yrange [0:1]
plot for [j=1:3] for [i=1:2] NaN with linespoints lc j dt i pt (i == 1 ? 7 : 6) ps 0.55 lw 1.3 \
       title word(label, j).", Ex. ".word(ex, i)
unset multiplot
set output
