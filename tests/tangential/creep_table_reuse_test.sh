#!/usr/bin/env bash
# The creep-table generator's --reuse (generators/creep_table_generator.cpp): a small table
# extended with more a/b, theta and r nodes, reusing earlier tables (one per nu, as a long
# extension is made one nu at a time), reuses exactly the earlier nodes and equals the same
# table solved from scratch bit for bit (the exact solve is deterministic), for both nu.
# Usage: creep_table_reuse_test.sh GENERATOR
set -euo pipefail
generator="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
common=(--n 8 --threads 1 --psi 0,0.4 --beta-count 5)
old=(--g 1,2 --theta-count 5 --r 0,1,2)
new=(--g 1,2,3 --theta-count 9 --r 0,1,2,3)
"$generator" "${common[@]}" "${old[@]}" --nu 0.25 --out "$dir/old25.h5" > /dev/null
"$generator" "${common[@]}" "${old[@]}" --nu 0.28 --out "$dir/old28.h5" > /dev/null
"$generator" "${common[@]}" "${new[@]}" --nu 0.25,0.28 --reuse "$dir/old25.h5,$dir/old28.h5" \
  --out "$dir/reused.h5" > "$dir/log"
# 2 a/b x 2 psi x 5 theta x 5 beta x 3 r of the 3 x 2 x 9 x 5 x 4 nodes, per nu, each from
# its own file.
for expected in "nu_0.25: 300 of 1080 nodes reused from $dir/old25.h5" \
  "nu_0.25: 0 of 1080 nodes reused from $dir/old28.h5" \
  "nu_0.28: 0 of 1080 nodes reused from $dir/old25.h5" \
  "nu_0.28: 300 of 1080 nodes reused from $dir/old28.h5"; do
  grep -qxF "$expected" "$dir/log" || {
    cat "$dir/log"
    echo "expected the line: $expected" >&2
    exit 1
  }
done
"$generator" "${common[@]}" "${new[@]}" --nu 0.25,0.28 --out "$dir/fresh.h5" > /dev/null
for nu in nu_0.25 nu_0.28; do
  for values in Fx_muN Fy_muN Mz_muNc; do
    h5diff "$dir/reused.h5" "$dir/fresh.h5" "$nu/$values" "$nu/$values"
  done
done
echo "--reuse: 300 of 1080 nodes per nu reused, each from its file; equal to a fresh table bit for bit"
