# article-refine.gp: the article's figure of the optimum under refinement
# (Theorem 3.1), drawn off the mesh sweep of make accuracy: Example 5.1's
# optimal design (a) and its contact pressure on the nodes in contact
# (gap zero) (b) on N = 16, 64, 256 and the finest mesh of the sweep.
# usage: gnuplot -e "out='figures/article-refine.pdf'; nmax=1024" paper/article-refine.gp
if (!exists("out")) { exit error "the variable out is required" }
if (!exists("runs")) { runs = "out/accuracy" }
if (!exists("nmax")) { nmax = 1024 }
set encoding utf8; set minussign
set terminal pdfcairo enhanced color size 16cm, 9cm font "DejaVu Sans,12.5" linewidth 1
set output out
Ns = sprintf("16 64 256 %d", nmax)
run(n) = sprintf("%s/N%s_pdas_1e-10_newton_1e-6/final", runs, n)
set multiplot layout 1,2 margins 0.1, 0.985, 0.33, 0.9 spacing 0.1, 0
set xlabel "{/:Italic x}_1 [m]"; set xrange [0:4]; set xtics 1
set grid lc rgb "#dddddd"
unset key
set ylabel "α* [mm]"; set yrange [-2:52]; set ytics 10
set title "(a) the optimal design"
plot for [i=1:4] run(word(Ns, i))."/shape.dat" using 1:($2*1000) with lines lw (5 - i)*0.8 lc i
set ylabel "{/:Italic p} [MPa]"; set yrange [0:*]; set ytics auto
set title "(b) the pressure on the nodes in contact"
plot for [i=1:4] run(word(Ns, i))."/contact.dat" using 1:($4 == 0 ? $6/1e6 : NaN) \
       with linespoints lw 1 pt 7 ps (i == 1 ? 0.5 : 0.15) lc i
# the key, below both panels: a plot of nothing across the whole width
set key at screen 0.5, 0.15 center top horizontal maxcols 4 font ",12.5" samplen 2.5 spacing 1.1 width 2
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set lmargin at screen 0.02; set rmargin at screen 0.98; set tmargin at screen 0.16; set bmargin at screen 0.01
set xrange [0:1]; set yrange [0:1]
plot for [i=1:4] NaN with linespoints lw (5 - i)*0.8 pt 7 ps 0.5 lc i title "N = ".word(Ns, i)
unset multiplot
set output
