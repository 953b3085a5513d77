#!/usr/bin/env python3
"""Per-call overhead of the Python module's creep() against the same C++ loop.

A creep curve of 1000 points (FASTSIM-SDEC, 50 x 50 cells, a = 6 mm, b = 3 mm, psi = 0.4,
N = 50 kN, mu = 0.3, spin 0 ... 2 1/m) on one thread: wheelwear.creep(threads=1) timed 20 times
against build/bench/wheelwear_creep_loop_bench (its plain solve_patch loop and the front ends'
CreepSolver loop, 20 repetitions each); medians, and a scalar call's overhead against
one solve. Writes bench/results/python_overhead.csv and prints it.

    PYTHONPATH=build/python python3 bench/python_overhead.py [BUILD_DIR]
"""

import csv
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import wheelwear

REPEATS = 20


def median_seconds(call) -> float:
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def cpp_medians(build: Path) -> dict:
    program = build / "bench" / "wheelwear_creep_loop_bench"
    done = subprocess.run(
        [str(program), f"--benchmark_repetitions={REPEATS}", "--benchmark_format=json",
         "--benchmark_report_aggregates_only=true"],
        check=True, capture_output=True, text=True)
    out = {}
    for b in json.loads(done.stdout)["benchmarks"]:
        if b.get("aggregate_name") == "median":
            scale = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[b["time_unit"]]
            out[b["run_name"]] = b["real_time"] * scale
    return out


def main() -> None:
    build = Path(sys.argv[1] if len(sys.argv) > 1 else "build")
    phi = np.linspace(0.0, 2.0, 1000)
    patch = dict(a=6e-3, b=3e-3, psi=0.4, N=50e3, mu=0.3)
    wheelwear.creep(phi=phi, threads=1, **patch)  # load and warm up
    python_curve = median_seconds(lambda: wheelwear.creep(phi=phi, threads=1, **patch))
    python_scalar = median_seconds(lambda: wheelwear.creep(phi=1.0, threads=1, **patch))
    cpp = cpp_medians(build)
    plain, front = cpp["BM_CreepCurveSolvePatch"], cpp["BM_CreepCurveFrontEnd"]
    rows = [
        ("C++ loop, solve_patch (1000 points)", plain, 1.0),
        ("C++ loop, CreepSolver (1000 points)", front, front / plain),
        ("wheelwear.creep, array of 1000", python_curve, python_curve / plain),
        ("wheelwear.creep, one point", python_scalar, python_scalar / (plain / 1000)),
    ]
    results = Path(__file__).resolve().parent / "results" / "python_overhead.csv"
    with open(results, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["call", "median_seconds", "ratio_to_cpp_loop"])
        for name, seconds, ratio in rows:
            w.writerow([name, f"{seconds:.6g}", f"{ratio:.4f}"])
    for name, seconds, ratio in rows:
        print(f"{name:40s} {seconds * 1e3:10.3f} ms  {ratio:7.3f} x")
    print(f"wrote {results}")


if __name__ == "__main__":
    main()
