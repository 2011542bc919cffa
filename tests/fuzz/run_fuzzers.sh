#!/usr/bin/env bash
# Builds the libFuzzer targets with clang in build-fuzz/ (FUZZ_BUILD_DIR) and runs each for a
# bounded time, SECONDS_EACH (default 60), from its hand-written seeds (tests/fuzz/seeds/<target>)
# and its corpus (tests/fuzz/corpus/<target>). A crash or timeout is written to
# tests/fuzz/regressions/<target>-<kind>-<hash>, where the regression test (tests/robust) replays
# it with the rest of the corpus.
# Usage: tests/fuzz/run_fuzzers.sh [SECONDS_EACH] [TARGET...]   targets: load_obj load_off
# load_ply load_stl fill (all by default). Needs clang (apt-get install clang). After each run
# the corpus is reduced to a small set of inputs that still reaches every line reached so far.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(load_obj load_off load_ply load_stl fill)
build=${FUZZ_BUILD_DIR:-build-fuzz}

cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DHOLEFILL_FUZZ=ON -DHOLEFILL_BUILD_TESTS=OFF -DHOLEFILL_BUILD_VIEWER=OFF \
  -DHOLEFILL_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --parallel "${JOBS:-$(nproc)}" --target \
  $(printf 'fuzz_%s ' "${targets[@]}")

status=0
for target in "${targets[@]}"; do
  corpus=tests/fuzz/corpus/$target
  fresh=$build/fuzz-fresh/$target
  mkdir -p "$corpus" "$fresh" tests/fuzz/regressions
  echo "fuzz: $target for ${seconds}s"
  "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=4096 -timeout=20 \
    -rss_limit_mb=2048 -dict=tests/fuzz/formats.dict -print_final_stats=1 \
    -artifact_prefix="tests/fuzz/regressions/$target-" "$fresh" "$corpus" \
    "tests/fuzz/seeds/$target" || status=1
  minimal=$build/fuzz-minimal/$target
  rm -rf "$minimal" && mkdir -p "$minimal"
  # Edges only (no hit counts): a few hundred inputs instead of thousands.
  "$build/tests/fuzz/fuzz_$target" -merge=1 -use_counters=0 -max_len=4096 "$minimal" \
    "$corpus" "$fresh" 2>/dev/null
  rm -rf "$corpus" "$fresh" && mv "$minimal" "$corpus"
done
exit $status
