#!/bin/sh
# accuracy-table.sh SWEEP: the table of the section "What accuracy costs"
# from SWEEP (written by accuracy.sh); LaTeX on standard output.
# Tangled from paper/accuracy.nw; do not edit.
awk -v once=data/accuracy-once.dat '
function num(x, d,   e, s) { if (x == 0) return "0"
  s = x < 0 ? "-" : ""; if (x < 0) x = -x
  e = int(log(x) / log(10)); if (x < 1 && 10^e != x) e--
  if (sprintf("%." d "f", x / 10^e) + 0 >= 10) e++
  return sprintf("%s%." d "f\\cdot10^{%d}", s, x / 10^e, e) }
function sci(x, d) { return "$" num(x, d) "$" }
function tol(x) { return sprintf("$10^{%d}$", log(x) / log(10) - 0.5) }
function heading(f,   n) { n = f; sub(/^[a-z]*-/, "", n)
  if (f == "mesh")
    return "(a) the mesh, $N = 16 \\ldots " nmax \
      "$: the Newton method, \\texttt{pdas} to $10^{-10}$"
  if (f ~ /^(pdas|cgssor)-/) return "(b) \\texttt{" substr(f, 1, index(f, "-") - 1) \
    "}, \\texttt{solver.tol} varied, $N = " n "$"
  if (f ~ /^opttol-/) return "(d) the Newton method, \\texttt{optimizer.tol} varied, $N = " n "$"
  if (f == "projgrad") return "(c) Algorithm 4.1 (\\texttt{projgrad})"
  return "(c) SLSQP, \\texttt{" n "} metric" }
function setting(f) { if (f ~ /^(pdas|cgssor)-/) return tol($5)
  if (f ~ /^opttol-/) return tol($7)
  return "$N = " $3 "$" }
/^# nmax / { nmax = $3 } /^# E_inf / { Einf = $3 } /^# p / { p = $3 }
/^# levels / { lv = $3 " " $4 " " $5; gsub(/N|_[^ ]*/, "", lv); gsub(/ /, ", ", lv) }
/^#/ || NF == 0 { next }
!head++ { print "\\begin{tabular}{@{}lrrrrrrrl@{}}\\toprule"
  print "& $E^*$ [J/m] & $|E^*-E_\\infty|/|E_\\infty|$ & same mesh & shape [m]" \
        " & solves & s & limits & stop\\\\" }
$1 != last { print "\\midrule\\multicolumn{9}{@{}l}{" heading($1) "}\\\\"; last = $1 }
{ stop = $15 == "converged" ? "" : "\\texttt{" $15 "}"; gsub(/_/, "\\_", stop)
  same = $1 == "mesh" ? "--" : sci($10, 1)
  shape = $1 == "mesh" && $3 == nmax ? "--" : sci($11, 1)
  limits = $16 ~ /^[0-9.]+$/ && $16 > 0 ? sprintf("%.1f", $13 / $16) : "--"
  printf "%s & %s & %s & %s & %s & %d & %.2f & %s & %s\\\\\n", setting($1), sci($8, 8),
    sci($9, 1), same, shape, $12, $13, limits, stop }
END { print "\\bottomrule\\end{tabular}"
      printf "\\par\\smallskip\\footnotesize Made by \\texttt{make accuracy} with"
      printf " \\texttt{ACCURACY\\_NMAX=%s}: $E_\\infty = %s$\\,J/m", nmax, num(Einf, 8)
      printf " from $N = %s$, observed rate $p = %.2f$. Errors relative to $|E_\\infty|$;", lv, p
      print " \\emph{same mesh}: against the run of (a) on the same mesh; \\emph{shape}:"
      print "largest difference from the final $\\alpha$ of (a) on $N = " nmax "$;"
      print "\\emph{s}: seconds of the optimisation; \\emph{limits}: those seconds over one"
      print "CHOLMOD analysis, factorisation and solve of the stiffness of that mesh, measured"
      print "in the same sweep; \\emph{stop} blank: converged."
      while ((getline line < once) > 0) {
        if (line ~ /^#/) continue
        split(line, f, " ")
        if (f[1] + 0 <= nmax + 0) continue
        err = (f[2] - Einf) / Einf
        printf " Measured once, beyond the sweep (\\texttt{make accuracy"
        printf " ACCURACY\\_NMAX=%d} on %s): $N = %d$,", f[1], f[6], f[1]
        printf " $E^* = %s$\\,J/m, $%s$ from $E_\\infty$,", num(f[2], 8), num(err < 0 ? -err : err, 1)
        printf " %d solves, %.0f\\,s", f[4], f[5]
        if (f[7] != "") printf ", a peak of %.1f\\,GiB", f[7]
        if (f[8] != "")
          printf "; one CHOLMOD analysis, factorisation and solve of its stiffness " \
                 "%.0f\\,s and %.1f\\,GiB", f[8], f[9]
        print "."

      } }' "$1"
