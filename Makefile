# Two commands do everything on a fresh Debian 12 machine:
#   make run   — install what is missing, build (release), run the main job on the embedded defaults
#   make test  — install what is missing, build, run every test through ctest
# CI (CI=true) builds with warnings as errors.

PRESET := $(if $(filter true,$(CI)),ci,release)
JOBS   ?= $(shell nproc)
BIN    := build/bin

.PHONY: run test build build-cli deps bench bench-anchors legibility clean

deps:
	@scripts/setup-deps.sh

build: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS)

# The main job needs only the command-line tool, not every test and benchmark.
build-cli: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS) --target gestura_cli

run: build-cli
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

# gestura against local checkouts of ozz-animation and ACL (docs/benchmarks.md, "Anchors"):
#   make bench-anchors OZZ=path/to/ozz-animation ACL=path/to/acl [RTM=path/to/rtm] [ARGS="--rounds 21"]
# Its own build directory; not part of `make test`.
bench-anchors: deps
	@if [ -z "$(OZZ)" ] || [ -z "$(ACL)" ]; then \
	  echo "usage: make bench-anchors OZZ=path/to/ozz-animation ACL=path/to/acl [RTM=path/to/rtm] [ARGS=...]"; exit 2; fi
	@cmake -S . -B build-anchors -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O3 -DNDEBUG" \
	  -DBUILD_TESTING=OFF -DGESTURA_OZZ_DIR="$(abspath $(OZZ))" -DGESTURA_ACL_DIR="$(abspath $(ACL))" \
	  $(if $(RTM),-DGESTURA_RTM_DIR="$(abspath $(RTM))") >/dev/null
	@cmake --build build-anchors -j $(JOBS) --target gestura-anchors
	@build-anchors/bin/gestura-anchors $(ARGS)

clean:
	rm -rf build build-debug build-anchors
