#!/usr/bin/env bash
# The main job of `make run`, on the embedded defaults (procedural avatar, built-in ASL lexicon):
# sign an English sentence to a video and a contact sheet, and say where they are.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin/gestura
out=out
mkdir -p "$out"
sentence="Hello! My name is Anna. How are you?"
echo "== gestura say \"$sentence\""
"$bin" say "$sentence" -o "$out/hello.mp4" --size 1280x720
"$bin" say "$sentence" -o "$out/hello.png" --size 1280x720 >/dev/null
echo
echo "gestura signed \"$sentence\" in ASL:"
echo "  video:         $(realpath "$out/hello.mp4")"
echo "  contact sheet: $(realpath "$out/hello.png")"
