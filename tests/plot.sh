# plot.sh: contactopt plot DIR (paper/figures.nw) on the output of every
# shipped scene and of a user's scene for each condition of a side
# (clamped, rollers, free, a load on a side) and for friction, read back:
# the figures exist as PDF and PNG, the PNGs are drawings (1600 pixels
# wide, many colours, not one), the scripts take their axes, sides and
# loads from the scene; and every refusal: one line, its exit status,
# nothing written.
. tests/lib.sh
scenes=$TMP/scenes
mkdir -p $scenes

# ---- the user's scenes -------------------------------------------------------
# steel FILE: the mesh and the material three of them share, added to FILE
steel() { printf '[mesh]\nM = 1\nR = 3\nC0prime = 0.25\n[material]\nE = 2.15e11\nnu = 0.29\n' >> $1; }
# both sides clamped, 10 m wide: the axes must run from a = 0 to b = 10
cat > $scenes/clamped.scene <<'EOF'
[geometry]
a = 0
b = 10
gamma = 1
[design]
N = 20
C0 = 0.05
C1 = 0.025
C2 = 9.75
initial = constant
constant = 0.025
[left]
bc = clamped
[right]
bc = clamped
[top]
bc = traction
from = 3
to = 7
P2 = -1e8
EOF
steel $scenes/clamped.scene
# both sides on rollers, a < 0, the whole top loaded
cat > $scenes/roller.scene <<'EOF'
[geometry]
a = -2
b = 2
gamma = 1
[design]
N = 16
C0 = 0.05
C1 = 0.025
C2 = 3.91
initial = line
line_start = 0.02
line_end = 0.025
[left]
bc = roller
[right]
bc = roller
[top]
bc = traction
from = -2
to = 2
P2 = -2e8
EOF
steel $scenes/roller.scene
# aluminium, the right side free, an oblique load and the body's weight
cat > $scenes/free.scene <<'EOF'
[geometry]
a = 0
b = 2
gamma = 0.5
[design]
N = 32
C0 = 0.02
C1 = 0.05
C2 = 0.99
initial = arc
arc_x1 = 2
arc_x2 = 100.02
arc_radius = 100.02
[mesh]
M = 1
R = 3
C0prime = 0.1
[material]
E = 7e10
nu = 0.33
[left]
bc = clamped
[right]
bc = free
[top]
bc = traction
from = 0.5
to = 2
P1 = 2e7
P2 = -1e8
[body_force]
F2 = -2.65e4
EOF
# Coulomb friction, and a load on the right side pushing to the left
cat > $scenes/friction.scene <<'EOF'
[geometry]
a = 0
b = 4
gamma = 1
[design]
N = 16
C0 = 0.05
C1 = 0.025
C2 = 3.91
initial = line
line_start = 0.05
line_end = 0
[left]
bc = clamped
[right]
bc = traction
from = 0.3
to = 0.9
P1 = -5e7
[top]
bc = traction
from = 2
to = 4
P2 = -5.75e8
[contact]
model = coulomb
friction = 0.3
EOF
steel $scenes/friction.scene

# a body six times taller than wide, its left side clamped, the right free
cat > $scenes/tall.scene <<'EOF'
[geometry]
a = 0
b = 0.5
gamma = 3
[design]
N = 16
C0 = 0.01
C1 = 0.05
C2 = 1.4985
initial = constant
constant = 0.002
[mesh]
M = 1
R = 8
C0prime = 0.05
[material]
E = 2.15e11
nu = 0.29
[left]
bc = clamped
[right]
bc = free
[top]
bc = traction
from = 0
to = 0.5
P2 = -1e8
EOF

# ---- reading a figure back ----------------------------------------------------
# png_width FILE: the width in the PNG's header
png_width() { od -An -tu1 -j16 -N4 "$1" | awk '{ print (($1 * 256 + $2) * 256 + $3) * 256 + $4 }'; }
# png_drawn FILE: a PNG of at least 20 colours where no colour covers more
# than 99 % (gnuplot reads it back, every fourth pixel of every fourth row)
png_drawn() {
  gnuplot -e "set table '$TMP/pixels'; plot '$1' binary filetype=png every 4:4 with rgbimage" 2>/dev/null \
    && awk '$1 ~ /^[0-9]/ && NF == 7 { c[$3 " " $4 " " $5]++; n++ }
      END { for (k in c) { m++; if (c[k] > top) top = c[k] }
            exit !(n > 1000 && m >= 20 && top < 0.99 * n) }' $TMP/pixels; }
# figure NAME: NAME.pdf is a PDF and NAME.png a drawing 1600 pixels wide
figure() {
  [ "$(head -c 5 "$1.pdf")" = "%PDF-" ] && [ "$(wc -c < "$1.pdf")" -gt 10000 ] \
    && [ "$(wc -c < "$1.png")" -gt 20000 ] && [ "$(png_width "$1.png")" -eq 1600 ] \
    && png_drawn "$1.png"; }
# off_page FIG: the words of FIG.pdf whose box passes an edge of the page
# by more than 1 pt (a clipped label), as tests/figures.sh reads them
off_page() { pdftotext -bbox $1.pdf - | awk -v W="$(pdfinfo $1.pdf | awk '/^Page size/ { print $3 }')" \
    -v H="$(pdfinfo $1.pdf | awk '/^Page size/ { print $5 }')" '
  /<word / { split($0, a, "\""); t = $0; sub(/.*">/, "", t); sub(/<\/word>.*/, "", t)
             if (a[2] < -1 || a[4] < -1 || a[6] > W + 1 || a[8] > H + 1) printf "%s ", t }'; }
# on_page DIR: no word of DIR's two figures passes an edge (off_page);
# a title or label wholly off the page is not reported at all (the check
# of (d)'s axis name, below, looks for its words)
on_page() { test -z "$(off_page $1/plot-body)$(off_page $1/plot-results)"; }
# plotted LABEL DIR: contactopt plot DIR draws both figures of DIR, and
# leaves no staging file
plotted() {
  $BIN plot "$2" > $TMP/out 2> $TMP/err; _rc=$?
  check "$1: plot exits 0 and says nothing but the names of both figures ($(head -c 200 $TMP/err))" \
    sh -c "[ $_rc -eq 0 ] && [ \$(grep -c '\\.pdf, .*\\.png' $TMP/out) -eq 2 ] && [ ! -s $TMP/err ]"
  check "$1: the body figure, a PDF and a PNG drawing 1600 pixels wide" figure "$2/plot-body"
  check "$1: the results figure, a PDF and a PNG drawing 1600 pixels wide" figure "$2/plot-results"
  check "$1: every word of both figures on its page ($(off_page $2/plot-body)$(off_page $2/plot-results))" on_page "$2"
  check "$1: no staging file is left" sh -c "! ls '$2'/*.partial-* 2>/dev/null"; }

# ---- every shipped scene, and the user's ------------------------------------------
for s in data/*.scene $scenes/*.scene; do
  n=$(basename $s .scene)
  $BIN solve $s -o $TMP/$n > /dev/null 2>&1
  check "solve $n (no --plot-files) exits 0" test -s $TMP/$n/summary.dat
  plotted "solve $n" $TMP/$n
done
for n in example-5.1 example-5.1-tresca; do
  $BIN optimize data/$n.scene -o $TMP/$n-opt > /dev/null 2>&1
  plotted "optimize $n" $TMP/$n-opt
done
$BIN optimize $scenes/free.scene -o $TMP/free-opt --plot-files > /dev/null 2>&1
plotted "optimize free (the user's), with --plot-files" $TMP/free-opt

# ---- what the scripts draw: the scene's axes, sides and loads ---------------------------
script() { $BIN plot "$@" --gnuplot > $TMP/script.gp; }
script $TMP/clamped --results
check "a = 0, b = 10: the contact pressure's x axis is [0:10]" \
  grep -q '^  set xrange \[0:10\]; set yrange \[plo:\*\]$' $TMP/script.gp
check "a = 0, b = 10: the body panels span [-0.25, 10.25] (2.5 % beside)" \
  grep -q '^bxlo = -0.25; bxhi = 10.25;' $TMP/script.gp
check "a = 0, b = 10: the tick marks run from 0 to 10 by 2" grep -q '^  set xtics 0, 2, 10 ' $TMP/script.gp
check "a solve has no graph of E" sh -c "! grep -q 'against iteration' $TMP/script.gp"
script $TMP/clamped --body
check "the body figure reads a, b, gamma from the scene" grep -q '^a = 0.0; b = 10.0; gamma = 1.0 ' $TMP/script.gp
check "both sides clamped: a wall left of a and right of b" sh -c \
  "grep -q 'set object rect from a - cx(0.528), a_left to a, gamma' $TMP/script.gp &&
   grep -q 'set object rect from b, a_right to b + cx(0.528), gamma' $TMP/script.gp"
check "both sides clamped: no rollers" sh -c "! grep -q 'object circle' $TMP/script.gp"
check "the load P2 = -1e8 on 3 < x1 < 7: 7 arrows downwards, their value" sh -c \
  "grep -q '# top: the traction (P1, P2) = (0, -100000000) N/m^2 on 3 < s < 7' $TMP/script.gp &&
   grep -q 'do for \[k=0:6\]' $TMP/script.gp &&
   grep -q 'set arrow from s + cx(0), gamma + cy(1.32) to s + cx(0), gamma + cy(0.088)' $TMP/script.gp &&
   grep -q '{/:Italic P}_2 = −10^{8} N/m^2' $TMP/script.gp"
xr() { awk '/^xlo = / { gsub(/;/, ""); print $3, $6 }' $TMP/script.gp; }
set -- $(xr)
check "the upper panel's x range [$1, $2] holds [0, 10] and its margins" holds 'lo < 0 && hi > 10 && lo > -2 && hi < 12' lo="$1" hi="$2"
script $TMP/roller --body
check "a = -2, b = 2: the tick marks run from -2 to 2" grep -q '^  set xtics -2, 1, 2 ' $TMP/script.gp
check "rollers on both sides: four circles beside a and beside b" sh -c \
  "[ \$(grep -c 'do for \[k=1:4\]' $TMP/script.gp) -eq 2 ] &&
   grep -q 'circle at a - cx(0.154)' $TMP/script.gp && grep -q 'circle at b + cx(0.154)' $TMP/script.gp"
check "rollers: the sides are named Γ_P 1, 2 and the loaded top 3" sh -c \
  "grep -q \"label 'Γ@^{/\\*0.85 1}_{/\\*0.85 P}' at a\" $TMP/script.gp &&
   grep -q \"label 'Γ@^{/\\*0.85 3}_{/\\*0.85 P}' at\" $TMP/script.gp"
script $TMP/free --body
check "a free right side: nothing drawn beside b, no wall, no rollers" sh -c \
  "! grep -q 'b + cx(0.528)\\|circle\\|rect from b' $TMP/script.gp"
check "the oblique load (2e7, -1e8): arrows along (0.196, -0.981) on the page, its value" sh -c \
  "grep -q 'set arrow from s + cx(-0.2416), gamma + cy(1.296) to s + cx(0), gamma + cy(0.088)' $TMP/script.gp &&
   grep -q '({/:Italic P}_1, {/:Italic P}_2) = (2·10^{7}, −10^{8}) N/m^2' $TMP/script.gp"
check "the body force is written" grep -q 'body force ({/:Italic F}_1, {/:Italic F}_2) = (0, −2.65·10^{4}) N/m^3' $TMP/script.gp
script $TMP/friction
check "a load on the right side: its arrows push to the left, their value upright" sh -c \
  "grep -q '# right: the traction (P1, P2) = (-50000000, 0) N/m^2 on 0.3 < s < 0.9' $TMP/script.gp &&
   grep -q 'set arrow from b + cx(1.32), s + cy(0) to b + cx(0.088), s + cy(0)' $TMP/script.gp &&
   grep -q 'rotate by 90' $TMP/script.gp"
check "Coulomb friction: the foundation says so" grep -q 'Coulomb friction {/:Italic F} = 0.3' $TMP/script.gp
check "friction: the tangential force and the slip are drawn" sh -c \
  "grep -q '(e) tangential force along' $TMP/script.gp && grep -q '(f) tangential displacement (slip)' $TMP/script.gp"
script $TMP/example-5.1
check "frictionless: no tangential graphs" sh -c "! grep -q 'tangential' $TMP/script.gp"
script $TMP/example-5.1-tresca-opt --results
check "Tresca, optimize: E against iteration, (i) and (j) with both states" sh -c \
  "grep -q 'against iteration' $TMP/script.gp && grep -q '(i) tangential force' $TMP/script.gp &&
   grep -q \"s1.'/contact.dat' using 1:(\\\$7/10.0\\*\\*ue)\" $TMP/script.gp"
script $TMP/example-5.1-opt --results --start $TMP/example-5.1 --title 'my_run ^1'
check "--start: the initial state is the solve folder's, E(alpha0) its summary's energy" sh -c \
  "grep -q \"^s0 = '$TMP/example-5.1' \" $TMP/script.gp && grep -q \"^start = '$TMP/example-5.1'\" $TMP/script.gp"
check "--title: the marks of enhanced text are escaped (my_run ^1)" grep -q "^title = 'my\\\\_run \\\\^1'$" $TMP/script.gp
# issue 35.7: the body panels' axes labelled with units; (d)'s iterations
# ticked one by one (Example 5.1 stops after a few), its key in a band
# above the points, fitted to them, that no point reaches
check "the six body panels label x1 and x2 in metres" sh -c \
  "[ \$(grep -c \"set xlabel '{/:Italic x}_1 \\[m\\]'\" $TMP/script.gp) -ge 6 ] &&
   [ \$(grep -c \"set ylabel '{/:Italic x}_2 \\[m\\]'\" $TMP/script.gp) -eq 6 ]"
its=$(awk '$1 == "iterations" { print $2 }' $TMP/example-5.1-opt/summary.dat)
check "(d): a tick at every iteration ($its of them)" sh -c \
  "[ $its -le 6 ] && grep -q '^  set xtics 0, 1 out nomirror' $TMP/script.gp"
check "(d): the objective's range fitted to its points, the key in a band of half of it above them" sh -c \
  "grep -q 'set autoscale yfix' $TMP/script.gp &&
   grep -q '^  set offsets 0.5, 0.5, graph 0.5, graph 0.05 ' $TMP/script.gp &&
   grep -q '; set key top right ' $TMP/script.gp"
check "(d) and (h): keys at the size of the text, which prints at 8.2 pt where the page prints 16.4 cm wide" sh -c \
  "[ \$(grep -c \"keyfont = sprintf(',%g', 1.0\\*fsz); set key top [a-z]* .*font keyfont\" $TMP/script.gp) -eq 2 ] &&
   grep -q '; fontpt = 8.2\\*Wcm/16.4 ' $TMP/script.gp"
script $TMP/example-5.1-opt --body
check "optimize: the body is the start (initial/), the final shape dashed in the strip" sh -c \
  "grep -q \"^shape = '$TMP/example-5.1-opt/initial/shape.dat'; final = '$TMP/example-5.1-opt/final/shape.dat'\" $TMP/script.gp"
rm -f $TMP/example-5.1-opt/plot-body.*
(cd $TMP && gnuplot script.gp) 2> $TMP/err
check "the printed script draws with gnuplot alone ($(head -c 200 $TMP/err))" figure $TMP/example-5.1-opt/plot-body

# ---- panel (d) and its marker follow objective.kind ------------------------------
# the objective of an optimisation of Example 5.1 by SLSQP, its script
for kind in compliance pressure_spread pressure_peak; do
  $BIN optimize data/example-5.1.scene -s objective.kind=$kind -s optimizer.method=slsqp \
    -o $TMP/$kind > /dev/null 2>&1
  script $TMP/$kind --results --start $TMP/example-5.1
  cp $TMP/script.gp $TMP/$kind.gp
done
check "compliance: (d) names the compliance J_c in J/m, not E_h" sh -c \
  "grep -q \"set title '(d) compliance {/:Italic J_c} against iteration'\" $TMP/compliance.gp &&
   grep -q \"set ylabel sprintf('{/:Italic J_c} \\[10^{%d} J/m\\]', ee)\" $TMP/compliance.gp &&
   ! grep -q 'E_h' $TMP/compliance.gp"
check "pressure_spread: (d) names the spread J_s, with no unit (no J/m anywhere)" sh -c \
  "grep -q \"set title '(d) pressure spread {/:Italic J_s} against iteration'\" $TMP/pressure_spread.gp &&
   ! grep -q 'J/m' $TMP/pressure_spread.gp && ! grep -q 'E_h' $TMP/pressure_spread.gp"
check "pressure_spread: a spread between 0.01 and 1000 is shown as it is, not in a power of ten" \
  grep -q '^ee = 0 ' $TMP/pressure_spread.gp
ce=$(awk '!/^#/ { m = $2 < 0 ? -$2 : $2; if (m > top) top = m } END { printf "%d", int(log(top) / log(10)) }' \
  $(awk -F"'" '/^opt = / { print $2 }' $TMP/compliance.gp)/history.dat)
check "compliance: shown in units of 10^$ce J/m, the power of ten of its largest value in history.dat" \
  grep -q "^ee = $ce " $TMP/compliance.gp
check "pressure_peak: (d) names the peak J_q and its q = 8, with no unit" sh -c \
  "grep -q \"(d) pressure peak {/:Italic J_q}, {/:Italic q} = 8 against\" $TMP/pressure_peak.gp &&
   ! grep -q 'J/m' $TMP/pressure_peak.gp"
for kind in compliance pressure_spread pressure_peak; do
  v=$(value $kind $TMP/example-5.1)
  check "$kind: the --start marker is the start's $kind ($v from its summary.dat), not its energy" sh -c \
    "[ -n '$v' ] && grep -q '^\\\$start << EOD .*$kind' $TMP/$kind.gp && grep -qx '0 $v' $TMP/$kind.gp &&
     ! grep -qx '0 $(value energy $TMP/example-5.1)' $TMP/$kind.gp"
  $BIN plot $TMP/$kind --results --start $TMP/example-5.1 -o $TMP/$kind-fig > /dev/null 2> $TMP/err
  check "$kind: the results figure is drawn ($(head -c 200 $TMP/err))" figure $TMP/$kind-fig
done
script $TMP/example-5.1-opt --results --start $TMP/example-5.1
check "energy: (d) is E_h in J/m, and the marker the start's energy" sh -c \
  "grep -q \"(d) {/:Italic E_h} against iteration\" $TMP/script.gp &&
   grep -qx '0 $(value energy $TMP/example-5.1)' $TMP/script.gp"

# ---- the deformed body and its contact ------------------------------------------------
# the roller body may sink as a whole: its sink is drawn unscaled, the
# lowest touching node on the foundation; Example 5.1, clamped on the
# left, has none, and says that its magnified contact falls below x2 = 0
script $TMP/roller --results
set -- $(awk '/^S0 = / { gsub(/;/, ""); print $3, $6 }' $TMP/script.gp)
sink=$(awk '$5 != "" && $4 <= 1e-12 && $1 !~ /^#/ { if (!n++ || $3 < m) m = $3 } END { print m }' $TMP/roller/contact.dat)
check "rollers on both sides: the sink T0 = $2 is u2 of the highest touching node ($sink)" \
  holds 't < 0 && abs(t - s) <= 1e-6 * abs(s)' t="$2" s="$sink"
check "rollers on both sides: the sink drawn unscaled, the rest × $1, and the title says so" sh -c \
  "grep -q \"deformed: sink .* m, the rest × %g', S0)\" $TMP/script.gp &&
   grep -q 'using (\$1 + S0\*\$3):(\$2 + T0 + S0\*(\$4 - T0))' $TMP/script.gp"
script $TMP/example-5.1 --results
check "Example 5.1 (clamped on the left): no sink, the magnified contact said to fall below x2 = 0" sh -c \
  "grep -q '^S0 = [0-9.]*; T0 = 0.0 ' $TMP/script.gp && grep -q 'Γ_C falls below' $TMP/script.gp &&
   ! grep -q 'deformed: sink' $TMP/script.gp"

# ---- a large mesh: thinned, drawn from the data blocks, in its own script ---------------
$BIN solve data/example-5.1.scene -s mesh.refine=32 -o $TMP/n512 > /dev/null
script $TMP/n512 --results
lines=$(awk '/^\$mesh0 << EOD/ { on = 1; next } /^EOD/ { on = 0 } on && NF { n++ } END { print n + 0 }' $TMP/script.gp)
check "N = 512: the triangulation drawn is every 8th column, every 10th row (lines 0.15 cm apart), $lines points, not the 66 177 nodes" sh -c \
  "grep -q \"(a) triangulation of Ω({/:Italic α}^0), every 8th column, every 10th row'\" $TMP/script.gp && [ $lines -lt 12000 ]"
check "N = 512: the arrows thinned, the contact graph marks every 16th node" sh -c \
  "grep -q 'one arrow in [0-9]' $TMP/script.gp && grep -q \"pt '▷' ps 1.3 lw 1.2 pi 16\" $TMP/script.gp"
check "N = 512: the title of (c), wider than its column, in a smaller font; that of (b) as it is" sh -c \
  "grep -q \"one arrow in [0-9]*', S0) font sprintf(',%g', 0\\.[0-9]*\\*fsz)\" $TMP/script.gp &&
   grep -q \"after deformation, displacements × %g', S0) font sprintf(',%g', 1\\.0\\*fsz)\" $TMP/script.gp"
script $TMP/example-5.1 --results
check "N = 16: the whole mesh and every arrow" sh -c "! grep -q 'every [0-9][0-9]*[snrt][tdh] \|one arrow in' $TMP/script.gp"
plotted "N = 512" $TMP/n512
script $TMP/n512 --results
rm -f $TMP/n512/plot-results.*
(cd $TMP && gnuplot script.gp) 2> $TMP/err
check "N = 512: the printed script of the results, its data blocks in it, draws with gnuplot alone ($(head -c 200 $TMP/err))" \
  figure $TMP/n512/plot-results

# a body 100 m wide and 1 m high, N = 400: its columns thinned, its rows kept
sed -e 's/^a = -2$/a = -50/' -e 's/^b = 2$/b = 50/' -e 's/^N = 16$/N = 400/' -e 's/^C2 = 3.91$/C2 = 99.99/' \
    -e 's/^from = -2$/from = -10/' -e 's/^to = 2$/to = 10/' $scenes/roller.scene > $TMP/wide.scene
$BIN solve $TMP/wide.scene -o $TMP/wide > /dev/null
script $TMP/wide --results
check "a body 100 m wide, 1 m high, N = 400: every 6th column, every row of its mesh" \
  grep -q "(a) triangulation of Ω({/:Italic α}^0), {/:Italic x}_2 ×20, every 6th column, every row'" $TMP/script.gp

# ---- titles that fit: a tall body ---------------------------------------------------------
script $TMP/tall --body
set -- $(awk '/^ucm = / { gsub(/;/, ""); u = $3 } /^xlo = / { gsub(/;/, ""); lo = $3; hi = $6 } END { print u, lo, hi }' $TMP/script.gp)
check "a body 0.5 m wide, 3 m tall: its panels widened to the strip's title ($(calc '(h - l) * u' u=$1 l=$2 h=$3) cm >= 17)" \
  holds '(h - l) * u >= 17' u=$1 l=$2 h=$3
check "a tall body: two x1 tick marks, not five that run together" grep -q '^  set xtics 0, 0.5, 0.5 ' $TMP/script.gp
check "a tall body: the top's name left of the arrows, clear of the load's value" \
  grep -q "set label 'Γ@^{/\\*0.85 2}_{/\\*0.85 P}' at -0.1022" $TMP/script.gp
check "a tall body: the names of the body and of Γ_C in its middle, clear of its clamp" sh -c \
  "grep -q \"set label 'Ω({/:Italic α}^0)' at a + 0.5\\*(b - a)\" $TMP/script.gp &&
   [ \$(grep -c \"set label 'Γ_C({/:Italic α}^0)' at a + 0.5\\*(b - a)\" $TMP/script.gp) -eq 2 ]"
check "a tall body: its horizontal scale exaggerated twice (1.47 cm wide at true scale), and the title says so" sh -c \
  "grep -q '^ucm = 5.86667; vex = 0.5 ' $TMP/script.gp && grep -q \"set title 'horizontal scale exaggerated ×2'\" $TMP/script.gp"
script $TMP/tall --results
check "a tall body: its body panels centred in their columns" sh -c \
  "grep -q '^bodyx(c) = colx(c) + (colw - pw)/2' $TMP/script.gp && grep -q 'set lmargin at screen sx(bodyx(0))' $TMP/script.gp"
set -- $(awk '/^ucm = / { gsub(/;/, ""); print $3, $6 }' $TMP/script.gp)
check "a tall body: 7 cm high, its panels ($(calc '1.05 * 0.5 * u' u="$1") cm, x1 ×$(calc '1 / v' v="$2")) narrower than a column (10.8 cm)" \
  holds 'abs(1.35 * 3 * u * v - 7) < 1e-3 && 1.05 * 0.5 * u < 10.8 && abs(v - 0.5) < 1e-12' u="$1" v="$2"
check "a tall body: the titles of its body panels say x1 ×2" \
  grep -q "(a) triangulation of Ω({/:Italic α}^0), {/:Italic x}_1 ×2[,']" $TMP/script.gp
# optimised, E changes by less than a millionth: the tick labels of (d)
# have eleven characters (-4.9793830), printed with the decimals of their
# step (gnuplot's own format repeats some), (d) starts right of its
# column so that its axis name stays on the page, the long titles of the
# right column fit, and so do the strip's tick labels (0.005) and the
# name of its axis on the body figure
$BIN optimize $scenes/tall.scene -o $TMP/tall-opt > /dev/null 2>&1
plotted "optimize a tall body" $TMP/tall-opt
script $TMP/tall-opt --results
check "a tall body optimised: (d) indented for its tick labels, which have the decimals of their step" sh -c \
  "grep -q '^  set lmargin at screen sx(colx(0) + [0-9.]*); ' $TMP/script.gp && grep -q \"^  set format y '%.[0-9]f'\" $TMP/script.gp"
check "a tall body optimised: the name of (d)'s axis, E_h [10^e J/m], on the page" \
  sh -c "pdftotext -bbox $TMP/tall-opt/plot-results.pdf - | grep -q '>J/m\]<'"
# the key of the pressure in a corner its curves leave free: Example 5.1's
# pressure rises to the right (top left); the steel strip's first
# pressure peaks at x1 = 4 of 10, in the left two fifths (top right); a
# column 0.5 m wide pressed evenly by its top fills both corners (top
# left, above the points, in a band)
script $TMP/example-5.1-opt --results
check "(h) of Example 5.1: the key top left, no band" sh -c \
  "grep -q 'set key top left font keyfont' $TMP/script.gp && ! grep -q '^  set offsets 0, 0, graph' $TMP/script.gp"
$BIN optimize tests/scenes/strip.scene -o $TMP/strip-opt > /dev/null 2>&1
script $TMP/strip-opt --results
check "(h) of the steel strip: the key top right" grep -q 'set key top right font keyfont' $TMP/script.gp
sed -e 's/^gamma = 3$/gamma = 6/' -e 's/^bc = clamped$/bc = roller/' -e 's/^bc = free$/bc = roller/' \
    -e 's/^C2 = 1.4985$/C2 = 2.9985/' $scenes/tall.scene > $TMP/column.scene
$BIN optimize $TMP/column.scene -o $TMP/column-opt > /dev/null 2>&1
script $TMP/column-opt --results
check "(h) of a column pressed evenly: the key top left, in a band above the points" sh -c \
  "grep -q 'set key top left font keyfont' $TMP/script.gp && grep -q '^  set offsets 0, 0, graph 0.5, 0 ' $TMP/script.gp"
$BIN plot $TMP/tall --title "$(printf 'a very long title %.0s' 1 2 3 4 5 6)" -o $TMP/long --gnuplot > $TMP/script.gp
set -- $(awk '/^Wcm = / { print $3 }' $TMP/script.gp)
check "a title of 108 characters: both pages ($1, $2 cm) wider than it and its end (at 0.254 cm a character)" \
  holds 'b >= 0.254 * (108 + 37) && r >= 0.254 * (108 + 19)' b="$1" r="$2"

# ---- the names of the figures -------------------------------------------------------
$BIN plot $TMP/example-5.1-opt --results --start $TMP/example-5.1 --title 'Example 5.1' \
  -o $TMP/fig-5.2 > /dev/null 2> $TMP/err; rc=$?
check "-o NAME with one figure: NAME.pdf and NAME.png, as the Makefile draws Fig. 5.2" \
  sh -c "[ $rc -eq 0 ] && test -s $TMP/fig-5.2.pdf -a -s $TMP/fig-5.2.png"
mkdir -p $TMP/figs
$BIN plot $TMP/free -o $TMP/figs/free > /dev/null; rc=$?
check "-o NAME with both figures: NAME-body and NAME-results" \
  sh -c "[ $rc -eq 0 ] && test -s $TMP/figs/free-body.png -a -s $TMP/figs/free-results.png"

# ---- refusals: one line, the documented exit status, nothing written ----------------------
# refused LABEL CODE PATTERN FIGURE ARGS...: plot ARGS exits CODE with one line
# matching PATTERN, and FIGURE.pdf is not there
refused() { _d=$1 _c=$2 _p=$3 _f=$4; shift 4
  $BIN plot "$@" > /dev/null 2> $TMP/err; _rc=$?
  check "$_d: exit $_c, one line ($(head -c 200 $TMP/err))" clean_failure $_rc $_c $TMP/err "$_f.pdf" "$_p"; }
refused "a folder that does not exist" 2 'nope: no such folder' $TMP/nope/plot-body $TMP/nope
mkdir -p $TMP/empty
refused "a folder that is not a run's" 2 'not an output folder of solve or optimize' \
  $TMP/empty/plot-body $TMP/empty
refused "a file, not a folder" 2 'not a folder' $TMP/x $scenes/free.scene
cp -r $TMP/free $TMP/free.partial-4242
rm -f $TMP/free.partial-4242/plot-*
refused "the staging folder of an unfinished run" 2 'staging folder of a run that did not finish' \
  $TMP/free.partial-4242/plot-body $TMP/free.partial-4242
$BIN gradcheck data/example-5.1.scene -o $TMP/gc > /dev/null 2>&1
refused "a folder of gradcheck" 2 'gradcheck' $TMP/gc/plot-body $TMP/gc
# a state's solution.vtu missing, cut short, or of another mesh
rm -f $TMP/free/plot-*
mv $TMP/free/solution.vtu $TMP/free.vtu
refused "a run whose solution.vtu is gone" 2 'not an output folder .*no solution.vtu' \
  $TMP/free/plot-body $TMP/free
head -c 3000 $TMP/free.vtu > $TMP/free/solution.vtu
refused "a solution.vtu cut short" 2 'solution.vtu: cut short' $TMP/free/plot-results $TMP/free --results
cp $TMP/roller/solution.vtu $TMP/free/solution.vtu
refused "the solution.vtu of another mesh" 2 'solution.vtu: 85 points, where the scene.s mesh has 165' \
  $TMP/free/plot-results $TMP/free --results
sed 's/"LittleEndian"/"X"/; s/"BigEndian"/"LittleEndian"/; s/"X"/"BigEndian"/' $TMP/free.vtu > $TMP/free/solution.vtu
refused "a solution.vtu of the other byte order" 2 'solution.vtu: written in the other byte order' \
  $TMP/free/plot-results $TMP/free --results
echo 'not a VTU file' > $TMP/free/solution.vtu
refused "a solution.vtu that is no state" 2 'solution.vtu: not a state of contactopt' \
  $TMP/free/plot-results $TMP/free --results
mv $TMP/free.vtu $TMP/free/solution.vtu
refused "--start with a run of solve" 2 'is a run of solve' $TMP/r \
  $TMP/free --results -o $TMP/r --start $TMP/example-5.1
refused "--start naming a run of optimize" 2 'a run of optimize, not of solve' \
  $TMP/r $TMP/free-opt --results -o $TMP/r --start $TMP/example-5.1-opt
refused "--start with the body figure alone" 2 'only the results figure' $TMP/r \
  $TMP/free-opt --body -o $TMP/r --start $TMP/free
refused "an unknown option" 2 'unknown option' $TMP/free/plot-x $TMP/free --colour
refused "no DIR" 2 'no DIR given' $TMP/plot-body
refused "a figure's folder that does not exist" 4 'cannot write .*missing/f.pdf' \
  $TMP/missing/f $TMP/free --body -o $TMP/missing/f
rm -f $TMP/free/plot-*
PATH=/nonexistent $BIN plot $TMP/free > /dev/null 2> $TMP/err; rc=$?
check "gnuplot missing: exit 4, one line that says so ($(cat $TMP/err))" \
  clean_failure $rc 4 $TMP/err $TMP/free/plot-body.pdf 'cannot run gnuplot' 'install it'
# a gnuplot that writes the staged PDF, then fails or is killed: the figure
# is refused and nothing of it stays
# nothing_left RC NAME PATTERN: a clean failure, nothing of NAME left
nothing_left() { clean_failure $1 4 $TMP/err $2.pdf "$3" && ! ls $2*.partial-* 2>/dev/null; }
mkdir -p $TMP/fake
for end in 'exit 1' 'kill -9 $$'; do
  pattern="gnuplot was killed by signal 9"
  [ "$end" = 'exit 1' ] && pattern="gnuplot failed \(exit status 1\) drawing .*: line 1: the fake gnuplot's message\$"
  cat > $TMP/fake/gnuplot <<EOF
#!/bin/sh
out=\$(sed -n "s/^out = '\\(.*\\)'\$/\\1/p")
echo partial > "\$out.pdf"
echo "line 1: the fake gnuplot's message" >&2
$end
EOF
  chmod +x $TMP/fake/gnuplot
  PATH=$TMP/fake:$PATH $BIN plot $TMP/free --body > /dev/null 2> $TMP/err; rc=$?
  check "gnuplot that fails ($end): exit 4, one line, no figure and no staged file ($(cat $TMP/err))" \
    nothing_left $rc $TMP/free/plot-body "$pattern"
done

# Ctrl-C while gnuplot draws the results: a terminal signals the process
# group, contactopt and gnuplot; the body figure, finished, stays, the
# results are removed, exit 130 with two lines: the signal's at once, the end's
if command -v setsid > /dev/null && env --default-signal=INT true 2>/dev/null; then
  $BIN solve data/example-5.1.scene -s mesh.refine=16 -o $TMP/big --plot-files > /dev/null
  setsid env --default-signal=INT $BIN plot $TMP/big -o $TMP/big/fig > /dev/null 2> $TMP/err &
  pid=$!
  for i in $(seq 1 3000); do ls $TMP/big/fig-results.partial-* > /dev/null 2>&1 && break; sleep 0.005; done
  kill -INT -$pid; wait $pid; rc=$?
  check "Ctrl-C while the results are drawn: exit 130, two lines, the body kept, nothing of the results ($(cat $TMP/err))" \
    sh -c "[ $rc -eq 130 ] && [ \$(wc -l < $TMP/err) -eq 2 ] && grep -q 'interrupted: the figures finished are kept' $TMP/err && grep -q 'interrupted by signal 2' $TMP/err &&
           test -s $TMP/big/fig-body.png -a ! -e $TMP/big/fig-results.pdf && ! ls $TMP/big/*.partial-* 2>/dev/null"
else
  echo "# setsid or env --default-signal is missing: the interruption of plot is not tried"
fi

# ---- a part of the user's own ------------------------------------------------------
# the band (0,4) x (0.25,1) of tests/parts/bore.geo on the strip, with a
# bore of radius 0.2 at (2, 0.625) under a pressure, the top loaded: the
# body figure draws the part's outline from its mesh, the bore a hole,
# the curves named with their loads; both figures on the page
mkdir -p $TMP/parts
{ part_scene $PWD/tests/parts/bore.geo; cat <<EOF2
[boundary.bore]
bc = pressure
p = 2e8
EOF2
} > $TMP/parts/bore.scene
$BIN optimize $TMP/parts/bore.scene -o $TMP/bore > /dev/null 2>&1
check "optimize a part with a bore exits 0" test -s $TMP/bore/final/solution.vtu
plotted "optimize a part with a bore" $TMP/bore
$BIN plot $TMP/bore --gnuplot > $TMP/bore.gp
# block NAME [SCRIPT]: the lines of the data block $NAME of the body figure
block() { awk -v n="\$$1" '$1 == n && $2 == "<<" { on = 1; next } $1 == "EOD" { on = 0 } on' ${2:-$TMP/bore.gp}; }
# the pad of two materials (data/parts/pad.geo: the plate from x2 = 0.003,
# the strip's top, to 0.013, the rubber from 0.013 to 0.033, 0.2 m wide,
# the strip of the plate's values): the edges between two materials all
# lie on x2 = 0.013 and run from x1 = 0 to 0.2 (not on the joining
# segment: the same values there), and each layer is named inside it
$BIN solve data/parts/pad.scene -o $TMP/pad > /dev/null 2>&1
$BIN plot $TMP/pad --body --gnuplot > $TMP/pad.gp
# the machine foot: its strip's tick labels have six characters (0.0006)
$BIN solve data/parts/machine-foot.scene -o $TMP/foot > /dev/null 2>&1
plotted "solve the machine foot" $TMP/foot
check "a part of two materials: their interface drawn, x2 = 0.013 from x1 = 0 to 0.2, and nothing else" sh -c \
  "$(block interfaces $TMP/pad.gp | awk 'NF == 2 && !($1 == 0 && $2 == 0) { n++; if ($2 != 0.013) bad++
     lo = n == 1 || $1 < lo ? $1 : lo; hi = n == 1 || $1 > hi ? $1 : hi }
     END { print (n > 0 && !bad && lo == 0 && hi == 0.2) ? "true" : "false" }')"
check "a part of two materials: each layer named inside it" sh -c \
  "grep \"set label 'plate' at\" $TMP/pad.gp | awk '{ y = \$6 + 0; exit !(y > 0.003 && y < 0.013) }' &&
   grep \"set label 'rubber' at\" $TMP/pad.gp | awk '{ y = \$6 + 0; exit !(y > 0.013 && y < 0.033) }'"
# on_outline: every point (x, y) of the input on the band's sides x = 0,
# x = 4 (0.25 <= y <= 1), its top y = 1 (0 <= x <= 4), or the bore
on_outline() { awk 'NF { x = $1; y = $2; r = sqrt((x - 2)^2 + (y - 0.625)^2); e = 1e-9
    side = (x < e || x > 4 - e) && y > 0.25 - e && y < 1 + e
    if (!(side || (y > 1 - e && x > -e && x < 4 + e) || (r > 0.2 - 1e-6 && r < 0.2 + 1e-6))) bad++ }
    END { exit bad > 0 }'; }
# chains: "points closed length" of each polyline of the input
chains() { awk 'function end() { if (n) printf "%d %d %.6f\n", n, (x0 == px && y0 == py), l; n = 0; l = 0 }
    !NF { end(); next } { if (n) l += sqrt(($1 - px)^2 + ($2 - py)^2); else { x0 = $1; y0 = $2 }
    px = $1; py = $2; n++ } END { end() }'; }
block outline > $TMP/outline
block holes > $TMP/hole
check "a part: every point of its outline is on the band's sides, its top or the bore" \
  on_outline < $TMP/outline
chains < $TMP/outline > $TMP/chains
chains < $TMP/hole > $TMP/holes
check "a part: two chains, the sides and top open, 5.5 m long, the bore closed, about 2 pi 0.2 m long ($(tr '\n' ' ' < $TMP/chains))" \
  sh -c "[ \$(wc -l < $TMP/chains) -eq 2 ] && awk '\$2 == 0 && \$3 > 5.5 - 1e-9 && \$3 < 5.5 + 1e-9 { o++ }
    \$2 == 1 && \$1 >= 9 && \$3 > 0.98 * 2 * 3.14159265 * 0.2 && \$3 <= 2 * 3.14159265 * 0.2 { c++ }
    END { exit !(o == 1 && c == 1) }' $TMP/chains"
check "a part: the bore, and only it, is filled white as a hole" \
  sh -c "[ \$(wc -l < $TMP/holes) -eq 1 ] && awk 'NF { r = sqrt((\$1 - 2)^2 + (\$2 - 0.625)^2); if (r < 0.2 - 1e-6 || r > 0.2 + 1e-6) bad++ } END { exit bad > 0 }' $TMP/hole"
check "a part: its curves named with their conditions" sh -c \
  "grep -q \"set label 'top'.': ({/:Italic P}_1, {/:Italic P}_2) = (0, −5.75·10^{8}) N/m^2'\" $TMP/bore.gp &&
   grep -q \"set label 'bore'.': {/:Italic p} = 2·10^{8} N/m^2'\" $TMP/bore.gp"
check "a part: its top is the mesh's, 1 m, and its strip ends at C0prime = 0.25" \
  grep -q '^a = 0.0; b = 4.0; gamma = 1.0 .*cprime = 0.25\|^cprime = 0.25 ' $TMP/bore.gp
# the pressure's arrows: those based on the bore (on its chords, at most
# 0.01 m inside its circle at these sizes) point away from its centre
# (into the body), their heads inside the bore; the top's point down
ucm=$(sed -n 's/^ucm = \([^;]*\); vex = \([^ ]*\) .*/\1/p' $TMP/bore.gp | head -1)
vex=$(sed -n 's/^ucm = \([^;]*\); vex = \([^ ]*\) .*/\2/p' $TMP/bore.gp | head -1)
check "a part: the pressure's arrows in the bore push into the body, the top's load points down" sh -c \
  "grep '^  set arrow from .*head filled' $TMP/bore.gp | sed 's/c[xy](\([^)]*\))/\1/g; s/,//g' |
   awk -v u=$ucm -v v=$vex '{ x = \$4; y = \$7; tx = x + \$6 / u; ty = y + \$9 / (u * v)
     hx = \$11 + \$13 / u; hy = \$14 + \$16 / (u * v); r = sqrt((x - 2)^2 + (y - 0.625)^2)
     rh = sqrt((hx - 2)^2 + (hy - 0.625)^2); rt = sqrt((tx - 2)^2 + (ty - 0.625)^2)
     if (r > 0.19 && r < 0.2 + 1e-6) { bore++; if (rh <= rt || rh > 0.2) bad++ }
     else if (y > 1 - 1e-9) { top++; if (!(hx == tx && hy < ty)) bad++ } else bad++ }
     END { exit !(bore >= 4 && top >= 8 && !bad) }'"
if command -v pdftotext > /dev/null && command -v pdfinfo > /dev/null; then
  for fig in body results; do
    check "a part: every word of the $fig figure on its page ($(off_page $TMP/bore/plot-$fig))" \
      test -z "$(off_page $TMP/bore/plot-$fig)"
  done
  check "a part: the curves' names are printed on the body figure" sh -c \
    "pdftotext $TMP/bore/plot-body.pdf - | grep -q '^bore: ' && pdftotext $TMP/bore/plot-body.pdf - | grep -q '^top: '"
else
  echo "# pdftotext or pdfinfo is missing: the words of a part's figures are not read"
fi
# refined four times (16 times the triangles) and the top clamped: the
# results draw the part's outline alone, and plot takes seconds
$BIN optimize $TMP/parts/bore.scene -s mesh.refine=4 -s boundary.top.bc=clamped -o $TMP/bore4 > /dev/null 2>&1
t0=$(date +%s.%N)
$BIN plot $TMP/bore4 > /dev/null 2> $TMP/err; rc=$?
t1=$(date +%s.%N)
el=$(calc 't1 - t0' t1=$t1 t0=$t0)
check "a part refined 4 times: plot exits 0 in under 20 s ($el s; $(head -c 200 $TMP/err))" \
  sh -c "[ $rc -eq 0 ] && [ -s $TMP/bore4/plot-results.png ] && awk 'BEGIN { exit !($el < 20) }'"
$BIN plot $TMP/bore4 --gnuplot > $TMP/bore4.gp
check "a part refined 4 times: the results draw its outline, the top clamped hatched" sh -c \
  "grep -q 'the part by its outline' $TMP/bore4.gp && grep -q \"set label 'top'.' (clamped)'\" $TMP/bore4.gp &&
   [ \$(grep -c \"nohead lw 1 lc 'gray40'\" $TMP/bore4.gp) -ge 40 ]"

# ---- the help ----------------------------------------------------------------------------
$BIN plot --help > $TMP/help; rc=$?
for opt in -o --body --results --start --title --gnuplot --plot-files 'Exit status'; do
  check "contactopt plot --help explains $opt" sh -c "[ $rc -eq 0 ] && grep -q -- '$opt' $TMP/help"
done
check "contactopt --help names plot" sh -c "$BIN --help | grep -q '^  plot '"
finish
