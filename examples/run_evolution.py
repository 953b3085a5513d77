"""The evolution of a wear run: the built-in scene (the built-in coach on the built-in route,
10^5 km in about 25 steps, about a minute on two cores) run from Python and read back into
arrays; the worn depth across the wheel and Sd, Sh, qR against distance. Writes
run_evolution.png into the folder given (default .).

    PYTHONPATH=build/python python3 examples/run_evolution.py docs/
"""

import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import wheelwear  # noqa: E402


def main(folder: Path) -> Path:
    with tempfile.TemporaryDirectory() as scratch:
        output = Path(scratch) / "run.h5"
        wheelwear.run(output=output)  # the built-in scene: 10^5 km, about a minute
        r = wheelwear.read_results(output)
    fig, (ax_p, ax_d) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    new = r.steps[0]
    for step in r.steps[4::4]:
        # The worn depth since the new profile, placed at the new profile's lateral positions.
        y = np.interp(step.wear_s, new.arc_length(), new.y)
        ax_p.plot(y * 1e3, step.wear_depth * 1e3, label=f"{step.distance / 1e3:,.0f} km")
    ax_p.set(xlabel="y on the new wheel [mm] (0: taping line, − flange)",
             ylabel="worn depth [mm]", title="wear across the wheel profile", xlim=(-45, 40))
    ax_p.legend(fontsize=8)
    km = r.distance / 1e3
    for values, name, style in ((r.Sd, "Sd", "o-"), (r.Sh, "Sh", "s-"), (r.qR, "qR", "x--")):
        ax_d.plot(km, (values - values[0]) * 1e3, style, ms=4, label=name)
    ax_d.set(xlabel="distance [km]", ylabel="change since new [mm]",
             title="EN 15313 flange parameters")
    ax_d.legend()
    for ax in (ax_p, ax_d):
        ax.grid(alpha=0.3)
    fig.suptitle("built-in scene: S1002 on 60E1 1:40, the Manchester benchmark coach on the "
                 "100 km mixed line", fontsize=10)
    out = folder / "run_evolution.png"
    fig.savefig(out, dpi=110)
    return out


if __name__ == "__main__":
    print(main(Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
