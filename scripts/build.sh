#!/usr/bin/env bash
# Configures and builds wheelwear for this machine (-march=native; plain CMake builds are
# portable). Usage: scripts/build.sh BUILD_DIR [--target NAME]... [extra cmake arguments]
# Without --target everything is built; extra arguments come last, so they can override
# -DWHEELWEAR_NATIVE=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
targets=()
cmake_args=()
while (($#)); do
  if [[ $1 == --target ]]; then
    targets+=(--target "$2")
    shift 2
  else
    cmake_args+=("$1")
    shift
  fi
done
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DWHEELWEAR_NATIVE=ON "${cmake_args[@]}"
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"
