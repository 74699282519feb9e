#!/usr/bin/env bash
# Runs gestura's libFuzzer targets (fuzz/, one per reader) for SECONDS each, under ASan + UBSan.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]      (make fuzz FUZZ_SECONDS=600)
#
# SECONDS defaults to $FUZZ_SECONDS, else 60; TARGETs default to all. FUZZ_JOBS=N runs N targets at
# a time (default 1). Builds the asan preset (build-asan/), makes the seed corpora from the shared
# test data and gestura's own outputs (build-asan/fuzz/seeds/), and keeps what each run finds in
# build-asan/fuzz/corpus/TARGET/ (inputs that reach new code) and build-asan/fuzz/findings/TARGET/
# (crashes, leaks, inputs over 1 s or 256 MB). Prints one line per target with its executions and
# exits 1 when any target found something; its log is build-asan/fuzz/logs/TARGET.log.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-${FUZZ_SECONDS:-60}}"
[ $# -gt 0 ] && shift
jobs="${FUZZ_JOBS:-1}"
build="$root/build-asan"
work="$build/fuzz"
shared="${GESTURA_SHARED_DATA:-$root/../shared/data}"

cmake --preset asan >/dev/null
cmake --build --preset asan --target fuzz -j "$(nproc)"

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then IFS=";" read -ra targets < "$build/fuzz-targets.txt" || true; fi

# Seeds are remade whenever the seed program changed.
if [ ! -f "$work/seeds/.made" ] || [ "$build/bin/gestura-fuzz-seeds" -nt "$work/seeds/.made" ]; then
  rm -rf "$work/seeds"
  "$build/bin/gestura-fuzz-seeds" "$shared" "$root" "$work/seeds" >/dev/null
  touch "$work/seeds/.made"
fi

# A small quarantine keeps ASan's own memory well under the 256 MB a single input may use.
export ASAN_OPTIONS="quarantine_size_mb=16:malloc_context_size=20:detect_leaks=1:handle_abort=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
mkdir -p "$work/logs"

run_target() {
  local target="$1"
  local dict=()
  [ -f "$work/seeds/$target.dict" ] && dict=("-dict=$work/seeds/$target.dict")
  mkdir -p "$work/corpus/$target" "$work/findings/$target"
  local status=0
  "$build/bin/fuzz_$target" -max_total_time="$seconds" -timeout=1 -rss_limit_mb=256 -malloc_limit_mb=256 \
    -print_final_stats=1 "${dict[@]}" -artifact_prefix="$work/findings/$target/" \
    "$work/corpus/$target" "$work/seeds/$target" >"$work/logs/$target.log" 2>&1 || status=$?
  local execs rate corpus
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/logs/$target.log" | tail -1)"
  rate="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/logs/$target.log" | tail -1)"
  corpus="$(find "$work/corpus/$target" -type f | wc -l)"
  printf '%-18s %6ss %12s execs %8s/s  corpus %6s  %s\n' "$target" "$seconds" "${execs:-?}" "${rate:-?}" "$corpus" \
    "$([ $status -eq 0 ] && echo ok || echo "FOUND (exit $status): see $work/logs/$target.log")"
  return $status
}

failed=0
running=0
for target in "${targets[@]}"; do
  if [ ! -x "$build/bin/fuzz_$target" ]; then echo "no fuzz target '$target'" >&2; exit 2; fi
  run_target "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || failed=1
    running=$((running - 1))
  fi
done
while [ "$running" -gt 0 ]; do
  wait -n || failed=1
  running=$((running - 1))
done
exit $failed
