#!/usr/bin/env python3
"""Regenerates the tables of README.md and docs/*.md from the CSV files of bench/results.

Every number in the documentation that a study measured is written by this script, never by
hand. A generated block sits between two markers in the Markdown source:

    <!-- table:NAME -->
    ... generated text, replaced on every run ...
    <!-- /table:NAME -->

NAME selects the generator below (GENERATORS), which reads bench/results and returns the
block's text. Usage:

    scripts/docs_tables.py           rewrite the blocks in place (after a study wrote new CSVs)
    scripts/docs_tables.py --check   change nothing; exit 1 naming every block whose text
                                     differs from what the CSVs give (the test docs_tables)

Python 3 standard library only.
"""

import argparse
import csv
import difflib
import math
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
# The files that may hold blocks.
DOC_FILES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]

BLOCK = re.compile(r"<!-- table:([a-z0-9-]+) -->\n(.*?)<!-- /table:\1 -->", re.DOTALL)
OPENING = re.compile(r"<!-- table:([a-z0-9-]+) -->")


# ---------------------------------------------------------------------------------------------
# Reading and formatting


def read_csv(name):
    """Rows of bench/results/NAME as dicts of strings."""
    path = RESULTS / name
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def sig(value, digits=2):
    """A plain decimal with `digits` significant digits, trailing zeros kept: 2.96 -> 3.0,
    0.0134 -> 0.013, 11.4 -> 11; numbers of more integer digits are rounded to integers."""
    value = float(value)
    if value == 0.0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    decimals = max(0, digits - 1 - exponent)
    return f"{round(value, decimals):.{decimals}f}"


def sci(value):
    """A small number in exponent form with one digit: 1.978e-07 -> 2e-7."""
    mantissa, exponent = f"{float(value):.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def percent_within(fraction, digits=2):
    """A fraction as a percentage rounded up to `digits` significant digits, for a bound
    ("within 1.7 %" for 1.646 %)."""
    value = float(fraction) * 100.0
    exponent = math.floor(math.log10(abs(value)))
    decimals = max(0, digits - 1 - exponent)
    scale = 10.0 ** decimals
    # The small offset keeps values that are exact at this precision from going up a step.
    return f"{math.ceil(value * scale - 1e-9) / scale:.{decimals}f}"


def percent(fraction, digits=2):
    """A fraction as a percentage with `digits` significant digits, without the sign."""
    return sig(float(fraction) * 100.0, digits)


def duration(seconds):
    """A time per call or per run in the unit that suits it: 0.97 µs, 0.33 ms, 106 ms, 10.2 s."""
    s = float(seconds)
    if s < 1e-4:
        return f"{sig(s * 1e6, 2)} µs"
    if s < 1.0:
        return f"{sig(s * 1e3, 2)} ms"
    return f"{sig(s, 3)} s"


def table(header, rows):
    """A Markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# bench/results/runtime_error.csv (studies/runtime_error_study.cpp)


def runtime_rows():
    return read_csv("runtime_error.csv")


def find(rows, case_set, method, scheme=None, n=None):
    for r in rows:
        if r["case_set"] != case_set or r["method"] != method:
            continue
        if scheme is not None and r["scheme"] != scheme:
            continue
        if n is not None and int(r["n"]) != n:
            continue
        return r
    raise KeyError(f"runtime_error.csv: no row {case_set} {method} {scheme} n={n}")


def grid(row):
    n = int(row["n"])
    return "–" if n == 0 else f"{n} × {n}"


def method_label(row):
    if row["method"] == "fastsim-sdec" and row["scheme"] == "second-order":
        return "`fastsim-sdec` (second order)"
    return f"`{row['method']}`"


# Rows of the pure-spin table: (method, scheme, grids); None: the grid-free methods.
PURE_SPIN_ROWS = [
    ("linear-sdec", None, [0]),
    ("she-sdec", None, [0]),
    ("fastsim-sdec", "kalker", [20, 200]),
    ("fastsim-sdec", "second-order", [20, 200]),
    ("fastsim-eql", "kalker", [20, 200]),
    ("fastsim-eqe-shifted", "kalker", [20, 200]),
    ("fastsim-eqe", "kalker", [20, 200]),
    ("fastsim-elliptic", "kalker", [20, 200]),
    ("exact", None, [10, 20, 30, 40, 60, 80]),
    ("table", None, [0]),
    ("best", None, [0]),
]


def validation_pure_spin():
    rows = runtime_rows()
    out = []
    for method, scheme, grids in PURE_SPIN_ROWS:
        for n in grids:
            r = find(rows, "pure_spin", method, scheme, n)
            own = "–" if method in ("linear-sdec", "she-sdec", "table", "best") else percent(
                r["err_converged"])
            out.append([method_label(r), grid(r), duration(r["time_per_call_s"]),
                        percent(r["err_contact_fx"]), percent(r["err_contact_fy"]), own])
    return table(["method", "grid", "time per call", "Fx vs CONTACT [% of μN]",
                  "Fy vs CONTACT [% of μN]", "vs own converged answer [% of μN]"], out)


LINEAR_ROWS = [
    ("linear-sdec", None, [0]),
    ("she-sdec", None, [0]),
    ("fastsim-sdec", "kalker", [20, 200]),
    ("fastsim-sdec", "second-order", [20, 200]),
    ("fastsim-eql", "kalker", [20, 200]),
    ("fastsim-eqe-shifted", "kalker", [20, 200]),
    ("exact", None, [20, 40, 80]),
    ("table", None, [0]),
    ("best", None, [0]),
]


def validation_linear():
    rows = runtime_rows()
    out = []
    for method, scheme, grids in LINEAR_ROWS:
        for n in grids:
            r = find(rows, "linear", method, scheme, n)
            skipped = int(r["skipped"])
            cases = f"{r['calls']}" + (f" ({skipped} outside)" if skipped else "")
            out.append([method_label(r), grid(r), cases, percent(r["err_contact"])])
    return table(["method", "grid", "calls", "largest |F − F_CONTACT| / |F_CONTACT| [%]"], out)


def readme_accuracy():
    rows = runtime_rows()
    sdec20 = find(rows, "pure_spin", "fastsim-sdec", "kalker", 20)
    sdec200 = find(rows, "pure_spin", "fastsim-sdec", "kalker", 200)
    eql200 = find(rows, "pure_spin", "fastsim-eql", "kalker", 200)
    shifted200 = find(rows, "pure_spin", "fastsim-eqe-shifted", "kalker", 200)
    exact40 = find(rows, "pure_spin", "exact", None, 40)
    exact80 = find(rows, "pure_spin", "exact", None, 80)
    tab = find(rows, "pure_spin", "table", None, 0)
    return (
        f"- FASTSIM-SDEC: Fx within {percent_within(sdec200['err_contact_fx'])} % of μN of "
        f"CONTACT on its 17 pure-spin SDEC cases on a fine grid, within "
        f"{percent_within(sdec20['err_contact_fx'])} % on 20 × 20 cells at "
        f"{duration(sdec20['time_per_call_s'])} per call (FASTSIM-EQ.L "
        f"{percent_within(eql200['err_contact_fx'])} %, the ellipse shifted to O′ "
        f"{percent_within(shifted200['err_contact_fx'])} %); its largest error is in Fy at high "
        f"spin, up to {percent_within(sdec200['err_contact_fy'])} % of μN.\n"
        f"- Kalker's exact theory in wheelwear: within {percent_within(exact40['err_contact'])} % "
        f"of μN on 40 × 40 elements ({duration(exact40['time_per_call_s'])}); on CONTACT's own "
        f"80 × 80 grid it reproduces CONTACT to {sci(exact80['err_contact'])} of μN.\n"
        f"- The book of exact-theory tables: within {percent_within(tab['err_contact'])} % of μN "
        f"in {duration(tab['time_per_call_s'])} per call.\n"
    )


def performance_target_error():
    """The cheapest grid of each FASTSIM-SDEC scheme that meets a discretisation error."""
    rows = [r for r in runtime_rows()
            if r["case_set"] == "pure_spin" and r["method"] == "fastsim-sdec"]
    out = []
    for target in (0.01, 0.005, 0.002, 0.001):
        cells = [f"{sig(target * 100)} %"]
        for scheme in ("kalker", "second-order"):
            fit = sorted((r for r in rows if r["scheme"] == scheme), key=lambda r: int(r["n"]))
            best = next((r for r in fit if float(r["err_converged"]) <= target), None)
            cells.append(f"beyond {grid(fit[-1])}" if best is None else
                         f"{grid(best)}, {duration(best['time_per_call_s'])}")
        out.append(cells)
    return table(["discretisation error [% of μN]", "Kalker's scheme (first order)",
                  "second-order scheme"], out)


def performance_exact_grids():
    rows = runtime_rows()
    out = []
    for n in (10, 20, 30, 40, 60, 80):
        r = find(rows, "pure_spin", "exact", None, n)
        out.append([grid(r), duration(r["time_per_call_s"]), percent(r["err_contact"], 2)])
    return table(["grid", "time per call", "largest error vs CONTACT 80 × 80 [% of μN]"], out)


# ---------------------------------------------------------------------------------------------
# bench/results/grid_error_constants.csv (the error models of --target-error)


def performance_grid_constants():
    out = []
    for r in read_csv("grid_error_constants.csv"):
        out.append([f"`{r['method']}`", r["scheme"], r["bound"], r["order"], r["n_min"],
                    sig(r["C"], 3)])
    return table(["method", "scheme", "bound", "order p", "from n", "C"], out)


# ---------------------------------------------------------------------------------------------
# bench/results/run_study.csv and run_study_savings.csv (studies/run_study.cpp)


def performance_run_study():
    out = []
    for r in read_csv("run_study.csv"):
        out.append([r["threads"], r["states"], r["steps"], r["evaluations"],
                    f"{sig(r['seconds'], 2)} s", f"{float(r['states_steps_per_second']):.0f}",
                    sig(r["speedup"], 3), "yes" if r["identical"] == "1" else "no"])
    return table(["threads", "states", "wear steps", "state evaluations", "wall time",
                  "states × steps per second", "speed-up", "identical results"], out)


def performance_run_savings():
    rows = {(r["case"], r["variant"]): r for r in read_csv("run_study_savings.csv")}
    reuse_on = rows[("geometry_reuse", "on")]
    reuse_off = rows[("geometry_reuse", "off")]
    maps_off = rows[("tgamma_maps", "off")]
    maps_on = rows[("tgamma_maps", "on")]
    ratio = float(maps_on["seconds"]) / float(maps_off["seconds"])
    return table(
        ["what is skipped", "case", "with the saving", "without", "ratio"],
        [
            ["contact geometry of states at the same position and loads solved once",
             reuse_on["note"], duration(reuse_on["seconds"]), duration(reuse_off["seconds"]),
             sig(float(reuse_off["seconds"]) / float(reuse_on["seconds"]), 2)],
            ["T gamma maps written only when `tgamma_maps = true`", maps_off["note"],
             duration(maps_off["seconds"]), duration(maps_on["seconds"]), sig(ratio, 2)],
        ])


# ---------------------------------------------------------------------------------------------
# bench/results/tangential_methods.csv (studies/tangential_study.cpp)


def performance_tangential_methods():
    rows = {r["method"]: r for r in read_csv("tangential_methods.csv")}
    exact = rows["exact"]
    out = []
    for name in ("fastsim", "best", "exact"):
        r = rows[name]
        is_exact = name == "exact"
        ratios = ("1" if is_exact else
                  f"{sig(r['work_ratio_p5'], 3)}, {sig(r['work_ratio_median'], 3)}, "
                  f"{sig(r['work_ratio_p95'], 3)}")
        area = float(r["worn_area_rate"]) / float(exact["worn_area_rate"]) - 1.0
        peak = abs(float(r["peak_s"]) - float(exact["peak_s"])) * 1e3
        centroid = abs(float(r["centroid_s"]) - float(exact["centroid_s"])) * 1e3
        table_patches = int(r["table_patches"])
        patches = r["patches"] + (f" ({table_patches} from the table)" if table_patches else "")
        out.append([
            f"`{name}`", duration(r["seconds"]), patches, ratios,
            "reference" if is_exact else f"{'+' if area >= 0 else '−'}{percent(abs(area))} %",
            "reference" if is_exact else f"{percent(r['l1_vs_exact'])} %",
            "reference" if is_exact else f"{sig(peak, 1)} mm, {sig(centroid, 1)} mm",
        ])
    return table(["`tangential_method`", "time", "patches",
                  "frictional work per patch / exact (5 %, median, 95 %)",
                  "worn area vs exact", "spread vs exact (L1)",
                  "peak, centroid shift vs exact"], out)


# ---------------------------------------------------------------------------------------------
# bench/results/time_domain_study.csv (studies/time_domain_study.cpp)


def vehicle_time_domain_study():
    labels = {"reference": "reference", "sample": "sample distance", "tangent": "tangent stretch",
              "run_in": "run-in", "seed": "seed", "quasi_static": "no time domain"}
    out = []
    for r in read_csv("time_domain_study.csv"):
        variant = r["variant"]
        if variant == "quasi_static":
            choice = "tangents centred, transitions at their midpoint"
        else:
            choice = (f"{sig(r['tangent_length_m'], 3)} m, {sig(r['sample_distance_m'], 2)} m, "
                      f"{sig(r['run_in_m'], 3)} m, seed {r['seed']}")
        reference = variant == "reference"
        out.append([
            labels[variant], choice, r["states"], f"{sig(r['vehicle_s'], 2)} s",
            f"{sig(r['wear_s'], 2)} s", sig(r["worn_area_mm2_per_1e5km"], 4),
            f"{percent(r['piece_share'], 2)} %",
            "–" if reference else f"{percent(r['max_rate_difference'], 2)} %",
            "–" if reference else f"{percent(r['l1_rate_difference'], 2)} %",
        ])
    return table(["varied", "tangent stretch, sample distance, run-in, seed", "states",
                  "vehicle solve", "wear evaluation", "worn area [mm² per 10⁵ km]",
                  "from the pieces", "wear rate vs reference: largest difference / peak",
                  "L1 / area"], out)


# ---------------------------------------------------------------------------------------------

# ---------------------------------------------------------------------------------------------
# bench/results/table_coverage.csv (studies/table_coverage_study.cpp)


def validation_table_coverage():
    names = {"frozen": "frozen-collective scene", "vehicle": "vehicle on the route",
             "flange sweep": "flange sweep"}
    out = []
    for r in read_csv("table_coverage.csv"):
        out.append([
            names.get(r["collective"], r["collective"]), f"{int(r['patches']):,}".replace(",", " "),
            f"{percent(r['share_from_table'], 2)} %", f"{percent(r['share_outside_ab'], 2)} %",
            f"{percent(r['share_outside_creepage'], 2)} %",
            f"{sig(r['ab_p01'], 2)} / {sig(r['ab_p50'], 3)} / {sig(r['ab_p99'], 3)}",
            sig(r["abs_psi_p99"], 2),
        ])
    return table(["collective", "patches", "work from the table", "outside its a/b range",
                  "beyond its creepages, short of full sliding",
                  "a/b, 1st / 50th / 99th percentile of the work", "99th percentile of \\|ψ\\|"],
                 out)


# ---------------------------------------------------------------------------------------------
# bench/results/table_interpolation.csv (studies/table_interpolation_study.cpp)


def validation_table_interpolation():
    out = []
    for r in read_csv("table_interpolation.csv"):
        if int(r["points_drawn"]) == 0:
            continue
        answered, drawn = int(r["points_answered"]), int(r["points_drawn"])
        points = str(answered) if answered == drawn else f"{answered} of {drawn}"
        out.append([
            r["set"].replace("r_max", "r_max (to 40)").replace("-", " … "), points,
            f"{percent(r['worst_F_muN'])} % / {percent(r['mean_F_muN'])} %",
            f"{percent(r['worst_Mz_muNc'])} % / {percent(r['mean_Mz_muNc'])} %",
        ])
    return table(["points", "answered by the table", "F: worst / mean, of μN",
                  "Mz: worst / mean, of μN c"], out)


# ---------------------------------------------------------------------------------------------
# bench/results/slender_patches.csv (studies/slender_patch_study.cpp)


def validation_slender_patches():
    by_g = {}
    for r in read_csv("slender_patches.csv"):
        by_g.setdefault(float(r["a_over_b"]), {}).setdefault(r["grid"], []).append(r)
    out = []
    for g in sorted(by_g):
        grids = by_g[g]
        contact, aspect, fastsim = grids["contact"], grids["aspect"], grids["fastsim"]

        def converged(rows):
            return f"{sum(int(r['converged']) for r in rows)} of {len(rows)}"

        def sweeps(rows):
            values = sorted(int(r["sweeps"]) for r in rows)
            return f"{values[len(values) // 2]} / {values[-1]}"

        def seconds(rows):
            values = sorted(float(r["seconds"]) for r in rows)
            return f"{duration(values[len(values) // 2])} / {duration(values[-1])}"

        def largest(rows):
            return f"{percent(max(float(r['dF_vs_aspect_muN']) for r in rows))} %"

        tabled = grids.get("table", [])
        out.append([
            sig(g, 2), f"{aspect[0]['nx']} × {aspect[0]['ny']}", converged(contact),
            sweeps(contact), converged(aspect), sweeps(aspect), seconds(aspect), largest(contact),
            largest(fastsim), f"{largest(tabled)} ({len(tabled)} of {len(aspect)})" if tabled else "–",
        ])
    return table(["a/b", "aspect grid", "80 × 80: converged", "sweeps (median / max)",
                  "aspect grid: converged", "sweeps (median / max)", "time (median / max)",
                  "80 × 80 vs aspect grid: largest ΔF / μN", "FASTSIM-SDEC 50 × 50 vs aspect grid",
                  "book of tables vs aspect grid (cases it covers)"], out)


# ---------------------------------------------------------------------------------------------
# bench/results/python_overhead.csv (bench/python_overhead.py)


def python_overhead():
    rows = [[r["call"], duration(r["median_seconds"]), sig(r["ratio_to_cpp_loop"], 3)]
            for r in read_csv("python_overhead.csv")]
    # The scalar call's ratio is against one solve of the loop, not the whole loop.
    rows[-1][2] += " × one solve"
    return table(["call (FASTSIM-SDEC 50 × 50, one thread)", "median of 20",
                  "against the C++ loop"], rows)


# ---------------------------------------------------------------------------------------------
# bench/results/mpi_scaling.csv (bench/mpi_scaling.sh)


def cluster_scaling():
    rows = read_csv("mpi_scaling.csv")
    out = []
    reference = {}
    for r in rows:
        key = (r["study"], r["scene"])
        wall = float(r["wall_seconds"])
        if r["study"] == "run":
            if r["processes"] == "1" and r["threads_per_process"] == "1":
                reference[key] = wall
            shape = f"{r['processes']} × {r['threads_per_process']}"
            gain = f"{sig(reference[key] / wall, 2)}×"
            detail = (f"{sig(r['waited_seconds'], 2)} s waited, {sig(r['writing_seconds'], 2)} s "
                      f"writing, {sig(r['gathered_mb_per_step'], 2)} MB per step gathered"
                      if r["processes"] != "1" else
                      f"{sig(r['writing_seconds'], 2)} s writing")
            what = (f"run: {r['scene']} ({r['steps']} wear steps, {r['states_per_step']} states "
                    "each)")
        else:
            if r["processes"] == "1":
                reference[key] = wall
            shape = f"{r['processes']} × 1"
            gain = f"{sig(reference[key] / wall, 2)} (efficiency)"
            detail = f"{r['runs']} runs"
            what = f"sweep: {r['scene']}, 2 runs per process"
        if r["oversubscribed"] == "yes":
            shape += " (oversubscribed)"
        out.append([what, shape, duration(wall), gain, detail])
    return table(["study", "processes × threads", "wall time", "against 1 × 1",
                  "where the time goes (process 0)"], out)


GENERATORS = {
    "cluster-scaling": ("docs/cluster.md", cluster_scaling),
    "python-overhead": ("docs/python.md", python_overhead),
    "vehicle-time-domain-study": ("docs/vehicle.md", vehicle_time_domain_study),
    "readme-accuracy": ("README.md", readme_accuracy),
    "validation-pure-spin": ("docs/validation.md", validation_pure_spin),
    "validation-linear": ("docs/validation.md", validation_linear),
    "validation-slender-patches": ("docs/validation.md", validation_slender_patches),
    "validation-table-coverage": ("docs/validation.md", validation_table_coverage),
    "validation-table-interpolation": ("docs/validation.md", validation_table_interpolation),
    "performance-target-error": ("docs/performance.md", performance_target_error),
    "performance-exact-grids": ("docs/performance.md", performance_exact_grids),
    "performance-grid-constants": ("docs/performance.md", performance_grid_constants),
    "performance-run-study": ("docs/performance.md", performance_run_study),
    "performance-run-savings": ("docs/performance.md", performance_run_savings),
    "performance-tangential-methods": ("docs/performance.md", performance_tangential_methods),
}


def process(path, check, problems):
    """Regenerates the blocks of one file; returns its new text."""
    text = path.read_text(encoding="utf-8")
    rel = path.relative_to(ROOT).as_posix()
    opened = OPENING.findall(text)
    closed = BLOCK.findall(text)
    if len(opened) != len(closed):
        problems.append(f"{rel}: a <!-- table:NAME --> marker without its <!-- /table:NAME -->")

    def replace(match):
        name, old = match.group(1), match.group(2)
        entry = GENERATORS.get(name)
        if entry is None:
            problems.append(f"{rel}: block '{name}' has no generator in scripts/docs_tables.py")
            return match.group(0)
        if entry[0] != rel:
            problems.append(f"{rel}: block '{name}' belongs in {entry[0]}")
            return match.group(0)
        try:
            new = entry[1]()
        except (OSError, KeyError, ValueError) as error:
            problems.append(f"{rel}: block '{name}': cannot read bench/results: {error}")
            return match.group(0)
        if new != old:
            if check:
                diff = "".join(difflib.unified_diff(
                    old.splitlines(True), new.splitlines(True), "documented", "from the CSVs"))
                problems.append(f"{rel}: block '{name}' is stale (differs from bench/results); "
                                f"run scripts/docs_tables.py\n{diff}")
            return f"<!-- table:{name} -->\n{new}<!-- /table:{name} -->"
        return match.group(0)

    return BLOCK.sub(replace, text), [name for name, _ in closed]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="change nothing; exit 1 naming the stale blocks")
    args = parser.parse_args()

    problems = []
    found = {}
    for path in DOC_FILES:
        if not path.exists():
            continue
        new_text, names = process(path, args.check, problems)
        for name in names:
            found[name] = found.get(name, 0) + 1
        if not args.check and new_text != path.read_text(encoding="utf-8"):
            path.write_text(new_text, encoding="utf-8")
            print(f"docs_tables: rewrote {path.relative_to(ROOT).as_posix()}")
    for name, (rel, _) in GENERATORS.items():
        if found.get(name, 0) != 1:
            problems.append(f"{rel}: block '{name}' appears {found.get(name, 0)} times "
                            "(expected once)")
    if problems:
        for p in problems:
            print(f"docs_tables: {p}", file=sys.stderr)
        return 1
    if args.check:
        print(f"docs_tables: {len(found)} blocks match bench/results")
    return 0


if __name__ == "__main__":
    sys.exit(main())
