# microfacet.h - build, test, bench, demo. Needs only a C compiler (gcc or
# clang), a C++ compiler for the C++ tests, make and the C library.
CC      ?= cc
CXX     ?= c++
PREFIX  ?= /usr/local
OPT     ?= -O2
WARN    := -Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion
TWARN   := -Wall -Wextra -Wshadow
BUILD   := build
TEST_SRC := tests/main.c tests/quad.c tests/test_core.c tests/test_ndf.c tests/test_sampling.c \
            tests/test_brdf.c tests/test_ltmd.c tests/test_ltc.c tests/test_leadr.c \
            tests/test_tabulated.c tests/test_ibm.c tests/test_microsurface.c \
            tests/test_robust.c tests/test_float.c tests/test_tu2.c tests/test_fuzzfound.c
HAVE_CLANG := $(shell command -v clang >/dev/null 2>&1 && echo yes)
HAVE_NVCC  := $(shell command -v nvcc >/dev/null 2>&1 && echo yes)

.PHONY: fuzz fuzz-smoke fuzz-build fastmath-check
.PHONY: all test test-c test-cpp test-double test-float warnings asan bench demo install clean cuda-check \
        header header-check config-check ltc-table

all: test

# ---- the single header is generated from the module sources src/*.h
SRC_MODULES := $(sort $(wildcard src/*.h))
header:
	@sh tools/amalgamate.sh > microfacet.h.tmp && mv microfacet.h.tmp microfacet.h
	@echo "microfacet.h generated from $(words $(SRC_MODULES)) modules in src/"
# make test runs this: module opt-outs, the allocator pair, precision mixing
config-check: | $(BUILD)
	@sh tests/config_check.sh "$(CC)" "$(CXX)" "$(WARN)" $(BUILD)
# make test runs this: the committed header must be what the generator makes
header-check:
	@sh tools/amalgamate.sh | cmp -s - microfacet.h || \
	  { echo "microfacet.h differs from src/: edit src/, run 'make header', commit both"; exit 1; }

# the built-in LTC table module, refitted (216 s here); it reproduces the
# shipped src/14_ltc_table.h byte for byte
ltc-table: | $(BUILD)
	$(CC) -std=c99 -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit.c -o $(BUILD)/ltc_fit -lm
	./$(BUILD)/ltc_fit --module > src/14_ltc_table.h.tmp && mv src/14_ltc_table.h.tmp src/14_ltc_table.h
	@$(MAKE) --no-print-directory header

$(BUILD):
	@mkdir -p $(BUILD)

# ---- test binaries: {C, C++} x {float, double}; ref_other.c is the same math
# ---- in the other precision (always C), for the float-vs-double comparison
$(BUILD)/ref_float.o: tests/ref_other.c microfacet.h | $(BUILD)
	$(CC) -std=c99 $(OPT) $(TWARN) -I. -c $< -o $@
$(BUILD)/ref_double.o: tests/ref_other.c microfacet.h | $(BUILD)
	$(CC) -std=c99 $(OPT) $(TWARN) -DMF_USE_DOUBLE -I. -c $< -o $@

$(BUILD)/test_c_double: $(TEST_SRC) $(BUILD)/ref_float.o microfacet.h tests/mf_test.h | $(BUILD)
	$(CC) -std=c99 $(OPT) $(TWARN) -DMF_USE_DOUBLE -DMFT_OTHER=float -I. -Itests $(TEST_SRC) $(BUILD)/ref_float.o -o $@ -lm
$(BUILD)/test_c_float: $(TEST_SRC) $(BUILD)/ref_double.o microfacet.h tests/mf_test.h | $(BUILD)
	$(CC) -std=c99 $(OPT) $(TWARN) -DMFT_OTHER=double -I. -Itests $(TEST_SRC) $(BUILD)/ref_double.o -o $@ -lm
$(BUILD)/test_cpp_double: $(TEST_SRC) $(BUILD)/ref_float.o microfacet.h tests/mf_test.h | $(BUILD)
	$(CXX) -x c++ -std=c++11 $(OPT) $(TWARN) -DMF_USE_DOUBLE -DMFT_OTHER=float -I. -Itests $(TEST_SRC) -x none $(BUILD)/ref_float.o -o $@ -lm
$(BUILD)/test_cpp_float: $(TEST_SRC) $(BUILD)/ref_double.o microfacet.h tests/mf_test.h | $(BUILD)
	$(CXX) -x c++ -std=c++11 $(OPT) $(TWARN) -DMFT_OTHER=double -I. -Itests $(TEST_SRC) -x none $(BUILD)/ref_double.o -o $@ -lm

TEST_BINS := $(BUILD)/test_c_double $(BUILD)/test_c_float $(BUILD)/test_cpp_double $(BUILD)/test_cpp_float

# warnings: the header alone must compile cleanly as C99/C11 and C++98..20,
# float and double, gcc and clang (when present), with -Werror.
warnings: | $(BUILD)
	@sh tests/warnings.sh "$(CC)" "$(CXX)" "$(HAVE_CLANG)" "$(WARN)" $(BUILD)

# make test: every check above, then all four test binaries; the last line is
# the total "N passed, N failed"; non-zero exit on any failure.
test: $(TEST_BINS)
	@sh tests/run_all.sh "$(MAKE)" $(TEST_BINS)

test-c: $(BUILD)/test_c_double $(BUILD)/test_c_float
	@sh tests/run_all.sh "" $^
test-cpp: $(BUILD)/test_cpp_double $(BUILD)/test_cpp_float
	@sh tests/run_all.sh "" $^
test-double: $(BUILD)/test_c_double $(BUILD)/test_cpp_double
	@sh tests/run_all.sh "" $^
test-float: $(BUILD)/test_c_float $(BUILD)/test_cpp_float
	@sh tests/run_all.sh "" $^

# ASan + UBSan, double and float
SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g
asan: | $(BUILD)
	$(CC) -std=c99 -O1 $(SAN) $(TWARN) -I. -c tests/ref_other.c -o $(BUILD)/asan_ref_f.o
	$(CC) -std=c99 -O1 $(SAN) $(TWARN) -DMF_USE_DOUBLE -I. -c tests/ref_other.c -o $(BUILD)/asan_ref_d.o
	$(CC) -std=c99 -O1 $(SAN) $(TWARN) -DMF_USE_DOUBLE -DMFT_OTHER=float -I. -Itests $(TEST_SRC) $(BUILD)/asan_ref_f.o -o $(BUILD)/asan_double -lm
	$(CC) -std=c99 -O1 $(SAN) $(TWARN) -DMFT_OTHER=double -I. -Itests $(TEST_SRC) $(BUILD)/asan_ref_d.o -o $(BUILD)/asan_float -lm
	@sh tests/run_all.sh "" $(BUILD)/asan_double $(BUILD)/asan_float

# make test runs this: the NaN/Inf robustness subset built with -ffast-math
# (tests/fastmath_check.c), float and double
fastmath-check: | $(BUILD)
	@$(CC) -std=c99 -O2 -ffast-math $(TWARN) -I. tests/fastmath_check.c -o $(BUILD)/fastmath_f -lm && ./$(BUILD)/fastmath_f >/dev/null
	@$(CC) -std=c99 -O2 -ffast-math $(TWARN) -DMF_USE_DOUBLE -I. tests/fastmath_check.c -o $(BUILD)/fastmath_d -lm && ./$(BUILD)/fastmath_d >/dev/null

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
# make test runs this: each target for FUZZ_SMOKE seconds (float), or one
# line saying why it was skipped
fuzz-smoke:
	@sh tests/fuzz/smoke.sh "$(MAKE)" $(BUILD)/fuzz $(FUZZ_SMOKE) $(FUZZ_TARGETS)

bench: | $(BUILD)
	$(CC) -std=c99 -O2 $(WARN) -DMF_BENCH_FLAGS="\"-std=c99 -O2\"" -I. bench/bench.c -o $(BUILD)/bench -lm
	$(CC) -std=c99 -O2 $(WARN) -DMF_USE_DOUBLE -DMF_BENCH_FLAGS="\"-std=c99 -O2 -DMF_USE_DOUBLE\"" -I. bench/bench.c -o $(BUILD)/bench_double -lm
	./$(BUILD)/bench
	./$(BUILD)/bench_double

EXAMPLES := $(basename $(notdir $(wildcard examples/*.c)))
demo: | $(BUILD)
	@mkdir -p out
	@for e in $(EXAMPLES); do \
	  $(CC) -std=c99 -O2 $(WARN) -I. examples/$$e.c -o $(BUILD)/$$e -lm || exit 1; \
	  ./$(BUILD)/$$e out/$$e.ppm out/$$e.pfm || exit 1; \
	done
	@echo "images written to out/"

# CUDA: device code must compile (no GPU needed); optional.
cuda-check: | $(BUILD)
ifeq ($(HAVE_NVCC),yes)
	nvcc -std=c++17 -I. -c tests/cuda_kernel.cu -o $(BUILD)/cuda_kernel.o
	nvcc -std=c++17 -DMF_USE_DOUBLE -I. -c tests/cuda_kernel.cu -o $(BUILD)/cuda_kernel_d.o
	@echo "cuda-check: device code compiles"
else
	@echo "cuda-check: nvcc not found, skipped"
endif

install:
	install -d $(DESTDIR)$(PREFIX)/include
	install -m 644 microfacet.h $(DESTDIR)$(PREFIX)/include/microfacet.h

clean:
	rm -rf $(BUILD) out
