"""Contact patches and their SDECs: the Kik-Piotrowski strips (the patch the normal problem
gives) against the two half-ellipses of the SDEC regularisation (Liu, Fu & Bruni 2022,
Eq. 13-14) on the tread and on the flange, and the T gamma map of the tread patch's wear.
S1002 on 60E1 1:40, 55 kN.
Writes contact_patch.png into the folder given (default .).

    PYTHONPATH=build/python python3 examples/contact_patch.py docs/
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as tri  # noqa: E402
import numpy as np  # noqa: E402

import wheelwear  # noqa: E402


def sdec_outline(a: float, b: float, psi: float) -> tuple:
    """The SDEC's edge: semi-width b(1 + psi) for y > 0, b(1 - psi) for y <= 0 (DIGEST Eq. 1-3)."""
    y = np.concatenate([np.linspace(-b * (1 - psi), 0, 100), np.linspace(0, b * (1 + psi), 100)])
    half = np.where(y > 0, b * (1 + psi), b * (1 - psi))
    x = a * np.sqrt(np.clip(1 - (y / half) ** 2, 0, None))
    return np.concatenate([y, y[::-1]]), np.concatenate([x, -x[::-1]])


def draw_patch(ax, patch, title: str) -> None:
    st = patch.strips
    ax.fill_between(st.s * 1e3, -st.x_lead * 1e3, st.x_lead * 1e3, step="mid", color="0.8",
                    label="Kik–Piotrowski strips")
    ys, xs = sdec_outline(patch.a, patch.b, patch.psi)
    ax.plot(ys * 1e3, xs * 1e3, "C3",
            label=f"SDEC a {patch.a * 1e3:.2f}, b {patch.b * 1e3:.2f} mm, ψ {patch.psi:+.2f}")
    ax.plot(0, 0, "k+", ms=10, label="O")
    ax.set(xlabel="s from O [mm] (+ gauge side)", ylabel="x [mm] (rolling)",
           title=f"{title}\nN {patch.N / 1e3:.1f} kN, {np.degrees(patch.contact_angle):.0f}°,"
                 f" pmax {patch.pmax / 1e6:.0f} MPa")
    ax.set_aspect("equal")
    ax.legend(fontsize=7, loc="lower right")


def main(folder: Path) -> Path:
    # A tread patch that is far from an ellipse (dy 0.5 mm) and a slender flank patch (7.5 mm).
    tread = wheelwear.wear(dy=0.5e-3, load=55e3, vx=-5e-4, vy=5e-4, phi=-0.1, V=20.0)
    flank = wheelwear.contact(dy=7.5e-3, load=55e3)
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.6), constrained_layout=True,
                             gridspec_kw={"width_ratios": [1.6, 0.8, 1.6]})
    patch = max(tread.patches, key=lambda p: p.N)
    draw_patch(axes[0], patch, "tread, dy 0.5 mm")
    draw_patch(axes[1], max(flank.patches, key=lambda p: p.N), "flank, dy 7.5 mm")
    m = patch.wear.tgamma
    # The cells' frictional work on a triangulation of their centres, without the triangles
    # that bridge the SDEC's concave side.
    grid = tri.Triangulation(m.y * 1e3, m.x * 1e3)
    cy, cx = (grid.x[grid.triangles].mean(axis=1) / 1e3, grid.y[grid.triangles].mean(axis=1) / 1e3)
    half = np.where(cy > 0, patch.b * (1 + patch.psi), patch.b * (1 - patch.psi))
    grid.set_mask((cx / patch.a) ** 2 + (cy / half) ** 2 > 1.0)
    shade = axes[2].tripcolor(grid, m.work / 1e6, shading="gouraud", cmap="magma")
    fig.colorbar(shade, ax=axes[2], label="frictional work [MJ/m² per m rolled]")
    axes[2].set(xlabel="y from O [mm]", ylabel="x [mm]",
                title="Tγ map of the tread patch (FASTSIM-SDEC 50 × 50)")
    axes[2].set_aspect("equal")
    fig.suptitle("S1002 on 60E1 1:40, 55 kN: the contact patch, its SDEC and where it wears",
                 fontsize=10)
    out = folder / "contact_patch.png"
    fig.savefig(out, dpi=110)
    return out


if __name__ == "__main__":
    print(main(Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
