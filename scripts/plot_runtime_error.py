#!/usr/bin/env python3
"""Pareto plot of run time against error from the study's CSV.

Usage: plot_runtime_error.py CSV PNG

CSV is bench/results/runtime_error.csv written by wheelwear_runtime_error_study (its columns are
documented at the head of studies/runtime_error_study.cpp). The figure has two log-log panels,
time per call against the error on the pure-spin cases (largest |F - F_ref|/(mu N) over the
cases and over Fx, Fy): left against Kalker's exact theory (CONTACT-SDEC, 80 x 80), right
against the method's own converged answer. One line per method, one marker per grid, labelled
with n (n x n cells) at both ends; the grid-free methods are single points (left panel only:
they have no discretisation error). Kalker's exact theory solved by the library (exact) is a
black dash-dotted line through its grids with square markers; the book of exact-theory tables
(table) is a single diamond, its label saying how many cases it covers when it skipped some.
In the left panel a dotted line with hollow markers adds the error in Fx alone for the methods
where it is clearly smaller than the larger of the two (FASTSIM-SDEC and EQ.L, whose largest
error is in Fy at high spin).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The methods in the order of the legend, with their label.
METHODS = [
    ("linear-sdec", "none", "linear SDEC (Eq. 11-12)"),
    ("she-sdec", "none", "SDEC + Shen-Hedrick-Elkins"),
    ("fastsim-elliptic", "kalker", "FASTSIM elliptic (= EQ.E at O here)"),
    ("fastsim-eqe", "kalker", "FASTSIM-EQ.E (at O)"),
    ("fastsim-eqe-shifted", "kalker", "FASTSIM-EQ.E (at O')"),
    ("fastsim-eql", "kalker", "FASTSIM-EQ.L"),
    ("fastsim-sdec", "kalker", "FASTSIM-SDEC"),
    ("fastsim-sdec", "second-order", "FASTSIM-SDEC, second order"),
    ("exact", "none", "exact theory (library, n x n; 80 x 80 is CONTACT's grid)"),
    ("table", "none", "book of tables (exact theory)"),
]

# Line style, marker and colour of the methods set apart from the FASTSIM family.
STYLES = {
    "exact": ("-.", "s", "black"),
    "table": ("none", "D", "tab:olive"),
}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["case_set"] == "pure_spin"]
    if not rows:
        sys.exit(f"{sys.argv[1]}: no pure_spin rows")

    fig, axes = plt.subplots(1, 2, figsize=(12, 5.2), sharey=True)
    colours = plt.get_cmap("tab10")
    for k, (method, scheme, label) in enumerate(METHODS):
        sel = sorted((r for r in rows if r["method"] == method and r["scheme"] == scheme),
                     key=lambda r: int(r["n"]))
        if not sel:
            continue
        t = [float(r["time_per_call_s"]) for r in sel]
        calls = int(sel[0]["calls"])
        skipped = int(sel[0].get("skipped") or 0)  # absent in files written before the column
        if skipped:
            label = f"{label} ({calls} of {calls + skipped} cases)"
        for ax, column in zip(axes, ("err_contact", "err_converged")):
            e = [float(r[column]) for r in sel]
            pts = [(ei, ti) for ei, ti in zip(e, t) if ei > 0]
            if not pts:
                continue
            style = "-" if scheme != "second-order" else "--"
            marker = "o" if len(pts) > 1 else "*"
            colour = colours(k)
            size = 4 if len(pts) > 1 else 12
            if method in STYLES:
                style, marker, colour = STYLES[method]
                size = 5 if len(pts) > 1 else 9
            ax.plot([p[0] for p in pts], [p[1] for p in pts], linestyle=style, marker=marker,
                    markersize=size, color=colour, label=label)
            # Left panel: where Fx alone is clearly closer to exact theory than the larger of
            # the two components (which Fy at high spin dominates), show it dotted.
            if column == "err_contact":
                ex = [float(r["err_contact_fx"]) for r in sel]
                if all(x < 0.8 * y for x, y in zip(ex, e)):
                    ax.plot(ex, t, ":", marker="o", markersize=3, markerfacecolor="none",
                            color=colour, alpha=0.8)
            if len(sel) > 1:
                for r, ei, ti in ((sel[0], e[0], t[0]), (sel[-1], e[-1], t[-1])):
                    if ei > 0:
                        ax.annotate(r["n"], (ei, ti), textcoords="offset points", xytext=(4, 2),
                                    fontsize=7, color=colour)
    axes[0].set_title("against Kalker's exact theory (CONTACT-SDEC)\n"
                      "dotted, hollow: Fx alone where it is clearly smaller", fontsize=10)
    axes[1].set_title("against the method's own converged answer\n"
                      "(FASTSIM: Richardson extrapolation of 800 x 800 and 1600 x 1600;\n"
                      "exact: its own 120 x 120 solution)", fontsize=10)
    for ax in axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("largest of |Fx - Fx_ref|, |Fy - Fy_ref| over the 17 cases, / (mu N)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("time per call [s] (one thread, CPU time)")
    # Centre left: the one region free of points (the exact theory's fine grids lie on top).
    axes[0].legend(fontsize=8, loc="center left")
    fig.suptitle("Run time against error, pure spin (g = 1, psi = -0.8 ... 0.8, "
                 "phi = 0.2 ... 1.6 1/m); FASTSIM grids 5 x 5 ... 200 x 200, "
                 "exact 10 x 10 ... 80 x 80", fontsize=10)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=130)


if __name__ == "__main__":
    main()
