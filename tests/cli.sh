# cli.sh: the command line: help texts, overrides, the files of solve, the
# Matrix Market export, and bad input: exit status 2, one line naming the
# file, nothing written.
. tests/lib.sh
scene=data/example-5.1.scene
top=$PWD      # the package's root, for commands run in another folder
$BIN --help > $TMP/help; rc=$?
check "contactopt --help exits 0 and names the solve command" \
  sh -c "[ $rc -eq 0 ] && grep -q solve $TMP/help"
$BIN solve --help > $TMP/help; rc=$?
for opt in -o -s --matrix-market --plot-files --help; do
  check "contactopt solve --help explains $opt" grep -q -- "$opt" $TMP/help
done
$BIN frobnicate $scene 2>$TMP/err; rc=$?
check "an unknown command exits 2" [ $rc -eq 2 ]

out=$TMP/run
$BIN solve $scene -o $out -s mesh.M=2 --matrix-market $TMP/A.mtx > $TMP/stdout; rc=$?
check "solve exits 0" [ $rc -eq 0 ]
for f in summary.dat shape.dat contact.dat solution.vtu; do
  check "solve writes $f" test -s $out/$f
done
check "solve writes no nodes.dat, no triangles.dat without --plot-files" \
  test ! -e $out/nodes.dat -a ! -e $out/triangles.dat
$BIN solve $scene -o $TMP/plot --plot-files > /dev/null
check "solve --plot-files writes nodes.dat (a row per node) and triangles.dat (4 rows per triangle)" \
  test "$(grep -vc '^#' $TMP/plot/nodes.dat)" -eq 85 -a "$(grep -v '^#' $TMP/plot/triangles.dat | grep -c .)" -eq 512
$BIN optimize $scene -o $TMP/plot-opt --plot-files > /dev/null
check "optimize --plot-files writes them in initial/ and final/, optimize alone does not" \
  sh -c "test -s $TMP/plot-opt/initial/nodes.dat -a -s $TMP/plot-opt/final/triangles.dat &&
         $BIN optimize $scene -o $TMP/opt > /dev/null && test ! -e $TMP/opt/final/nodes.dat"
for k in energy kkt_residual iterations active_contact_nodes dofs seconds; do
  check "summary.dat has $k" grep -q "^$k " $out/summary.dat
done
check "-s mesh.M=2 is applied (M 2 in the summary)" grep -q '^M 2$' $out/summary.dat
check "no staging folder is left behind" sh -c "! ls -d $out.partial-* 2>/dev/null"
# Matrix Market: the banner, then n n nnz with n = dofs
dofs=$(value dofs $out)
mtx_order_is_dofs() {
  head -1 $TMP/A.mtx | grep -q '^%%MatrixMarket matrix coordinate real' || return 1
  set -- $(grep -v '^%' $TMP/A.mtx | head -1)
  holds 'rows == n && columns == n' rows="$1" columns="$2" n="$dofs"; }
check "the Matrix Market file is a real matrix of order dofs = $dofs" mtx_order_is_dofs
check "shape.dat has N+1 = 17 rows" sh -c "[ \$(grep -vc '^#' $out/shape.dat) -eq 17 ]"
# round-off leaves |T| ~ 1e-15 max T at the nodes out of contact
check "contact.dat: every gap >= 0 and every contact force >= -1e-12 max T" \
  holds 'gap >= -1e-12 && T >= -1e-12 * max(Tmax, 0)' gap="$(rows_min '$4' $out/contact.dat)" \
    T="$(rows_min '$5' $out/contact.dat)" Tmax="$(rows_max '$5' $out/contact.dat)"
check "the default output folder is out/NAME" sh -c "cd $TMP && mkdir -p d && cp $top/$scene d/x.scene &&
  $top/$BIN solve d/x.scene >/dev/null && test -s out/x/summary.dat"

# one override switches a side, the contact law or the initial shape: the
# file's keys that the new word makes meaningless are dropped
$BIN solve $scene -o $TMP/free -s top.bc=free > /dev/null 2> $TMP/err; rc=$?
check "solve -s top.bc=free alone: exit 0, no load, E = 0 ($(cat $TMP/err))" \
  sh -c "[ $rc -eq 0 ] && [ \"\$(awk '\$1 == \"energy\" { print \$2 }' $TMP/free/summary.dat)\" = 0 ]"
$BIN solve data/example-5.1-tresca.scene -o $TMP/coulomb -s contact.model=coulomb \
  -s contact.friction=0.2 > /dev/null 2> $TMP/err; rc=$?
check "solve -s contact.model=coulomb on the Tresca scene drops its g: exit 0 ($(cat $TMP/err))" \
  sh -c "[ $rc -eq 0 ] && grep -q '^contact coulomb' $TMP/coulomb/summary.dat"
check "summary.dat and effective.scene echo friction = 0.2 as given (not 0.20000000000000001)" \
  sh -c "grep -q '^friction 0.2\$' $TMP/coulomb/summary.dat && grep -q '^friction = 0.2\$' $TMP/coulomb/effective.scene"

# a fine mesh from a coarse optimum: the final shape.dat of an optimisation
# on N = 16, read on the mesh refined four times, is resampled onto its 65
# nodes, and the program says so in one line
$BIN optimize $scene -o $TMP/coarse > /dev/null 2>&1
$BIN solve $scene -o $TMP/fine -s mesh.refine=4 -s design.initial=file \
  -s design.file=$TMP/coarse/final/shape.dat > $TMP/stdout 2> $TMP/err; rc=$?
check "solve on N = 64 from the optimum on N = 16: exit 0, the note on stdout ($(head -1 $TMP/stdout | cut -c1-150))" \
  sh -c "[ $rc -eq 0 ] && grep -q 'shape.dat: 17 rows on \[0, 4\] resampled by linear interpolation onto the N + 1 = 65 design nodes' $TMP/stdout"
# design.file given by -s is relative to the scene's folder, as in the
# scene file; run elsewhere, a file that is not there says where it was
# looked for
( cd $TMP/coarse/final && "$top/$BIN" solve "$top/$scene" -o $TMP/rel -s design.initial=file \
    -s design.file=shape.dat > /dev/null 2> $TMP/err ); rc=$?
check "-s design.file=shape.dat run in another folder: exit $rc, the message says the path is the scene's ($(cat $TMP/err))" \
  sh -c "[ $rc -eq 2 ] && grep -q 'cannot read .*/data/shape.dat (design.file is relative to the scene.s folder)' $TMP/err"
grep -v '^#' $TMP/fine/shape.dat | awk 'NR % 4 == 1' > $TMP/every4
grep -v '^#' $TMP/coarse/final/shape.dat | paste $TMP/every4 - > $TMP/both
check "the resampled shape is the coarse optimum at every fourth node (to 1e-15 m)" \
  le "$(rows_max 'abs($2 - $4) + abs($1 - $3)' $TMP/both)" 1e-15

# bad input: status 2, one line naming the file, no output folder
bad() { # description expected-words... -- arguments
  desc=$1; shift; words=""
  while [ "$1" != "--" ]; do words="$words $1"; shift; done; shift
  rm -rf $TMP/bad
  $BIN solve "$@" -o $TMP/bad > /dev/null 2> $TMP/err; rc=$?
  if clean_failure $rc 2 $TMP/err $TMP/bad $words; then ok "$desc: exit 2, $(cat $TMP/err)"
  else fail "$desc: exit $rc, wrote $(ls $TMP/bad 2>/dev/null | wc -l) files: $(cat $TMP/err)"; fi
}
bad "a missing scene" missing.scene -- $TMP/missing.scene
bad "an unknown key" solver.frobnicate -- $scene -s solver.frobnicate=1
bad "nu = 0.5" material.nu 0.5 -- $scene -s material.nu=0.5
bad "a malformed number" mesh.M -- $scene -s mesh.M=4x
bad "the schur metric with Algorithm 4.1" optimizer.metric schur slsqp -- $scene \
  -s optimizer.method=projgrad -s optimizer.metric=schur
bad "an unknown metric" optimizer.metric sobolev -- $scene -s optimizer.metric=sobolev
bad "a metric with the Newton method" optimizer.metric "no effect" newton -- $scene \
  -s optimizer.method=newton -s optimizer.metric=schur
bad "a key of an override that the switch makes meaningless" top.P2 "no effect" -- $scene \
  -s top.bc=free -s top.P2=1e6
printf '# x1 alpha\n0 0.01\n1 0.01\n' > $TMP/short.dat
bad "a shape on [0, 1] for a body on [0, 4]" design.file 'short.dat line 3' 'ends at x1 = b = 4' -- $scene \
  -s design.initial=file -s design.file=$TMP/short.dat
bad "a named section without part.geometry" boundary.bore.bc "needs part.geometry" -- $scene \
  -s boundary.bore.bc=clamped
bad "a geometry file that is not there" part.geometry "cannot read the geometry file" -- $scene \
  -s part.geometry=$TMP/nosuch.geo -s design.C2=0.91
# what the mesher refuses as the scene loads: a name that tests/parts/bore.geo
# (curves bore and top, surface block) lacks, a roller on its circle
part="-s part.geometry=$top/tests/parts/bore.geo -s design.C2=0.91"
bad "a boundary name the geometry lacks" example-5.1.scene bore.geo boundary.seat \
  "no physical curve seat" -- $scene $part -s boundary.seat.bc=clamped
bad "a roller on a circle" example-5.1.scene bore.geo "boundary.bore.bc = roller" \
  "not a straight line along x1 or x2" -- $scene $part -s boundary.bore.bc=roller
bad "an unknown material kind" material.kind "unknown value" -- $scene -s material.kind=cubic
bad "an orthotropic key in the isotropic material" material.E1 "no effect with kind = isotropic" -- $scene \
  -s material.E1=2e11
bad "an unknown option" --frobnicate -- $scene --frobnicate
bad "two scenes" more -- $scene $scene
rm -rf $TMP/bad
$BIN gradcheck $scene -o $TMP/bad --plot-files > /dev/null 2> $TMP/err; rc=$?
if clean_failure $rc 2 $TMP/err $TMP/bad --plot-files gradcheck; then
  ok "gradcheck refuses --plot-files (it writes no mesh): exit 2, $(cat $TMP/err)"
else fail "gradcheck --plot-files: exit $rc: $(cat $TMP/err)"; fi
# every path the command line names is checked before any work: a
# gradcheck at N = 64 (seconds of work, a line of progress a second) that
# is refused prints nothing on the standard output, one line on the
# standard error naming the path and the reason, and writes nothing
early() { # description exit pattern -- arguments (after "gradcheck SCENE")
  desc=$1 code=$2 pat=$3; shift 4
  rm -rf $TMP/bad
  ( cd $TMP && "$top/$BIN" gradcheck "$top/$scene" -s mesh.refine=4 "$@" > $TMP/stdout 2> $TMP/err ); rc=$?
  check "$desc: exit $rc at once, one line naming the path and the reason ($(cat $TMP/err))" \
    at_once $rc $code $TMP/err $TMP/bad "$pat"; }
# at_once RC CODE ERR DIR PATTERN: clean_failure, no line of work, no staging folder
at_once() { [ ! -s $TMP/stdout ] && ! ls -a $TMP | grep -q 'partial-' && clean_failure "$@"; }
early "--matrix-market /nonexistent/A.mtx" 4 \
  '/nonexistent/A.mtx: cannot create it in /nonexistent: No such file or directory' -- \
  -o $TMP/bad --matrix-market /nonexistent/A.mtx
early "-o ''" 2 "-o '': the output folder has an empty name" -- -o ''
touch $TMP/afile
early "-o under a file" 4 'afile/bad: cannot create it in .*afile: Not a directory' -- -o $TMP/afile/bad
early "-o DIR/." 2 'cannot replace the folder \.' -- -o $TMP/bad/.
# a folder that exists but cannot be moved aside (immutable, chattr +i):
# refused before any work, not after it (exit 4); where the file system
# has no such attribute, said so and skipped
mkdir -p $TMP/bad && if chattr +i $TMP/bad 2>/dev/null; then
  ( cd $TMP && "$top/$BIN" gradcheck "$top/$scene" -s mesh.refine=4 -o $TMP/bad > $TMP/stdout 2> $TMP/err ); rc=$?
  chattr -i $TMP/bad
  check "-o an immutable empty folder: exit $rc at once, one line ($(cat $TMP/err))" \
    holds 'rc == 4 && out == 0 && lines == 1 && said' rc=$rc out="$(wc -l < $TMP/stdout)" \
      lines="$(wc -l < $TMP/err)" said=$(grep -q "bad: cannot replace it (it cannot be moved aside)" $TMP/err && echo 1 || echo 0)
else ok "# skip: chattr +i is not supported here"; fi
rm -rf $TMP/bad
# a folder that cannot be made (under /proc): the message names the
# user's folder, not the staging folder beside it
$BIN solve $scene -o /proc/contactopt-test > /dev/null 2> $TMP/err; rc=$?
check "-o under /proc: exit $rc, the user's path named ($(cat $TMP/err))" \
  holds 'rc == 4 && said && !staged' rc=$rc said=$(grep -q '/proc/contactopt-test: cannot create' $TMP/err && echo 1 || echo 0) \
    staged=$(grep -q partial $TMP/err && echo 1 || echo 0)
early "--matrix-market ''" 2 "--matrix-market '': the file has an empty name" -- -o $TMP/bad --matrix-market ''
early "--matrix-market a folder" 4 "$TMP: cannot write: Is a directory" -- -o $TMP/bad --matrix-market $TMP
early "--matrix-market in a folder that is not there" 4 'sub/A.mtx: cannot create it in .*bad/sub: No such file' -- \
  -o $TMP/bad --matrix-market $TMP/bad/sub/A.mtx
early "--components beyond N" 2 'example-5.1.scene: command line: --components 65: not a list of nodes .* in 0..N = 0..64' -- \
  -o $TMP/bad --components 65
early "--components 3," 2 'command line: --components 3,: not a list' -- -o $TMP/bad --components 3,
early "--components 4-0" 2 'command line: --components 4-0: not a list' -- -o $TMP/bad --components 4-0
early "--components 0-8/0" 2 'command line: --components 0-8/0: not a list' -- -o $TMP/bad --components 0-8/0
$BIN solve $scene -o $TMP/bad --components 1 > /dev/null 2> $TMP/err; rc=$?
check "solve refuses --components (it checks no gradient): exit 2, $(cat $TMP/err)" \
  clean_failure $rc 2 $TMP/err $TMP/bad '--components: solve checks no gradient'
# names that work: a trailing slash (twice: the second replaces the first
# run), and a matrix in the output folder the run is to make
$BIN solve $scene -o $TMP/slash/ > /dev/null 2> $TMP/err && $BIN solve $scene -o $TMP/slash/ > /dev/null 2>> $TMP/err; rc=$?
check "-o DIR/ twice: exit $rc, the run in DIR, nothing beside it $(cat $TMP/err)" \
  sh -c "[ $rc -eq 0 ] && [ -s $TMP/slash/summary.dat ] && [ \$(ls -d $TMP/slash* | wc -l) -eq 1 ]"
$BIN solve $scene -o $TMP/new/run --matrix-market $TMP/new/./run/A.mtx > /dev/null 2> $TMP/err; rc=$?
check "--matrix-market into the output folder the run makes: exit $rc, the matrix there $(cat $TMP/err)" \
  sh -c "[ $rc -eq 0 ] && [ -s $TMP/new/run/A.mtx ] && [ -s $TMP/new/run/summary.dat ]"

# --components: the nodes listed, a row of gradient.dat each
$BIN gradcheck $scene -o $TMP/some --components 0,3-9/3,16 > $TMP/stdout 2> $TMP/err; rc=$?
check "gradcheck --components 0,3-9/3,16: exit $rc, nodes 0 3 6 9 16 in gradient.dat, nodes_checked 5" \
  test $rc -eq 0 -a "$(awk '!/^#/ { printf "%s ", $1 }' $TMP/some/gradient.dat)" = "0 3 6 9 16 " \
    -a "$(value nodes_checked $TMP/some)" = 5
# node 16 lies on the foundation (the arc meets it at x1 = b): its five
# differences are one-sided, three solves each; the others two each
check "gradcheck says first how long it will take: 5 of 17 nodes, 57 state solves (4 x 10 + 15, and 2 at the design)" \
  grep -q '^gradcheck: 5 of 17 nodes, 57 state solves of about .* s: about [0-9]* s$' $TMP/stdout
check "a short check warns of nothing (stderr empty)" test ! -s $TMP/err

# a state solver's failure names the scene, as every failure does
$BIN solve $scene -o $TMP/bad -s solver.max_iter=2 > /dev/null 2> $TMP/err; rc=$?
check "pdas stopped after 2 iterations: exit 3, one line naming the scene first: $(cat $TMP/err)" \
  clean_failure $rc 3 $TMP/err $TMP/bad "^contactopt: $scene: pdas: not converged after 2 iterations"
$BIN optimize $scene -o $TMP/bad -s solver.state=cgssor -s solver.max_iter=2 > /dev/null 2> $TMP/err; rc=$?
check "cgssor stopped after 2 iterations in optimize: exit 3, one line naming the scene first: $(cat $TMP/err)" \
  clean_failure $rc 3 $TMP/err $TMP/bad "^contactopt: $scene: cgssor: not converged after 2 iterations"

printf '[geometry\na = 0\n' > $TMP/broken.scene
bad "a syntax error" broken.scene line -- $TMP/broken.scene
# found by make fuzz (tests/fuzz/): a NUL byte on the last line, which has
# no newline, cut the line silently; with a non-zero traction the scene
# loaded.  Its line 26 is "\0...\0[right]P2e.slo".
bad "a NUL byte cutting the last line (fuzzing)" fuzz-nul-byte.scene 'line 26' 'NUL byte' -- \
  tests/scenes/fuzz-nul-byte.scene -s top.P1=1e3
finish
