"""Creep curves of FASTSIM-SDEC against the book of exact-theory tables, for a few psi.

Lateral force against lateral creepage and against spin on an SDEC patch (a = 6 mm, b = 3 mm,
N = 50 kN, mu = 0.3): the table (Kalker's exact theory, interpolated) and FASTSIM-SDEC on
50 x 50 cells, each curve of 400 points one vectorised call. Writes creep_curves.png into the folder given (default .).

    PYTHONPATH=build/python python3 examples/creep_curves.py docs/
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import wheelwear  # noqa: E402


def main(folder: Path) -> Path:
    vy = np.linspace(0.0, 4e-3, 400)  # lateral creepage [-]
    phi = np.linspace(0.0, 1.8, 400)  # spin creepage [1/m], within the table's range here
    fig, (ax_vy, ax_phi) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    for psi, colour in zip((0.0, 0.4, 0.8), ("C0", "C1", "C2")):
        for method, style in (("table", "-"), ("fastsim-sdec", "--")):
            lateral = wheelwear.creep(method, a=6e-3, b=3e-3, psi=psi, vy=vy, N=50e3, mu=0.3)
            spin = wheelwear.creep(method, a=6e-3, b=3e-3, psi=psi, phi=phi, N=50e3, mu=0.3)
            ax_vy.plot(vy * 1e3, -lateral.Fy_muN, style, color=colour, label=f"{method}, ψ = {psi}")
            ax_phi.plot(phi, -spin.Fy_muN, style, color=colour)
    ax_vy.set(xlabel="lateral creepage vy [‰]", ylabel="−Fy / μN",
              title="lateral creep force: saturation")
    ax_phi.set(xlabel="spin φ [1/m]", ylabel="−Fy / μN", title="lateral force under pure spin")
    ax_vy.legend(fontsize=8)
    for ax in (ax_vy, ax_phi):
        ax.grid(alpha=0.3)
    fig.suptitle("SDEC a = 6 mm, b = 3 mm, N = 50 kN, μ = 0.3: book of tables (exact theory) —,"
                 " FASTSIM-SDEC 50 × 50 - -", fontsize=10)
    out = folder / "creep_curves.png"
    fig.savefig(out, dpi=110)
    return out


if __name__ == "__main__":
    print(main(Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
