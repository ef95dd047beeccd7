# tests/fuzz/fuzz.mk: fuzzing the scene parser and validator (scene_load,
# paper/scene.nw) with libFuzzer, under AddressSanitizer, UBSan and
# LeakSanitizer.  Included by the Makefile; it relies on nothing of it but
# the tangled sources (made by the rule of src/.tangled, listed in TANGLED)
# and the Makefile's recipe apt_install.
#
#   make fuzz [FUZZ_SECONDS=60] [FUZZ_JOBS=1]
#       fuzz for FUZZ_SECONDS seconds; the corpus grows in build/fuzz/corpus
#       (seeded from tests/fuzz/corpus), a crash, leak, UB or broken
#       contract is saved in build/fuzz/crashes/ and fails the target.
#   make fuzz-shape [FUZZ_SECONDS=60]
#       the same for the shape-file reader (tests/fuzz/fuzz_shape.c),
#       seeded from tests/fuzz/shapes.
#   make fuzz-replay
#       run both harnesses once on their seed corpora, on the corpora
#       that fuzzing grew, merged to the inputs that add coverage
#       (tests/fuzz/found/: libFuzzer's -merge=1 of 300 s runs of each),
#       and on every tests/scenes/fuzz-*.scene (inputs that once crashed
#       it); CI runs it.
#
# The harness needs clang and libFuzzer (Debian 12: clang, libclang-rt-14-dev);
# fuzz-deps installs them as root or says how.

FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 60
FUZZ_JOBS    ?= 1
FUZZ_DIR     := build/fuzz
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_CFLAGS  := -g -O1 -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra \
                -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
                -fno-omit-frame-pointer -I/usr/include/suitesparse -Isrc
# a value that broke the contract aborts; so does any UB (no recovery)
FUZZ_ENV     := UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
                ASAN_OPTIONS=detect_leaks=1
FUZZ_RUN     := -dict=tests/fuzz/scene.dict -max_len=8192 -timeout=10 \
                -rss_limit_mb=2048 -malloc_limit_mb=1024 \
                -artifact_prefix=$(FUZZ_DIR)/crashes/
FUZZ_SHAPE_RUN := -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
                -malloc_limit_mb=1024 -artifact_prefix=$(FUZZ_DIR)/crashes/shape-

.PHONY: fuzz fuzz-replay fuzz-deps
fuzz: $(FUZZ_DIR)/fuzz_scene
	@mkdir -p $(FUZZ_DIR)/corpus $(FUZZ_DIR)/crashes
	$(FUZZ_ENV) $< $(FUZZ_RUN) -max_total_time=$(FUZZ_SECONDS) \
	  $(if $(filter-out 1,$(FUZZ_JOBS)),-fork=$(FUZZ_JOBS)) \
	  -print_final_stats=1 $(FUZZ_DIR)/corpus tests/fuzz/corpus

fuzz-replay: $(FUZZ_DIR)/fuzz_scene $(FUZZ_DIR)/fuzz_shape
	@mkdir -p $(FUZZ_DIR)/crashes
	$(FUZZ_ENV) $(FUZZ_DIR)/fuzz_scene $(FUZZ_RUN) tests/fuzz/corpus/* tests/fuzz/found/scene/* \
	  $(wildcard tests/scenes/fuzz-*.scene)
	$(FUZZ_ENV) $(FUZZ_DIR)/fuzz_shape $(FUZZ_SHAPE_RUN) tests/fuzz/shapes/* tests/fuzz/found/shape/*

# The scene adapter reads the modules' defaults and samples the initial
# shape with the design module, so the fuzzer links every module.
$(FUZZ_DIR)/fuzz_scene: tests/fuzz/fuzz_scene.c tests/fuzz/contract.h tests/fuzz/folder.h \
                        tests/part_geometry.h $(SOURCES) \
                        $(filter %.h,$(TANGLED)) | fuzz-deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -o $@ tests/fuzz/fuzz_scene.c \
	  $(SOURCES) $(LDLIBS)

fuzz-deps:
	$(call apt_install,fuzz-deps,$(FUZZ_PACKAGES))

# make fuzz-shape [FUZZ_SECONDS=60]: the same for the shape-file reader
# (design.file): an input is a shape file, read beside a fixed scene at
# three N (tests/fuzz/fuzz_shape.c); seeds in tests/fuzz/shapes.
.PHONY: fuzz-shape
fuzz-shape: $(FUZZ_DIR)/fuzz_shape
	@mkdir -p $(FUZZ_DIR)/shape-corpus $(FUZZ_DIR)/crashes
	$(FUZZ_ENV) $< $(FUZZ_SHAPE_RUN) -max_total_time=$(FUZZ_SECONDS) \
	  -print_final_stats=1 $(FUZZ_DIR)/shape-corpus tests/fuzz/shapes

$(FUZZ_DIR)/fuzz_shape: tests/fuzz/fuzz_shape.c tests/fuzz/contract.h tests/fuzz/folder.h $(SOURCES) \
                        $(filter %.h,$(TANGLED)) | fuzz-deps
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -o $@ tests/fuzz/fuzz_shape.c \
	  $(SOURCES) $(LDLIBS)
