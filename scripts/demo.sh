#!/usr/bin/env bash
# The main job of `make run`, on the embedded defaults (procedural avatar, built-in lexicon):
# sign ASL MOTHER from HamNoSys to a video and a contact sheet, and say where they are.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin/gestura
out=out
mkdir -p "$out"
mother="hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart"
"$bin" sign --names "$mother" -o "$out/mother.mp4" --camera front,side --size 1280x720
"$bin" sign --names "$mother" -o "$out/mother-sheet.png" --sheet --size 1280x720
echo
echo "gestura: the avatar signed ASL MOTHER:"
echo "  video:         $out/mother.mp4"
echo "  contact sheet: $out/mother-sheet.png"
