# microfacet.h - build, test, bench, demo. Needs only a C compiler (gcc or
# clang), a C++ compiler for the C++ tests, make and the C library.
CC      ?= cc
CXX     ?= c++
PREFIX  ?= /usr/local
OPT     ?= -O2
WARN    := -Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion
TWARN   := -Wall -Wextra -Wshadow
BUILD   := build
# the test modules: tests/modules.h is the one list (MFT_QUICK ones also run in
# make check and in make test's C++ builds; test_sampling, test_brdf and
# test_fuzzfound hold checks and the counting allocator the others share)
TEST_MODULES := $(shell sed -n 's/^MFT_[A-Z]*(\(test_[a-z0-9_]*\)).*/\1/p' tests/modules.h)
QUICK_MODULES := $(shell sed -n 's/^MFT_QUICK(\(test_[a-z0-9_]*\)).*/\1/p' tests/modules.h)
TEST_SRC := tests/main.c tests/quad.c $(TEST_MODULES:%=tests/%.c)
QUICK_SRC := tests/quad.c $(sort $(QUICK_MODULES:%=tests/%.c) tests/test_sampling.c tests/test_brdf.c tests/test_fuzzfound.c)
HAVE_CLANG := $(shell command -v clang >/dev/null 2>&1 && echo yes)
HAVE_NVCC  := $(shell command -v nvcc >/dev/null 2>&1 && echo yes)
# OpenEXR is optional (apt-get install libopenexr-dev): found through
# pkg-config, examples then also write .exr and make test reads EXR inputs;
# make EXR=no ignores it
ifneq ($(EXR),no)
HAVE_EXR   := $(shell pkg-config --exists OpenEXR 2>/dev/null && echo yes)
endif
ifeq ($(HAVE_EXR),yes)
EXR_CFLAGS := $(patsubst -I%,-isystem %,$(shell pkg-config --cflags OpenEXR))
EXR_LIBS   := $(shell pkg-config --libs OpenEXR)
EXR_DEFS   := -DMF_EXAMPLE_EXR $(EXR_CFLAGS)
EXR_HDR    := tools/exr_io.h
EXR_STEPS  := exr_float exr_double
else
EXR_STEPS  := exr_skip
endif

.PHONY: fuzz fuzz-build check-all check-float api kinds prefix history warnings config fastmath package readme include_cost
.PHONY: all test check test-c test-cpp asan bench bench-inline demo install clean cuda-check cuda-run \
        header header-check ltc-table ltc-table-ggx ltc-table-beckmann ltc-table-aniso energy-table sheen-table tools \
        $(foreach s,header api kinds prefix history warnings config include_cost package readme examples exr_float exr_double exr_skip fastmath fuzz \
          c_double c_double_b c_float cpp_double cpp_float asan_double asan_float,step-$(s))

all: test

# ---- the single header is generated from the module sources src/*.h
SRC_MODULES := $(sort $(wildcard src/*.h))
header:
	@sh tools/amalgamate.sh > microfacet.h.tmp && mv microfacet.h.tmp microfacet.h
	@sh tools/amalgamate.sh --readme > README.md.tmp && mv README.md.tmp README.md
	@mkdir -p docs && sh tools/amalgamate.sh --api > docs/API.md.tmp && mv docs/API.md.tmp docs/API.md
	@echo "microfacet.h generated from $(words $(SRC_MODULES)) modules in src/ (and the API index: README.md, docs/API.md)"
	@sh tools/prefix_check.sh "$(CC)"
# make test runs this: the committed header and README's API index must be
# what the generator makes
header-check:
	@sh tools/amalgamate.sh | cmp -s - microfacet.h || \
	  { echo "microfacet.h differs from src/: edit src/, run 'make header', commit both"; exit 1; }
	@sh tools/amalgamate.sh --readme | cmp -s - README.md || \
	  { echo "README.md's API index differs from src/: run 'make header', commit both"; exit 1; }
	@sh tools/amalgamate.sh --api | cmp -s - docs/API.md || \
	  { echo "docs/API.md differs from src/: run 'make header', commit both"; exit 1; }

# the built-in LTC table modules, refitted (GGX with its refinement on
# polygons 259 s CPU, Beckmann 264 s here; ltc-table-ggx and ltc-table-beckmann
# refit one); they reproduce src/14_ltc_table.h and
# src/14_ltc_table_beckmann.h byte for byte
ltc-table: ltc-table-ggx ltc-table-beckmann ltc-table-aniso
ltc-table-ggx: | $(BUILD)
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit.c -o $(BUILD)/ltc_fit -lm
	./$(BUILD)/ltc_fit --module > src/14_ltc_table.h.tmp && mv src/14_ltc_table.h.tmp src/14_ltc_table.h
	@$(MAKE) --no-print-directory header
# the anisotropic GGX table (src/14_ltc_table_aniso.h, about 10 min CPU):
# its isotropic slice and warm starts come from src/14_ltc_table.h, so
# refit it after ltc-table-ggx; byte for byte reproducible
ltc-table-aniso: | $(BUILD)
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit_aniso.c -o $(BUILD)/ltc_fit_aniso -lm
	./$(BUILD)/ltc_fit_aniso --module > src/14_ltc_table_aniso.h.tmp && mv src/14_ltc_table_aniso.h.tmp src/14_ltc_table_aniso.h
	@$(MAKE) --no-print-directory header
ltc-table-beckmann: | $(BUILD)
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit.c -o $(BUILD)/ltc_fit -lm
	./$(BUILD)/ltc_fit --module beckmann > src/14_ltc_table_beckmann.h.tmp && mv src/14_ltc_table_beckmann.h.tmp src/14_ltc_table_beckmann.h
	@$(MAKE) --no-print-directory header

# the built-in directional-albedo tables (GGX, Beckmann), retabulated (about
# 10 s), then the rough-dielectric tables relative to them (about 1 minute);
# reproduces the shipped src/17_energy_table.h and
# src/17_energy_table_dielectric.h byte for byte
energy-table: | $(BUILD)
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/energy_fit.c -o $(BUILD)/energy_fit -lm
	./$(BUILD)/energy_fit > src/17_energy_table.h.tmp && mv src/17_energy_table.h.tmp src/17_energy_table.h
	@$(MAKE) --no-print-directory header
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/energy_fit_dielectric.c -o $(BUILD)/energy_fit_dielectric -lm
	./$(BUILD)/energy_fit_dielectric > src/17_energy_table_dielectric.h.tmp && mv src/17_energy_table_dielectric.h.tmp src/17_energy_table_dielectric.h
	@$(MAKE) --no-print-directory header

# the built-in volumetric sheen LTC table: simulates the fibre layer and
# fits each entry (about 3 minutes on one core); reproduces the shipped
# src/22_sheen_table.h byte for byte (fixed seeds)
sheen-table: | $(BUILD)
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/sheen_fit.c -o $(BUILD)/sheen_fit -lm
	./$(BUILD)/sheen_fit > src/22_sheen_table.h.tmp && mv src/22_sheen_table.h.tmp src/22_sheen_table.h
	@$(MAKE) --no-print-directory header

$(BUILD):
	@mkdir -p $(BUILD)

# ---- make uses every core unless told otherwise (make -j1 ... runs serially)
ifeq ($(MAKELEVEL),0)
NPROC   := $(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
MAKEFLAGS += -j$(NPROC)
endif
# V=1 prints the full compiler commands
ifeq ($(V),1)
Q :=
else
Q := @
endif

# ---- test binaries: {C, C++} x {float, double}, one object per test source so
# ---- that make -j compiles in parallel and rebuilds only what changed.
# build/test_<cfg> holds every module; build/quick_<cfg> the MFT_QUICK ones
# (its main.c built with MFT_QUICK_ONLY). ref_other.c is the same math in the
# other precision (always C), for the float-vs-double comparison. c_double's
# implementation unit (main.c) is built as users build (hot paths
# always_inline); every other object with plain `static inline` hot paths,
# which the compiler inlines by its own measure: the same IEEE results
# (tests/test_tu2.c compares inline and cold paths bit for bit) in about half
# the compile time.
TEST_CFGS := c_double c_float cpp_double cpp_float
PLAIN_INLINE := '-DMF_FORCE_INLINE=static inline'
CMD_c_double_users := $(CC) -std=c99 $(OPT) $(TWARN) -DMF_USE_DOUBLE -DMFT_OTHER=float
CMD_c_double   := $(CMD_c_double_users) $(PLAIN_INLINE)
CMD_c_float    := $(CC) -std=c99 $(OPT) $(TWARN) $(PLAIN_INLINE) -DMFT_OTHER=double
CMD_cpp_double := $(CXX) -x c++ -std=c++11 $(OPT) $(TWARN) $(PLAIN_INLINE) -DMF_USE_DOUBLE -DMFT_OTHER=float
CMD_cpp_float  := $(CXX) -x c++ -std=c++11 $(OPT) $(TWARN) $(PLAIN_INLINE) -DMFT_OTHER=double
LINK_c_double := $(CC)
LINK_c_float := $(CC)
LINK_cpp_double := $(CXX)
LINK_cpp_float := $(CXX)
REF_c_double := ref_float
REF_c_float := ref_double
REF_cpp_double := ref_float
REF_cpp_float := ref_double
# ---- what the build depends on besides sources: the compilers, their flags
# ---- and OpenEXR's presence; a change rewrites build/config.stamp, and every
# ---- object, test and example rebuilds
CONFIG_LINE := $(CC) | $(CXX) | $(OPT) | $(HAVE_EXR) $(EXR_DEFS) $(EXR_LIBS) | $(foreach c,$(TEST_CFGS),$(CMD_$(c)) |)
CONFIG := $(BUILD)/config.stamp
$(shell mkdir -p $(BUILD))
$(file >$(CONFIG).new,$(CONFIG_LINE))
$(shell cmp -s $(CONFIG).new $(CONFIG) || mv $(CONFIG).new $(CONFIG); rm -f $(CONFIG).new)

TEST_HDRS := microfacet.h tests/mf_test.h tests/modules.h tests/quad.h tests/ref_other.h $(CONFIG)

# (at -O1: ISO C mode contracts nothing, so the values are those of -O2)
$(BUILD)/ref_float.o: tests/ref_other.c microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O1 $(TWARN) $(PLAIN_INLINE) -I. -c $< -o $@
$(BUILD)/ref_double.o: tests/ref_other.c microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O1 $(TWARN) $(PLAIN_INLINE) -DMF_USE_DOUBLE -I. -c $< -o $@

# make test's steps write "passed failed" to $(RES)/<step> (tests/run_step.sh)
RES := $(BUILD)/results
RUN_STEP := sh tests/run_step.sh
SUM := sh tests/sum_results.sh $(RES)
# one template per configuration: its objects, the full and the quick binary,
# and the make test step that runs it
define TEST_CFG
$(BUILD)/$(1)/%.o: tests/%.c $(TEST_HDRS)
	@mkdir -p $(BUILD)/$(1)
	@echo "  CC      $$@"
	$(Q)$(CMD_$(1)) -I. -Itests -c $$< -o $$@
$(BUILD)/$(1)/main_quick.o: tests/main.c $(TEST_HDRS)
	@mkdir -p $(BUILD)/$(1)
	@echo "  CC      $$@"
	$(Q)$(CMD_$(1)) -DMFT_QUICK_ONLY -I. -Itests -c $$< -o $$@
$(BUILD)/test_$(1): $(patsubst tests/%.c,$(BUILD)/$(1)/%.o,$(TEST_SRC)) $(BUILD)/$(REF_$(1)).o
	@echo "  LINK    $$@"
	$(Q)$(LINK_$(1)) $$^ -o $$@ -lm
$(BUILD)/quick_$(1): $(BUILD)/$(1)/main_quick.o $(patsubst tests/%.c,$(BUILD)/$(1)/%.o,$(QUICK_SRC)) $(BUILD)/$(REF_$(1)).o
	@echo "  LINK    $$@"
	$(Q)$(LINK_$(1)) $$^ -o $$@ -lm
step-$(1): $(BUILD)/$(RUN_$(1))_$(1) | $(RES)
	@$$(RUN_STEP) $(1) $(RES)/$(1) tests ./$$< $$(if $$(filter test,$$(RUN_$(1))),$$(FULL) $$(MODS_$(1)),--quick)
endef
# make test: the C double build runs every module, the C float build the
# quick ones (make check-float, run by .ci/run too: every module in C float,
# the quick ones in C++ float; make check-all: every module in all four
# builds, full size)
RUN_c_double := test
RUN_c_float := quick
RUN_cpp_double := quick
RUN_cpp_float := quick
# the double build's modules run as two steps, one per core: c_double the
# first ones, c_double_b the rest
MODS_c_double := test_core test_ndf test_sampling test_brdf test_ltmd test_ltc test_ltc_shapes
MODS_c_double_b := $(filter-out $(MODS_c_double),$(TEST_MODULES))
$(foreach c,$(TEST_CFGS),$(eval $(call TEST_CFG,$(c))))
$(BUILD)/c_double/main.o: tests/main.c $(TEST_HDRS)
	@mkdir -p $(BUILD)/c_double
	@echo "  CC      $@"
	$(Q)$(CMD_c_double_users) -I. -Itests -c $< -o $@
step-c_double_b: $(BUILD)/test_c_double | $(RES)
	@$(RUN_STEP) c_double_b $(RES)/c_double_b tests ./$< $(FULL) $(MODS_c_double_b)

# ---- make test: every step streams its output with [step] in front of each
# ---- line; steps run in parallel (include_cost first, alone: it times the
# ---- compiler; then c_double, the longest, so that its run starts early);
# ---- the last line is the total "N passed, N failed" and the exit
# ---- status is non-zero on any failure. make check-all adds the long
# ---- campaigns: every module at full size (--full) in all four builds, the
# ---- fuzz smoke run and the sanitizers.
CHECK_STEPS := header api kinds prefix history warnings config fastmath package readme
TEST_STEPS := include_cost c_double c_double_b $(CHECK_STEPS) c_float examples $(EXR_STEPS)

$(RES):
	@mkdir -p $(RES)
# the checks of make test, each one script or target (name: command)
CHECK_header := $(MAKE) --no-print-directory header-check
CHECK_api := sh tools/api_rules.sh
# no module but 05_ndf.h and the kinds' own tests a kind by name (traits instead)
CHECK_kinds := sh tests/kind_names_check.sh
# a module uses only the modules before it (each prefix of the list compiles)
CHECK_prefix := sh tools/prefix_check.sh "$(CC)"
CHECK_history := sh tests/history_check.sh
# the header alone compiles cleanly as C99/C11 and C++98..20, float and
# double, gcc and clang (when present), with -Werror
CHECK_warnings := sh tests/warnings.sh "$(CC)" "$(CXX)" "$(HAVE_CLANG)" "$(WARN)" $(BUILD)
# module opt-outs, the allocator pair, precision mixing, determinism
CHECK_config := sh tests/config_check.sh "$(CC)" "$(CXX)" "$(WARN)" $(BUILD)
# the NaN/Inf robustness subset built with -ffast-math: float (FASTMATH, make
# check-all: float and double)
FASTMATH ?= float
CHECK_fastmath := sh tests/fastmath_check.sh "$(CC)" "$(TWARN)" $(BUILD) "$(FASTMATH)"
# the CMake package and pkg-config, when cmake is present
CHECK_package := sh tests/package_check.sh "$(CC)" $(BUILD)
CHECK_readme := sh tests/readme_check.sh "$(CC)" "$(CXX)" "$(WARN)" $(BUILD)
CHECK_include_cost := sh tests/include_cost.sh "$(CC)" $(BUILD)
define CHECK_STEP
step-$(1): | $(RES)
	@$$(RUN_STEP) $(1) $(RES)/$(1) check $$(CHECK_$(1))
endef
$(foreach c,$(CHECK_STEPS) include_cost,$(eval $(call CHECK_STEP,$(c))))
# each check alone: make warnings, make config, ... (make header-check: the header)
CHECK_ALONE := api kinds prefix history warnings config fastmath package readme include_cost
$(CHECK_ALONE): %: step-%
	@$(SUM) $*
step-examples: $(CONFIG) | $(RES)
	@$(RUN_STEP) examples $(RES)/examples tests sh tests/examples_check.sh "$(CC)" "$(WARN)" $(BUILD) "$(EXR_DEFS)" "$(EXR_LIBS)"
# OpenEXR inputs read into the IBM and LEADR builders (tests/exr_check.c),
# float and double; one line saying it was skipped when OpenEXR is absent
ifeq ($(HAVE_EXR),yes)
$(BUILD)/exr_check_float: tests/exr_check.c tools/exr_io.h tools/ibm_exr.h microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O2 $(TWARN) -I. $(EXR_CFLAGS) $< -o $@ $(EXR_LIBS) -lm
$(BUILD)/exr_check_double: tests/exr_check.c tools/exr_io.h tools/ibm_exr.h microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O2 $(TWARN) -DMF_USE_DOUBLE -I. $(EXR_CFLAGS) $< -o $@ $(EXR_LIBS) -lm
$(BUILD)/ibm_from_exr: tools/ibm_from_exr.c tools/exr_io.h tools/ibm_exr.h microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O2 $(WARN) -I. $(EXR_CFLAGS) $< -o $@ $(EXR_LIBS) -lm
step-exr_float: $(BUILD)/exr_check_float | $(RES)
	@mkdir -p $(BUILD)/exr_float
	@$(RUN_STEP) exr_float $(RES)/exr_float tests ./$< $(BUILD)/exr_float
step-exr_double: $(BUILD)/exr_check_double | $(RES)
	@mkdir -p $(BUILD)/exr_double
	@$(RUN_STEP) exr_double $(RES)/exr_double tests ./$< $(BUILD)/exr_double
tools: $(BUILD)/ibm_from_exr
	@echo "tools: $(BUILD)/ibm_from_exr (an IBM file from an EXR normal map)"
else
step-exr_skip: | $(RES)
	@echo "[exr] EXR skipped: OpenEXR not found (apt-get install libopenexr-dev), or EXR=no"
	@echo "0 0" > $(RES)/exr_skip
tools:
	@echo "tools: EXR skipped: OpenEXR not found (apt-get install libopenexr-dev), or EXR=no; nothing to build"
endif
step-fuzz: | $(RES)
	@$(RUN_STEP) fuzz $(RES)/fuzz tests sh tests/fuzz/smoke.sh "$(MAKE)" $(BUILD)/fuzz $(FUZZ_SMOKE) $(FUZZ_TARGETS)

# include_cost runs first and alone (a timing); then the rest in parallel
# (the double build's objects are goals of their own, ahead of the steps:
# make shares its job slots among goals, and that build's run is the longest)
C_DOUBLE_OBJS = $(patsubst tests/%.c,$(BUILD)/c_double/%.o,$(TEST_SRC))
test:
	@$(MAKE) --no-print-directory step-include_cost
	@$(MAKE) --no-print-directory $(C_DOUBLE_OBJS) $(filter-out step-include_cost,$(TEST_STEPS:%=step-%))
	@$(SUM) $(TEST_STEPS)
# smoke test, under 30 s on a fresh clone: the header is current, the quick
# modules in float (the same binary and step as make test's c_float)
check: step-header step-c_float
	@$(SUM) header c_float
# make test, then every module at full size in all four builds, the fuzz
# smoke run and the sanitizers
check-all:
	@$(MAKE) --no-print-directory step-include_cost
	@$(MAKE) --no-print-directory FULL=--full FASTMATH="float double" RUN_c_float=test RUN_cpp_double=test RUN_cpp_float=test \
	  $(filter-out step-include_cost,$(TEST_STEPS:%=step-%)) step-cpp_double step-cpp_float step-fuzz step-asan_double step-asan_float
	@$(SUM) $(TEST_STEPS) cpp_double cpp_float fuzz asan_double asan_float
# the float builds: every module in C float (make test runs the quick ones
# there) and the quick ones in C++ float; .ci/run runs it after make test
check-float:
	@$(MAKE) --no-print-directory RUN_c_float=test step-c_float step-cpp_float
	@$(SUM) c_float cpp_float
test-c:
	@$(MAKE) --no-print-directory RUN_c_float=test step-c_double step-c_double_b step-c_float
	@$(SUM) c_double c_double_b c_float
test-cpp:
	@$(MAKE) --no-print-directory RUN_cpp_double=test RUN_cpp_float=test step-cpp_double step-cpp_float
	@$(SUM) cpp_double cpp_float

# ASan + UBSan, double and float
SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g
$(BUILD)/asan_ref_f.o: tests/ref_other.c microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O1 $(SAN) $(TWARN) -I. -c $< -o $@
$(BUILD)/asan_ref_d.o: tests/ref_other.c microfacet.h $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O1 $(SAN) $(TWARN) -DMF_USE_DOUBLE -I. -c $< -o $@
$(BUILD)/asan_double: $(TEST_SRC) $(TEST_HDRS) $(BUILD)/asan_ref_f.o
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O1 $(SAN) $(TWARN) -DMF_USE_DOUBLE -DMFT_OTHER=float -I. -Itests $(TEST_SRC) $(BUILD)/asan_ref_f.o -o $@ -lm
$(BUILD)/asan_float: $(TEST_SRC) $(TEST_HDRS) $(BUILD)/asan_ref_d.o
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O1 $(SAN) $(TWARN) -DMFT_OTHER=double -I. -Itests $(TEST_SRC) $(BUILD)/asan_ref_d.o -o $@ -lm
step-asan_double: $(BUILD)/asan_double | $(RES)
	@$(RUN_STEP) asan_double $(RES)/asan_double tests ./$<
step-asan_float: $(BUILD)/asan_float | $(RES)
	@$(RUN_STEP) asan_float $(RES)/asan_float tests ./$<
asan: step-asan_double step-asan_float
	@$(SUM) asan_double asan_float

# ---- libFuzzer targets (tests/fuzz/): clang with -fsanitize=fuzzer,address,
# ---- undefined. `make fuzz` runs each for FUZZ_TIME seconds in float and in
# ---- double; make test runs each (float) for FUZZ_SMOKE seconds.
FUZZ_TARGETS := generic ibm_load builders ltc
FUZZ_TIME  ?= 60
FUZZ_SMOKE ?= 2
FUZZ_FLAGS := -std=c99 -g -O1 -fno-sanitize-recover=undefined -I. -Itests/fuzz
FUZZ_PREC  ?= float double
$(BUILD)/fuzz/impl_float.o: tests/fuzz/fuzz_impl.c microfacet.h
	@mkdir -p $(BUILD)/fuzz
	clang $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link,address,undefined -c $< -o $@
$(BUILD)/fuzz/impl_double.o: tests/fuzz/fuzz_impl.c microfacet.h
	@mkdir -p $(BUILD)/fuzz
	clang $(FUZZ_FLAGS) -DMF_USE_DOUBLE -fsanitize=fuzzer-no-link,address,undefined -c $< -o $@
$(BUILD)/fuzz/fuzz_%_float: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h $(BUILD)/fuzz/impl_float.o
	clang $(FUZZ_FLAGS) -fsanitize=fuzzer,address,undefined $< $(BUILD)/fuzz/impl_float.o -o $@ -lm
$(BUILD)/fuzz/fuzz_%_double: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h $(BUILD)/fuzz/impl_double.o
	clang $(FUZZ_FLAGS) -DMF_USE_DOUBLE -fsanitize=fuzzer,address,undefined $< $(BUILD)/fuzz/impl_double.o -o $@ -lm
$(BUILD)/fuzz/make_seeds: tests/fuzz/make_seeds.c
	@mkdir -p $(BUILD)/fuzz
	$(CC) -std=c99 -O1 $(TWARN) $< -o $@
fuzz-build: $(BUILD)/fuzz/make_seeds $(foreach p,$(FUZZ_PREC),$(foreach t,$(FUZZ_TARGETS),$(BUILD)/fuzz/fuzz_$(t)_$(p)))
fuzz:
ifeq ($(HAVE_CLANG),yes)
	@$(MAKE) --no-print-directory fuzz-build
	@sh tests/fuzz/run.sh $(BUILD)/fuzz $(FUZZ_TIME) "$(FUZZ_PREC)" $(FUZZ_TARGETS)
else
	@echo "fuzz: clang not found, skipped"
endif

bench: | $(BUILD)
	$(CC) -std=c99 -O2 $(WARN) -DMF_BENCH_FLAGS="\"-std=c99 -O2\"" -I. bench/bench.c -o $(BUILD)/bench -lm
	$(CC) -std=c99 -O2 $(WARN) -DMF_USE_DOUBLE -DMF_BENCH_FLAGS="\"-std=c99 -O2 -DMF_USE_DOUBLE\"" -I. bench/bench.c -o $(BUILD)/bench_double -lm
	./$(BUILD)/bench
	./$(BUILD)/bench_double
	sh tools/bench_inline.sh "$(CC)" 5
# the hot paths at -O2, -O3 -march=native and in a large translation unit
bench-inline: | $(BUILD)
	sh tools/bench_inline.sh "$(CC)" 5

# ---- make demo: each example is rebuilt only when its source or the header
# ---- changed and rerun only when rebuilt; its output is printed with
# ---- [example] in front, and the list of images written ends the target.
EXAMPLES := $(basename $(notdir $(wildcard examples/*.c)))
$(BUILD)/ex_%: examples/%.c examples/example_common.h microfacet.h $(EXR_HDR) $(CONFIG)
	@echo "  CC      $@"
	$(Q)$(CC) -std=c99 -O2 $(WARN) $(EXR_DEFS) -I. $< -o $@ $(EXR_LIBS) -lm
out/%.png: $(BUILD)/ex_%
	@mkdir -p out
	@echo "  RUN     examples/$*.c"
	@{ ./$< out/$* 2>&1; echo $$? > out/$*.rc; } | sed 's/^/[$*] /'; \
	  rc=$$(cat out/$*.rc); rm -f out/$*.rc; [ "$$rc" -eq 0 ] || { rm -f $@; exit 1; }
.SECONDARY: $(EXAMPLES:%=$(BUILD)/ex_%)
demo: $(EXAMPLES:%=out/%.png)
	@echo "make demo: $(words $(EXAMPLES)) examples; images in out/$(if $(EXR_DEFS),, (no .exr: OpenEXR not found, or EXR=no))"
	@cd out && ls -1 $(foreach e,$(EXAMPLES),$(e).png $(e).pfm $(if $(EXR_DEFS),$(e).exr)) | sed 's|^|  out/|'

# CUDA: device code must compile (no GPU needed); optional. cuda-check also
# builds the GPU test (tests/cuda_run.cu: the implementation compiled by nvcc
# too, warnings are errors) and runs its host half; cuda-run runs it on a GPU
# (CUDA_ARCH: the GPU's architecture, e.g. make cuda-run CUDA_ARCH=sm_80).
NVCC_FLAGS = -std=c++17 -O2 -arch=$(CUDA_ARCH) -Werror all-warnings -I.
CUDA_ARCH ?= sm_90
HAVE_GPU   = $(if $(HAVE_NVCC),$(shell nvidia-smi -L >/dev/null 2>&1 && echo yes))
cuda-check: | $(BUILD)
ifeq ($(HAVE_NVCC),yes)
	nvcc -std=c++17 -Werror all-warnings -I. -c tests/cuda_kernel.cu -o $(BUILD)/cuda_kernel.o
	nvcc -std=c++17 -Werror all-warnings -DMF_USE_DOUBLE -I. -c tests/cuda_kernel.cu -o $(BUILD)/cuda_kernel_d.o
	@$(MAKE) --no-print-directory $(BUILD)/cuda_run $(BUILD)/cuda_run_d
	@./$(BUILD)/cuda_run --host | tail -1 && ./$(BUILD)/cuda_run_d --host | tail -1
	@echo "cuda-check: device code compiles"
else
	@echo "cuda-check: nvcc not found, skipped"
endif
$(BUILD)/cuda_run: tests/cuda_run.cu microfacet.h | $(BUILD)
	nvcc $(NVCC_FLAGS) tests/cuda_run.cu -o $@
$(BUILD)/cuda_run_d: tests/cuda_run.cu microfacet.h | $(BUILD)
	nvcc $(NVCC_FLAGS) -DMF_USE_DOUBLE tests/cuda_run.cu -o $@
cuda-run:
ifeq ($(HAVE_NVCC)$(HAVE_GPU),yesyes)
	@$(MAKE) --no-print-directory $(BUILD)/cuda_run $(BUILD)/cuda_run_d
	./$(BUILD)/cuda_run && ./$(BUILD)/cuda_run_d
else
	@echo "cuda-run: needs nvcc and a CUDA GPU (nvidia-smi -L), skipped"
endif

# make install: the header, LICENSE and the pkg-config file (the CMake package
# comes with cmake --install, see CMakeLists.txt)
VERSION := $(shell sed -n 's/^\#define MF_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$$/\2/p' microfacet.h | paste -sd. -)
install:
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/share/licenses/microfacet $(DESTDIR)$(PREFIX)/share/pkgconfig
	install -m 644 microfacet.h $(DESTDIR)$(PREFIX)/include/microfacet.h
	install -m 644 LICENSE $(DESTDIR)$(PREFIX)/share/licenses/microfacet/LICENSE
	sed -e 's|@MF_PC_VERSION@|$(VERSION)|' -e 's|@MF_PC_INCLUDEDIR@|include|' cmake/microfacet.pc.in > $(DESTDIR)$(PREFIX)/share/pkgconfig/microfacet.pc
	chmod 644 $(DESTDIR)$(PREFIX)/share/pkgconfig/microfacet.pc


clean:
	rm -rf $(BUILD) out
