# converged.sh: one meaning of "converged" for the three optimisers
# (paper/opt.nw, "Stopping"): a KKT point of the shape programme min E over
# B (4.4) to the tolerance.  From the same start on each scene below, the
# Newton method, SLSQP and Algorithm 4.1 run with the defaults.  A run that
# says converged must have every iterate in B to 1e-12 and end at a KKT
# point (the signs and complementarity of the multipliers the program
# writes, stationarity within 1e-4 of the largest gradient); and no run from
# the same start, whatever its stop reason, may end at an energy lower than
# a converged one's by more than 1e-9 of it.  (Two runs that stop at
# pi <= 1e-6 at the same KKT point differ in E by far less: at most 4e-11
# of it on the suite's scenes.)  A run that does not converge exits 3 and
# says why in one line.  The scenes: Example 5.1, Example 5.1 with E = 210
# Pa (GPa meant: the command line warns; the mesh terms of the gradient
# outweigh the contact stiffness by fifteen orders of magnitude) and with
# E = 1e-6 Pa (where the Newton method's model needs the second weight
# of its faces, paper/newton.nw), the
# flat start of Example 5.2 in plane strain, and four scenes of the
# robustness suite on which SLSQP or Algorithm 4.1 does not converge in
# its 200 iterations.
. tests/lib.sh
# one start: LABEL SCENE [-s KEY=VALUE...]
start() {
  label=$1 sc=$2; shift 2
  read -r C0 d S L h <<B
$(scene_B $sc)
B
  for m in newton slsqp projgrad; do
    o=$TMP/$label-$m; rm -rf $o
    $BIN optimize $sc -o $o -s optimizer.method=$m "$@" >/dev/null 2>$TMP/$label-$m.err
    echo $? > $TMP/$label-$m.rc
    if [ ! -f $o/summary.dat ]; then fail "$label $m: no result: $(cat $TMP/$label-$m.err)"; continue; fi
    stop=$(value stop_reason $o); rc=$(cat $TMP/$label-$m.rc)
    if [ "$stop" = converged ]; then
      check "$label $m: converged, exit $rc (pi $(value projected_gradient $o), $(value iterations $o) it)" [ "$rc" -eq 0 ]
      in_B "$label $m" $o 1e-12 $C0 $d $S $L $h
      kkt_point "$label $m" $o $C0 $d $h
    else
      check "$label $m: $stop, exit $rc, says why in one line ($(grep -v warning $TMP/$label-$m.err))" \
        holds 'rc == 3 && lines == 1 && said' rc=$rc lines=$(grep -vc warning $TMP/$label-$m.err) \
          said=$(grep -q "not converged ($stop)" $TMP/$label-$m.err && echo 1 || echo 0)
    fi
  done
  for m in newton slsqp projgrad; do
    c=$TMP/$label-$m
    [ "$(value stop_reason $c 2>/dev/null)" = converged ] || continue
    for o in newton slsqp projgrad; do
      [ $o = $m ] || [ ! -f $TMP/$label-$o/summary.dat ] && continue
      check "$label: $o ($(value stop_reason $TMP/$label-$o)) finds no energy below $m's converged one by more than 1e-9 ($(value energy $TMP/$label-$o) >= $(value energy $c))" \
        holds 'e >= c - 1e-9 * abs(c)' e="$(value energy $TMP/$label-$o)" c="$(value energy $c)"
    done
  done
}
start example-5.1 data/example-5.1.scene
start example-5.1-E210 data/example-5.1.scene -s material.E=210
start example-5.1-E1e-6 data/example-5.1.scene -s material.E=1e-6
start example-5.2-flat-strain data/example-5.2-flat.scene -s material.model=plane_strain
start aluminium-arc data/suite/aluminium-arc.scene
start clamped-strip data/suite/clamped-strip.scene
start cantilever-gravity data/suite/cantilever-gravity.scene
start roller-lift data/suite/roller-lift.scene
finish
