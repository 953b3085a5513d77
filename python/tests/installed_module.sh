#!/usr/bin/env bash
# The installed module: `cmake --install` into a scratch prefix puts it where Debian's python3
# looks (PREFIX/lib/python3/dist-packages/wheelwear), and it finds its data (the book of creep
# tables) in PREFIX/share/wheelwear with no environment set, away from the source tree.
# Usage: installed_module.sh BUILD_DIR PYTHON
set -euo pipefail
build=$1 python=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
cd "$prefix"
env -u WHEELWEAR_DATA_DIR PYTHONPATH="$prefix/lib/python3/dist-packages" "$python" -c "
import os, wheelwear
assert wheelwear.__file__.startswith('$prefix/lib/python3/dist-packages/wheelwear/'), wheelwear.__file__
r = wheelwear.creep('table', a=6e-3, b=3e-3, phi=1.0, N=5e4)
assert os.environ['WHEELWEAR_DATA_DIR'] == '$prefix/share/wheelwear', os.environ['WHEELWEAR_DATA_DIR']
assert r.Fy < 0  # the table's answer: the lateral force opposes the spin
print('installed module: ok,', wheelwear.__file__, 'Fy', r.Fy)
"
