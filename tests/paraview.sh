# paraview.sh: the VTU files read back by a real reader (meshio, Debian's
# python3-meshio, run by tests/paraview.py): counts, array names, values
# against the text files, and the stress recomputed from the displacement.
. tests/lib.sh
PYTHON=${PYTHON:-/usr/bin/python3}
# material SCENE KEY: the value of KEY in the [material] section of SCENE
material() { awk -F' *= *' '/^\[/ { in_m = ($0 == "[material]") } in_m && $1 == k { print $2 }' k=$2 $1; }
# state LABEL SCENE MODEL [-s ...]: solve into $TMP/LABEL, check its VTU
state() { label=$1 scene=$2 model=$3; shift 3
  if $BIN solve $scene -o $TMP/$label -s material.model=$model "$@" >/dev/null 2>$TMP/err; then
    $PYTHON tests/paraview.py state $TMP/$label "$(material $scene E)" "$(material $scene nu)" $model \
      || failures=$((failures + 1))
  else fail "$label: solve: $(cat $TMP/err)"; fi; }
state example-5.1 data/example-5.1.scene plane_stress
state example-5.1-strain data/example-5.1.scene plane_strain
state example-5.2-x2 data/example-5.2.scene plane_stress -s mesh.refine=2
state tresca data/example-5.1-tresca.scene plane_stress -s contact.g=2.5e8
finish
