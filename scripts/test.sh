#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every test with ctest.
# In CI (CI=true), or with HOLEFILL_SANITIZE_PASS=1, the library and the CLI are then built once
# more with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/, or SANITIZE_BUILD_DIR),
# with the tests (themselves not instrumented) that drive them, and the suite runs again there;
# any report fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each phase's start time, so a slow run shows where its time went.
phase() { echo "test: $(date -u +%T) $*"; }
phase "install and build"
scripts/setup.sh
phase "run the suite"
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure --parallel "$(nproc)")

if [ "${CI:-}" = true ] || [ "${HOLEFILL_SANITIZE_PASS:-0}" = 1 ]; then
  SANITIZE_DIR=${SANITIZE_BUILD_DIR:-build-asan}
  phase "sanitizer build in $SANITIZE_DIR"
  # Not -Werror here: GCC's -Wmaybe-uninitialized misfires inside OpenMesh's headers under ASan.
  # -O1 -g1 halves the compile time of -O2 -g and keeps line numbers in the reports.
  # Unity batches of 16 files: the instrumented inline code of OpenMesh, CLI11 and the standard
  # library is compiled once a batch instead of once a file (the library: 442 -> 313 s of CPU).
  # So names private to a file (anonymous namespaces, static) must differ across the files of a
  # target, as they must in any unity build.
  cmake -S . -B "$SANITIZE_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DHOLEFILL_SANITIZE=ON \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
    -DHOLEFILL_BUILD_VIEWER=OFF -DHOLEFILL_BUILD_BENCH=OFF >/dev/null
  cmake --build "$SANITIZE_DIR" --parallel "$(nproc)"
  phase "run the suite under the sanitizers"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$SANITIZE_DIR" --output-on-failure --parallel "$(nproc)"
fi
phase done
