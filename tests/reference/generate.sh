#!/bin/sh
# generate.sh: make data/reference/, the values the figures' data are
# checked against, each with its provenance.  They come from computations
# independent of the ones 'make figures' runs on the same discrete
# problems: the state by CG-SSOR (MPRGP) to a KKT residual of 1e-12 where
# the figures use the primal-dual active set method, the optimum by
# Algorithm 4.1 (projected gradient) to 1e-7 where the figures use SLSQP.
# Run it by hand (make reference) after a change that is meant to change
# the results; commit the result with the reason.
cd "$(dirname "$0")/../.." || exit 1
set -e
. tests/lib.sh
tmp=$TMP
trap 'rm -rf $tmp' EXIT
today=$(date -u +%Y-%m-%d)
for ex in 5.1 5.2; do
  scene=data/example-$ex.scene
  ref=data/reference/example-$ex.dat
  # the keys of the scene's own initial shape, removed to read a shape file
  unset=$(awk -F' *= *' '/^(arc_|line_|constant)/ { printf "-s design.%s= ", $1 }' $scene)
  bin/contactopt solve $scene -o $tmp/alpha0 -s solver.state=cgssor -s solver.tol=1e-12 >/dev/null
  bin/contactopt optimize $scene -o $tmp/opt -s optimizer.method=projgrad -s optimizer.tol=1e-7 \
    -s solver.state=pdas >/dev/null
  # the state at the projected start, again by CG-SSOR
  bin/contactopt solve $scene -o $tmp/start -s solver.state=cgssor -s solver.tol=1e-12 \
    -s design.initial=file -s design.file=$tmp/opt/initial/shape.dat $unset >/dev/null
  bin/contactopt solve $scene -o $tmp/final -s solver.state=cgssor -s solver.tol=1e-12 \
    -s design.initial=file -s design.file=$tmp/opt/final/shape.dat $unset >/dev/null
  {
    echo "# Reference values for Example $ex on the article's mesh (N = 16, M = 1, R = 3),"
    echo "# plane stress; written by tests/reference/generate.sh on $today."
    echo "# name value # provenance"
    echo "energy_alpha0 $(value energy $tmp/alpha0) # E at alpha0 as given: solve, cgssor, tol 1e-12"
    echo "energy_start $(value energy $tmp/start) # E at the projection of alpha0 onto B: solve, cgssor, tol 1e-12"
    echo "energy_final $(value energy $tmp/final) # E at the optimum of Algorithm 4.1 (projgrad, tol 1e-7): solve, cgssor, tol 1e-12"
    echo "active_final $(value active_contact_nodes $tmp/final) # contact nodes in contact at that optimum (cgssor)"
  } > $ref
  {
    echo "# Final shape of Example $ex: Algorithm 4.1 (projgrad, optimizer.tol 1e-7);"
    echo "# written by tests/reference/generate.sh on $today."
    cat $tmp/opt/final/shape.dat
  } > data/reference/example-$ex-shape.dat
  for which in alpha0 final; do
    {
      echo "# Contact state of Example $ex at the $which design: solve, cgssor, tol 1e-12;"
      echo "# written by tests/reference/generate.sh on $today."
      cat $tmp/$which/contact.dat
    } > data/reference/example-$ex-contact-$which.dat
  done
  echo "wrote $ref and its shape and contact files"
done
