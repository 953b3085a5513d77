#!/usr/bin/env python3
"""Side-by-side comparison of wheelwear runs: Sd, Sh, qR, equivalent conicity and worn area
against distance, and their changes per 10^5 km.

    scripts/compare_runs.py RUN.h5 [RUN.h5 ...] [--labels A,B] [--png FILE] [--csv FILE]

Prints a table; with --png draws the four quantities against distance, with --csv writes the
table. Needs h5py and matplotlib (Debian: python3-h5py, python3-matplotlib).
"""

import argparse
import csv
import sys

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as error:  # pragma: no cover - depends on the machine
    sys.exit(f"compare_runs.py: {error}; install python3-h5py and python3-matplotlib")

PER = 1e8  # 10^5 km in m


def worn_area(profile, y0, z0):
    """Worn cross-section since new [m^2]: the recorded depth along the new profile's normal
    integrated along it (results version 6); for older files the vertical gap between the new
    and the worn profile, which overstates the flange's share (steep there)."""
    if "cumulative_wear" in profile:
        worn = profile["cumulative_wear"]
        return float(np.trapz(np.nan_to_num(np.asarray(worn["depth"])), np.asarray(worn["s"])))
    z1_on_0 = np.interp(y0, np.asarray(profile["y"]), np.asarray(profile["z"]))
    return float(np.trapz(np.clip(z0 - z1_on_0, 0.0, None), y0))


def history(path):
    with h5py.File(path, "r") as f:
        groups = [f["steps"][name] for name in sorted(f["steps"].keys())]
        # The shared profile, else the left wheel's, else the leading wheelset's left wheel's.
        name = next(n for n in ("wheel", "wheel_left", "wheelsets/1/wheel_left") if n in groups[0])
        y0 = np.asarray(groups[0][name]["y"])
        z0 = np.asarray(groups[0][name]["z"])
        rows = []
        for g in groups:
            rows.append({
                "distance_km": g["distance"][()] / 1e3,
                "Sd_mm": g[name]["Sd"][()] * 1e3,
                "Sh_mm": g[name]["Sh"][()] * 1e3,
                "qR_mm": g[name]["qR"][()] * 1e3,
                "conicity": g["equivalent_conicity"][()],
                "worn_area_mm2": worn_area(g[name], y0, z0) * 1e6,
            })
        return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", help="results files of `wheelwear run`")
    parser.add_argument("--labels", help="comma-separated names of the runs")
    parser.add_argument("--png", help="plot file to write")
    parser.add_argument("--csv", help="table file to write")
    args = parser.parse_args()
    labels = args.labels.split(",") if args.labels else args.runs
    if len(labels) != len(args.runs):
        sys.exit("compare_runs.py: give one label per run")
    runs = {label: history(path) for label, path in zip(labels, args.runs)}
    keys = ("Sd_mm", "Sh_mm", "qR_mm", "conicity", "worn_area_mm2")
    table = []
    for label, rows in runs.items():
        first, last = rows[0], rows[-1]
        span = (last["distance_km"] - first["distance_km"]) * 1e3
        row = {"run": label, "distance_km": last["distance_km"]}
        for k in keys:
            row[k + "_start"] = first[k]
            row[k + "_end"] = last[k]
            row[k + "_per_1e5_km"] = (last[k] - first[k]) * PER / span if span > 0 else float("nan")
        table.append(row)
    for row in table:
        print(f"{row['run']}: {row['distance_km']:.0f} km")
        for k in keys:
            print(f"  {k:14s} {row[k + '_start']:9.4f} -> {row[k + '_end']:9.4f}"
                  f"   per 10^5 km {row[k + '_per_1e5_km']:+9.4f}")
    if args.csv:
        with open(args.csv, "w", newline="") as out:
            writer = csv.DictWriter(out, fieldnames=list(table[0].keys()))
            writer.writeheader()
            writer.writerows(table)
    if args.png:
        fig, axes = plt.subplots(2, 2, figsize=(10, 7))
        panels = (("Sd_mm", "flange thickness Sd [mm]"), ("qR_mm", "flange slope qR [mm]"),
                  ("conicity", "equivalent conicity (3 mm)"),
                  ("worn_area_mm2", "worn area [mm²]"))
        for ax, (key, title) in zip(axes.ravel(), panels):
            for label, rows in runs.items():
                ax.plot([r["distance_km"] for r in rows], [r[key] for r in rows], marker="o",
                        ms=3, label=label)
            ax.set_title(title)
            ax.set_xlabel("distance [km]")
            ax.grid(alpha=0.3)
        axes[0, 0].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.png, dpi=120)
        print(args.png)


if __name__ == "__main__":
    main()
