#!/usr/bin/env bash
# The main job: install what is missing, build, run the wear evolution of the built-in default
# scene (the built-in coach on the built-in 100 km route, S1002 on 60E1 1:40, 10^5 km) and plot
# it.
#   results: build/default-run/run.h5, plots: build/default-run/*.png
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# Only the tool: the tests, fuzz replays, benchmarks and studies are the test command's, which
# builds them in the same directory with the same configuration.
scripts/build.sh build --target wheelwear
mkdir -p build/default-run
build/wheelwear run -o build/default-run/run.h5 --overwrite
# Debian's interpreter, which has h5py and matplotlib whatever python3 comes first on PATH.
/usr/bin/python3 scripts/plot_run.py build/default-run/run.h5 --out build/default-run
