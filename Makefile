# Two commands do everything on a fresh Debian 12 machine:
#   make run   — install what is missing, build (release), run the main job on the embedded defaults
#   make test  — install what is missing, build, run every test through ctest
# CI (CI=true) builds with warnings as errors.
# Also: make fuzz (libFuzzer targets, FUZZ_SECONDS each), make test-asan (every test under ASan + UBSan),
# make bench. docs/reliability.md explains the first two.

PRESET := $(if $(filter true,$(CI)),ci,release)
JOBS   ?= $(shell nproc)
BIN    := build/bin

FUZZ_SECONDS ?= 60
# LeakSanitizer: the one suppression (Mesa's EGL driver) is explained in tests/lsan.supp.
SANITIZER_ENV := ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
                 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0

.PHONY: run test build deps bench clean fuzz fuzz-smoke test-asan

deps:
	@scripts/setup-deps.sh

build: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS)

run: build
	@scripts/demo.sh

test: build
	@ctest --preset $(PRESET) -j $(JOBS)

# The libFuzzer targets (fuzz/), each for FUZZ_SECONDS, under ASan + UBSan (clang 14, build-asan/).
fuzz: deps
	@scripts/fuzz.sh $(FUZZ_SECONDS)

# A few seconds per target: that every reader survives its seeds and a little mutation.
fuzz-smoke: deps
	@FUZZ_JOBS=$(JOBS) scripts/fuzz.sh 3

# Every test, built with clang 14 under ASan + UBSan (no recovery) and LeakSanitizer.
test-asan: deps
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan -j $(JOBS)
	@$(SANITIZER_ENV) ctest --preset asan -j $(JOBS)

bench: build
	@$(BIN)/gestura-bench

clean:
	rm -rf build build-debug build-asan
