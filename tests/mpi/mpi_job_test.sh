#!/usr/bin/env bash
# Runs and sweeps spread over the processes of an MPI job against the same on one process.
# Usage: mpi_job_test.sh CASE WHEELWEAR MPIEXEC WORK_DIR
#   identical    a 3-step run over 2 and 3 processes: files identical to one process's
#   resume       a run over 3 processes stopped by SIGTERM (as Slurm stops a job) says how to
#                resume, and resumed over 2 gives the file of an uninterrupted run
#   errors       a bad scene: one message, exit status 2; a process that cannot read the book
#                of tables ends the job with its own message (MPI_Abort), no hang
#   sweep        a sweep over 2 and 3 processes: each run's file and the summary as on one process
#   vehicle      a vehicle run on a short route (its conditions and pieces spread at every
#                solve) over 2 and 3 processes: files identical to one process's
# Files are compared with h5diff, /run_info (times, process count) excluded. The options are
# Open MPI's mpirun (Debian's MPI); its processes are not bound to cores, so that tests running
# at the same time do not pile onto the same ones.
set -euo pipefail
case_name=$1 wheelwear=$2 mpiexec=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
cd "$work"

mpi=("$mpiexec" --oversubscribe --bind-to none)
((EUID != 0)) || mpi+=(--allow-run-as-root)
fail() {  # says why, with what the commands printed
  echo "FAIL: $*" >&2
  for f in *.out *.err; do
    [[ -e $f ]] && { echo "--- $f" >&2; cat "$f" >&2; }
  done
  exit 1
}

# The processes whose parent is $1 (from /proc: no procps needed).
children() {
  local status
  for status in /proc/[0-9]*/status; do
    [[ $(awk '/^PPid:/ {print $2}' "$status" 2>/dev/null) == "$1" ]] && basename "$(dirname "$status")"
  done
  return 0
}

same() {  # same A B: identical results files, and h5diff does tell different ones apart
  h5diff --exclude-path /run_info "$1" "$2" || fail "$2 differs from $1"
  echo "identical: $1 $2"
}

# The frozen-collective scene (1000 states, exported beside the built-in one) over DISTANCE in
# steps of STEP.
scene() {
  "$wheelwear" run --export-default-scene base --overwrite >/dev/null
  sed -e "s/^distance_m = [^ ]*/distance_m = $1/" -e "s/^step_distance_m = [^ ]*/step_distance_m = $2/" \
    base/frozen_collective.toml >"base/$3"
  [[ $(grep -c "^distance_m = $1" "base/$3") == 1 ]] || fail "scene distance not set"
}

case $case_name in
  identical)
    scene 15e3 5e3 short.toml
    "$wheelwear" run base/short.toml -o one.h5 -q >/dev/null
    for n in 2 3; do
      "${mpi[@]}" -np "$n" "$wheelwear" run base/short.toml -o "np$n.h5" -q >"np$n.out" 2>"np$n.err" ||
        fail "-np $n: exit status $?"
      cat "np$n.out"
      grep -q "spread over $n processes" "np$n.out" || fail "-np $n: not spread over $n processes"
      same one.h5 "np$n.h5"
    done
    [[ $(h5ls -r one.h5 | grep -c "steps/00000[0-3] ") == 4 ]] || fail "not a 3-step run"
    # A run that differs (another friction) is told apart: the comparison is not vacuous.
    sed "s/^friction = .*/friction = 0.25/" base/short.toml >base/other.toml
    "$wheelwear" run base/other.toml -o other.h5 -q >/dev/null
    if h5diff -q --exclude-path /run_info one.h5 other.h5; then fail "h5diff sees no difference"; fi
    ;;
  resume)
    scene 60e3 2e3 long.toml
    "${mpi[@]}" -np 3 "$wheelwear" run base/long.toml -o stopped.h5 >/dev/null 2>stopped.err &
    job=$!
    for _ in $(seq 2400); do
      grep -q "step 2 " stopped.err 2>/dev/null && break
      sleep 0.1
    done
    grep -q "step 2 " stopped.err || fail "no step 2 within 4 minutes"
    # SIGTERM to every process of the job, as Slurm ends one (not to the launcher: mpirun then
    # tears the job down and may drop process 0's last output).
    processes=$(children "$job")
    [[ -n $processes ]] || fail "no process of the job to stop"
    kill -TERM $processes
    status=0
    wait "$job" || status=$?
    ((status != 0)) || fail "the stopped job exited with status 0"
    grep -q "stopped by SIGTERM; the steps finished so far are in stopped.h5; continue with: wheelwear run --resume stopped.h5" \
      stopped.err || { cat stopped.err >&2; fail "no resume message"; }
    [[ $(grep -c "stopped by SIGTERM" stopped.err) == 1 ]] || fail "more than one stop message"
    "${mpi[@]}" -np 2 "$wheelwear" run --resume stopped.h5 -q >/dev/null
    "$wheelwear" run base/long.toml -o one.h5 -q >/dev/null
    same one.h5 stopped.h5
    ;;
  errors)
    printf '[run]\ndistance_m = -5\n' >bad.toml
    status=0
    timeout 120 "${mpi[@]}" -np 3 "$wheelwear" run bad.toml -o bad.h5 2>bad.err || status=$?
    ((status == 2)) || fail "bad scene: exit status $status, not 2"
    [[ $(grep -c "^wheelwear: " bad.err) == 1 ]] || { cat bad.err >&2; fail "not one message"; }
    [[ ! -e bad.h5 ]] || fail "a bad scene left a file"
    scene 15e3 5e3 best.toml
    sed -i 's/^tangential_method = "fastsim"/tangential_method = "best"/' base/best.toml
    grep -q '^tangential_method = "best"' base/best.toml || fail "scene method not set"
    status=0
    timeout 120 "${mpi[@]}" -np 1 "$wheelwear" run base/best.toml -o best.h5 -q : \
      -np 1 -x WHEELWEAR_DATA_DIR=/nonexistent "$wheelwear" run base/best.toml -o best.h5 -q \
      2>best.err || status=$?
    ((status != 0 && status != 124)) || fail "a failing process: exit status $status"
    grep -q "wheelwear: error (process 1 of 2): creep table" best.err ||
      { cat best.err >&2; fail "no message from the failing process"; }
    ;;
  sweep)
    scene 10e3 5e3 sweep_base.toml
    printf 'scene = "base/sweep_base.toml"\noutput_dir = "%s"\n[vary]\n"contact.friction" = [0.25, 0.3, 0.4]\n' \
      one >one.toml
    "$wheelwear" sweep one.toml -q >/dev/null
    # The summary without its last column (each run's seconds) and the file names' folder.
    strip() { cut -d, -f1,3- "$1" | rev | cut -d, -f2- | rev; }
    for n in 2 3; do
      sed "s/output_dir = \"one\"/output_dir = \"np$n\"/" one.toml >"np$n.toml"
      "${mpi[@]}" -np "$n" "$wheelwear" sweep "np$n.toml" -q >"np$n.out" 2>"np$n.err" ||
        fail "sweep over $n: exit status $?"
      cat "np$n.out"
      grep -q "3 runs, 0 failed" "np$n.out" || fail "sweep over $n: summary line"
      for run in run_0001.h5 run_0002.h5 run_0003.h5; do same "one/$run" "np$n/$run"; done
      diff <(strip one/summary.csv) <(strip "np$n/summary.csv") || fail "summaries differ ($n)"
      [[ $(wc -l <"np$n/summary.csv") == 4 ]] || fail "summary rows ($n)"
    done
    ;;
  vehicle)
    cat >route.toml <<'ROUTE'
[route]
name = "short"
speed_m_s = 40
[[section]]
kind = "curve"
length_m = 1000
radius_m = 3000
cant_m = 0.03
friction_flange = 0.1
[[section]]
kind = "transition"
length_m = 60
radius_m = 0
cant_m = 0
[[section]]
kind = "tangent"
length_m = 940
ROUTE
    cat >vehicle.toml <<'SCENE'
[contact]
grid_nx = 12
grid_ny = 12
[run]
distance_m = 20e3
step_distance_m = 10e3
max_depth_step_m = 1e-3
[vehicle]
file = "default"
resolve_depth_m = 0
[route]
file = "route.toml"
[time_domain]
tangent_length_m = 40
run_in_m = 10
sample_distance_m = 2
SCENE
    "$wheelwear" run vehicle.toml -o one.h5 -q >/dev/null
    for n in 2 3; do
      "${mpi[@]}" -np "$n" "$wheelwear" run vehicle.toml -o "np$n.h5" -q >"np$n.out" 2>"np$n.err" ||
        fail "-np $n: exit status $?"
      same one.h5 "np$n.h5"
    done
    [[ $(h5ls -r one.h5 | grep -c "vehicle/cases/converged ") == 3 ]] || fail "not a 3-step vehicle run"
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
echo "PASS $case_name"
