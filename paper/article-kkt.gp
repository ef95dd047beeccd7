# article-kkt.gp: the article's figure of the optimality condition of
# Example 5.1 at its optimum on the article's mesh, drawn off the run's
# multipliers.dat (i x1 alpha dE/dX_i and the multipliers of the bounds of
# B) and contact.dat (x1 alpha u2 gap T pressure), every term of (4.8)
# per unit of the node's tributary length w_i (h inside, h/2 at the ends):
# (a) the pressure T_i/w_i, the descent -(dE/dX_i)/w_i and the area
# multiplier mu; (b) the term of the moving mesh m_i/w_i = (dE/dX_i +
# T_i)/w_i and the multipliers of the bounds 0 <= alpha_i <= C0.
# usage: gnuplot -e "out='figures/article-kkt.pdf'" paper/article-kkt.gp
if (!exists("out")) { exit error "the variable out is required" }
if (!exists("run")) { run = "out/example-5.1-optimize" }
set encoding utf8; set minussign
set terminal pdfcairo enhanced color size 16cm, 9cm font "DejaVu Sans,12.5" linewidth 1
set output out
# x1 w dE T lower upper, one row a design node (T = 0 on the clamped one)
data = "< awk 'FNR == 1 { f++ } /^#/ { next }".\
       " f == 1 { T[$1] = $5; next } { x[n+0] = $2; d[n+0] = $4; lo[n+0] = $5; up[n+0] = $6; n++ }".\
       " END { h = x[1] - x[0]; for (i = 0; i < n; i++) { w = (i == 0 || i == n - 1) ? h / 2 : h;".\
       " print x[i], w, d[i], (x[i] in T) ? T[x[i]] : 0, lo[i], up[i] } }' ".\
       run."/final/contact.dat ".run."/multipliers.dat"
mu = real(system("awk '$1 == \"area_multiplier\" { print $2 }' ".run."/summary.dat"))
set multiplot layout 1,2 margins 0.1, 0.985, 0.33, 0.9 spacing 0.1, 0
set xlabel "{/:Italic x}_1 [m]"; set xrange [-0.1:4.1]; set xtics 1
set grid lc rgb "#dddddd"
unset key
set ylabel "per unit length [MPa]"
set title "(a) the pressure and the descent of {/:Italic E}"
plot data using 1:($4/$2/1e6) with linespoints pt 7 ps 0.6 lw 1.5 lc 1, \
     data using 1:(-$3/$2/1e6) with points pt 6 ps 1.1 lw 1.2 lc 2, \
     mu/1e6 with lines dt 2 lw 1.5 lc 3
set title "(b) the moving mesh and the bounds of {/:Italic B}"
plot data using 1:(($3 + $4)/$2/1e6) with linespoints pt 7 ps 0.6 lw 1.5 lc 4, \
     data using 1:($5/$2/1e6) with impulses lw 4 lc 6, \
     data using 1:($6/$2/1e6) with impulses lw 4 lc 7
# the key, below both panels: a plot of nothing across the whole width
set key at screen 0.5, 0.15 center top horizontal maxcols 3 font ",12.5" samplen 2.5 spacing 1.1 width 1
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set lmargin at screen 0.02; set rmargin at screen 0.98; set tmargin at screen 0.16; set bmargin at screen 0.01
set xrange [0:1]; set yrange [0:1]
plot NaN with linespoints pt 7 ps 0.6 lw 1.5 lc 1 title "pressure {/:Italic T_i}/{/:Italic w_i}", \
     NaN with points pt 6 ps 1.1 lw 1.2 lc 2 title "−(∂{/:Italic E}/∂{/:Italic X_i})/{/:Italic w_i}", \
     NaN with lines dt 2 lw 1.5 lc 3 title "area multiplier μ", \
     NaN with linespoints pt 7 ps 0.6 lw 1.5 lc 4 title "mesh term {/:Italic m_i}/{/:Italic w_i}", \
     NaN with lines lw 4 lc 6 title "multiplier of α_i ≥ 0, per {/:Italic w_i}", \
     NaN with lines lw 4 lc 7 title "multiplier of α_i ≤ {/:Italic C}_0, per {/:Italic w_i}"
unset multiplot
set output
