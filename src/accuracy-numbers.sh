#!/bin/sh
# accuracy-numbers.sh SWEEP STATE: the numbers that the prose of the
# section "What accuracy costs" quotes, as macros \acc{KEY}, from SWEEP
# (written by accuracy.sh) and from the rows of STATE (the state table
# of make bench, paper/bench-state.tex); LaTeX on standard output.
# Tangled from paper/accuracy.nw; do not edit.
echo "% written by src/accuracy-numbers.sh from $1 and $2; do not edit"
printf '%s\n' '\providecommand{\acc}[1]{\ifcsname acc:#1\endcsname' \
  '  \csname acc:#1\endcsname' \
  '\else--\message{accuracy: no number #1 (make accuracy)}\fi}'
awk 'function num(x, d,   e, s) { if (x == 0) return "0"
  s = x < 0 ? "-" : ""; if (x < 0) x = -x
  e = int(log(x) / log(10)); if (x < 1 && 10^e != x) e--
  if (sprintf("%." d "f", x / 10^e) + 0 >= 10) e++
  if (d == 0 && sprintf("%.0f", x / 10^e) + 0 == 1)
    return sprintf("%s10^{%d}", s, e)
  return sprintf("%s%." d "f\\cdot10^{%d}", s, x / 10^e, e) }
function math(x, d) { return "\\ensuremath{" num(x, d) "}" }
function def(k, v) {
  printf "\\expandafter\\def\\csname acc:%s\\endcsname{%s}\n", k, v }
function abs(x) { return x < 0 ? -x : x }
FNR == 1 { f++ }
f == 1 && /^# nmax / { def("nmax", $3) }
f == 1 && /^# E_inf / { Einf = $3; def("Einf", math($3, 6)) }
f == 1 && /^# p / { def("p", sprintf("%.2f", $3)) }
f == 1 && (/^#/ || NF == 0) { next }
f == 1 { k = $2; gsub(/_/, "/", k); def(k ":same", math($10, 0))
  def(k ":solves", $12); def(k ":sec", sprintf("%.2g", $13))
  if ($1 == "mesh") { m[++n] = $3; E[n] = $8; s[n] = $13
    def("err:" $3, math($9, 1)); def("sec:" $3, sprintf("%.2g", $13))
    def("shape:" $3, math($11, 1)) }
  next }
f == 2 && $1 == 64 && $3 ~ /^[0-9]+$/ { sub(/\\\\$/, ""); gsub(/ /, "")
  split($0, c, "&"); def("psor/pdas", sprintf("%.0f", c[8] / c[4]))
  def("cgssor/pdas", sprintf("%.1f", c[6] / c[4])) }
END { for (i = 3; i <= n; i++) {
    r = (E[i-2] - E[i-1]) / (E[i-1] - E[i]); if (!(r > 1)) continue
    p = log(r) / log(2); x = E[i] + (E[i] - E[i-1]) / (2^p - 1)
    def("xerr:" m[i], math(abs(x - Einf) / abs(Einf), 1))
    def("xp:" m[i], sprintf("%.2f", p))
    def("xsec:" m[i], sprintf("%.2g", s[i-2] + s[i-1] + s[i])) } }' "$1" "$2"
