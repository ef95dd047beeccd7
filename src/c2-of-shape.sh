#!/bin/sh
# c2-of-shape.sh GAMMA SHAPE: the C2 = GAMMA (b - a) - int alpha for which
# the design of SHAPE (a shape.dat: x1 alpha) is feasible, its area by the
# trapezoid rule of B, 17 digits on standard output.
# Tangled from paper/reproduction.nw; do not edit.
awk -v gamma="$1" '!/^#/ { if (n++) s += (alpha + $2) / 2 * ($1 - x); else a = $1
    x = $1; alpha = $2 }
  END { if (n < 2) exit 1; printf "%.17g\n", gamma * (x - a) - s }' "$2"
