"""
A microcapsule squeezed between two plates, and its wall fitted
===============================================================

The standard test of a microcapsule or a cell: squeeze it between two parallel plates and record the force on
each plate against the gap between them. This example makes such a test with the model (a capsule of radius
R = 50 um, its wall neo-Hookean with E T = 0.75 N/m, filled with a liquid at P_I = 3 kPa, squeezed up to 20 uN;
0.05 um seeded noise on the gaps), plots it as the literature does (the force in units of E T R against the
compression 1 - gap / (2 lambda_I R)), and fits the wall back with ``pocket.apps.fit`` (no thickness given: the
fit returns mu T, and E T = 3 mu T).

Run it as a script: ``python examples/plot_13_capsule_fit.py``.
"""

# %%
# The made-up test: the shooting solver squeezes the true capsule at forces from 0 to 20 uN.
import math
import pathlib
import tempfile

import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting
from pocket.apps.fit.capsuledata import read
from pocket.apps.fit.capsuletest import fit
from pocket.apps.fit.model import Setup
from pocket.core.materials import check

RADIUS, PRESSURE = 50e-6, 3e3  # m, Pa (P_I)
ET = 0.75  # N/m: the wall's E T behind the made-up test (E = 3 mu for a neo-Hookean rubber)
FORCES = np.linspace(0.0, 20e-6, 11)  # N, on each plate
NOISE, SEED = 0.05e-6, 3  # m: the gaps' noise (a microscope's resolution), and its seed
NEO = check("neo-hookean", {"mu": 1.0})  # a neo-Hookean wall in units of its own mu


def curve(et, forces):
    """The capsule of wall stiffness ``et`` = E T (N/m) squeezed by ``forces`` (N): the states, lambda_I."""
    phat = PRESSURE * RADIUS / et
    states = shooting.compression_curve(NEO, phat, list(np.asarray(forces) / (PRESSURE * math.pi * RADIUS**2)),
                                        geometry="capsule")
    return states, states[0].inflated.stretch_pole


def squeeze_test(path: pathlib.Path) -> None:
    """Write the made-up test: the force on each plate (uN) and the gap between the plates (um)."""
    states, _ = curve(ET, FORCES)
    gaps = np.array([2.0 * s.height * RADIUS for s in states])
    gaps += NOISE * np.random.default_rng(SEED).standard_normal(gaps.size)
    rows = [f"{f * 1e6:.6g},{g * 1e6:.6g}" for f, g in zip(FORCES, gaps, strict=True)]
    path.write_text("force [uN],gap [um]\n" + "\n".join(rows) + "\n")


# %%
# The fit solves the capsule for each trial wall at every measured force and minimises the gaps' residuals in
# units of the diameter. P_I is given (``--initial-pressure`` on the command line); without a thickness the
# law's stress comes out times T, in N/m.
def main(out: pathlib.Path) -> dict:
    """Make the test in ``out``, fit it, print the result; returns ``{"fit": the fit's result, "test": the
    test}``."""
    data = out / "squeeze.csv"
    squeeze_test(data)
    test = read(data)
    result = fit(Setup((test,), RADIUS, None), "neo-hookean", PRESSURE)
    s = result.statistics
    mu_t, error = s.values[0], s.standard_errors[0]
    low, high = s.intervals[0]
    print(f"neo-hookean wall fitted to {data.name} ({len(FORCES)} forces): {result.calls} solver calls, "
          f"residual RMS {s.rms:.3g}")
    print(f"  mu T = {mu_t:.6g} N/m +- {error:.2g}, 95 % interval [{low:.6g}, {high:.6g}]")
    print(f"  E T = 3 mu T = {3 * mu_t:.6g} N/m (truth {ET:g} N/m), Phat_I = P_I R / (E T) = "
          f"{PRESSURE * RADIUS / (3 * mu_t):.4g}")
    for warning in s.warnings:
        print(f"  warning: {warning}")
    return {"fit": result, "test": test}


# %%
# The figure: the test and the fitted capsule as the literature plots them, F / (E T R) against the
# compression 1 - gap / (2 lambda_I R) (lambda_I R the inflated radius); and the shape of the squeezed capsule
# at the largest force, its upper half mirrored through the equatorial plane.
def draw(numbers: dict):
    """The force-compression curve (data and fit) and the squeezed capsule's meridian."""
    result, test = numbers["fit"], numbers["test"]
    et = 3.0 * result.statistics.values[0]
    dense = np.linspace(0.0, FORCES[-1], 41)
    states, lam = curve(et, dense)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    axes[0].plot(1.0 - test.responses["gap"] / (2 * lam * RADIUS), test.control / (et * RADIUS), "o",
                 label="squeeze.csv")
    axes[0].plot([1.0 - s.height / lam for s in states], [s.extra["force_ETR"] for s in states],
                 label=f"fitted, E T = {et:.4g} N/m")
    axes[0].set_xlabel("compression 1 - gap / (2 lambda_I R)")
    axes[0].set_ylabel("F / (E T R)")
    axes[0].legend()
    last = states[-1].profile
    for sign in (1.0, -1.0):
        for side in (1.0, -1.0):
            axes[1].plot(side * last.rho * RADIUS * 1e6, sign * last.eta * RADIUS * 1e6, color="C1")
    theta = np.linspace(0.0, 2.0 * np.pi, 200)
    axes[1].plot(lam * RADIUS * 1e6 * np.cos(theta), lam * RADIUS * 1e6 * np.sin(theta), "--", color="0.6",
                 label="inflated")
    for sign in (1.0, -1.0):
        axes[1].axhline(sign * states[-1].height * RADIUS * 1e6, color="0.3", lw=2)
    axes[1].set_aspect("equal")
    axes[1].set_xlabel("r (um)")
    axes[1].set_ylabel("z (um)")
    axes[1].set_title(f"squeezed by {FORCES[-1] * 1e6:g} uN")
    axes[1].legend(loc="lower right")
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


# %%
# Run it; the test's file lives in a temporary folder.
if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        draw(main(pathlib.Path(folder)))
    plt.show()
