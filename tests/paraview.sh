# paraview.sh: the VTU files read back by a real reader (meshio, Debian's
# python3-meshio, run by tests/paraview.py): counts, array names, values
# against the text files, and the stress recomputed from the displacement.
. tests/lib.sh
PYTHON=${PYTHON:-/usr/bin/python3}
# material SCENE KEY: the value of KEY in the [material] section of SCENE
material() { awk -F' *= *' '/^\[/ { in_m = ($0 == "[material]") } in_m && $1 == k { print $2 }' k=$2 $1; }
# state LABEL SCENE MODEL [-s ...]: solve into $TMP/LABEL, check its VTU
state() { label=$1 scene=$2 model=$3; shift 3
  if $BIN solve $scene -o $TMP/$label --plot-files -s material.model=$model "$@" >/dev/null 2>$TMP/err; then
    $PYTHON tests/paraview.py state $TMP/$label "$(material $scene E)" "$(material $scene nu)" $model \
      || failures=$((failures + 1))
  else fail "$label: solve: $(cat $TMP/err)"; fi; }
state example-5.1 data/example-5.1.scene plane_stress
state example-5.1-strain data/example-5.1.scene plane_strain
state example-5.2-x2 data/example-5.2.scene plane_stress -s mesh.refine=2
state tresca data/example-5.1-tresca.scene plane_stress -s contact.g=2.5e8

# optimize: iterates.pvd and iterates/, by each optimiser, in plane stress
# and strain; a rerun into the same folder that stops sooner (max_iter,
# exit 3) leaves only its own iterates
# iterates LABEL SCENE MODEL EXIT [-s ...]: optimize into $TMP/LABEL, which
# must exit with EXIT, check its collection
iterates() { label=$1 scene=$2 model=$3 want=$4; shift 4
  $BIN optimize $scene -o $TMP/$label -s material.model=$model "$@" >/dev/null 2>$TMP/err
  if [ $? -eq $want ] && [ -s $TMP/$label/iterates.pvd ]; then
    $PYTHON tests/paraview.py pvd $TMP/$label "$(material $scene E)" "$(material $scene nu)" $model \
      || failures=$((failures + 1))
  else fail "$label: optimize: $(cat $TMP/err)"; fi; }
iterates opt-newton data/example-5.1.scene plane_stress 0
iterates opt-slsqp data/example-5.2.scene plane_strain 0 -s optimizer.method=slsqp
iterates opt-projgrad data/example-5.1.scene plane_stress 0 -s optimizer.method=projgrad
echo "# opt-projgrad again, into the same folder, stopped at max_iter = 3 (exit 3):"
iterates opt-projgrad data/example-5.1.scene plane_stress 3 -s optimizer.method=projgrad \
  -s optimizer.max_iter=3
check "the rerun's folder holds only its own iterates: 4 rows in history.dat" \
  test "$(awk 'NF && !/^#/' $TMP/opt-projgrad/history.dat | wc -l)" -eq 4
finish
