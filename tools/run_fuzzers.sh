#!/usr/bin/env bash
# Builds the libFuzzer harnesses of tests/fuzz (clang-15, ASan + UBSan) and runs each for a fixed time
# from the committed seed corpus, as many at once as there are cores (STIPPLE_JOBS; each harness is
# one process on one core). Fails on any crash, sanitizer report, leak, hang (-timeout) or allocation
# over the limits (-rss_limit_mb, -malloc_limit_mb); the input that did it is left in
# <build>/fuzz/<harness>/ (turn it into a regression file: tests/fuzz/README.md).
# Usage: tools/run_fuzzers.sh [SECONDS per harness, default 60] [HARNESS...: obj ply stl gltf anim scene]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
source "$(dirname "${BASH_SOURCE[0]}")/sanitizer_env.sh"
cd "$STIPPLE_ROOT"
seconds="${1:-60}"
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(obj ply stl gltf anim scene)
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "run_fuzzers: SECONDS must be a whole number, got '$seconds'" >&2; exit 2; }

third_party_config/install_deps.sh
configure_sanitized_build
cmake --build "$STIPPLE_ASAN_BUILD" -j "$STIPPLE_JOBS" --target "${harnesses[@]/#/fuzz_}"

# Each harness is one process on one core (libFuzzer's default): STIPPLE_JOBS of them run at once, and
# their results are reported in the order given.
fuzz_one() {
  local h=$1 out="$STIPPLE_ASAN_BUILD/fuzz/$1" rc=0
  mkdir -p "$out/corpus"
  # New inputs go to the first folder (the build's); the committed seeds are only read. fuzz_anim reads
  # glTF too and shares its dictionary.
  "$STIPPLE_ASAN_BUILD/tests/fuzz/fuzz_$h" "$out/corpus" "tests/fuzz/corpus/$h" \
    -dict="tests/fuzz/dict/${h/#anim/gltf}.dict" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=16384 -print_final_stats=1 \
    -artifact_prefix="$out/" >"$out/log.txt" 2>&1 || rc=$?
  echo "$rc" >"$out/exit_code"
}

pending=()
for h in "${harnesses[@]}"; do
  rm -f "$STIPPLE_ASAN_BUILD/fuzz/$h/exit_code"
  fuzz_one "$h" &
  pending+=($!)
  if [ ${#pending[@]} -ge "$STIPPLE_JOBS" ]; then wait "${pending[0]}" || true; pending=("${pending[@]:1}"); fi
done
wait || true

failed=()
for h in "${harnesses[@]}"; do
  out="$STIPPLE_ASAN_BUILD/fuzz/$h"
  rc=$(cat "$out/exit_code" 2>/dev/null || echo "?")
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out/log.txt" | grep -o '[0-9]*$' || echo "?")
  if [ "$rc" = 0 ]; then
    echo "fuzz_$h: ${seconds} s, $runs executions, no finding"
  else
    echo "fuzz_$h: FAILED (exit $rc) after $runs executions; log $out/log.txt, input:" >&2
    ls "$out" | grep -E '^(crash|leak|timeout|oom|slow-unit)-' | sed "s|^|  $out/|" >&2 || true
    grep -E 'ERROR|SUMMARY|contract broken|==[0-9]+==' "$out/log.txt" | head -20 >&2 || true
    failed+=("$h")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "run_fuzzers: findings in ${failed[*]}" >&2
  exit 1
fi
echo "run_fuzzers: ${#harnesses[@]} harnesses, no finding"
