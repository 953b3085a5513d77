#!/usr/bin/env bash
# The creep-table generator's --reuse (generators/creep_table_generator.cpp): a small table
# extended with more a/b, theta and r nodes, reusing earlier tables (one per nu, as a long
# extension is made one nu at a time), reuses exactly the earlier nodes and equals the same
# table solved from scratch bit for bit (the exact solve is deterministic), for both nu, with
# its full-sliding limits per direction node; --add-sliding writes those limits into a table
# without them, the same bits, and refuses a file that is no table, leaving it as it was;
# --into writes a group into a copy of another table, keeping that table's other groups.
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
  for values in Fx_muN Fy_muN Mz_muNc Fx_sliding_muN Fy_sliding_muN Mz_sliding_muNc; do
    h5diff "$dir/reused.h5" "$dir/fresh.h5" "$nu/$values" "$nu/$values"
  done
done
# --into: the nu 0.25 group extended (every node reused) into a copy of the old nu 0.28 table,
# whose group stays as it was: groups with different a/b nodes in one file. An --into file
# that does not exist is refused before anything is written.
"$generator" "${common[@]}" "${new[@]}" --nu 0.25 --reuse "$dir/reused.h5" \
  --into "$dir/old28.h5" --out "$dir/into.h5" > "$dir/log"
grep -qxF "nu_0.25: 1080 of 1080 nodes reused from $dir/reused.h5" "$dir/log"
for values in a_over_b Fx_muN Fy_muN Mz_muNc Fx_sliding_muN Fy_sliding_muN Mz_sliding_muNc; do
  h5diff "$dir/into.h5" "$dir/fresh.h5" "nu_0.25/$values" "nu_0.25/$values"
  h5diff "$dir/into.h5" "$dir/old28.h5" "nu_0.28/$values" "nu_0.28/$values"
done
if "$generator" "${common[@]}" --nu 0.25 --into "$dir/missing.h5" --out "$dir/into.h5" \
  2> "$dir/err"; then
  echo "--into accepted a file that does not exist" >&2
  exit 1
fi
grep -q "missing.h5: no such file" "$dir/err"
h5diff "$dir/into.h5" "$dir/fresh.h5" nu_0.25/Fx_muN nu_0.25/Fx_muN
# --beta: a direction node added to a table from a file of that node alone (as the shipped
# table's nodes at +-75 and +-85 degrees were) equals the table solved with it from scratch.
extra=1.3
refined=$(/usr/bin/python3 -c "import math; print(','.join(repr(b) for b in sorted([-math.pi/2 + math.pi*i/4 for i in range(5)] + [$extra])))")
"$generator" "${common[@]}" "${old[@]}" --nu 0.25 --beta "$extra" --out "$dir/one_beta.h5" > /dev/null
"$generator" "${common[@]}" "${old[@]}" --nu 0.25 --beta "$refined" \
  --reuse "$dir/old25.h5,$dir/one_beta.h5" --out "$dir/refined.h5" > "$dir/log"
grep -qxF "nu_0.25: 300 of 360 nodes reused from $dir/old25.h5" "$dir/log"
grep -qxF "nu_0.25: 60 of 360 nodes reused from $dir/one_beta.h5" "$dir/log"
"$generator" "${common[@]}" "${old[@]}" --nu 0.25 --beta "$refined" --out "$dir/refined_fresh.h5" \
  > /dev/null
for values in beta Fx_muN Fy_muN Mz_muNc Fx_sliding_muN Fy_sliding_muN Mz_sliding_muNc; do
  h5diff "$dir/refined.h5" "$dir/refined_fresh.h5" "nu_0.25/$values" "nu_0.25/$values"
done
# A table without the limits (as the shipped one was solved) gets them from --add-sliding, the
# same bits as the generator writes, its forces untouched. (Debian's python3-h5py removes them.)
cp "$dir/fresh.h5" "$dir/added.h5"
/usr/bin/python3 - "$dir/added.h5" << 'EOF'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    for group in ("nu_0.25", "nu_0.28"):
        for name in ("Fx_sliding_muN", "Fy_sliding_muN", "Mz_sliding_muNc"):
            del f[group][name]
EOF
"$generator" --add-sliding "$dir/added.h5" > "$dir/log"
grep -qxF "full-sliding limits written into every group of $dir/added.h5" "$dir/log"
for nu in nu_0.25 nu_0.28; do
  for values in Fx_muN Fy_muN Mz_muNc Fx_sliding_muN Fy_sliding_muN Mz_sliding_muNc; do
    h5diff "$dir/added.h5" "$dir/fresh.h5" "$nu/$values" "$nu/$values"
  done
done
# A file that is no table, and an HDF5 file without a table's groups: refused, left as they were.
echo "not a table" > "$dir/junk.h5"
/usr/bin/python3 -c "import h5py, sys; h5py.File(sys.argv[1], 'w')['x'] = [1.0]" "$dir/other.h5"
cp "$dir/other.h5" "$dir/other_before.h5"
for bad in junk other; do
  if "$generator" --add-sliding "$dir/$bad.h5" 2> "$dir/err"; then
    echo "--add-sliding accepted $bad.h5, which holds no creep table" >&2
    exit 1
  fi
  grep -q "the file is unchanged" "$dir/err"
  [[ ! -e "$dir/$bad.h5.sliding.partial" ]]
done
[[ "$(cat "$dir/junk.h5")" == "not a table" ]]
cmp "$dir/other.h5" "$dir/other_before.h5"
echo "--reuse: 300 of 1080 nodes per nu reused, each from its file; equal to a fresh table bit for bit;"
echo "--beta: a direction node from a file of its own, equal to the table solved with it"
echo "--into: the extended nu 0.25 group beside the old nu 0.28 one, each as solved"
echo "--add-sliding: the same limits in place; a file that is no table refused and left as it was"
