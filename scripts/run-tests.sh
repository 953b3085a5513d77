#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: the optimised build, then the same
# suite built with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc)

scripts/build.sh build
ctest --test-dir build --output-on-failure -j "$jobs"

scripts/build.sh build-asan -DWHEELWEAR_SANITIZE=ON -DWHEELWEAR_BUILD_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs"

# Fuzz the readers of untrusted input briefly (profile formats, the profile loader, the scene
# parser): a clang build with libFuzzer in build-fuzz, each target for FUZZ_SECONDS (default 10)
# with a fixed seed; scripts/fuzz.sh [SECONDS] runs them for longer.
scripts/fuzz.sh "${FUZZ_SECONDS:-10}"
