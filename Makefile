# contactopt: shape optimisation in contact problems (Haslinger & Neittaanmaki 1987).
# The literate sources paper/*.nw are the only sources of the program;
# src/ is tangled from them (committed, never edited by hand).

# The parts of the paper, in the order of the argument: the driver
# paper/contactopt.nw \inputs them, and this list is read from it.
PARTS := $(shell sed -n 's/^\\input{\([a-z0-9_-]*\)}$$/\1/p' paper/contactopt.nw)
NW := paper/contactopt.nw $(PARTS:%=paper/%.nw)

# Modules tangled into src/, each a .c and a .h; the files that do part of
# a module's job behind its header (the methods of the state solver, the
# optimisers, the projection onto B, the interior point of the Newton
# model, the figures' parts, the parts of the scene and output modules),
# which share the module's private header; and the program.
MODULES := status resources problem scene part mesh fem qp condense friction held model grad objective coulomb design newton opt output usage interrupt args threads plot
 INNER   := qp_base pdas cgssor psor condense_adjoint objective_grad model_read objective_evaluate grad_check design_project newton_ip opt_eval opt_projgrad opt_slsqp opt_mma opt_newton \
           plot_text plot_state plot_body plot_results plot_part \
           scene_keys scene_message scene_ini scene_value scene_check scene_shape scene_write \
           output_path output_state output_vtu output_solve output_optimize \
           design_set
# A header of no module: the index type of CHOLMOD's arrays (paper/fem.nw).
HEADERS := sparse
PRIVATE := qp_private qp_inline model_private pdas cgssor psor opt_private plot_private design_private newton_private scene_private output_private
SOURCES := $(MODULES:%=src/%.c) $(INNER:%=src/%.c)
SCRIPTS := src/reproduction.sh src/c2-of-shape.sh src/suite-table.sh src/parts-table.sh \
           src/friction.sh src/fig-friction.gp src/coulomb.sh src/fig-coulomb.gp \
           src/objectives.sh src/fig-objectives.gp \
           src/accuracy-run.sh src/accuracy.sh src/accuracy-table.sh src/accuracy-numbers.sh src/fig-accuracy.gp \
           src/huge.sh src/man.sh src/completion.sh \
           src/hard-nu.sh src/hard-units.sh src/hard-thin.sh src/hard-vertex.sh src/hard-parts.sh src/cgssor-table.sh \
           src/depends.sh
TANGLED := $(HEADERS:%=src/%.h) $(MODULES:%=src/%.h) $(PRIVATE:%=src/%.h) $(SOURCES) src/main.c src/example.c $(SCRIPTS)
# make SAN=1 check: the whole suite under AddressSanitizer and UBSan, built
# apart in build/san so that the two builds never mix.
B       := $(if $(filter 1,$(SAN)),build/san,build)
PROGRAM := $(if $(filter 1,$(SAN)),build/san/contactopt,bin/contactopt)
OBJ     := $(SOURCES:src/%.c=$(B)/%.o)

# The runs behind the figures of Section 5, and the figures (see below).
EXAMPLES := 5.1 5.2 5.2-flat
RUNS := $(EXAMPLES:%=out/example-%/summary.dat) \
        $(EXAMPLES:%=out/example-%-optimize/summary.dat) \
        $(EXAMPLES:%=out/example-%-strain-optimize/summary.dat) \
        out/example-5.1-C2arc-optimize/summary.dat
FIGURES := $(foreach f,5.1 5.2 5.3 5.4,figures/fig-$(f).pdf figures/fig-$(f).png) \
           figures/reproduction.tex figures/suite.tex \
           figures/fig-friction.pdf figures/fig-friction.png figures/friction.tex \
           figures/fig-coulomb.pdf figures/fig-coulomb.png figures/coulomb.tex \
           figures/fig-objectives.pdf figures/fig-objectives.png figures/objectives.tex
# The tables of the hard cases (paper/stability.nw) and of MPRGP's cost
# (paper/cgssor.nw), each written by the script that runs its cases (under
# a minute together): rebuilt, not tracked (the last one is timed).
HARD_FIGS := figures/hard-nu.tex figures/hard-units.tex figures/hard-thin.tex figures/hard-vertex.tex figures/hard-parts.tex \
             figures/cgssor.tex figures/parts.tex
# The robustness suite of the optimiser (paper/opt.nw): each scene by the
# Newton method and by SLSQP, whose failures to converge are its result.
SUITE := $(patsubst data/suite/%.scene,%,$(wildcard data/suite/*.scene))
SUITE_RUNS := $(foreach s,$(SUITE),out/suite/$(s)-newton/summary.dat out/suite/$(s)-slsqp/summary.dat)

CC      ?= cc
CFLAGS  ?= -O2 -g
CFLAGS  += -std=c11 -Wall -Wextra -pedantic -D_POSIX_C_SOURCE=200809L \
           -I/usr/include/suitesparse -Isrc
LDLIBS  := -lcholmod -lsuitesparseconfig -lnlopt -lgsl -lblas -linih -lm
ifeq ($(SAN),1)
CFLAGS  += -O1 -fsanitize=address,undefined -fno-sanitize-recover=undefined \
           -fno-omit-frame-pointer
LDFLAGS += -fsanitize=address,undefined
endif

# Debian packages the package needs, and the command that proves each one
# (groff-base, man-db, mandoc, bsdextrautils: tests/install.sh renders and
# lints the manual page; poppler-utils: tests/article.sh reads the
# article's text and pages; universal-ctags: the layers of src/ that the
# paper prints and tests/cycles.sh checks, src/depends.sh).
PACKAGES := noweb libgsl-dev libnlopt-dev gnuplot-nox numdiff libinih-dev \
            libsuitesparse-dev libblas-dev libopenblas0-pthread pkg-config lmodern valgrind \
            python3-meshio universal-ctags libgmsh-dev \
            groff-base man-db mandoc bsdextrautils \
            texlive-latex-base \
            texlive-latex-recommended texlive-fonts-recommended poppler-utils

.PHONY: all deps tangle tangle-check paper article figures accuracy check check-kernels check-kernels-full check-fine kernels-table faults bench reference clean install uninstall
all: $(PROGRAM) $(B)/example $(B)/contactopt.1 $(B)/contactopt.bash

# ---- dependencies: install what is missing, or say exactly how -------------
# $(call apt_install,NAME,PACKAGES): the recipe of a target NAME that
# installs the Debian PACKAGES not yet installed: as root (its log in
# build-NAME.log if apt-get fails), by sudo without a password, or else it
# prints the command to run as root and fails.  deps and fuzz-deps use it.
define apt_install
@missing=$$(for p in $(2); do \
  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'ok installed' || echo $$p; \
done); \
if [ -n "$$missing" ]; then \
  cmd="apt-get update && apt-get install -y --no-install-recommends $$(echo $$missing)"; \
  if [ "$$(id -u)" = 0 ]; then echo "$(1): installing $$(echo $$missing)"; \
    export DEBIAN_FRONTEND=noninteractive; sh -c "$$cmd" >build-$(1).log 2>&1 \
      || { echo "$(1): apt-get failed, see build-$(1).log"; exit 1; }; rm -f build-$(1).log; \
  elif sudo -n true 2>/dev/null; then sudo sh -c "$$cmd"; \
  else echo "$(1): missing Debian packages; run as root:"; echo "  $$cmd"; exit 1; fi; \
fi
endef
deps:
	$(call apt_install,deps,$(PACKAGES))

# ---- tangling ----------------------------------------------------------------
tangle: src/.tangled
src/.tangled: $(NW) paper/tangle.sh | deps
	sh paper/tangle.sh src $(NW)
	@touch $@
$(TANGLED): src/.tangled ;

tangle-check: | deps
	@rm -rf build/tangle-check && mkdir -p build/tangle-check
	@sh paper/tangle.sh build/tangle-check $(NW)
	@diff -r -x .tangled build/tangle-check src \
	  && echo "tangle-check: src/ matches a fresh tangle of paper/*.nw" \
	  || { echo "tangle-check: src/ differs from paper/*.nw (edit the .nw, run make)"; exit 1; }

# ---- building ------------------------------------------------------------------
$(B)/%.o: src/%.c | src/.tangled
	@mkdir -p $(B)
	$(CC) $(CFLAGS) -MMD -MP -c -o $@ $<
$(PROGRAM): $(B)/main.o $(OBJ)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)
# the overview's client program: optimize's pipeline without the files
$(B)/example: $(B)/example.o $(OBJ)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)
-include $(wildcard $(B)/*.d $(B)/tests/*.d)

# ---- installing (paper/install.nw) -------------------------------------------------
# make install copies the program, the manual page contactopt(1), the
# completion for bash and the example scenes (data/*.scene, which name no
# other file, and the parts of data/parts/, each scene beside its geometry)
# under PREFIX, by the GNU conventions; DESTDIR stages the whole
# tree elsewhere (for a package). make uninstall removes them, and the
# folders the install created (it lists them in
# DATADIR/contactopt/installed-dirs), not those it found.
PREFIX  ?= /usr/local
BINDIR  ?= $(PREFIX)/bin
DATADIR ?= $(PREFIX)/share
MANDIR  ?= $(DATADIR)/man
INSTALL ?= install
SHIPPED := $(wildcard data/*.scene data/parts/*.scene data/parts/*.geo)
INSTALL_DIRS := $(BINDIR) $(MANDIR)/man1 $(DATADIR)/contactopt/examples \
                $(DATADIR)/bash-completion/completions
INSTALLED := $(BINDIR)/contactopt $(MANDIR)/man1/contactopt.1 \
             $(addprefix $(DATADIR)/contactopt/examples/,$(notdir $(SHIPPED))) \
             $(DATADIR)/bash-completion/completions/contactopt
# The manual page and the completion are written from the program's own
# texts (src/man.sh, src/completion.sh); the page names DATADIR, which is
# kept in $(B)/install-paths, rewritten only when it changes. The page's
# date is that of the last commit (of the program's build outside git).
.PHONY: install-paths
$(B)/install-paths: install-paths
	@mkdir -p $(@D)
	@echo '$(DATADIR)' > $@.new
	@cmp -s $@.new $@ && rm $@.new || mv $@.new $@
$(B)/contactopt.1: src/man.sh $(PROGRAM) $(B)/install-paths
	d=$$(git log -1 --format=%cs 2>/dev/null || date -u -r $(PROGRAM) +%F) && \
	  sh src/man.sh $(PROGRAM) '$(DATADIR)' "$$d" $(notdir $(SHIPPED)) > $@.partial && mv $@.partial $@
$(B)/contactopt.bash: src/completion.sh $(PROGRAM)
	sh src/completion.sh $(PROGRAM) > $@.partial && mv $@.partial $@
install: $(PROGRAM) $(B)/contactopt.1 $(B)/contactopt.bash
	@m='$(DESTDIR)$(DATADIR)/contactopt/installed-dirs'; \
	{ for d in $(INSTALL_DIRS); do \
	    while [ "$$d" != / ] && [ "$$d" != . ] && [ ! -d "$(DESTDIR)$$d" ]; do \
	      echo "$$d"; d=$$(dirname "$$d"); done; done; \
	  [ ! -f "$$m" ] || cat "$$m"; } | sort -u > $(B)/installed-dirs
	$(INSTALL) -d $(INSTALL_DIRS:%=$(DESTDIR)%)
	$(INSTALL) -m 755 $(PROGRAM) $(DESTDIR)$(BINDIR)/contactopt
	$(INSTALL) -m 644 $(B)/contactopt.1 $(DESTDIR)$(MANDIR)/man1/contactopt.1
	$(INSTALL) -m 644 $(SHIPPED) $(DESTDIR)$(DATADIR)/contactopt/examples
	$(INSTALL) -m 644 $(B)/contactopt.bash $(DESTDIR)$(DATADIR)/bash-completion/completions/contactopt
	$(INSTALL) -m 644 $(B)/installed-dirs $(DESTDIR)$(DATADIR)/contactopt/installed-dirs
uninstall:
	rm -f $(INSTALLED:%=$(DESTDIR)%)
	@m='$(DESTDIR)$(DATADIR)/contactopt/installed-dirs'; \
	dirs=$$([ ! -f "$$m" ] || sort -r "$$m"); rm -f "$$m"; \
	for d in $$dirs $(DATADIR)/contactopt/examples $(DATADIR)/contactopt; do \
	  [ ! -d "$(DESTDIR)$$d" ] || rmdir "$(DESTDIR)$$d" 2>/dev/null || true; done

# The fault-injection shim and the shim of a CPU that OpenBLAS does not
# know (rules below): named before make check needs them.
FAULT_SHIM := build/faults/inject.so
UNKNOWN_CPU := build/kernels/unknown_cpu.so

# Test programs link the library modules directly.
TEST_PROGS := $(patsubst tests/%.c,$(B)/tests/%,$(wildcard tests/*.c))
$(B)/tests/%: tests/%.c $(OBJ) tests/check.h
	@mkdir -p $(B)/tests
	$(CC) $(CFLAGS) -Itests -MMD -MP $(LDFLAGS) -o $@ $< $(OBJ) $(LDLIBS)

# make check: every test program and script by tests/run, JOBS at a time
# (default: the cores; make check JOBS=1 runs them one after another), the
# log in build/tests.log whatever JOBS is.  That src/ matches paper/*.nw
# (make tangle-check) is one of the tests, tests/tangle.sh.  The
# benchmarks' programs are built too, so that a change of an interface
# they call fails here, not in make bench or make paper.
check: $(PROGRAM) $(B)/example $(TEST_PROGS) $(FAULT_SHIM) $(UNKNOWN_CPU) $(RUNS) \
       build/bench/bench_cholmod build/bench/walltime build/bench/orderings
	@BIN=$(PROGRAM) TESTS=$(B)/tests UNKNOWN_CPU=$(UNKNOWN_CPU) JOBS=$(JOBS) sh tests/run

# make check-kernels: what a user's other machine would meet. The test
# programs under every OpenBLAS kernel family this CPU can execute
# (tests/kernels/programs.sh), the optimisation of every shipped and suite
# scene at mesh.refine 1 and 4 under Haswell's, Sandybridge's and Prescott's
# kernels (tests/kernels/optimize.sh; make check-kernels-full adds refine 8),
# every optimiser on the thin bodies of tests/hard_cases.sh in plane stress
# and strain, which must end alike in as many iterations,
# and the suite again under each of KERNEL_SETTINGS: unknown-cpu, every
# test on 16 cores of a CPU that OpenBLAS does not know (its Prescott
# kernels, chosen by OpenBLAS, not by the user, and the threads OpenBLAS
# and the program start on 16 cores: the shim UNKNOWN_CPU), as the
# issue's 16-core Xeon ran it; sixteen-threads, every test with 16 BLAS threads
# asked for; one-thread, the test programs and the scripts that solve and
# optimise on one thread. A verdict that changes with the kernel or the
# threads then fails here, on the developer's machine, before it fails on
# a user's. CI runs it.
KERNEL_SETTINGS ?= unknown-cpu sixteen-threads one-thread
kernel_env.unknown-cpu := OPENBLAS_CORETYPE=Prescott UNKNOWN_CPU_CORES=16 LD_PRELOAD=$(abspath $(UNKNOWN_CPU))
kernel_env.sixteen-threads := OPENBLAS_NUM_THREADS=16
kernel_env.one-thread := OPENBLAS_NUM_THREADS=1
kernel_scripts.one-thread = $(NUMERIC_SCRIPTS)
KERNEL_REFINES ?= 1 4
NUMERIC_SCRIPTS := $(patsubst %,tests/%.sh,optimize suite friction hard_cases solvers_agree \
                     gradcheck convergence flat_punch magnitudes reproducible thin_bodies)
check-kernels: $(PROGRAM) $(TEST_PROGS) $(FAULT_SHIM) $(UNKNOWN_CPU) $(RUNS)
	@TESTS=$(B)/tests sh tests/kernels/programs.sh
	@BIN=$(PROGRAM) REFINES="$(KERNEL_REFINES)" sh tests/kernels/optimize.sh
	@$(foreach m,plane_stress plane_strain,BIN=$(PROGRAM) REFINES=1 ITERATIONS=1 \
	    METHODS="slsqp newton projgrad" SCENES="$(wildcard tests/scenes/hard-thin*.scene)" \
	    OVERRIDES=material.model=$(m) sh tests/kernels/optimize.sh;)
	@$(foreach k,$(KERNEL_SETTINGS),env $(kernel_env.$(k)) BIN=$(PROGRAM) TESTS=$(B)/tests \
	    UNKNOWN_CPU=$(UNKNOWN_CPU) SCRIPTS="$(kernel_scripts.$(k))" LOG=build/tests-$(k).log \
	    sh tests/run | tail -n 1 | sed "s/^/check-kernels: $(k): /";) \
	  ! grep -l '^FAIL - ' $(KERNEL_SETTINGS:%=build/tests-%.log)
# The table of the paper's section "Every machine": the test programs under
# each kernel family this CPU executes (written by the run, committed).
kernels-table: $(TEST_PROGS)
	TESTS=$(B)/tests TABLE=paper/bench-kernels.tex.partial sh tests/kernels/programs.sh; \
	  mv paper/bench-kernels.tex.partial paper/bench-kernels.tex
check-kernels-full: check-fine
	@$(MAKE) --no-print-directory check-kernels KERNEL_REFINES="1 4 8"
# The robustness suite's aluminium plate at N = 1024 (tests/kernels/fine.sh):
# the Newton method under three kernel families and SLSQP once, several
# minutes; tests/suite.sh runs the plate at N = 256 and 512 in make check.
check-fine: $(PROGRAM)
	@BIN=$(PROGRAM) TESTS=/nonexistent SCRIPTS=tests/kernels/fine.sh LOG=build/tests-fine.log sh tests/run
# Fault injection (tests/faults.sh): an LD_PRELOAD shim that makes the k-th
# allocation or write of a run fail, built without the sanitizers, so that
# one shim serves both builds. make check runs the solve's legs; make faults
# every leg (a few minutes), make SAN=1 faults with LeakSanitizer on every run.
$(UNKNOWN_CPU): tests/kernels/unknown_cpu.c
	@mkdir -p $(@D)
	$(CC) -O2 -g -std=gnu11 -Wall -Wextra -fPIC -shared -o $@ $< -ldl
$(FAULT_SHIM): tests/faults/inject.c
	@mkdir -p $(@D)
	$(CC) -O2 -g -std=gnu11 -Wall -Wextra -fPIC -shared -o $@ $< -ldl
faults: $(PROGRAM) $(FAULT_SHIM)
	@BIN=$(PROGRAM) FAULTS=all sh tests/faults.sh

# make bench: the state-solver table, then the performance tables (issue 5;
# BENCH_NMAX=256 shortens the latter), the optimisation and the whole solve
# (issue 14: tests/bench/output.sh) against one CHOLMOD factorisation, and
# the optimisation under each thread setting (issue 26: tests/bench/threads.sh), and
# CHOLMOD's long integers against its ints (tests/bench/cholmod_long.sh), and the
# coarse-to-fine start of optimize (issue 27: tests/bench/levels.sh).  bench_cholmod links the modules
# like a test program; walltime times a whole run of the program.
build/bench/bench_cholmod: tests/bench/bench_cholmod.c $(OBJ)
	@mkdir -p build/bench
	$(CC) $(CFLAGS) -MMD -MP $(LDFLAGS) -o $@ $< $(OBJ) $(LDLIBS)
build/bench/orderings: tests/bench/orderings.c $(OBJ)
	@mkdir -p build/bench
	$(CC) $(CFLAGS) -MMD -MP $(LDFLAGS) -o $@ $< $(OBJ) $(LDLIBS)
build/bench/walltime: tests/bench/walltime.c
	@mkdir -p build/bench
	$(CC) $(CFLAGS) -o $@ $<
-include $(wildcard build/bench/*.d)

bench: bin/contactopt build/bench/bench_cholmod build/bench/walltime build/bench/orderings
	@sh tests/bench/state.sh
	@sh tests/bench/performance.sh
	@sh tests/bench/optimize.sh
	@sh tests/bench/output.sh
	@sh tests/bench/threads.sh
	@sh tests/bench/cholmod_long.sh
	@sh tests/bench/levels.sh
	@sh tests/bench/orderings.sh
	@sh tests/bench/frontier.sh

# ---- accuracy: accuracy against time (paper/accuracy.nw) -------------------------
# Every point of the sweep is one optimisation of Example 5.1 in a folder of
# its own, out/accuracy/N<N>_<state>_<solver.tol>_<method>_<optimizer.tol>,
# its settings read from the name by src/accuracy-run.sh; so make -j2 runs
# the points side by side and reruns only what changed. A family is a list
# of points drawn as one curve; the first, the mesh sweep (a), gives E_inf.
# ACCURACY_NMAX caps every N (make figures ACCURACY_NMAX=256 for a short sweep);
# the table and the figure say which NMAX made them. make paper depends on the
# sweep too: export ACCURACY_NMAX to keep a cap for later commands.
ACCURACY_NMAX ?= 1024
ACC_N := $(shell awk 'BEGIN { for (n = 16; n <= $(ACCURACY_NMAX); n *= 2) print n }')
$(if $(filter $(ACCURACY_NMAX),$(wordlist 3,99,$(ACC_N))),,\
  $(error ACCURACY_NMAX=$(ACCURACY_NMAX): must be 16 times a power of two, at least 64))
# $(call acc_points,Ns,state,solver.tols,method,optimizer.tols): all combinations
acc_points = $(foreach n,$(filter $(1),$(ACC_N)),$(foreach t,$(3),$(foreach o,$(5),N$(n)_$(2)_$(t)_$(4)_$(o))))
ACC_TOL := 1e-4 1e-6 1e-8 1e-10 1e-12
ACC.mesh            := $(call acc_points,$(ACC_N),pdas,1e-10,newton,1e-6)
ACC.pdas-64         := $(call acc_points,64,pdas,$(ACC_TOL),newton,1e-6)
ACC.cgssor-64       := $(call acc_points,64,cgssor,$(ACC_TOL),newton,1e-6)
ACC.pdas-128        := $(call acc_points,128,pdas,$(ACC_TOL),newton,1e-6)
ACC.cgssor-128      := $(call acc_points,128,cgssor,$(ACC_TOL),newton,1e-6)
ACC.projgrad        := $(call acc_points,16 32 64 128,pdas,1e-10,projgrad,1e-6)
ACC.slsqp-schur     := $(call acc_points,16 32 64 128,pdas,1e-10,slsqp-schur,1e-6)
ACC.slsqp-euclidean := $(call acc_points,16 32 64 128,pdas,1e-10,slsqp-euclidean,1e-6)
ACC.opttol-64       := $(call acc_points,64,pdas,1e-10,newton,1e-3 1e-4 1e-5 1e-6)
ACC.opttol-128      := $(call acc_points,128,pdas,1e-10,newton,1e-3 1e-4 1e-5 1e-6)
ACC_FAMILIES := $(foreach f,mesh pdas-64 cgssor-64 pdas-128 cgssor-128 projgrad \
                  slsqp-schur slsqp-euclidean opttol-64 opttol-128,$(if $(ACC.$(f)),$(f)))
ACC_RUNS := $(patsubst %,out/accuracy/%/summary.dat,$(sort $(foreach f,$(ACC_FAMILIES),$(ACC.$(f)))))
ACCURACY_FIGS := figures/accuracy-time.pdf figures/accuracy-time.png figures/accuracy.tex figures/accuracy-numbers.tex \
                 figures/huge.tex

accuracy: $(ACCURACY_FIGS)
	@awk '$$2 == "nmax" { n = $$3 } $$2 == "E_inf" { e = $$3 } $$2 == "p" { p = $$3 } \
	  !/^#/ && NF && !seen[$$2]++ { k++ } END { printf "accuracy: %d runs to N = %d," \
	  " E_inf = %.10g J/m, p = %.2f\n", k, n, e, p }' out/accuracy/sweep.dat
out/accuracy/%/summary.dat: src/accuracy-run.sh data/example-5.1.scene bin/contactopt
	@sh $< bin/contactopt data/example-5.1.scene $* $(@D)
# The plan, the families and their points, is rewritten only when it changes.
.PHONY: accuracy-plan
out/accuracy/plan.dat: accuracy-plan
	@mkdir -p $(@D)
	@{ echo '# family points: the plan of make accuracy, ACCURACY_NMAX=$(ACCURACY_NMAX)'; \
	  $(foreach f,$(ACC_FAMILIES),echo '$(f) $(ACC.$(f))';) } > $@.new
	@cmp -s $@.new $@ && rm $@.new || mv $@.new $@
# the limit of each mesh: one CHOLMOD analyse + factorise + solve of its
# stiffness (bench_cholmod --limit), measured in the same sweep
ACC_LIMITS := $(ACC_N:%=out/accuracy/limit/N%.dat)
out/accuracy/limit/N%.dat: build/bench/bench_cholmod
	@mkdir -p $(@D)
	$< --limit data/example-5.1.scene mesh.refine=$$(($* / 16)) > $@.partial && mv $@.partial $@
out/accuracy/sweep.dat: src/accuracy.sh out/accuracy/plan.dat $(ACC_RUNS) $(ACC_LIMITS)
	sh $< out/accuracy > $@.partial && mv $@.partial $@
figures/accuracy.tex: src/accuracy-table.sh out/accuracy/sweep.dat data/accuracy-once.dat
	@mkdir -p figures
	sh $< out/accuracy/sweep.dat > $@.partial && mv $@.partial $@
# the layers of the files of src/, read from the code (paper/overview.nw)
figures/layers.tex: src/depends.sh $(SOURCES) src/main.c src/example.c | deps
	@mkdir -p figures
	sh $< layers src > $@.partial && mv $@.partial $@
# Example 5.1 on N = 1024 (paper/stability.nw): timed, so rebuilt, not tracked
figures/huge.tex: src/huge.sh bin/contactopt data/example-5.1.scene
	@mkdir -p figures
	sh $< out/huge > $@.partial && mv $@.partial $@
figures/hard-%.tex: src/hard-%.sh bin/contactopt data/example-5.1.scene
	@mkdir -p figures
	sh $< out/hard-$* > $@.partial && mv $@.partial $@
figures/hard-thin.tex: tests/scenes/hard-thin.scene tests/scenes/hard-thinner.scene
figures/hard-parts.tex: $(B)/tests/test_kirsch tests/scenes/kirsch.scene tests/parts/kirsch.geo tests/parts/example-5.1.geo
figures/cgssor.tex: src/cgssor-table.sh bin/contactopt data/example-5.1-tresca.scene
	@mkdir -p figures
	sh $< out/cgssor > $@.partial && mv $@.partial $@
# the shipped parts against the rectangles of the same N (paper/parts-examples.nw):
# timed, so rebuilt, not tracked
figures/parts.tex: src/parts-table.sh bin/contactopt $(wildcard data/parts/*.scene data/parts/*.geo)
	@mkdir -p figures
	sh $< out/parts > $@.partial && mv $@.partial $@
# the figures of each optimised part by contactopt plot (the body at its
# initial shape, the results of its optimisation), from the runs of
# figures/parts.tex: among those of make figures, and make parts-plots alone
PARTS_PLOTS := $(patsubst data/parts/%.scene,figures/part-%-results.pdf,$(wildcard data/parts/*.scene))
.PHONY: parts-plots
parts-plots: $(PARTS_PLOTS)
figures/part-%-results.pdf: figures/parts.tex
	bin/contactopt plot out/parts/$*-solve --body --title '$*' -o figures/part-$*-body
	bin/contactopt plot out/parts/$*-optimize --results --start out/parts/$*-solve \
	  --title '$*' -o figures/part-$*-results
figures/accuracy-numbers.tex: src/accuracy-numbers.sh out/accuracy/sweep.dat paper/bench-state.tex
	@mkdir -p figures
	sh $< out/accuracy/sweep.dat paper/bench-state.tex > $@.partial && mv $@.partial $@
figures/accuracy-time.pdf figures/accuracy-time.png &: src/fig-accuracy.gp out/accuracy/sweep.dat data/accuracy-once.dat
	@mkdir -p figures
	gnuplot -e "sweep='out/accuracy/sweep.dat'; once='data/accuracy-once.dat'; out='figures/accuracy-time'" $<
# ---- end of the accuracy block ----------------------------------------------------

# ---- the woven paper -------------------------------------------------------------
# Each part is woven on its own and \input by the driver; the identifiers
# every part defines are collected first (nodefs), so that each part's
# index and cross-references reach the others. A part defines explicitly
# (@ %def after the chunk of its header that declares them) the names its
# header exports, and only those: the index lists the interfaces, and noindex gathers the
# chunk and identifier indices of the whole from LaTeX's .aux (noweb's
# external-index method, noindex(1)). An undefined reference stops it.
paper: paper/contactopt.pdf paper/article.pdf
article: paper/article.pdf
WOVEN := build/paper/contactopt.tex $(PARTS:%=build/paper/%.tex)
build/paper/all.defs: $(NW) | deps
	@mkdir -p $(@D)
	@for f in $(NW); do nodefs $$f; done | sort -u | cpif $@
build/paper/contactopt.tex: paper/contactopt.nw | deps
	@mkdir -p $(@D)
	noweave -delay paper/contactopt.nw > $@
build/paper/%.tex: paper/%.nw build/paper/all.defs
	noweave -n -indexfrom build/paper/all.defs $< > $@
# noindex sorts the identifiers with their case folded, ties in the order
# of the .aux, and drops an entry only where it repeats the one before: the
# entries of two identifiers that differ only in case (Design_set, the
# type, and design_set, the function) alternate, part by part, and each
# stayed in the index as often as parts use it. The awk after it keeps the
# first of each entry. The build fails where the pages do not set: an
# overfull box over 20 pt, a float too large, an undefined reference, an
# index entry twice (paper/latex-log.sh reads the log and the index).
paper/contactopt.pdf: $(WOVEN) paper/latex-log.sh $(FIGURES) $(ACCURACY_FIGS) $(HARD_FIGS) $(PARTS_PLOTS) figures/keys.tex figures/layers.tex paper/bench-state.tex \
                      paper/bench-performance.tex paper/bench-optimize.tex \
                       paper/bench-output.tex paper/bench-kernels.tex \
                       paper/cholmod-long.tex paper/bench-levels.tex paper/bench-orderings.tex | deps
	cd build/paper && for i in 1 2 3 4 5; do \
	  pdflatex -interaction=nonstopmode -halt-on-error contactopt.tex >/dev/null \
	    || { tail -40 contactopt.log; exit 1; }; \
	  noindex contactopt && awk '!seen[$$0]++' contactopt.nwi > contactopt.nwi.new \
	    && mv contactopt.nwi.new contactopt.nwi; \
	  [ $$i -gt 1 ] && ! grep -q 'Rerun' contactopt.log && break; done; true
	sh paper/latex-log.sh program 20 build/paper/contactopt.log
	cp build/paper/contactopt.pdf $@

# ---- the article -------------------------------------------------------------------
# paper/article.tex: the reproduction as a short paper (ReScience C), beside
# the woven program. Its numbers are macros that paper/article-numbers.sh
# writes from the runs (build/article/numbers.tex), its tables the
# generated ones (figures/*.tex, paper/bench-*.tex), its two figures of its
# own drawn off the runs by paper/article-shapes.gp,
# paper/article-histories.gp, paper/article-refine.gp and
# paper/article-kkt.gp; it cites the program's sections through the
# woven document's .aux (xr), so it is built after it. The build fails on
# an undefined reference or citation, an overfull box over 5 pt and a
# float too large (paper/latex-log.sh reads the log).
ART_METHODS := slsqp projgrad
ART_RUNS := $(foreach e,5.1 5.2,$(foreach m,$(ART_METHODS),out/example-$(e)-$(m)/summary.dat))
out/example-%-slsqp/summary.dat: data/example-%.scene bin/contactopt
	@mkdir -p out
	bin/contactopt optimize $< -o $(@D) -s optimizer.method=slsqp > $(@D).log
out/example-%-projgrad/summary.dat: data/example-%.scene bin/contactopt
	@mkdir -p out
	bin/contactopt optimize $< -o $(@D) -s optimizer.method=projgrad > $(@D).log
ART_FIGS := figures/article-shapes.pdf figures/article-histories.pdf figures/article-refine.pdf \
            figures/article-kkt.pdf
figures/article-shapes.pdf: paper/article-shapes.gp $(RUNS)
	@mkdir -p figures
	gnuplot -e "out='$@'" $<
figures/article-histories.pdf: paper/article-histories.gp $(RUNS) $(ART_RUNS)
	@mkdir -p figures
	gnuplot -e "out='$@'" $<
figures/article-kkt.pdf: paper/article-kkt.gp out/example-5.1-optimize/summary.dat
	@mkdir -p figures
	gnuplot -e "out='$@'" $<
figures/article-refine.pdf: paper/article-refine.gp out/accuracy/sweep.dat
	@mkdir -p figures
	gnuplot -e "out='$@'; nmax=$(ACCURACY_NMAX)" $<
build/article/numbers.tex: paper/article-numbers.sh $(RUNS) $(ART_RUNS) figures/objectives.tex \
                           out/accuracy/sweep.dat paper/bench-frontier.tex paper/bench-optimize.tex $(wildcard data/suite/*.scene) \
                           paper/bench-output.tex paper/bench-levels.tex
	@mkdir -p $(@D)
	sh $< out $(@D) > $@.partial && mv $@.partial $@
paper/article.pdf: paper/article.tex build/article/numbers.tex $(ART_FIGS) paper/contactopt.pdf \
                   paper/latex-log.sh data/example-5.1.scene $(FIGURES) $(ACCURACY_FIGS) | deps
	cp paper/article.tex build/article/article.tex
	cd build/article && for i in 1 2 3 4; do \
	  pdflatex -interaction=nonstopmode -halt-on-error article.tex >/dev/null \
	    || { tail -40 article.log; exit 1; }; \
	  [ $$i -gt 1 ] && ! grep -q 'Rerun' article.log && break; done; true
	sh paper/latex-log.sh article 5 build/article/article.log
	cp build/article/article.pdf $@

# The table of the keys of a scene (the scene appendix): printed by the
# program from the table its scene loader reads (paper/scene.nw).
figures/keys.tex: bin/contactopt
	@mkdir -p figures
	bin/contactopt keys --latex > $@.partial && mv $@.partial $@

# ---- the figures of Section 5 ---------------------------------------------------
# Every figure is drawn from the data files the program writes; each run is
# a rule of its own, so a changed scene or source reruns exactly what
# depends on it, and make -j2 runs them side by side.  The figures draw the
# meshes from nodes.dat and triangles.dat, which only --plot-files writes.

figures: $(FIGURES) $(ACCURACY_FIGS) $(HARD_FIGS) $(PARTS_PLOTS)
	@echo "figures: $(words $(FIGURES) $(ACCURACY_FIGS) $(HARD_FIGS) $(PARTS_PLOTS)) files in figures/ (Fig. 5.1-5.4 and the friction and Coulomb figures as PDF and PNG, the reproduction, suite, friction and Coulomb tables, the accuracy figure and table, the tables of the hard cases, of MPRGP and of the shipped parts, and the figures of the parts)"

out/example-%/summary.dat: data/example-%.scene bin/contactopt
	bin/contactopt solve $< -o $(@D) --plot-files > /dev/null
out/example-%-optimize/summary.dat: data/example-%.scene bin/contactopt
	@mkdir -p out
	bin/contactopt optimize $< -o $(@D) --plot-files > $(@D).log
out/example-%-strain-optimize/summary.dat: data/example-%.scene bin/contactopt
	@mkdir -p out
	bin/contactopt optimize $< -o $(@D) -s material.model=plane_strain > $(@D).log

# Decision (area): C2 = 3.91 as printed.  The alternative, the C2 for which
# Example 5.1's arc (gamma = 1) is feasible (src/c2-of-shape.sh), shows what
# that decision changes.
out/example-5.1-C2arc-optimize/summary.dat: data/example-5.1.scene out/example-5.1/summary.dat \
                                            src/c2-of-shape.sh bin/contactopt
	@mkdir -p out
	c2=$$(sh src/c2-of-shape.sh 1 out/example-5.1/shape.dat) && \
	  bin/contactopt optimize $< -o $(@D) -s design.C2=$$c2 > $(@D).log

# Fig. 5.1 and 5.3: the initial bodies; Fig. 5.2 and 5.4: the results,
# drawn by contactopt plot as a user's run is (paper/figures.nw).
figures/fig-5.1.pdf figures/fig-5.1.png &: out/example-5.1/summary.dat bin/contactopt
	@mkdir -p figures
	bin/contactopt plot out/example-5.1 --body --title 'Example 5.1' -o figures/fig-5.1
figures/fig-5.3.pdf figures/fig-5.3.png &: out/example-5.2/summary.dat bin/contactopt
	@mkdir -p figures
	bin/contactopt plot out/example-5.2 --body --title 'Example 5.2' -o figures/fig-5.3
figures/fig-5.2.pdf figures/fig-5.2.png &: out/example-5.1/summary.dat \
                                           out/example-5.1-optimize/summary.dat bin/contactopt
	@mkdir -p figures
	bin/contactopt plot out/example-5.1-optimize --results --start out/example-5.1 \
	  --title 'Example 5.1' -o figures/fig-5.2
figures/fig-5.4.pdf figures/fig-5.4.png &: out/example-5.2/summary.dat \
                                           out/example-5.2-optimize/summary.dat bin/contactopt
	@mkdir -p figures
	bin/contactopt plot out/example-5.2-optimize --results --start out/example-5.2 \
	  --title 'Example 5.2' -o figures/fig-5.4
out/suite/%-newton/summary.dat: data/suite/%.scene bin/contactopt
	@mkdir -p out/suite
	bin/contactopt optimize $< -o $(@D) -s optimizer.method=newton > $(@D).log
out/suite/%-slsqp/summary.dat: data/suite/%.scene bin/contactopt
	@mkdir -p out/suite
	bin/contactopt optimize $< -o $(@D) -s optimizer.method=slsqp > $(@D).log 2>&1 \
	  || [ $$? -eq 3 ]
figures/suite.tex: src/suite-table.sh $(SUITE_RUNS)
	@mkdir -p figures
	sh $< out/suite > $@.partial && mv $@.partial $@
# Given friction (paper/friction.nw): the friction scene for twelve slip
# bounds and three Coulomb coefficients, their table and their figure.
figures/friction.tex: src/friction.sh data/example-5.1-tresca.scene bin/contactopt
	@mkdir -p figures
	sh $< data/example-5.1-tresca.scene out/friction > $@.partial && mv $@.partial $@
figures/fig-friction.pdf figures/fig-friction.png &: src/fig-friction.gp figures/friction.tex
	gnuplot -e "runs='out/friction'; out='figures/fig-friction'" $<
# Shape optimisation with Coulomb friction (paper/coulomb.nw): the friction
# scene as a Coulomb scene optimised for four coefficients on two meshes,
# its gradient check, the Tresca comparison, their tables and figure.
figures/coulomb.tex: src/coulomb.sh data/example-5.1-tresca.scene bin/contactopt
	@mkdir -p figures
	sh $< data/example-5.1-tresca.scene out/coulomb > $@.partial && mv $@.partial $@
figures/fig-coulomb.pdf figures/fig-coulomb.png &: src/fig-coulomb.gp figures/coulomb.tex
	gnuplot -e "runs='out/coulomb'; out='figures/fig-coulomb'" $<
figures/reproduction.tex: src/reproduction.sh $(RUNS)
	@mkdir -p figures
	sh $< out > $@.partial && mv $@.partial $@
# The optima of Example 5.1 for each objective (paper/objective.nw).
figures/objectives.tex: src/objectives.sh data/example-5.1.scene bin/contactopt
	@mkdir -p figures
	sh $< data/example-5.1.scene out/objectives > $@.partial && mv $@.partial $@
figures/fig-objectives.pdf figures/fig-objectives.png &: src/fig-objectives.gp figures/objectives.tex
	gnuplot -e "runs='out/objectives'; out='figures/fig-objectives'" $<

# Reference values (data/reference/) are independent computations, made by
# hand when a change is meant to change the results; see the script.
reference: bin/contactopt
	sh tests/reference/generate.sh

clean:
	rm -rf build bin out src/.tangled

# make fuzz: libFuzzer on the scene parser and validator (tests/fuzz/).
include tests/fuzz/fuzz.mk
