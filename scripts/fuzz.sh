#!/usr/bin/env bash
# Fuzzes the readers of untrusted input (tests/fuzz): configures a clang build with libFuzzer,
# AddressSanitizer and UBSan in build-fuzz, builds every fuzz target, replays the regression
# inputs of tests/fuzz/regressions/, then runs each target for SECONDS (default 20) from the
# seed files of tests/data with a fixed seed.
#
# Usage: scripts/fuzz.sh [SECONDS]
#
# Exits non-zero on a crash. The input that crashed is left in build-fuzz/artifacts/<target>/;
# once the reader is fixed, copy it into tests/fuzz/regressions/<target>/ so that the test
# fuzz_replay_<target> (every build with tests) and this script replay it from then on.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
build=build-fuzz
jobs=$(nproc)

# clang with its libFuzzer runtime (Debian: clang, libclang-rt-14-dev).
if ! command -v clang++ >/dev/null ||
  ! compgen -G "$(clang++ --print-runtime-dir)/libclang_rt.fuzzer*.a" >/dev/null; then
  echo "fuzz.sh: needs clang++ and libFuzzer; on Debian: apt-get install clang libclang-rt-14-dev" >&2
  exit 1
fi

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DWHEELWEAR_FUZZ=ON -DWHEELWEAR_BUILD_TESTS=OFF -DWHEELWEAR_BUILD_BENCH=OFF >/dev/null

# The targets this tree has (the scene parser's only once it exists).
targets=()
known=$(cmake --build "$build" --target help)
for source in tests/fuzz/*_fuzzer.cpp; do
  name=$(basename "$source" _fuzzer.cpp)
  if grep -q -- "fuzz_${name}\$" <<<"$known"; then
    targets+=("$name")
  fi
done
cmake --build "$build" -j "$jobs" --target "${targets[@]/#/fuzz_}"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
for name in "${targets[@]}"; do
  exe="$build/tests/fuzz/fuzz_$name"
  seeds="$build/corpus/$name/seeds"
  work="$build/corpus/$name/work"
  artifacts="$build/artifacts/$name"
  rm -rf "$build/corpus/$name"
  mkdir -p "$seeds" "$work" "$artifacts"
  if [[ $name == scene ]]; then
    find tests/data data -name '*.toml' -exec cp {} "$seeds/" \;
  else
    cp tests/data/contact/profiles/*.pr? tests/data/measured/*.whl tests/data/measured/*.BAN \
      tests/data/profiles/*.csv "$seeds/"
  fi
  if compgen -G "tests/fuzz/regressions/$name/*" >/dev/null; then
    echo "== fuzz_$name: replaying tests/fuzz/regressions/$name"
    "$exe" tests/fuzz/regressions/"$name"/* 2>&1 | tail -n 1 || { status=1; continue; }
  fi
  echo "== fuzz_$name: ${seconds} s"
  # New inputs go to the first directory (in the build tree); the seeds are only read.
  if ! "$exe" -seed=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=32768 -print_final_stats=1 -artifact_prefix="$artifacts/" \
      "$work" "$seeds" >"$build/fuzz_$name.log" 2>&1; then
    status=1
    echo "fuzz_$name: CRASH, input in $artifacts/ (log: $build/fuzz_$name.log)"
    grep -m 20 -E "ERROR|SUMMARY|runtime error|terminate|what\(\)" "$build/fuzz_$name.log" || true
  else
    grep -E "stat::number_of_executed_units|cov: .*corp" "$build/fuzz_$name.log" | tail -n 2
  fi
done
exit "$status"
