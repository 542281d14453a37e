"""Draw ``pocket.png``, the picture of the documentation's front page and of the README.

The paper's sample 1 (Mooney-Rivlin, alpha = C2/C1 = 47/160, Phat_I = 0.31, a liquid): on the left its
cross-section, inflated and then pressed by the flat plate to Fhat = 0.5 (the shooting solver); on the
right its pressure rise P/P_I against the force Fhat by the shooting solver, the P2 finite elements and
the paper's small-strain model. Run from anywhere (a minute, the solvers' first compilation included):

    python docs/_static/draw_front.py
"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from pocket import analytical, fem, shooting
from pocket.core.errors import OutOfRangeError

ALPHA, PRESSURE, PRESSED = 47 / 160, 0.31, 0.5  # the rubber, Phat_I, the force of the cross-section
OUT = pathlib.Path(__file__).with_name("pocket.png")


def meridian(state):
    """The whole cross-section of a state's sheet: its meridian mirrored about the axis, in R."""
    rho, eta = state.profile.rho, state.profile.eta
    return np.concatenate([-rho[::-1], rho]), np.concatenate([eta[::-1], eta])


def cross_section(ax) -> None:
    """The pocket inflated (dashed) and pressed by the plate (solid, the fluid shaded), the clamp in black."""
    pressed = shooting.compress(ALPHA, PRESSURE, PRESSED)
    x, z = meridian(pressed.inflated)
    ax.plot(x, z, "--", color="0.45", lw=1.2, label=f"inflated, $\\hat P_I$ = {PRESSURE:g}")
    x, z = meridian(pressed)
    ax.fill_between(x, 0.0, z, color="#9ecae1", alpha=0.7, lw=0)
    ax.plot(x, z, color="#08519c", lw=2.0, label=f"pressed, $\\hat F$ = {PRESSED:g}")
    ax.fill_between([-0.8, 0.8], pressed.height, pressed.height + 0.05, color="0.55", label="plate")
    for side in (-1, 1):
        ax.fill_between([side * 1.0, side * 1.15], -0.04, 0.0, color="black")
    ax.axhline(0.0, color="black", lw=0.6)
    ax.set_aspect("equal")
    ax.set_xlim(-1.2, 1.2)
    ax.set_ylim(-0.08, 0.8)
    ax.set_xlabel("radius / R")
    ax.set_ylabel("height / R")
    ax.legend(loc="upper center", ncols=3, fontsize=8, frameon=False)
    ax.set_title("a clamped sheet, inflated, then pressed", fontsize=10)


def pressure_rise(ax) -> None:
    """P/P_I against Fhat: shooting (line), P2 finite elements (markers), the paper's analytical model."""
    forces = np.linspace(0.0, 2.0, 41)[1:]
    curve = shooting.compression_curve(ALPHA, PRESSURE, list(forces))
    ax.plot(forces, [s.pressure_ratio for s in curve], color="#08519c", lw=2.0, label="shooting")
    marks = forces[3::6]
    ax.plot(marks, [fem.compress(ALPHA, PRESSURE, f).pressure_ratio for f in marks], "o", mfc="none",
            color="#d94801", label="finite elements (P2)")
    small = []
    for f in forces:
        try:
            small.append((f, analytical.compress(ALPHA, PRESSURE, f).pressure_ratio))
        except OutOfRangeError:  # past the small-strain model's own range
            break
    ax.plot(*zip(*small, strict=True), "--", color="0.3", label="analytical (small strain)")
    ax.set_xlabel(r"force $\hat F = F / (P_I \pi R^2)$")
    ax.set_ylabel(r"pressure rise $P / P_I$")
    ax.legend(fontsize=8, frameon=False)
    ax.set_title("its pressure rise by three models", fontsize=10)


def main() -> None:
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 3.2), gridspec_kw={"width_ratios": [1.5, 1.0]},
                                      layout="constrained")
    cross_section(left)
    pressure_rise(right)
    fig.savefig(OUT, dpi=100)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
