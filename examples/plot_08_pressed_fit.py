"""
Your rubber from a pressed pocket
=================================

A pocket already built can be tested as it is: press it with a flat plate and read the fluid's pressure
and the plate's height at several forces. This example makes such a test with the model (the paper's
silicone, Mooney-Rivlin C1 = 160 kPa, C2 = 47 kPa, a 0.5 mm sheet over a 20 mm radius filled with a
liquid at 5 kPa, pressed up to 2 N; 0.2 % seeded noise on the readings), fits the Mooney-Rivlin law to
it with ``pocket.apps.fit`` and sets the fit's intervals against the truth. It also shows what such a
test cannot tell: C1 and C2 apart.

Run it as a script: ``python examples/plot_08_pressed_fit.py``.
"""

# %%
# The made-up test: the shooting solver presses the true rubber at forces from 0 to 2 N. The row at
# zero force gives the initial pressure; the fit is told it too (``Request``'s ``initial_pressure``).
import pathlib
import tempfile

import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting
from pocket.apps.fit.case import Request
from pocket.apps.fit.leastsquares import fit
from pocket.core.materials import check

RADIUS, THICKNESS, PRESSURE = 0.020, 0.0005, 5e3  # m, m, Pa (P_I)
TRUTH = {"c1": 160e3, "c2": 47e3}  # Pa: the rubber behind the made-up test
FORCES = np.linspace(0.0, 2.0, 11)  # N
NOISE, SEED = 0.002, 2  # relative noise of the pressures and heights, and its seed


def curve(material, forces):
    """The pocket of ``material`` (stresses in Pa) pressed at ``forces`` (N): pressures (Pa), heights (m)."""
    scale = material.modulus * THICKNESS / RADIUS  # E T / R, Pa
    states = shooting.compression_curve(material.scaled(), PRESSURE / scale,
                                        list(np.asarray(forces) / (PRESSURE * np.pi * RADIUS**2)))
    return np.array([s.pressure * scale for s in states]), np.array([s.height * RADIUS for s in states])


def press_test(path: pathlib.Path) -> None:
    """Write the made-up compression test: forces (N), pressures (kPa), plate heights (mm)."""
    pressures, heights = curve(check("mooney-rivlin", TRUTH), FORCES)
    rng = np.random.default_rng(SEED)
    noisy = [(1.0 + NOISE * rng.standard_normal(2)) for _ in FORCES]
    rows = [f"{f:.6g},{(p if f == 0 else p * n[0]) / 1e3:.6g},{h * n[1] * 1e3:.6g}"
            for f, p, h, n in zip(FORCES, pressures, heights, noisy, strict=True)]
    path.write_text("force [N],pressure [kPa],height [mm]\n" + "\n".join(rows) + "\n")


# %%
# The fit solves the pocket for each trial rubber at every force and minimises the relative residuals
# of the pressures and heights. Under compression the liquid's volume is fixed and the sheet is
# already stretched, so the data see the rubber mostly through its stiffness at that stretch: one
# combination of C1 and C2. The fit says so (a correlation near -1, with the combination the data do
# determine) and its intervals on C1 and C2 are wide, while mu_0 = 2 (C1 + C2) is pinned down.
def main(out: pathlib.Path) -> dict:
    """Make the test in ``out``, fit it, print the result; returns ``{"fit": the fit's result
    (pocket.apps.fit)}``."""
    data = out / "press.csv"
    press_test(data)
    result = fit(Request((data,), "mooney-rivlin", RADIUS, THICKNESS, PRESSURE).setup(), "mooney-rivlin")
    s = result.statistics
    truth = check("mooney-rivlin", TRUTH)
    print(f"mooney-rivlin fitted to {data.name} ({len(FORCES)} forces): {result.calls} solver calls, "
          f"residual RMS {s.rms:.3g}")
    print(f"  {'':<4} {'fitted (Pa)':>12} {'std error':>10} {'95 % interval (Pa)':>24} {'truth (Pa)':>11}")
    for name, value, error, (low, high) in zip(s.names, s.values, s.standard_errors, s.intervals, strict=True):
        print(f"  {name:<4} {value:>12.6g} {error:>10.2g} {f'[{low:.6g}, {high:.6g}]':>24} {TRUTH[name]:>11g}")
    print(f"  mu_0 = {s.mu0:.6g} Pa +- {s.mu0_error:.2g}, 95 % interval [{s.mu0_interval[0]:.6g}, "
          f"{s.mu0_interval[1]:.6g}] (truth {truth.mu0:g} Pa)")
    print(f"  correlation of c1 and c2: {s.correlation[0, 1]:+.4f}")
    for warning in s.warnings:
        print(f"  warning: {warning}")
    return {"fit": result}


# %%
# The figure: the readings with the fitted model, and the 95 % confidence region of (C1, C2) from the
# fit's covariance: a long, thin ellipse along the combination the data determine, with the truth
# inside it.
def draw(numbers: dict):
    """Data and fitted curves; the (c1, c2) confidence ellipse with the truth."""
    result = numbers["fit"]
    test = result.setup.tests[0]
    dense = np.linspace(0.0, FORCES[-1], 30)
    pressures, heights = curve(result.material, dense)
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), layout="constrained")
    axes[0].plot(test.control, test.responses["pressure"] / 1e3, "o", label="press.csv")
    axes[0].plot(dense, pressures / 1e3, label="fitted")
    axes[0].set_ylabel("pressure (kPa)")
    axes[1].plot(test.control, test.responses["height"] * 1e3, "o", label="press.csv")
    axes[1].plot(dense, heights * 1e3, label="fitted")
    axes[1].set_ylabel("plate height (mm)")
    for ax in axes[:2]:
        ax.set_xlabel("force (N)")
        ax.legend()
    s = result.statistics
    chi2 = 5.991  # the 95 % quantile of chi-squared with 2 degrees of freedom
    values, vectors = np.linalg.eigh(s.covariance)
    t = np.linspace(0, 2 * np.pi, 200)
    ellipse = s.values[:, None] + vectors @ (np.sqrt(chi2 * values)[:, None] * np.array([np.cos(t), np.sin(t)]))
    axes[2].plot(ellipse[0] / 1e3, ellipse[1] / 1e3, label="95 % region")
    axes[2].plot(s.values[0] / 1e3, s.values[1] / 1e3, "o", label="fitted")
    axes[2].plot(TRUTH["c1"] / 1e3, TRUTH["c2"] / 1e3, "*", ms=12, label="truth")
    axes[2].set_xlabel("C1 (kPa)")
    axes[2].set_ylabel("C2 (kPa)")
    axes[2].legend()
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


# %%
# Run it; the test's file lives in a temporary folder.
if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        draw(main(pathlib.Path(folder)))
    plt.show()
