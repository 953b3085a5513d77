#!/usr/bin/env python3
"""Plots of a wheelwear results file: profile evolution (the profiles, the depth worn since new,
Delta r(y), the worn area) of every worn wheel, wear depth per step, wheel parameters and
conicity, where the contacts fall on the wheel, T gamma maps where the run recorded them, and a
vehicle run's curving states, the route sections the wear comes from, time-domain pieces and
linear critical speed.

    scripts/plot_run.py RUN.h5 [--out DIR]

Writes PNGs next to RUN.h5 (or into DIR) and prints their names. Needs h5py and matplotlib
(Debian: python3-h5py, python3-matplotlib).
"""

import argparse
import os
import sys
import warnings

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as error:  # pragma: no cover - depends on the machine
    sys.exit(f"plot_run.py: {error}; install python3-h5py and python3-matplotlib")


# The results file layout this script reads (docs/results.md).
FORMAT_VERSION = 6


def steps(f):
    return [f["steps"][name] for name in sorted(f["steps"].keys())]


WHEELSET_PROFILES = [f"wheelsets/{k}/{side}" for k in range(1, 5)
                     for side in ("wheel_left", "wheel_right")]


def wheel_groups(step):
    """The worn profiles of a step: the shared one, left and right, or each wheelset's two."""
    names = ("wheel", "wheel_left", "wheel_right", *WHEELSET_PROFILES)
    return [name for name in names if name in step]


def distance_colours(groups):
    """A colour per step from its distance, and the colour bar's mappable (km)."""
    km = np.array([g["distance"][()] for g in groups]) / 1e3
    norm = plt.Normalize(0.0, max(km[-1], 1e-9))
    mappable = plt.cm.ScalarMappable(norm=norm, cmap=plt.cm.viridis)
    return [plt.cm.viridis(norm(d)) for d in km], mappable


def text(dataset):
    """A text dataset as str (h5py returns variable-length strings as bytes)."""
    value = dataset[()]
    return value.decode() if isinstance(value, bytes) else str(value)


def file_label(name):
    """'wheelsets/2/wheel_left' -> 'wheelset2_left' for file names."""
    return name.replace("wheelsets/", "wheelset").replace("/wheel_", "_").replace("/", "_")


def plot_profiles(f, out):
    """Per worn profile: the profiles, the depth worn since step 0 (along the new profile's
    normal, as recorded), the change of rolling radius and the worn area, against distance."""
    groups = steps(f)
    paths = []
    for index, name in enumerate(wheel_groups(groups[0])):
        paths.append(plot_profile(groups, name, out, "profile_evolution.png" if index == 0
                                  else f"profile_evolution_{file_label(name)}.png"))
    return paths


def plot_profile(groups, name, out, file_name):
    fig, axes = plt.subplots(4, 1, figsize=(9, 12),
                             gridspec_kw={"height_ratios": [1.0, 1.0, 1.0, 0.7]})
    first = groups[0]
    y0 = np.asarray(first[name]["y"]) * 1e3
    z0 = np.asarray(first[name]["z"]) * 1e3
    s0 = np.asarray(first[name]["cumulative_wear"]["s"])
    # Where each point of the new profile's arc-length grid lies across the wheel.
    y_of_s = np.interp(s0, np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(y0), np.diff(z0)))])
                       / 1e3, y0)
    colours, mappable = distance_colours(groups)
    # Delta r in um while it stays below 0.1 mm, so that a running-in run does not look flat.
    last_dr = np.asarray(groups[-1][name]["radius_change"]["value"])
    small = not np.nanmax(np.abs(last_dr), initial=0.0) >= 1e-4
    dr_scale, dr_unit = (1e6, "µm") if small else (1e3, "mm")
    area = []
    for g, colour in zip(groups, colours):
        p = g[name]
        axes[0].plot(np.asarray(p["y"]) * 1e3, np.asarray(p["z"]) * 1e3, color=colour, lw=0.8)
        depth = np.asarray(p["cumulative_wear"]["depth"])
        axes[1].plot(y_of_s, depth * 1e6, color=colour, lw=0.8)
        area.append(np.trapz(np.nan_to_num(depth), s0) * 1e6)  # [mm^2]
        axes[2].plot(np.asarray(p["radius_change"]["y"]) * 1e3,
                     np.asarray(p["radius_change"]["value"]) * dr_scale, color=colour, lw=0.8)
    mask = (y0 > -45) & (y0 < 50)
    axes[0].set_ylim(z0[mask].max() + 1, z0[mask].min() - 1)
    axes[0].set_ylabel("z [mm] (down)")
    axes[0].set_title(f"{wheel_label(name)} profile, {len(groups) - 1} wear steps "
                      f"to {groups[-1]['distance'][()] / 1e3:.1f} km")
    axes[1].set_ylabel("worn since new, normal [µm]")
    axes[1].set_title("depth worn since step 0, along the new profile's normal", fontsize=10)
    axes[2].set_ylabel(f"Δr(y) [{dr_unit}]")
    axes[2].set_title("change of rolling radius at each lateral position", fontsize=10)
    axes[2].set_xlabel("y [mm] (profile frame: + field side, 0 taping line, flange at -y)")
    for ax in axes[:3]:
        ax.set_xlim(-45, 50)
        ax.grid(alpha=0.3)
        fig.colorbar(mappable, ax=ax, label="distance [km]", pad=0.01)
    km = np.array([g["distance"][()] for g in groups]) / 1e3
    axes[3].plot(km, area, marker="o", ms=3)
    axes[3].set_xlabel("distance [km]")
    axes[3].set_ylabel("worn area [mm²]")
    axes[3].set_title("worn cross-section (the worn depth integrated along the profile)",
                      fontsize=10)
    axes[3].grid(alpha=0.3)
    path = os.path.join(out, file_name)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def state_weights(f, g):
    """Each state's share of the running distance at step g (the step's own collective in a
    vehicle or hook run, else the run's)."""
    collective = g["collective"] if "collective" in g else f["load_collective"]
    weight = np.asarray(collective["weight"], dtype=float)
    return weight / weight.sum(), collective


def plot_contact_positions(f, out):
    """Where the contacts fall on each wheel, first and last step: the normal force of every
    patch weighted by its state's share of the distance, in 1 mm bins across the wheel."""
    groups = steps(f)
    if "states" not in groups[0] or "y_wheel" not in groups[0]["states"]:
        return None
    fig, axes = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    bins = np.arange(-45.0, 51.0, 1.0)
    for g, style, when in ((groups[0], "-", "first step"), (groups[-1], "--", "last step")):
        weight, _ = state_weights(f, g)
        y = np.asarray(g["states"]["y_wheel"]) * 1e3
        force = np.asarray(g["states"]["normal_force"])
        angle = np.asarray(g["states"]["contact_angle"])
        for wheel, side in enumerate(("left", "right")):
            w = (weight[:, None] * force[:, wheel, :]).ravel()
            yy = y[:, wheel, :].ravel()
            ok = np.isfinite(yy) & np.isfinite(w)
            hist, _ = np.histogram(yy[ok], bins=bins, weights=w[ok] / 1e3)
            axes[0].step(bins[:-1], hist, style, where="post", label=f"{side} wheel, {when}")
            a = angle[:, wheel, :].ravel()
            axes[1].plot(yy[ok], np.degrees(a[ok]), "o" if when == "first step" else "x",
                         ms=3, alpha=0.5, label=f"{side} wheel, {when}")
    axes[0].set_ylabel("normal force × share [kN] per mm")
    axes[0].set_title("where the contacts fall on the wheel")
    axes[1].set_ylabel("contact angle [°]")
    axes[1].set_xlabel("y on the wheel [mm] (profile frame: + field side, flange at -y)")
    for ax in axes:
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    path = os.path.join(out, "contact_positions.png")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_wear_depth(f, out):
    groups = steps(f)
    fig, ax = plt.subplots(figsize=(9, 4.5))
    colours, mappable = distance_colours(groups)
    for g, colour in zip(groups[:-1], colours):
        for name in wheel_groups(g):
            step = g[name]["wear_step"]
            ax.plot(np.asarray(step["y"]) * 1e3, np.asarray(step["depth"]) * 1e6, color=colour,
                    lw=0.8)
    ax.set_xlabel("y on the wheel [mm]")
    ax.set_ylabel("wear depth of the step [µm]")
    ax.set_xlim(-40, 50)
    ax.set_title("wear depth of each step")
    fig.colorbar(mappable, ax=ax, label="distance at the step's start [km]", pad=0.01)
    path = os.path.join(out, "wear_depth_per_step.png")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def wheel_label(name):
    """'wheelsets/2/wheel_left' -> 'wheelset 2 left'; 'wheel_right' -> 'right'."""
    parts = name.replace("wheel_", "").split("/")
    return f"wheelset {parts[1]} {parts[2]}" if len(parts) == 3 else parts[0]


# EN 15313's in-service parameters with the scene's limits (/steps/N/limits): (key, limit, sense).
PARAMETERS = (("Sd", "Sd_min", "flange thickness", ">="), ("Sh", "Sh_max", "flange height", "<="),
              ("qR", "qR_min", "flange slope qR", ">="))


def parameter_panel(ax, groups, names, key, limit_key, title, sense, distance):
    """One parameter on its own axis, a line per wheel, and its limit where it is in reach.
    A change below 50 µm is drawn in µm from the start value, which the label states."""
    colours = plt.cm.tab10(np.arange(4))
    several = len(names) > 1
    series = [np.array([g[name][key][()] for g in groups]) * 1e3 for name in names]
    values = np.concatenate(series)
    values = values[np.isfinite(values)]
    span = values.max() - values.min() if values.size else 0.0
    small = span < 0.05
    origin = series[0][0] if small else 0.0
    scale = 1e3 if small else 1.0
    for i, (name, v) in enumerate(zip(names, series)):
        ax.plot(distance, (v - origin) * scale, marker="o", ms=3,
                ls="--" if several and name.endswith("right") else "-",
                color=colours[i // 2 if len(names) > 2 else i] if several else "C0",
                label=wheel_label(name) if several else None)
    limit = groups[-1]["limits"][limit_key][()] * 1e3 if "limits" in groups[-1] else np.nan
    heading = f"{key}: {title}"
    if np.isfinite(limit):
        heading += f", limit {sense} {limit:.1f} mm"
        # The limit drawn where it does not squeeze the change into a line: within three
        # times the parameter's range of its values.
        if not small and values.size and abs(limit - values.mean()) < 3.0 * max(span, 0.05) + 0.5:
            ax.axhline(limit, color="crimson", ls=":", lw=1.2, label="EN 15313 limit")
    ax.set_title(heading, fontsize=10)
    ax.set_xlabel("distance [km]")
    ax.set_ylabel(f"{key} − {origin:.3f} mm [µm]" if small else f"{key} [mm]")
    ax.ticklabel_format(axis="y", useOffset=False)
    ax.grid(alpha=0.3)
    if several or ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)


def plot_parameters(f, out):
    groups = steps(f)
    distance = np.array([g["distance"][()] for g in groups]) / 1e3
    names = wheel_groups(groups[0])
    # Each parameter on its own axis (a real change of tenths of a millimetre must not look
    # flat beside another parameter's 20 mm), a line per wheel (solid left, dashed right).
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    for ax, (key, limit_key, title, sense) in zip(axes.flat, PARAMETERS):
        parameter_panel(ax, groups, names, key, limit_key, title, sense, distance)
    ax = axes.flat[3]
    colours = plt.cm.tab10(np.arange(4))
    wheelsets = [k for k in range(1, 5) if f"wheelsets/{k}/equivalent_conicity" in groups[0]]
    if wheelsets:
        for k in wheelsets:
            ax.plot(distance, [g[f"wheelsets/{k}/equivalent_conicity"][()] for g in groups],
                    marker="o", ms=3, color=colours[k - 1], label=f"wheelset {k}")
        ax.legend(fontsize=7)
    else:
        ax.plot(distance, [g["equivalent_conicity"][()] for g in groups], marker="o", ms=3)
    ax.set_xlabel("distance [km]")
    ax.set_ylabel("tan γe at 3 mm")
    ax.set_title("equivalent conicity (EN 15302)", fontsize=10)
    ax.grid(alpha=0.3)
    path = os.path.join(out, "parameters.png")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_tgamma(f, out):
    first = steps(f)[0]
    if "tgamma" not in first:
        return None
    work = np.asarray(first["tgamma"]["work"])
    x = np.asarray(first["tgamma"]["x"])
    y = np.asarray(first["tgamma"]["y"])
    # The contact with the largest total frictional work of the first step.
    totals = np.nansum(work, axis=(3, 4))
    state, wheel, patch = np.unravel_index(np.nanargmax(totals), totals.shape)
    fig, ax = plt.subplots(figsize=(6, 5))
    # Each strip has its own cell length, so x is not a tensor grid; the cells still tile the
    # patch and matplotlib's warning about guessed cell edges does not apply.
    warnings.filterwarnings("ignore", message="The input coordinates to pcolormesh")
    mesh = ax.pcolormesh(y[state, wheel, patch] * 1e3, x[state, wheel, patch] * 1e3,
                         work[state, wheel, patch], shading="auto", cmap="inferno")
    fig.colorbar(mesh, ax=ax, label="Tγ density [J/m²/m]")
    ax.set_xlabel("y [mm] (+ flange)")
    ax.set_ylabel("x [mm] (rolling)")
    side = "left" if wheel == 0 else "right"
    ax.set_title(f"Tγ map, state {state}, {side} wheel, patch {patch + 1}")
    path = os.path.join(out, "tgamma_map.png")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_vehicle(f, out):
    """A vehicle run's quasi-static states against curvature, first and last step, and where
    the wear of the first step comes from."""
    groups = steps(f)
    if "vehicle" not in groups[0]:
        return None
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    markers = ("o", "s", "^", "v")
    for g, style, when in ((groups[0], "-", "first step"), (groups[-1], "--", "last step")):
        c = g["vehicle"]["cases"]
        # The worn conditions only: those of share 0 just start a time-domain piece.
        worn = np.asarray(c["share"]) > 0
        radius = np.asarray(c["curve_radius_m"])[worn]
        hand = np.sign(radius)  # + right-hand: the left rail outer
        curvature = np.where(radius != 0.0, 1e3 / np.where(radius == 0.0, 1.0, np.abs(radius)), 0.0)
        order = np.argsort(curvature)
        converged = np.asarray(c["converged"])[worn] > 0
        dy = np.asarray(c["dy"])[worn] * 1e3
        aoa = np.asarray(c["angle_of_attack"])[worn] * 1e3
        Q = np.asarray(c["Q"])[worn]
        Y = np.asarray(c["Y"])[worn]
        for k in range(dy.shape[1]):
            colour = plt.cm.tab10(k)
            label = f"wheelset {k + 1}, {when}"
            # Towards the outer rail (+) whatever the curve's hand.
            axes[0, 0].plot(curvature[order], (hand * dy[:, k])[order], style, color=colour,
                            marker=markers[k], ms=4, label=label)
            axes[0, 1].plot(curvature[order], (hand * aoa[:, k])[order], style, color=colour,
                            marker=markers[k], ms=4)
            outer = np.where(hand >= 0, 0, 1)  # left wheel outer in right-hand curves
            ratio = Y[np.arange(len(radius)), k, outer] / Q[np.arange(len(radius)), k, outer]
            axes[1, 0].plot(curvature[order], ratio[order], style, color=colour,
                            marker=markers[k], ms=4)
        bad = ~converged
        if bad.any():
            axes[0, 0].plot(curvature[bad], (hand * dy[:, 0])[bad], "kx", ms=9,
                            label=f"not converged ({when})")
    axes[0, 0].set_ylabel("shift towards the outer rail [mm]")
    axes[0, 1].set_ylabel("angle of attack, + towards the outer rail [mrad]")
    axes[1, 0].set_ylabel("Y/Q of the outer wheel")
    for ax in (axes[0, 0], axes[0, 1], axes[1, 0]):
        ax.set_xlabel("curvature 1000/|R| [1/km]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    axes[0, 0].set_title("quasi-static curving on the current profiles")
    # Where the first step's wear comes from: worn area per route condition.
    first = groups[0]
    ax = axes[1, 1]
    if "states" in first and "worn_area" in first["states"] and "collective" in first:
        area = np.nansum(np.asarray(first["states"]["worn_area"]), axis=(1, 2))
        weight = np.asarray(first["collective"]["weight"])
        weight = weight / weight.sum()
        labels = text(first["collective"]["label"]).splitlines()
        conditions = [label.rsplit(", wheelset", 1)[0] for label in labels]
        totals = {}
        for condition, a, w in zip(conditions, area, weight):
            totals[condition] = totals.get(condition, 0.0) + a * w
        names = sorted(totals, key=totals.get, reverse=True)[:12]
        values = np.array([totals[n] for n in names])
        ax.barh(range(len(names)), 100 * values / max(sum(totals.values()), 1e-300))
        ax.set_yticks(range(len(names)), names, fontsize=7)
        ax.invert_yaxis()
        ax.set_xlabel("share of the worn area, first step [%]")
        ax.set_title("where the wear comes from")
    else:
        ax.set_axis_off()
    path = os.path.join(out, "vehicle.png")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_vehicle_motion(f, out):
    """A vehicle run's time-domain pieces and linear critical speed against the distance run:
    per piece the leading wheelset's rms and largest shift and the largest Y/Q, at every step
    that solved the vehicle."""
    groups = steps(f)
    if "vehicle" not in groups[0] or "pieces" not in groups[0]["vehicle"]:
        return None
    solved = [g for g in groups if float(g["vehicle"]["solved"][()]) > 0]
    distance = np.array([float(g["distance"][()]) for g in solved]) / 1e3
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    speed = np.array([float(g["vehicle"]["critical_speed"][()]) if "critical_speed" in
                      g["vehicle"] else np.nan for g in solved])
    axes[0, 0].plot(distance, speed * 3.6, "o-")
    axes[0, 0].set_ylabel("linear critical speed [km/h]")
    axes[0, 0].set_title("linear critical speed on tangent track (none: stable to 360 km/h)")
    tangent = np.asarray(solved[0]["vehicle"]["pieces"]["tangent"]) > 0
    for g, style, when in ((solved[0], "o", "first solve"), (solved[-1], "s", "last solve")):
        p = g["vehicle"]["pieces"]
        start = np.asarray(p["start_m"]) / 1e3
        rms = np.asarray(p["dy_rms"])[:, 0] * 1e3
        peak = np.asarray(p["dy_max"])[:, 0] * 1e3
        ratio = np.asarray(p["Y_over_Q_max"]).max(axis=1)
        axes[0, 1].plot(start[tangent], rms[tangent], style, label=f"tangents, rms, {when}")
        axes[0, 1].plot(start[tangent], peak[tangent], style, mfc="none",
                        label=f"tangents, largest, {when}")
        axes[1, 0].plot(start[~tangent], peak[~tangent], style, label=f"transitions, {when}")
        axes[1, 1].plot(start, ratio, style, label=when)
    axes[0, 1].set_ylabel("leading wheelset |dy| [mm]")
    axes[0, 1].set_title("motion over the track's irregularities")
    axes[1, 0].set_ylabel("leading wheelset largest |dy| [mm]")
    axes[1, 1].set_ylabel("largest Y/Q of any wheel")
    for ax in (axes[0, 1], axes[1, 0], axes[1, 1]):
        ax.set_xlabel("piece's place along the route [km]")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    axes[0, 0].set_xlabel("distance run [km]")
    axes[0, 0].grid(alpha=0.3)
    path = os.path.join(out, "vehicle_motion.png")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="results file written by `wheelwear run`")
    parser.add_argument("--out", help="directory for the PNGs (default: next to RUN)")
    args = parser.parse_args()
    out = args.out or os.path.dirname(os.path.abspath(args.run))
    os.makedirs(out, exist_ok=True)
    try:
        f = h5py.File(args.run, "r")
    except OSError as error:
        sys.exit(f"plot_run.py: cannot read {args.run}: {error}")
    with f:
        if "steps" not in f or len(f["steps"]) == 0:
            sys.exit(f"plot_run.py: {args.run} holds no steps")
        version = int(f.attrs.get("format_version", 1))
        if version < FORMAT_VERSION:
            sys.exit(f"plot_run.py: {args.run} has results layout version {version}; this script "
                     f"reads version {FORMAT_VERSION} (docs/results.md): run the scene again "
                     "with this program")
        for plot in (plot_profiles, plot_wear_depth, plot_parameters, plot_contact_positions,
                     plot_tgamma, plot_vehicle, plot_vehicle_motion):
            paths = plot(f, out)
            for path in paths if isinstance(paths, list) else [paths]:
                if path:
                    print(path)


if __name__ == "__main__":
    main()
