# Two commands do everything on a fresh Debian 12 machine:
#   make run   — install what is missing, build (release), run the main job on the embedded defaults
#   make test  — install what is missing, build, run every test through ctest
# CI (CI=true) builds with warnings as errors.

PRESET := $(if $(filter true,$(CI)),ci,release)
JOBS   ?= $(shell nproc)
BIN    := build/bin

.PHONY: run test build deps bench legibility clean

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

# MediaPipe Holistic on rendered signs (minutes: ~5-10 s per frame); not part of make test.
# LEGIBILITY_ARGS passes options, e.g. LEGIBILITY_ARGS="--size 640x360 --step 3 house".
legibility: build
	@[ tools/legibility/node_modules -nt tools/legibility/package.json ] || \
	  { cd tools/legibility && npm install --no-audit --no-fund --loglevel=error </dev/null && touch node_modules; }
	@node tools/legibility/legibility.mjs --gestura $(BIN)/gestura --out out/legibility $(LEGIBILITY_ARGS)

clean:
	rm -rf build build-debug
