#!/bin/sh
# article-numbers.sh OUT DIR: the numbers of the article (paper/article.tex),
# read from the runs in OUT (make figures and the article's runs of
# SLSQP and Algorithm 4.1): the macros \art{KEY} on standard output, which
# the article's prose and its tables cite. Nothing is typed: every
# value is a field of a summary.dat, a row of a contact.dat or
# multipliers.dat, or the sweep of make accuracy. A missing file or field
# stops the script with a message (exit 1), and a key the article asks
# for that is not written stops LaTeX (\art's \errmessage).
# The tables of make bench that the article repeats define their macros
# beside their tabular; a float is a group, so the article takes the
# macros here (global, on standard output) and the tabular alone from
# DIR/bench-NAME.tex, which this script writes.
out=${1:-out} dir=${2:-build/article}
die() { echo "article-numbers.sh: $*" >&2; exit 1; }
for f in example-5.1 example-5.2 example-5.2-flat example-5.1-optimize example-5.2-optimize \
         example-5.2-flat-optimize example-5.1-slsqp example-5.2-slsqp example-5.1-projgrad \
         example-5.2-projgrad example-5.1-strain-optimize; do
  [ -f "$out/$f/summary.dat" ] || die "no $out/$f/summary.dat (make figures, make paper)"
done
[ -f "$out/accuracy/sweep.dat" ] || die "no $out/accuracy/sweep.dat (make accuracy)"

# v KEY RUN: the value of KEY in RUN's summary.dat
v() { r=$(awk -v k="$1" '$1 == k { print $2; f = 1; exit } END { exit !f }' "$out/$2/summary.dat") \
        || die "$out/$2/summary.dat has no $1"; echo "$r"; }
# def KEY VALUE: one macro
def() { printf '\\expandafter\\def\\csname art:%s\\endcsname{%s}\n' "$1" "$2"; }
# sci X [DIGITS]: X as \ensuremath{m\cdot10^{e}} with DIGITS decimals of m (default 7)
sci() { awk -v x="$1" -v d="${2:-7}" 'BEGIN { a = x < 0 ? -x : x
  if (a == 0) { print "\\ensuremath{0}"; exit }
  e = int(log(a) / log(10)); if (a < 1 && 10 ^ e != a) e--
  m = x / 10 ^ e; if (sprintf("%." d "f", m < 0 ? -m : m) + 0 >= 10) { e++; m /= 10 }
  printf "\\ensuremath{%." d "f\\cdot10^{%d}}\n", m, e }'; }
# fix X DIGITS: X with DIGITS decimals
fix() { awk -v x="$1" -v d="$2" 'BEGIN { printf "%." d "f\n", x }'; }

# the contact of a contact.dat (x1 alpha u2 gap T pressure): a node is in
# contact where its gap is zero, the rule of every table of the article;
# contact FILE: "nodes spread peak[MPa] first last parts" of those
# nodes, the spread the standard deviation over the mean of their
# pressure, parts the runs of neighbouring nodes in contact
contact() { [ -f "$1" ] || die "no $1"
  awk '!/^#/ { if ($4 == 0) { n++; s += $6; ss += $6 * $6; if ($6 > m) m = $6
         if (n == 1) a = $1; b = $1; if (!on) k++; on = 1 } else on = 0 }
       END { if (!n) { print 0, 0, 0, "-", "-", 0; exit }
         mu = s / n; var = ss / n - mu * mu; if (var < 0) var = 0
         printf "%d %.3f %.1f %s %s %d\n", n, sqrt(var) / mu, m / 1e6, a, b, k }' "$1"; }
# zone FIRST LAST PARTS: the zone as the article prints it
zone() { if [ "$3" -gt 1 ]; then echo "[$1, $2] ($3 parts)"; else echo "[$1, $2]"; fi; }

echo "% written by paper/article-numbers.sh from $out; do not edit"
printf '%s\n' '\providecommand{\art}[1]{\ifcsname art:#1\endcsname\csname art:#1\endcsname\else\errmessage{build/article/numbers.tex has no #1}\fi}'

# ---- the reproduction: three starts, at alpha0, at P_B(alpha0), at the optimum
for e in 5.1 5.2 5.2-flat; do
  o=example-$e-optimize
  def "$e:Ealpha0" "$(sci "$(v energy example-$e)")"
  def "$e:Estart" "$(sci "$(v initial_energy $o)")"
  def "$e:Estar" "$(sci "$(v energy $o)")"
  def "$e:moved" "$(fix "$(v initial_moved $o)" 4)"
  def "$e:its" "$(v iterations $o)"
  def "$e:solves" "$(v evaluations $o)"
  def "$e:stop" "$(v stop_reason $o)"
  for where in alpha0:$out/example-$e/contact.dat start:$out/$o/initial/contact.dat \
               final:$out/$o/final/contact.dat; do
    set -- $(contact "${where#*:}")
    def "$e:${where%%:*}:nodes" "$1"; def "$e:${where%%:*}:spread" "$2"
    def "$e:${where%%:*}:peak" "$3"; def "$e:${where%%:*}:zone" "$(zone $4 $5 $6)"
  done
done
def Estar "$(sci "$(v energy example-5.1-optimize)")"
def Estrain "$(sci "$(v energy example-5.1-strain-optimize)")"
# the largest difference of the final shapes from Example 5.1's
for e in 5.2 5.2-flat; do
  def "$e:shapediff" "$(sci "$(paste "$out/example-5.1-optimize/final/shape.dat" \
    "$out/example-$e-optimize/final/shape.dat" | awk '!/^#/ { d = $2 - $4; if (d < 0) d = -d
      if (d > m) m = d } END { printf "%.17g\n", m }')" 1)"
done
# the largest difference of the final energies of the three starts, relative
def Espread "$(sci "$(for e in 5.1 5.2 5.2-flat; do v energy example-$e-optimize; done |
  awk '{ e[NR] = $1 } END { m = 0; for (i = 1; i <= NR; i++) for (j = 1; j <= NR; j++) {
    d = (e[i] - e[j]) / e[1]; if (d < 0) d = -d; if (d > m) m = d }; printf "%.17g\n", m }')" 1)"

# ---- the optimisers on both examples
for e in 5.1 5.2; do
  for m in slsqp projgrad; do
    def "$e:$m:its" "$(v iterations example-$e-$m)"
    def "$e:$m:solves" "$(v evaluations example-$e-$m)"
    def "$e:$m:stop" "$(v stop_reason example-$e-$m)"
    def "$e:$m:dE" "$(sci "$(awk -v a="$(v energy example-$e-$m)" -v b="$(v energy example-$e-optimize)" \
      'BEGIN { d = (a - b) / b; printf "%.17g\n", d < 0 ? -d : d }')" 1)"
  done
done

# ---- the physics: E = -J_c/2 - sum T_i alpha_i / 2 on the files
for e in 5.1 5.2; do
  for w in initial final; do
    o=example-$e-optimize
    E=$(v ${w}_energy $o)
    Jc=$(v ${w}_compliance $o)
    S=$(awk '!/^#/ { s += $5 * $2 } END { printf "%.17g\n", s }' "$out/$o/$w/contact.dat")
    def "$e:$w:Jc" "$(sci "$Jc" 4)"
    def "$e:$w:halfJc" "$(sci "$(awk -v j="$Jc" 'BEGIN { printf "%.17g\n", -j / 2 }')" 4)"
    def "$e:$w:TalphaHalf" "$(sci "$(awk -v s="$S" 'BEGIN { printf "%.17g\n", -s / 2 }')" 4)"
    def "$e:$w:E" "$(sci "$E" 4)"
    def "$e:$w:identity" "$(sci "$(awk -v e="$E" -v j="$Jc" -v s="$S" \
      'BEGIN { d = (e + j / 2 + s / 2) / e; printf "%.17g\n", d < 0 ? -d : d }')" 1)"
  done
done
# ---- the flat pressure: (4.8) at the optimum of Example 5.1
o=$out/example-5.1-optimize
[ -f "$o/multipliers.dat" ] || die "no $o/multipliers.dat"
mu=$(v area_multiplier example-5.1-optimize)
def mu "$(fix "$(awk -v m="$mu" 'BEGIN { print m / 1e6 }')" 1)"
# the free nodes (no bound of B active) and those at the bounds: i x1
# alpha dE lower upper rise fall, and the pressure of contact.dat by x1
awk -v mu="$mu" 'FILENAME ~ /contact/ { if (!/^#/) p[$1] = $6; next }
  /^#/ { next }
  { x = $2; if ($5 == 0 && $6 == 0 && $7 == 0 && $8 == 0) {
      nf++; if (x in p) { d = (p[x] - mu) / mu; if (d < 0) d = -d; if (d > dm) dm = d
        if (!f1) f1 = x; f2 = x } }
    else if ($5 != 0) { nl++; lo = x } else if ($6 != 0) { nu++; up = x; pu = p[x] } }
  END { printf "free %d\nfreefirst %s\nfreelast %s\nfreedev %.17g\nlower %d\nlowerlast %s\n", nf, f1, f2, dm, nl, lo
        printf "upper %d\nupperx %s\nupperpressure %.1f\n", nu, up, pu / 1e6 }' \
  "$o/final/contact.dat" "$o/multipliers.dat" |
while read -r k x; do
  case $k in freedev) def "flat:$k" "$(awk -v x="$x" 'BEGIN { printf "%.1f\n", 100 * x }')" ;;
             *) def "flat:$k" "$x" ;; esac
done

# ---- the objectives (figures/objectives.tex's runs): compliance of each optimum
for k in energy compliance pressure_spread pressure_peak; do
  s=$out/objectives/N16-$k/summary.dat
  [ -f "$s" ] || die "no $s (make figures)"
  def "obj:$k:Jc" "$(sci "$(awk '$1 == "final_compliance" { print $2 }' "$s")" 2)"
done

# ---- the accuracy sweep
sw=$out/accuracy/sweep.dat
def acc:Einf "$(sci "$(awk '$2 == "E_inf" { print $3 }' "$sw")" 6)"
def acc:p "$(fix "$(awk '$2 == "p" { print $3 }' "$sw")" 2)"
def acc:nmax "$(awk '$2 == "nmax" { print $3 }' "$sw")"
def acc:err16 "$(sci "$(awk '$1 == "mesh" && $3 == 16 { print $9 }' "$sw")" 1)"
def acc:errmax "$(sci "$(awk '$1 == "mesh" { e = $9 } END { print e }' "$sw")" 1)"


# ---- the tables of make bench: their macros here, their tabulars apart
macro='^\\(expandafter\\def|providecommand|newcommand|def)'
for b in frontier optimize output levels; do
  f=paper/bench-$b.tex
  [ -f "$f" ] || die "no $f (make bench)"
  grep -E "$macro" "$f" | sed 's/\\newcommand{/\\providecommand{/g'
  grep -v -E "$macro" "$f" > "$dir/bench-$b.tex" || die "no tabular in $f"
done

# ---- the optimum under refinement: the mesh sweep of make accuracy, one
# row a mesh, in DIR/refine.tex; and the area multiplier of each mesh
{
  printf '%s\n' '\begin{tabular}{@{}rrrrrlrr@{}}\toprule' \
    '$N$ & $E_h^*$ [J/m] & $|E_h^* - E_\infty|/|E_\infty|$ & $\mu$ [MPa] & nodes & zone [m] & spread & peak [MPa]\\\midrule'
  awk '$1 == "mesh" { print $3, $2, $9 }' "$sw" | while read -r n point err; do
    r=$out/accuracy/$point
    [ -f "$r/summary.dat" ] || die "no $r/summary.dat (make accuracy)"
    set -- $(contact "$r/final/contact.dat")
    mu=$(awk '$1 == "area_multiplier" { printf "%.1f\n", $2 / 1e6 }' "$r/summary.dat")
    printf '%s & %s & %s & %s & %s & %s & %s & %s\\\\\n' "$n" \
      "$(sci "$(awk '$1 == "energy" { print $2 }' "$r/summary.dat")" 6)" "$(sci "$err" 1)" \
      "$mu" "$1" "$(zone $4 $5 $6)" "$2" "$3"
  done
  printf '%s\n' '\bottomrule\end{tabular}'
} > "$dir/refine.tex"
def acc:mu16 "$(awk '$1 == "area_multiplier" { printf "%.1f\n", $2 / 1e6 }' \
  "$out/accuracy/N16_pdas_1e-10_newton_1e-6/summary.dat")"
def acc:mumax "$(awk '$1 == "mesh" { p = $2 } END { print p }' "$sw" | xargs -I{} awk \
  '$1 == "area_multiplier" { printf "%.1f\n", $2 / 1e6 }' "$out/accuracy/{}/summary.dat")"
# the decision of the area: Example 5.1 with the C2 that makes its arc feasible
o=example-5.1-C2arc-optimize
def C2arc:Estar "$(sci "$(v energy $o)")"
def C2arc:its "$(v iterations $o)"
set -- $(contact "$out/$o/final/contact.dat")
def C2arc:nodes "$1"; def C2arc:spread "$2"; def C2arc:peak "$3"
set -- $(contact "$out/$o/initial/contact.dat")
def C2arc:nodes0 "$1"; def C2arc:spread0 "$2"; def C2arc:peak0 "$3"
# the robustness suite: its scenes
def suite:scenes "$(ls data/suite/*.scene | wc -l | tr -d ' ')"
