# Two commands do everything on a fresh Debian 12 machine:
#   make run   — install what is missing, build (release), run the main job on the embedded defaults
#   make test  — install what is missing, build, run every test through ctest
# CI (CI=true) builds with warnings as errors.

PRESET := $(if $(filter true,$(CI)),ci,release)
JOBS   ?= $(shell nproc)
BIN    := build/bin

.PHONY: run test build deps bench coverage clean

deps:
	@scripts/setup-deps.sh

build: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS)

run: build
	@scripts/demo.sh

test: build
	@ctest --preset $(PRESET) -j $(JOBS)

bench: build
	@$(BIN)/gestura-bench

# How many content words of everyday English sentences the ASL lexicon signs (docs/asl-lexicon.md).
coverage: build
	@python3 tools/coverage.py --gestura $(BIN)/gestura
	@python3 tools/coverage.py --gestura $(BIN)/gestura --sentences data/eval/heldout-sentences.txt --quiet

clean:
	rm -rf build build-debug
