"""
Your rubber from a bulge test
=============================

Most users have a sheet, a clamp and a pressure gauge, not a rubber's parameters. A bulge test (the
sheet inflated, its pole height read at several pressures) is enough to find them. Here a 1 mm silicone
sheet clamped over a 20 mm radius is "tested" by the model itself: a Yeoh rubber (C10 = 85 kPa,
C20 = -2 kPa, C30 = 0.2 kPa) inflated to 15 pressures, the heights given 0.2 % of seeded noise and
written to a spreadsheet-like CSV file. ``pocket.apps.fit`` fits the Yeoh law to it, as ``pocket fit``
does, and the fit's 95 % intervals are set against the parameters that made the data. The fitted sheet
is then written as a case file and pressed by the plate, as ``pocket run`` would.

Run it as a script: ``python examples/plot_07_bulge_fit.py [OUTPUT_FOLDER]`` (without a folder, the
files go to a temporary one).
"""

# %%
# The made-up test: the shooting solver inflates the true rubber, in the model's units, and the
# pressures and heights are turned into kPa and mm with E T / R (E = 3 mu_0 = 6 C10 for Yeoh).
import pathlib
import sys
import tempfile

import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting
from pocket.apps.casefile import solve
from pocket.apps.cases import load
from pocket.apps.fit.case import Request
from pocket.apps.fit.leastsquares import fit
from pocket.apps.fit.report import CASE, FIGURE, write
from pocket.core.materials import check

RADIUS, THICKNESS = 0.020, 0.001  # m
TRUTH = {"c10": 85e3, "c20": -2e3, "c30": 0.2e3}  # Pa: the rubber behind the made-up test
NOISE, SEED, POINTS = 0.002, 1, 15  # relative noise of the heights, its seed, the test's pressures


def bulge_test(path: pathlib.Path) -> None:
    """Write the made-up bulge test: POINTS pressures (kPa) and pole heights (mm)."""
    truth = check("yeoh", TRUTH)
    tension = 3.0 * truth.mu0 * THICKNESS  # E T, N/m
    rng = np.random.default_rng(SEED)
    phats = np.linspace(0.02, 0.6, POINTS)
    states = shooting.inflation_curve(truth.scaled(), list(phats))
    rows = [f"{p * tension / RADIUS / 1e3:.6g},{s.height * RADIUS * 1e3 * (1.0 + NOISE * rng.standard_normal()):.6g}"
            for p, s in zip(phats, states, strict=True)]
    path.write_text("pressure [kPa],height [mm]\n" + "\n".join(rows) + "\n")


# %%
# The fit solves the model at every datum for each trial rubber and minimises the squared relative
# residuals (model / data - 1) with scipy's least squares, from several starts. Each parameter's
# standard error comes from the Jacobian and the residuals' variance; its 95 % interval from the
# profile likelihood: the parameter held at trial values, the others re-fitted, until the rise of the
# squared residuals reaches Student's t. ``write`` stores the fit's figure and the fitted sheet as a
# case file (``fitted.toml``), which ``solve`` presses with the plate at its forces.
def main(out: pathlib.Path) -> dict:
    """Make the bulge test, fit it, press the fitted sheet, print each, write the files into ``out``; returns
    what it printed, unrounded: ``{"fit": the fit's result (pocket.apps.fit), "case": the fitted sheet's case
    file, "pressed": its solved case (pocket.apps.casefile.solve)}``."""
    out.mkdir(parents=True, exist_ok=True)
    data = out / "bulge.csv"
    bulge_test(data)
    request = Request((data,), "yeoh", RADIUS, THICKNESS)
    result = fit(request.setup(), request.law)
    s = result.statistics
    print(f"yeoh fitted to {data.name}: {result.calls} solver calls, residual RMS {s.rms:.3g}")
    print(f"  {'':<4} {'fitted (Pa)':>12} {'std error':>10} {'95 % interval (Pa)':>24} {'truth (Pa)':>11}")
    for name, value, error, (low, high) in zip(s.names, s.values, s.standard_errors, s.intervals, strict=True):
        print(f"  {name:<4} {value:>12.6g} {error:>10.2g} {f'[{low:.6g}, {high:.6g}]':>24} {TRUTH[name]:>11g}")
    print(f"  mu_0 = {s.mu0:.6g} Pa +- {s.mu0_error:.2g} (truth {check('yeoh', TRUTH).mu0:g} Pa)")
    for warning in s.warnings:
        print(f"  warning: {warning}")
    folder = write(result, (out / "fit").resolve())
    print(f"wrote fit/{FIGURE} and fit/{CASE} in the output folder")
    pressed = solve(load(folder / CASE))
    print(f"the fitted sheet pressed by the plate at P_I = {pressed['inflated']['pressure_Pa'] / 1e3:.4g} kPa "
          f"(H0 = {pressed['inflated']['height_m'] * 1e3:.4g} mm):")
    print(f"  {'force_N':>10} {'pressure_kPa':>13} {'travel_mm':>10}")
    for row in pressed["states"]:
        print(f"  {row['force_N']:>10.4g} {row['pressure_Pa'] / 1e3:>13.6g} {row['travel_m'] * 1e3:>10.6g}")
    return {"fit": result, "case": folder / CASE, "pressed": pressed}


# %%
# The figure: the data with the fitted curve, the residuals, and each parameter's 95 % interval
# relative to the truth (a fit to noisy data lands near the truth, not on it; the interval says how
# near).
def draw(numbers: dict):
    """Data and fitted curve, residuals, and the intervals against the truth."""
    result = numbers["fit"]
    test = result.setup.tests[0]
    material = result.material
    tension = 3.0 * material.mu0 * THICKNESS  # E T of the fitted sheet, N/m
    phats = np.linspace(test.control[0], test.control[-1], 60) * RADIUS / tension
    curve = shooting.inflation_curve(material.scaled(), list(phats))
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), layout="constrained")
    axes[0].plot(test.control / 1e3, test.responses["height"] * 1e3, "o", label="bulge.csv")
    axes[0].plot(phats * tension / RADIUS / 1e3, [s.height * RADIUS * 1e3 for s in curve], "-", label="fitted Yeoh")
    axes[0].set_xlabel("pressure (kPa)")
    axes[0].set_ylabel("pole height (mm)")
    axes[0].legend()
    axes[1].axhline(0.0, color="0.6")
    axes[1].plot(test.control / 1e3, result.residuals, "o")
    axes[1].set_xlabel("pressure (kPa)")
    axes[1].set_ylabel("model / data - 1")
    s = result.statistics
    truth = np.array([TRUTH[name] for name in s.names])
    ratio = s.values / truth - 1
    low, high = np.sort(s.intervals / truth[:, None] - 1, axis=1).T  # a negative truth flips the ends
    y = np.arange(len(s.names))
    axes[2].errorbar(ratio, y, xerr=[ratio - low, high - ratio], fmt="o", capsize=4)
    axes[2].axvline(0.0, color="k", lw=0.8)
    axes[2].set_yticks(y, s.names)
    axes[2].set_xlabel("fitted / truth - 1 (95 % interval)")
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


# %%
# Run it: the files go to the folder given on the command line, or to a temporary one.
if __name__ == "__main__":
    if len(sys.argv) > 1:
        draw(main(pathlib.Path(sys.argv[1])))
    else:
        with tempfile.TemporaryDirectory() as folder:
            draw(main(pathlib.Path(folder)))
    plt.show()
