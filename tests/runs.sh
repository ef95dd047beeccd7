# runs.sh: what a run leaves behind and how it ends (issue "a user's first
# hour"): a problem too large for the memory is refused before any work
# (exit 5), memory running out on the way is exit 5 too; Ctrl-C or SIGTERM
# during optimize says so at once and writes every file of the best design
# so far, with stop_reason interrupted, exit 130 and no staging folder; a
# second one stops at once and removes the staging folder; a SIGINT ignored
# when the program starts stays ignored; an output folder
# holds exactly one run's files and is replaced as a whole; a folder that
# is not a run's is never replaced; a killed run's staging folder goes;
# gradcheck reports progress; --matrix-market works with every command.
. tests/lib.sh
ex=data/example-5.1.scene

# ---- memory ------------------------------------------------------------------
$BIN solve $ex -o $TMP/N100000 -s design.N=100000 >/dev/null 2>$TMP/err
check "design.N = 100000: refused before any work, exit 5, one line with the estimate and the memory" \
  clean_failure $? 5 $TMP/err $TMP/N100000 'needs about [0-9.e+]+ GB, more than the [0-9.]+ GB this process may use'
# no index type bounds a model, only the memory: N = 8192, whose factor
# (4.3e9 entries estimated) CHOLMOD's int interface could not index, is
# refused by the memory alone (its estimate, tens of GB, against a limit
# of 8 GB; under make SAN=1 the limit is skipped, see below), and
# design.N = 2000000 by its dense contact arrays on any machine
$BIN solve $ex -o $TMP/big -s design.N=2000000 >/dev/null 2>$TMP/err
check "design.N=2000000: refused before any work by the memory, exit 5, one line" \
  clean_failure $? 5 $TMP/err $TMP/big 'needs about [0-9.e+]+ GB, more than the [0-9.]+ GB this process may use'
# under make SAN=1 the limits are skipped, and said so (limits_run of
# tests/lib.sh); the ordinary build runs them in make check
if limits_run; then
  ( ulimit -v 8000000; $BIN solve $ex -o $TMP/big -s mesh.refine=512 >/dev/null 2>$TMP/err )
  check "ulimit -v 8 GB, N = 8192: refused by the memory alone (no index type bounds it), exit 5, one line" \
    clean_failure $? 5 $TMP/err $TMP/big 'N = 8192 .*needs about [0-9.e+]+ GB, more than the 8.19? GB this process may use'
  ( ulimit -v 400000; $BIN solve $ex -o $TMP/ulimit -s mesh.refine=64 >/dev/null 2>$TMP/err )
  check "ulimit -v 400 MB, N = 1024 (0.85 GB estimated): refused by the estimate, exit 5" \
    clean_failure $? 5 $TMP/err $TMP/ulimit 'more than the 0.41 GB this process may use'
  # 900 MB passes the estimate but not the allocations: out of memory on the
  # way (unasked: a thread count of the user's that the limit cannot give
  # is said in a line of its own, tests/threads.sh)
  ( ulimit -v 900000; unasked $BIN solve $ex -o $TMP/oom -s mesh.refine=64 >/dev/null 2>$TMP/err )
  check "ulimit -v 900 MB, N = 1024: memory runs out on the way, exit 5, one line, nothing written" \
    clean_failure $? 5 $TMP/err $TMP/oom 'out of memory'
  # a part's scene loads gmsh's library and the libraries it needs, which
  # 150 MB of address space cannot map: a matter of memory, exit 5, not
  # of a missing package
  ( ulimit -v 150000; unasked $BIN solve data/parts/pad.scene -o $TMP/gmsh-limit >/dev/null 2>$TMP/err )
  check "ulimit -v 150 MB, a part: gmsh's library cannot be mapped, exit 5, one line" \
    clean_failure $? 5 $TMP/err $TMP/gmsh-limit "cannot load gmsh's library .*: the memory this process may use is too small for it"
fi

# ---- interrupts ------------------------------------------------------------------
# SLSQP on N = 256 takes about 10 s: the signal comes after the first
# iterations are printed.  A script starts its background jobs with SIGINT
# ignored (POSIX), which the program keeps: env --default-signal starts
# them as a terminal does.
dflt=
env --default-signal=INT true 2>/dev/null && dflt="env --default-signal=INT"
[ -n "$dflt" ] || echo "# env --default-signal is missing: SIGINT is sent to runs that ignore it"
# heard PID: the line of the first signal appears while the run PID works
heard() { for _t in $(seq 500); do
    grep -q 'interrupted: the run stops at the next iterate' $TMP/err && break; sleep 0.01; done
  grep -q 'interrupted: the run stops at the next iterate' $TMP/err && kill -0 $1 2>/dev/null; }
for sig in INT TERM; do
  d=$TMP/sig$sig
  rm -f $TMP/out $TMP/err
  # one level: from a coarse-to-fine start too few iterations would remain to interrupt
  $dflt $BIN optimize $ex -o $d -s mesh.refine=16 -s optimizer.method=slsqp -s optimizer.levels=1 >$TMP/out 2>$TMP/err &
  pid=$!
  for t in $(seq 300); do grep -q '^   2  E' $TMP/out 2>/dev/null && break; sleep 0.1; done
  kill -$sig $pid; wait $pid; rc=$?
  check "SIG$sig during optimize: exit 130, two lines: the first's, that the run stops at the next iterate, and the last saying where the files are" \
    holds 'rc == 130 && lines == 2 && first && last' rc=$rc lines="$(wc -l < $TMP/err)" \
      last="$(tail -1 $TMP/err | grep -c "interrupted by signal .* the files of the best design so far are in $d/")" \
      first="$(head -1 $TMP/err | grep -c 'interrupted: the run stops at the next iterate and writes the files of that design; interrupt again')"
  check "SIG$sig: the files of the best design so far, stop_reason interrupted ($(value stop_reason $d), iteration $(value iterations $d))" \
    test "$(value stop_reason $d)" = interrupted -a -s $d/final/contact.dat -a -s $d/multipliers.dat \
      -a "$(value iterations $d)" -ge 2
  check "SIG$sig: the last iterate recorded is the final design (iterates.dat, final/shape.dat)" \
    test "$(awk 'NF == 4 { x[$2] = $4 } END { for (i = 0; i < 257; i++) printf "%.10e\n", x[i] }' $d/iterates.dat | md5sum)" \
       = "$(awk 'NR > 1 { printf "%.10e\n", $2 }' $d/final/shape.dat | md5sum)"
  check "SIG$sig: no staging folder is left" test -z "$(ls -d $d.partial-* 2>/dev/null)"
done
# Ctrl-C while the coarse levels run (N = 1024, sent as the run starts
# its initial state, seconds before the levels begin): they end at their
# next iterate, and the fine run stops at its start, the scene's design,
# instead of after every level
d=$TMP/sig-levels
rm -f $TMP/out $TMP/err
$dflt $BIN optimize $ex -o $d -s mesh.refine=64 >$TMP/out 2>$TMP/err &
pid=$!
for t in $(seq 300); do grep -q 'initial design is not in B' $TMP/out $TMP/err 2>/dev/null && break; sleep 0.1; done
kill -INT $pid; wait $pid; rc=$?
check "SIGINT before the coarse levels end: exit 130, they say they were interrupted, and the run stops at the scene's design (iterations $(value iterations $d), E $(value energy $d), initial $(value initial_energy $d))" \
  holds 'rc == 130 && said == 1 && it == 0 && e == e0' rc=$rc \
    said="$(grep -c 'coarse to fine: interrupted after [0-9]* evaluations\{0,1\}' $TMP/out)" \
    it="$(value iterations $d)" e="$(value energy $d)" e0="$(value initial_energy $d)"
# at N = 512 an iterate of SLSQP takes seconds: the first SIGINT's line
# comes at once, while the run works on its iterate; a second SIGINT then
# stops it: the staging folder is removed, the folder that held a
# previous run is as it was, into a new folder nothing is left.  A first
# signal that falls in the monitor's writing of iterate 0 stops the run
# there, and the second then ends it once its files are in place (a
# complete run, stop_reason interrupted); such a run is tried again, up to
# three times.
for into in new old; do
  d=$TMP/twice-$into
  for try in 1 2 3; do
    rm -rf $d $d.prev $TMP/out $TMP/err
    [ $into = old ] && $BIN solve $ex -o $d >/dev/null 2>&1 && cp -R $d $d.prev
    $dflt $BIN optimize $ex -o $d --replace -s mesh.refine=32 -s optimizer.method=slsqp >$TMP/out 2>$TMP/err &
    pid=$!
    for t in $(seq 600); do grep -q '^   0  E' $TMP/out 2>/dev/null && break; sleep 0.05; done
    sleep 0.5; kill -INT $pid; heard $pid; at_once=$?
    kill -INT $pid; wait $pid; rc=$?
    if [ $into = new ]; then kept=$([ ! -e $d ] && echo 1 || echo 0)
    else kept=$(diff -r $d $d.prev >/dev/null 2>&1 && echo 1 || echo 0); fi
    [ $kept = 1 ] || [ "$(value stop_reason $d 2>/dev/null)" != interrupted ] || [ -n "$(ls -d $d.partial-* 2>/dev/null)" ] || continue
    break
  done
  check "SIGINT at N = 512 ($into folder, try $try): its line at once, while the run works on its iterate" test $at_once -eq 0
  check "two SIGINTs into the $into folder: exit 130, one line (the first's), no staging folder, the folder as it was (exit $rc, $(wc -l < $TMP/err) lines, $(ls -d $d.partial-* 2>/dev/null | wc -l) staging, kept $kept)" \
    holds 'rc == 130 && lines == 1 && left == 0 && kept' rc=$rc lines="$(wc -l < $TMP/err)" \
      left="$(ls -d $d.partial-* 2>/dev/null | wc -l)" kept=$kept
done
# SIGINT ignored when the program starts (a script's background job) stays
# ignored: the optimisation goes on to its end
d=$TMP/ignored
rm -f $TMP/out $TMP/err
sh -c 'trap "" INT; exec "$@"' sh $BIN optimize $ex -o $d -s mesh.refine=8 >$TMP/out 2>$TMP/err &
pid=$!
for t in $(seq 300); do grep -q '^   1  E' $TMP/out 2>/dev/null && break; sleep 0.05; done
kill -INT $pid; wait $pid; rc=$?
check "SIGINT ignored at the start stays ignored: the run ends by itself (exit $rc, stop_reason $(value stop_reason $d)), no line" \
  holds 'rc == 0 && lines == 0 && converged' rc=$rc lines="$(wc -l < $TMP/err)" \
    converged=$([ "$(value stop_reason $d)" = converged ] && echo 1 || echo 0)

# ---- output folders ---------------------------------------------------------------
d=$TMP/folder
$BIN optimize $ex -o $d >/dev/null 2>&1 && $BIN solve $ex -o $d >/dev/null 2>$TMP/err; rc=$?
check "a solve into an optimisation's folder is refused (exit $rc, '$(cat $TMP/err)'), the optimisation kept" \
  holds 'rc == 2 && lines == 1 && kept' rc=$rc lines="$(wc -l < $TMP/err)" \
    kept=$([ "$(value command $d)" = optimize ] && [ -s $d/history.dat ] && echo 1 || echo 0)
grep -q "folder: holds the run of contactopt optimize: solve would replace it; choose another -o, or give --replace" $TMP/err
check "... with one line that names the folder, both commands and --replace" [ $? -eq 0 ]
$BIN solve $ex -o $d --replace >/dev/null 2>$TMP/err
check "--replace lets it: no history.dat, no final/ beside the new files, summary.dat says command solve" \
  test -s $d/summary.dat -a ! -e $d/history.dat -a ! -e $d/final -a "$(value command $d)" = solve
$BIN solve $ex -o $d >/dev/null 2>$TMP/err
check "a solve replaces a solve's folder without --replace ($(cat $TMP/err))" [ $? -eq 0 ]
mkdir -p $TMP/mine && echo precious > $TMP/mine/notes.txt
$BIN solve $ex -o $TMP/mine >/dev/null 2>$TMP/err; rc=$?
check "a folder that is not a run's is refused (exit 2, one line) and left alone" \
  holds 'rc == 2 && lines == 1 && kept' rc=$rc lines="$(wc -l < $TMP/err)" \
    kept=$(grep -q precious $TMP/mine/notes.txt && echo 1 || echo 0)
$BIN gradcheck $ex -o $TMP/mine -s mesh.refine=4 > $TMP/out 2>$TMP/err; rc=$?
check "... and refused before any work: gradcheck at N = 64 (seconds of work) prints no progress line" \
  holds 'rc == 2 && out == 0' rc=$rc out="$(wc -l < $TMP/out)"
dead=999999; while kill -0 $dead 2>/dev/null; do dead=$((dead - 1)); done
mkdir -p $d.partial-$dead/final $d.partial-$$ && touch $d.partial-$dead/final/x
$BIN solve $ex -o $d >/dev/null 2>&1
check "a dead run's staging folder is removed by the next run; a live one's is not" \
  test ! -e $d.partial-$dead -a -d $d.partial-$$
rmdir $d.partial-$$

# ---- a displacement that is not small -------------------------------------------
$BIN solve $ex -o $TMP/gpa -s material.E=215 >/dev/null 2>$TMP/err; rc=$?
check "E = 215 (GPa meant): one warning line on the largest displacement, exit 0, the files written" \
  holds 'rc == 0 && lines == 1 && warned && written' rc=$rc lines="$(wc -l < $TMP/err)" \
    warned=$(grep -c 'warning: .*largest displacement.*exceeds 0.1 of the body' $TMP/err) \
    written=$([ -s $TMP/gpa/summary.dat ] && echo 1 || echo 0)
$BIN solve $ex -o $TMP/steel >/dev/null 2>$TMP/err
check "Example 5.1 as given: no warning" test ! -s $TMP/err

# ---- effective.scene: the run's scene, every default written ------------------
tr=data/example-5.1-tresca.scene
for cmd in solve gradcheck optimize; do
  d=$TMP/eff-$cmd
  $BIN $cmd $tr -o $d -s mesh.refine=2 -s contact.g=2e8 -s material.model=plane_strain >/dev/null 2>&1
  $BIN $cmd $d/effective.scene -o $d-again >/dev/null 2>&1
  f=contact.dat; [ $cmd = optimize ] && f=final/contact.dat; [ $cmd = gradcheck ] && f=gradient.dat
  check "$cmd: effective.scene in the folder reproduces the run bit for bit ($f, energy $(value energy $d))" \
    test -s $d/effective.scene -a "$(value energy $d)" = "$(value energy $d-again)" -a \
         "$(md5sum < $d/$f)" = "$(md5sum < $d-again/$f)"
done

# ---- gradcheck progress, --matrix-market ------------------------------------------------
$BIN gradcheck $ex -o $TMP/gc -s mesh.refine=8 --matrix-market $TMP/gc.mtx >$TMP/out 2>$TMP/err
check "gradcheck at N = 128 prints progress lines, the last at node 129 of 129" \
  test "$(grep -c '^gradcheck: node ' $TMP/out)" -ge 2 -a \
       "$(grep '^gradcheck: node ' $TMP/out | tail -1 | awk '{ print $3, $5 }')" = "129 129,"
check "... each with the time left at the pace so far" \
  test "$(grep '^gradcheck: node ' $TMP/out | grep -c -v 'about [0-9]* s left$')" -eq 0
# a long check is announced before it starts: at N = 512 every node (ten
# state solves each, fifteen on the foundation) takes minutes; the warning
# names the time and a --components spread that takes under a minute.
# The run is stopped once it has said so (SIGINT before it stages its folder).
rm -f $TMP/out $TMP/err
$dflt $BIN gradcheck $ex -o $TMP/long -s mesh.refine=32 > $TMP/out 2> $TMP/err &
pid=$!
for t in $(seq 600); do grep -q 'warning' $TMP/err 2>/dev/null && break; kill -0 $pid 2>/dev/null || break; sleep 0.1; done
kill -INT $pid 2>/dev/null; wait $pid
set -- $(sed -n 's/^gradcheck: 513 of 513 nodes, \([0-9]*\) state solves of about \([0-9.e+-]*\) s: about \([0-9]*\) s$/\1 \2 \3/p' $TMP/out)
check "gradcheck at N = 512 says first: 513 nodes, $1 state solves (between 10 and 15 a node, 2 more), about $3 s" \
  holds 'solves >= 10 * 513 + 2 && solves <= 15 * 513 + 2 && total >= 0.9 * solves * t' solves="$1" t="$2" total="$3"
set -- $(sed -n 's/^contactopt: warning: .*example-5.1.scene: gradcheck of 513 nodes will take about \([0-9]*\) s ([0-9]* state solves of [0-9.e+-]* s); --components 0-512\/\([0-9]*\) checks \([0-9]*\) of them in about \([0-9]*\) s$/\1 \2 \3 \4/p' $TMP/err)
# (under a minute unless the ends alone, the smallest spread, take longer:
# a state solve measured while the machine is loaded, as make
# check-kernels's sixteen threads on two cores load it, may take seconds)
check "... and warns: about $1 s; --components 0-512/$2 checks $3 nodes in about $4 s" \
  holds 'total > 60 && count == int(512 / step) + 1 && (short <= 60 || count == 2) && lines == 1' \
    total="$1" step="$2" count="$3" short="$4" lines="$(wc -l < $TMP/err)"
$BIN solve $ex -o $TMP/s128 -s mesh.refine=8 --matrix-market $TMP/s.mtx >/dev/null 2>&1
check "gradcheck --matrix-market writes A at the design checked: the solve's matrix" cmp -s $TMP/gc.mtx $TMP/s.mtx
$BIN optimize $ex -o $TMP/opt --matrix-market $TMP/opt.mtx >/dev/null 2>&1
$BIN solve $ex -o $TMP/s16 --matrix-market $TMP/s16.mtx >/dev/null 2>&1
check "optimize --matrix-market writes A at the final design: a Matrix Market file of the same size, other values" \
  test "$(head -1 $TMP/opt.mtx | cut -c1-14)" = "%%MatrixMarket" -a \
       "$(grep -v '^%' $TMP/opt.mtx | head -1)" = "$(grep -v '^%' $TMP/s16.mtx | head -1)" -a \
       "$(md5sum < $TMP/opt.mtx)" != "$(md5sum < $TMP/s16.mtx)"
finish
