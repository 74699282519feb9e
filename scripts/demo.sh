#!/usr/bin/env bash
# The main job of `make run`, on the embedded defaults. Grows as the pipeline grows.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin/gestura
out=out; mkdir -p "$out"
sentence="Hello! My name is Anna. How are you?"
echo "== gestura say \"$sentence\""
"$bin" say "$sentence" -o "$out/hello.mp4" --size 640x480
"$bin" say "$sentence" -o "$out/hello.png" --size 960x720 >/dev/null
echo "video:         $(realpath "$out/hello.mp4")"
echo "contact sheet: $(realpath "$out/hello.png")"
