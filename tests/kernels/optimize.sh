# tests/kernels/optimize.sh: the optimisation of every shipped scene (data/*.scene) and
# every scene of the robustness suite (data/suite/*.scene) at mesh.refine
# 1, 4 and 8 must end the same way under every OpenBLAS kernel family:
# the same exit status and the same stop reason (summary.dat's
# stop_reason, or, for a run that wrote nothing, the solver its one line
# of stderr names).  The rounding of the kernels differs in the last bits;
# a result that depends on it is a defect (paper/opt.nw, "Rounding").
# Long (see paper/opt.nw for its time): make check-kernels runs it at
# REFINES="1 4", make check-kernels-full at all three. The environment chooses:
#   KERNELS  OPENBLAS_CORETYPE values, default "Haswell Sandybridge Prescott"
#   REFINES  mesh.refine values, default "1 4 8"
#   METHODS  optimizer.method values, default "newton" (the default method)
#   SCENES   scene files, default data/*.scene data/suite/*.scene
#   OVERRIDES  section.key=value overrides for every run (-s), default none
#   ITERATIONS  1: the iteration count must not change with the kernel either
. tests/lib.sh
KERNELS=${KERNELS:-Haswell Sandybridge Prescott}
REFINES=${REFINES:-1 4 8}
METHODS=${METHODS:-newton}
SCENES=${SCENES:-$(ls data/*.scene data/suite/*.scene)}
over=; for o in ${OVERRIDES:-}; do over="$over -s $o"; done
# outcome DIR ERR RC: "exit RC, STOP (I iterations)" of one run, or for a
# run that wrote nothing "exit RC, SOLVER failed" (the word before the
# first colon of its message, after the program's name)
outcome() {
  if [ -f "$1/summary.dat" ]; then
    echo "exit $3, $(value stop_reason $1) ($(value iterations $1) iterations)"
  else
    echo "exit $3, $(sed -n '1s/^[^:]*: *//; 1s/:.*//p' $2) failed"
  fi
}
# the part of an outcome that must not depend on the kernel: exit and stop
same_part() { if [ "${ITERATIONS:-0}" = 1 ]; then cat; else sed 's/ (.*//'; fi; }
what="the same exit status and stop reason"
[ "${ITERATIONS:-0}" = 1 ] && what="the same exit status, stop reason and iteration count"
start=$(date +%s)
for sc in $SCENES; do
  name=$(basename $sc .scene)
  for r in $REFINES; do
    for m in $METHODS; do
      first= all= differ=0
      for k in $KERNELS; do
        out=$TMP/$name-$r-$m-$k; rm -rf $out
        OPENBLAS_CORETYPE=$k $BIN optimize $sc -o $out -s mesh.refine=$r -s optimizer.method=$m $over \
          >/dev/null 2>$out.err; rc=$?
        o=$(outcome $out $out.err $rc)
        all="$all; $k: $o"
        if [ -z "$first" ]; then first=$o
        elif [ "$(echo "$o" | same_part)" != "$(echo "$first" | same_part)" ]; then differ=1; fi
        rm -rf $out
      done
      check "$name${OVERRIDES:+ ($OVERRIDES)} refine $r $m: $what under every kernel (${all#; })" \
        [ $differ -eq 0 ]
    done
  done
done
echo "# kernels/optimize.sh: $(($(date +%s) - start)) s for $(echo $SCENES | wc -w) scenes x refine $REFINES x $METHODS x $KERNELS${OVERRIDES:+ with $OVERRIDES}"
finish
