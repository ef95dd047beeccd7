# keys.sh: contactopt keys and --version.  Every key that keys prints is
# accepted by the loader (set by -s, it is never an unknown key), every
# key the loader accepts is printed (the loader's own list of each
# section's keys, which it tells for an unknown key, is the printed one,
# and so is its list of sections; every key of every shipped scene is
# printed), and the copies in README.md and figures/keys.tex are the
# program's output.  That the printed defaults are the loader's is
# tests/test_scene_keys.c.
. tests/lib.sh
scene=data/example-5.1.scene
$BIN keys > $TMP/keys; rc=$?
check "contactopt keys exits 0 and prints a header and 80 keys" \
  sh -c "[ $rc -eq 0 ] && [ \$(wc -l < $TMP/keys) -eq 81 ] && head -1 $TMP/keys | grep -q '^section.key  *unit  *default  *accepted  *meaning$'"
tail -n +2 $TMP/keys | awk '{ print $1 }' > $TMP/names

# every key printed is accepted: -s KEY=@ is refused for its value, or as
# having no effect, never as an unknown key
for k in $(cat $TMP/names); do
  $BIN solve $scene -o $TMP/out -s "$k=@" > /dev/null 2> $TMP/err; rc=$?
  check "$k is accepted by the loader (exit $rc: $(cat $TMP/err))" \
    sh -c "[ $rc -eq 2 ] && grep -q -F '$k' $TMP/err && ! grep -q 'unknown key\|unknown section' $TMP/err"
done

# every key accepted is printed: the loader's list of each section's keys
# and its list of sections are the printed ones (a named section is
# printed as boundary.NAME, material.NAME: its keys are those of any name)
sections=$(sed 's/\.[^.]*$//' $TMP/names | uniq)
for s in $sections; do
  $BIN solve $scene -o $TMP/out -s "$s.nosuchkey=1" > /dev/null 2> $TMP/err
  told=$(sed -n "s/.*(\[$s\] has \(.*\))$/\1/p" $TMP/err)
  printed=$(grep "^$s\.[^.]*$" $TMP/names | sed "s/^$s\.//" | paste -s -d, - | sed 's/,/, /g')
  check "[$s]: the keys the loader accepts are the keys printed ($told)" [ "$told" = "$printed" ]
done
$BIN solve $scene -o $TMP/out -s "nosuchsection.a=1" > /dev/null 2> $TMP/err
told=$(sed -n 's/.*(the sections are \(.*\))$/\1/p' $TMP/err)
check "the sections the loader accepts are the sections printed ($told)" \
  [ "$told" = "$(echo $sections | sed 's/ /, /g')" ]
for f in data/*.scene data/parts/*.scene data/suite/*.scene tests/scenes/*.scene; do
  case $f in */fuzz-*) continue ;; esac     # fuzzing's inputs: not scenes
  unlisted=$(awk '/^\[/ { gsub(/[][]/, ""); s = $1
      sub(/^boundary\.[A-Za-z0-9_]+$/, "boundary.NAME", s)
      sub(/^material\.[A-Za-z0-9_]+$/, "material.NAME", s); next }
    /^[A-Za-z_0-9]+ *=/ { sub(/ *=.*/, ""); print s "." $0 }' "$f" | grep -v -x -F -f $TMP/names)
  check "every key of $f is printed by contactopt keys${unlisted:+; not: }$unlisted" [ -z "$unlisted" ]
done

# the copies
sed -n '/^<!-- contactopt keys -->$/,/^<!-- end of contactopt keys -->$/p' README.md \
  | sed '1,2d;$d' | sed '$d' > $TMP/readme
check "README.md shows the output of contactopt keys" cmp -s $TMP/keys $TMP/readme
$BIN keys --latex > $TMP/keys.tex
check "figures/keys.tex is the output of contactopt keys --latex" cmp -s $TMP/keys.tex figures/keys.tex
check "keys --latex is a longtable of 80 rows" \
  sh -c "grep -c 'tabularnewline' $TMP/keys.tex | grep -q -x 81 && grep -q 'begin{longtable}' $TMP/keys.tex"

# the help, a bad option, the version
$BIN keys --help > $TMP/help; rc=$?
check "keys --help exits 0 and explains --latex" sh -c "[ $rc -eq 0 ] && grep -q -- --latex $TMP/help"
$BIN keys --frobnicate > $TMP/out 2> $TMP/err; rc=$?
check "keys --frobnicate: exit 2, one line, nothing printed ($(cat $TMP/err))" \
  sh -c "[ $rc -eq 2 ] && [ \$(wc -l < $TMP/err) -eq 1 ] && [ ! -s $TMP/out ] && grep -q frobnicate $TMP/err"
$BIN --version > $TMP/version; rc=$?
version=$(sed -n 's/^#define CONTACTOPT_VERSION "\(.*\)"$/\1/p' src/usage.h)
check "--version prints contactopt $version, as src/usage.h defines it, then what computes (the BLAS, its kernels, the threads)" \
  sh -c "[ $rc -eq 0 ] && [ -n '$version' ] && [ \"\$(head -n 1 $TMP/version)\" = 'contactopt $version' ] \
         && grep -q '^BLAS: .* kernels\$' $TMP/version && grep -q '^threads: a BLAS call on ' $TMP/version"
$BIN --help > $TMP/help
check "--help names keys and --version" sh -c "grep -q '^  keys ' $TMP/help && grep -q -- --version $TMP/help"
finish
