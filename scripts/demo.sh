#!/usr/bin/env bash
# The main job of `make run`, on the embedded defaults. Grows as the pipeline grows.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin/gestura
out=out; mkdir -p "$out"
"$bin" --help
