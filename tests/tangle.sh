# tangle.sh: src/ is exactly what paper/*.nw tangles to.
. tests/lib.sh
check "src/ matches a fresh tangle of paper/*.nw" make -s tangle-check
finish
