#!/usr/bin/env python3
"""scripts/plot_run.py on real runs: a short run of one shared profile and one of left and
right wheels, each plotted whole. Fails when the script raises or leaves out a figure, and
checks the worn area it draws against the one the program computes (the run's JSON summary),
within the 1 % a trapezoid sum over its 0.1 mm grid of the normal depth allows."""

import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

SCENE = """
[contact]
grid_nx = 12
grid_ny = 12
[run]
distance_m = 20e3
step_distance_m = 5e3
max_depth_step_m = 1e-3
wheels = "{wheels}"
[[load_collective.state]]
dy_m = 0.003
yaw_rad = 0.002
axle_load_N = 110e3
speed_m_s = 30
curve_radius_m = 800
[[load_collective.state]]
dy_m = -0.002
axle_load_N = 110e3
speed_m_s = 40
"""


def run_and_plot(exe, folder, wheels):
    scene = os.path.join(folder, f"{wheels}.toml")
    with open(scene, "w") as f:
        f.write(SCENE.format(wheels=wheels))
    out = os.path.join(folder, f"{wheels}.h5")
    run = subprocess.run([exe, "run", scene, "-o", out, "-q", "--json"], capture_output=True,
                         text=True, check=True)
    summary = json.loads(run.stdout)
    plots = os.path.join(folder, f"{wheels}_plots")
    os.mkdir(plots)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "plot_run.py"), out,
                    "--out", plots], check=True, capture_output=True, text=True)
    names = ["profile_evolution.png", "wear_depth_per_step.png", "parameters.png",
             "contact_positions.png"]
    if wheels == "separate":  # both wheels, each its own evolution
        names.append("profile_evolution_wheel_right.png")
    for name in names:
        path = os.path.join(plots, name)
        assert os.path.getsize(path) > 10000, f"{wheels}: {name} missing or empty"
    return out, summary


def drawn_worn_area(path):
    """The worn area plot_run.py draws at the last step, recomputed the same way [mm^2]: the
    recorded depth since new integrated along the new profile."""
    with h5py.File(path) as f:
        worn = f["final"]["wheel"]["cumulative_wear"]
        return np.trapz(np.nan_to_num(np.asarray(worn["depth"])), np.asarray(worn["s"])) * 1e6


def main():
    exe = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        shared, summary = run_and_plot(exe, folder, "shared")
        run_and_plot(exe, folder, "separate")
        area = drawn_worn_area(shared)
        reference = summary["worn_area"] * 1e6
        assert abs(area - reference) <= 0.01 * reference, (area, reference)
        # A file of an earlier layout is refused with a message, not a traceback.
        with h5py.File(shared, "r+") as f:
            f.attrs["format_version"] = 5
        old = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "plot_run.py"),
                              shared, "--out", folder], capture_output=True, text=True)
        assert old.returncode != 0 and "layout version 5" in old.stderr, old.stderr
    print("plot_run: both runs plotted; worn area %.4g mm2 drawn, %.4g mm2 computed"
          % (area, reference))


if __name__ == "__main__":
    main()
