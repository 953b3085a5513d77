#!/usr/bin/env bash
# Strong scaling of a run and weak scaling of a sweep over the processes of an MPI job, on this
# machine; writes bench/results/mpi_scaling.csv (docs/cluster.md shows it).
# Needs a build with -DWHEELWEAR_MPI=ON (scripts/run-tests.sh makes one).
#
#   run, strong:   one scene, 1 process of 1 and of all threads, then 2 and 4 processes of one
#                  thread each (more processes than cores: oversubscribed, labelled so)
#   sweep, weak:   2 runs per process, every process one thread
#
# Usage: bench/mpi_scaling.sh [BUILD_DIR]   (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
wheelwear=$PWD/$build/wheelwear
out=bench/results/mpi_scaling.csv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cores=$(nproc)
mpi=(mpirun --oversubscribe)
((EUID != 0)) || mpi+=(--allow-run-as-root)

# json FILE KEY: a number from the run's --json summary.
json() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

echo "study,scene,processes,threads_per_process,oversubscribed,runs,steps,states_per_step,wall_seconds,waited_seconds,writing_seconds,gathered_mb_per_step" >"$out"

# run_case STUDY SCENE_FILE_OR_EMPTY PROCESSES THREADS
run_case() {
  local study=$1 scene=$2 n=$3 threads=$4 label=$5
  local result=$work/run.h5 summary=$work/run.json
  rm -f "$result"
  local command=("$wheelwear" run $scene -o "$result" -q --json --threads "$threads")
  ((n == 1)) || command=("${mpi[@]}" -np "$n" "${command[@]}")
  local start end
  start=$(date +%s.%N)
  "${command[@]}" >"$summary"
  end=$(date +%s.%N)
  local steps states
  steps=$(json "$summary" steps)
  states=$(python3 -c "import json; d=json.load(open('$summary')); print(round(d['evaluations']/(d['steps']+1)))")
  printf '%s,%s,%d,%d,%s,1,%s,%s,%.2f,%.2f,%.2f,%.2f\n' "$study" "$label" "$n" "$threads" \
    "$( ((n * threads > cores)) && echo yes || echo no)" "$steps" "$states" \
    "$(python3 -c "print($end - $start)")" "$(json "$summary" waited_seconds)" \
    "$(json "$summary" writing_seconds)" \
    "$(python3 -c "import json; d=json.load(open('$summary')); print(d['gathered_bytes']/(d['steps']+1)/1e6)")" \
    >>"$out"
  tail -1 "$out"
}

for scene in data/scenes/frozen_collective.toml data/scenes/vehicle_route.toml \
  bench/scenes/vehicle_1e5km.toml; do
  label=${scene##*/}
  run_case run "$scene" 1 1 "$label"
  run_case run "$scene" 1 "$cores" "$label"
  run_case run "$scene" 2 1 "$label"
  run_case run "$scene" 4 1 "$label"
done

# Weak scaling: a sweep of 2 runs per process (the frozen-collective scene over 20 km, friction
# varied).
"$wheelwear" run --export-default-scene "$work/base" >/dev/null
sed -i 's/^distance_m = [^ ]*/distance_m = 20e3/' "$work/base/frozen_collective.toml"
for n in 1 2 4; do
  runs=$((2 * n))
  values=$(python3 -c "print(', '.join(str(round(0.2 + 0.02 * i, 2)) for i in range($runs)))")
  printf 'scene = "base/frozen_collective.toml"\noutput_dir = "sweep_%d"\n[vary]\n"contact.friction" = [%s]\n' \
    "$n" "$values" >"$work/sweep_$n.toml"
  command=("$wheelwear" sweep "$work/sweep_$n.toml" -q --threads 1)
  ((n == 1)) || command=("${mpi[@]}" -np "$n" "${command[@]}")
  start=$(date +%s.%N)
  "${command[@]}" >/dev/null
  end=$(date +%s.%N)
  printf 'sweep,frozen_collective.toml 20 km,%d,1,%s,%d,,,%.2f,,,\n' "$n" "$( ((n > cores)) && echo yes || echo no)" \
    "$runs" "$(python3 -c "print($end - $start)")" >>"$out"
  tail -1 "$out"
done
echo "wrote $out"
