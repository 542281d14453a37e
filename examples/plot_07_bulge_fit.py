"""Your rubber from your bulge test: fit a Yeoh sheet to a spreadsheet of pressures and heights, then press it.

A sheet of 1 mm silicone clamped over a 20 mm radius is inflated and its pole height read at 30
pressures: ``bulge.csv``, in kPa and mm as a spreadsheet would give them (here made by the model from
a known Yeoh rubber, C10 = 85 kPa, C20 = -2 kPa, C30 = 0.2 kPa, with 0.2 % seeded noise, so that
you can see what the fit recovers). The script fits the Yeoh law to it as ``pocket fit`` does,
prints each parameter with its standard error, writes the figure of the fit (data, curve, residuals)
and the fitted sheet's case file, then presses that sheet with the flat plate from its case file, as
``pocket run`` does, and prints the force against the pressure and the travel.

    python examples/bulge_fit.py [OUTPUT_FOLDER]      (default: bulge-fit)
"""

import pathlib
import sys

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
NOISE, SEED = 0.002, 1  # relative noise of the heights, and its seed


def bulge_test(path: pathlib.Path) -> None:
    """Write the made-up bulge test: 30 pressures (kPa) and pole heights (mm)."""
    truth = check("yeoh", TRUTH)
    tension = 3.0 * truth.mu0 * THICKNESS  # E T, N/m
    rng = np.random.default_rng(SEED)
    phats = np.linspace(0.02, 0.6, 30)
    states = shooting.inflation_curve(truth.scaled(), list(phats))
    rows = [f"{p * tension / RADIUS / 1e3:.6g},{s.height * RADIUS * 1e3 * (1.0 + NOISE * rng.standard_normal()):.6g}"
            for p, s in zip(phats, states, strict=True)]
    path.write_text("pressure [kPa],height [mm]\n" + "\n".join(rows) + "\n")


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
    print(f"yeoh fitted to {data.name}: {result.calls} solver calls, {result.seconds:.1f} s, residual RMS {s.rms:.3g}")
    for name, value, error in zip(s.names, s.values, s.standard_errors, strict=True):
        print(f"  {name} = {value:.6g} Pa +- {error:.2g}")
    print(f"  mu_0 = {s.mu0:.6g} Pa +- {s.mu0_error:.2g}")
    for warning in s.warnings:
        print(f"  warning: {warning}")
    folder = write(result, (out / "fit").resolve())
    print(f"wrote {folder / FIGURE} and {folder / CASE}")
    pressed = solve(load(folder / CASE))
    print(f"the fitted sheet pressed by the plate at P_I = {pressed['inflated']['pressure_Pa'] / 1e3:.4g} kPa "
          f"(H0 = {pressed['inflated']['height_m'] * 1e3:.4g} mm):")
    print(f"  {'force_N':>10} {'pressure_kPa':>13} {'travel_mm':>10}")
    for row in pressed["states"]:
        print(f"  {row['force_N']:>10.4g} {row['pressure_Pa'] / 1e3:>13.6g} {row['travel_m'] * 1e3:>10.6g}")
    return {"fit": result, "case": folder / CASE, "pressed": pressed}


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "bulge-fit"))
