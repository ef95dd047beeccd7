#!/bin/sh
# hard-nu.sh OUT: Example 5.1 solved by pdas in both plane models at
# nu = 0.29, 0.45, 0.499, 0.4999 on N = 16 .. 256 into OUT/<model>-<nu>-<N>;
# the table of the section "Near incompressibility" (LaTeX, on standard
# output), and the macros \nuN{sinklo}, \nuN{sinkhi} of the sinking at
# x1 = 2.  A solve that pdas ends unconverged at the default tolerance
# (exit 3: the rounding of A u above it) is run again at solver.tol = 1e-9
# and its cells are starred.  Tangled from paper/stability.nw; do not edit.
set -e
bin=${BIN:-bin/contactopt}
out=$1; ex=data/example-5.1.scene
mkdir -p "$out"
v() { awk -v k="$1" '$1 == k { print $2; exit }' "$2/summary.dat"; }
echo "% written by src/hard-nu.sh; do not edit"
printf '%s\n' '\begin{tabular}{@{}llrrrrrrrrr@{}}' '\toprule' \
  '& & \multicolumn{5}{c}{$-u_2(4,1)$ [mm] on $N =$} & $u_2^{16}/u_2^{256}$' \
  '& \multicolumn{2}{c}{$-E_h$ [MJ/m]} & \texttt{pdas} steps\\' \
  '\cmidrule(lr){3-7}\cmidrule(lr){9-10}' \
  'model & $\nu$ & 16 & 32 & 64 & 128 & 256 & & $N=16$ & $N=256$ & $N=16..256$\\'
for m in plane_strain plane_stress; do
  echo '\midrule'
  for nu in 0.29 0.45 0.499 0.4999; do
    for N in 16 32 64 128 256; do
      d=$out/$m-$nu-$N; set -- -s material.model=$m -s material.nu=$nu \
        -s mesh.refine=$((N / 16))
      rm -f "$d.star"
      "$bin" solve $ex -o "$d" --plot-files "$@" > "$d.log" 2>&1 || {
        [ $? = 3 ] || exit 1
        "$bin" solve $ex -o "$d" --plot-files "$@" -s solver.tol=1e-9 > "$d.log"
        touch "$d.star"; }
      # -u2 of the top right corner (column N, row N/4) in mm; the energy
      # in MJ/m; the steps; a star where the tolerance was 1e-9
      awk -v N=$N '$2 == N && $3 == N / 4 { printf "%.3f", -1000 * $7 }' \
        "$d/nodes.dat"
      printf ' %.3f %d %s\n' "$(v energy "$d" | awk '{ print -$1 / 1e6 }')" \
        "$(v iterations "$d")" "$([ -f "$d.star" ] && echo '$^*$' || echo '')"
    done > "$out/$m-$nu.row"
    # one line of the table from the five meshes' rows
    awk -v m="${m#plane_}" -v nu=$nu '{ u[NR] = $1 $4; e[NR] = $2 $4; r[NR] = $1
        s = $3; if (NR == 1 || s < lo) lo = s; if (NR == 1 || s > hi) hi = s }
      END { printf "%s & %s", nu == 0.29 ? m : "", nu
        for (i = 1; i <= 5; i++) printf " & %s", u[i]
        printf " & %.3f & %s & %s & %d--%d\\\\\n", r[1] / r[5], e[1], e[5],
          lo, hi }' \
      "$out/$m-$nu.row"
  done
done
printf '%s\n' '\bottomrule' '\end{tabular}'
# the note of the stars, where there are any
ls "$out"/*.star > /dev/null 2>&1 && printf '%s\n' '\\[2pt]{\footnotesize $^*$' \
  'solved at \texttt{solver.tol = 1e-9}: at $10^{-10}$ \texttt{pdas} stops' \
  'unconverged there (exit 3).}'
# the macros \nuN{sinklo}, \nuN{sinkhi}: the least and the most sinking
# -u2 of the contact node at x1 = 2 (column N/2, row 0) over every run of
# the table, in mm
for f in "$out"/*/nodes.dat; do
  N=$(awk '$1 == "N" { print $2 }' "${f%/nodes.dat}/summary.dat")
  awk -v N=$N '$2 == N / 2 && $3 == 0 { printf "%.17g\n", -1000 * $7 }' "$f"
done | sort -g | awk 'NR == 1 { lo = $1 } { hi = $1 }
  END { printf "\\gdef\\nuN#1{\\csname nu:#1\\endcsname}\n"
        printf "\\expandafter\\gdef\\csname nu:sinklo\\endcsname{%.1f}\n", lo
        printf "\\expandafter\\gdef\\csname nu:sinkhi\\endcsname{%.1f}\n", hi }'
