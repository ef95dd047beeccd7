# kinds.sh: the objective has one owner.  No file of src/ outside the
# objective module (src/objective*.c, and its header src/objective.h,
# which declares the enumeration) names an enumerator of Objective_kind:
# a caller asks objective_evaluate for a value and a gradient, and the
# objective_* functions for a property of a kind (its name, unit, whether
# it is the energy), and never tests the kind itself (issue 36).
. tests/lib.sh
# the enumerators, read from the declaration itself
kinds=$(sed -n '/typedef enum *{ *OBJECTIVE_/,/} *Objective_kind;/p' src/objective.h \
        | grep -o 'OBJECTIVE_[A-Z_]*' | sort -u)
check "the enumerators of Objective_kind read from src/objective.h: $(echo $kinds)" \
  test "$(echo "$kinds" | grep -c .)" -ge 5
pattern=$(echo $kinds | sed 's/ /\\|/g')
# the search finds them where they belong, so an empty result below means
# something
check "the search finds the enumerators in src/objective.c" \
  grep -qw "$pattern" src/objective.c
others=$(ls src/*.c src/*.h | grep -v '^src/objective[._]')
hits=$(grep -nw "$pattern" $others)
check "no file of src/ outside the objective module names a kind${hits:+: $(echo "$hits" | head -5 | tr '\n' ' ')}" \
  test -z "$hits"
finish
