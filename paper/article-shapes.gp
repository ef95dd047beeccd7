# article-shapes.gp: the article's figure of the shapes, drawn off the runs
# of make figures: (a) the initial designs of the three starts as given
# (alpha0, the solves out/example-*/shape.dat) and as projected onto B
# (P_B(alpha0), out/example-*-optimize/initial/shape.dat); (b) the final
# designs of the three starts overlaid (one key, below both). alpha in mm against x1 in m: the
# vertical scale is 80 times the horizontal one (4 m wide, 50 mm high).
# usage: gnuplot -e "out='figures/article-shapes.pdf'" paper/article-shapes.gp
if (!exists("out")) { exit error "the variable out is required" }
if (!exists("runs")) { runs = "out" }
set encoding utf8; set minussign
set terminal pdfcairo enhanced color size 16cm, 9cm font "DejaVu Sans,12.5" linewidth 1
set output out
set multiplot layout 1,2 margins 0.1, 0.985, 0.33, 0.9 spacing 0.1, 0
starts = "5.1 5.2 5.2-flat"
names = "'Example 5.1' 'Example 5.2' '5.2, α^0 = 0.05'"
set xlabel "{/:Italic x}_1 [m]"; set ylabel "α [mm]"
set xrange [0:4]; set yrange [-2:52]; set xtics 1; set ytics 10
set grid lc rgb "#dddddd"
unset key
set title "(a) the starts α^0 (dashed) and P_B(α^0) (solid)"
plot for [i=1:3] runs."/example-".word(starts, i)."/shape.dat" using 1:($2*1000) \
       with lines dt 2 lw 1.5 lc i notitle, \
     for [i=1:3] runs."/example-".word(starts, i)."-optimize/initial/shape.dat" using 1:($2*1000) \
       with linespoints lw 1.5 pt 6+i ps 0.6 lc i title word(names, i)
set title "(b) the optimal designs α^* from them"
plot for [i=1:3] runs."/example-".word(starts, i)."-optimize/final/shape.dat" using 1:($2*1000) \
       with linespoints lw (i == 1 ? 3 : 1.2) pt 6+i ps (i == 1 ? 0.5 : 0.9) lc i title word(names, i)
# the key, below both panels: a plot of nothing across the whole width
set key at screen 0.5, 0.15 center top horizontal maxrows 1 font ",12.5" samplen 2.5 spacing 1.1 width 1
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set lmargin at screen 0.02; set rmargin at screen 0.98; set tmargin at screen 0.16; set bmargin at screen 0.01
set xrange [0:1]; set yrange [0:1]
plot NaN with lines dt 2 lw 1.5 lc rgb "gray40" title "α^0 as given", \
     for [i=1:3] NaN with linespoints lw 1.5 pt 6+i ps 0.6 lc i title word(names, i)
unset multiplot
set output
