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
# LeakSanitizer reads tests/lsan.supp (what it may suppress, and why, is explained there).
SANITIZER_ENV := ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
                 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0

.PHONY: run test build build-cli deps bench start-dependence arm-sweep bench-studio bench-anchors legibility coverage serve load load-rooms test-capture clean fuzz fuzz-smoke test-asan

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

# The libFuzzer targets (fuzz/), each for FUZZ_SECONDS, under ASan + UBSan (clang 14, build-asan/).
fuzz: deps
	@scripts/fuzz.sh $(FUZZ_SECONDS)

# A few seconds per target: that every reader survives its seeds and a little mutation.
fuzz-smoke: deps
	@FUZZ_JOBS=$(JOBS) scripts/fuzz.sh 3

# Every test, built with gcc 12 (the release build's compiler) under ASan + UBSan (no recovery) and
# LeakSanitizer, in build-sanitize/. The default target is what ctest runs (the benchmarks are not in
# it); the libFuzzer targets stay in the clang `asan` preset (make fuzz). docs/reliability.md, section 5.
test-asan: deps
	@cmake --preset sanitize >/dev/null
	@cmake --build --preset sanitize -j $(JOBS)
	@$(SANITIZER_ENV) ctest --preset sanitize -j $(JOBS)

# The benchmarks are not part of the default build (make test does not need them).
bench: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS) --target gestura-bench
	@$(BIN)/gestura-bench $(ARGS)

# Whether where a sign's hands land depends on where they came from (docs/say.md); ~20 s on 2 cores.
start-dependence: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS) --target gestura-start-dependence
	@$(BIN)/gestura-start-dependence data/lexicon/ase.jsonl $(ARGS)

# One line per sign of a lexicon or SiGML file: the arm solver's key misses, depth, elbow height and
# check's verdict, to diff two solvers sign by sign (docs/sign-phonology.md). make arm-sweep ARGS=FILE
arm-sweep: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS) --target gestura-arm-sweep
	@$(BIN)/gestura-arm-sweep $(if $(ARGS),$(ARGS),data/lexicon/ase.jsonl)

# How many content words of everyday English sentences the ASL lexicon signs (docs/asl-lexicon.md).
coverage: build-cli
	@python3 tools/coverage.py --gestura $(BIN)/gestura
	@python3 tools/coverage.py --gestura $(BIN)/gestura --sentences data/eval/heldout-sentences.txt --quiet

# The studio's frame time and edit-to-preview latency at 1280x800 under Xvfb (docs/benchmarks.md, "Studio").
bench-studio: build-cli
	@db=$$(mktemp -d)/bench.sqlite; xvfb-run -a -s '-screen 0 1400x900x24' $(BIN)/gestura studio $$db --size 1280x800 \
	  --script bench/studio/frame-time.script --frame-log $$(dirname $$db)/frames.tsv $(ARGS); rm -rf $$(dirname $$db)

# The web service and page at http://127.0.0.1:$(PORT)/ (Ctrl-C stops it).
PORT ?= 8080
serve: build-cli
	@$(BIN)/gestura serve --port $(PORT) --web web

# A bounded load run of the server on the loopback (docs/benchmarks.md, "Server"); not part of make test.
# LOAD_ARGS="--clients 200 --seconds 60 --threads 2" are the defaults.
load: build-cli
	@node tools/serve-load.mjs --gestura $(BIN)/gestura $(LOAD_ARGS)

# A bounded load run of the shared rooms (docs/benchmarks.md, "Rooms"); not part of make test.
# ROOM_LOAD_ARGS="--clients 40 --seconds 30 --capture 8 --threads 2" are the defaults.
load-rooms: build-cli
	@node --experimental-websocket tools/room-load.mjs --gestura $(BIN)/gestura $(ROOM_LOAD_ARGS)

# Driving a room avatar by camera in headless chromium: gestura's own HELLO as a fake camera, MediaPipe Holistic
# in the page, a second client sees the wrist move (web/tests/capture.test.mjs). MediaPipe runs in software and
# takes 2-4 minutes with every core, so it is not part of make test.
test-capture: build-cli
	@cd web && node tests/capture.test.mjs --gestura $(CURDIR)/$(BIN)/gestura

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
	rm -rf build build-debug build-asan build-anchors
