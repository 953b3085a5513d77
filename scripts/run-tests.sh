#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: the optimised build (with MPI, so that
# runs spread over an MPI job are tested too: docs/cluster.md), then a short fuzzing run of the
# input readers under AddressSanitizer and UndefinedBehaviorSanitizer.
# With --sanitizers the whole suite is also built and run under both sanitizers (about 19 more
# minutes on two cores, which would take CI past its budget; run it before a release and after
# changes to memory handling). Each stage prints its elapsed time, and a summary of all of them
# closes the output.
#
# Usage: scripts/run-tests.sh [--sanitizers]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
sanitizers=false
case "${1:-}" in
  --sanitizers) sanitizers=true ;;
  "") ;;
  *)
    echo "run-tests.sh: unknown option '$1'; usage: scripts/run-tests.sh [--sanitizers]" >&2
    exit 2
    ;;
esac

summary=()
# stage NAME COMMAND...: runs COMMAND, prints and records its wall-clock time; a failing stage
# ends the script with its status, after the summary.
stage() {
  local name=$1 start=$SECONDS status=0
  shift
  echo "== stage: $name"
  "$@" || status=$?
  local elapsed=$((SECONDS - start))
  local line
  line=$(printf '%-18s %3dm%02ds' "$name" $((elapsed / 60)) $((elapsed % 60)))
  ((status == 0)) || line+="  FAILED ($status)"
  summary+=("$line")
  echo "== stage time: $line"
  if ((status != 0)); then
    print_summary
    exit "$status"
  fi
}
print_summary() {
  echo "== stage times (elapsed):"
  printf '   %s\n' "${summary[@]}"
}

release_tests() { ctest --test-dir build --output-on-failure -j "$jobs"; }
sanitizer_tests() {
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j "$jobs"
}

stage "install deps" scripts/install-deps.sh --mpi
stage "release build" scripts/build.sh build -DWHEELWEAR_MPI=ON
stage "release tests" release_tests
if $sanitizers; then
  # -O1 with line tables only: about 40 % less compile time than -O2 -g, and the reports still
  # name file and line. The benchmarks and studies are checked by the optimised build.
  stage "sanitizer build" scripts/build.sh build-asan -DWHEELWEAR_SANITIZE=ON \
    -DWHEELWEAR_BUILD_BENCH=OFF -DWHEELWEAR_BUILD_STUDIES=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  stage "sanitizer tests" sanitizer_tests
fi
# Fuzz the readers of untrusted input briefly (profile formats, the profile loader, the scene
# parser): a clang build with libFuzzer in build-fuzz, each target for FUZZ_SECONDS (default 10)
# with a fixed seed; scripts/fuzz.sh [SECONDS] runs them for longer.
stage "fuzz build+runs" scripts/fuzz.sh "${FUZZ_SECONDS:-10}"
print_summary
