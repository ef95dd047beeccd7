# opaque.sh: the model has one owner.  src/model.h declares Model without
# its fields; the structure is in src/model_private.h, which only the
# model's own files, src/model.c and src/model_read.c (its accessors),
# include, so that no other file of src/ or tests/ can read
# or write a field of a Model: they go through the accessors of model.h
# (paper/model.nw, issue 36).
. tests/lib.sh
check "src/model.h declares Model as an incomplete type" \
  grep -q '^typedef struct Model Model;' src/model.h
check "src/model.h does not define the structure" \
  sh -c '! grep -q "^struct Model *{" src/model.h'
check "src/model_private.h defines the structure" \
  grep -q '^struct Model *{' src/model_private.h
# the search finds the include where it belongs, so an empty result below
# means something
check "the search finds the private header included in src/model.c" \
  grep -q '#include "model_private.h"' src/model.c
hits=$(grep -ln '#include "model_private.h"' src/*.c src/*.h tests/*.c tests/*.h tests/bench/*.c \
       | grep -v '^src/model\.c$' | grep -v '^src/model_read\.c$')
check "no file of src/ or tests/ but src/model.c and src/model_read.c include model_private.h${hits:+: $(echo $hits)}" \
  test -z "$hits"
finish
