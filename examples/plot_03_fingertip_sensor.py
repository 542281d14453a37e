"""
A fingertip force sensor filled with air
========================================

The paper's closing idea: a pocket is a force sensor, for the force on it can be read from the rise of
its pressure. Here the pocket is the paper's sample 1 (a 0.25 mm silicone sheet over a 20 mm radius)
filled with air at 5 kPa above the atmosphere, and what presses it is a fingertip, a sphere of 8 mm
radius. ``pocket.apps.sense`` gives its calibration (pressure against force), its sensitivity dP/dF,
the sensitivity at rest from the inflated pocket alone, and the linearity of P(F) over the range.

Run it as a script: ``python examples/plot_03_fingertip_sensor.py``.
"""

# %%
# A case in physical units, as a case file would hold it: the sheet, the clamp, the initial pressure,
# the fluid (air, an ideal gas sealed at P_I, compressed isothermally: gamma = 1) and the indenter.
# ``resolve`` turns it into the model's dimensionless pocket.
import matplotlib.pyplot as plt
import numpy as np

from pocket.apps.cases import parse
from pocket.apps.physical import resolve
from pocket.apps.sense import calibration, linearity, sense, sensitivity_at_rest

CASE = {"name": "air sensor",
        "sheet": {"thickness": "0.25 mm", "c1": "160 kPa", "c2": "47 kPa"}, "clamp": {"radius": "20 mm"},
        "initial": {"pressure": "5 kPa"}, "fluid": {"kind": "gas", "ambient": "101.325 kPa", "gamma": 1.0},
        "indenter": {"shape": "sphere", "radius": "8 mm"}, "loads": {"forces": ["0 N", "1 N"]}}
FULL_SCALE, POINTS = "1 N", 11  # the calibration's force range (from 0) and its rows
READING = "6 kPa"  # a pressure read on the sensor


# %%
# The calibration solves the compression curve at evenly spaced forces and takes dP/dF there by
# central differences. The sensitivity at rest comes another way, by reciprocity (Maxwell-Betti): the
# pressure and the volume, the force and the indenter's descent, are conjugate pairs, so
# dP/dF at F = 0 is (dH0/dP) / (dV0/dP + V / (gamma (P + P_atm))), from inflations alone. The air's
# compliance, the second term of the denominator, makes the sensor less sensitive than a liquid one.
# A pressure read on the sensor is turned into a force by inverting the model (no fitted curve).
def main() -> dict:
    """Calibrate the sensor, print it; returns ``{"calibration": [Reading, ...], "at_rest": dP/dF at F = 0
    (kPa/N), "linearity": % of full scale, "reading": the Reading at READING}`` (``pocket.apps.sense``)."""
    pocket = resolve(parse(CASE, where="air sensor"))
    rows = calibration(pocket, FULL_SCALE, POINTS)
    at_rest = sensitivity_at_rest(pocket)
    forces, pressures = [r.force_N for r in rows], [r.pressure_Pa for r in rows]
    span = linearity(forces, pressures)
    reading = sense(pocket, pressure=READING)
    print(f"air at P_I = {pocket.pressure_initial_Pa / 1e3:g} kPa (Phat_I = {pocket.pressure_initial:.4g}) under an "
          f"8 mm fingertip")
    print(f"{'F (N)':>7} {'P (kPa)':>9} {'dP/dF (kPa/N)':>14} {'travel (mm)':>12} {'contact (mm^2)':>15}")
    for r in rows:
        print(f"{r.force_N:>7.3f} {r.pressure_Pa / 1e3:>9.4f} {r.sensitivity_kPa_per_N:>14.4f} "
              f"{r.travel_m * 1e3:>12.4f} {r.contact_area_m2 * 1e6:>15.3f}")
    print(f"sensitivity at rest: {at_rest:.7f} kPa/N by reciprocity from the inflated pocket, "
          f"{rows[0].sensitivity_kPa_per_N:.7f} kPa/N from the compression curve")
    print(f"linearity over 0 to {FULL_SCALE}: {span:.3g} % of full scale")
    print(f"a reading of {READING} means F = {reading.force_N:.4f} N")
    return {"calibration": rows, "at_rest": at_rest, "linearity": span, "reading": reading}


# %%
# The figure: the calibration beside a straight line (the linearity is measured against the line that
# makes the largest deviation smallest; the least-squares line drawn is close to it), and the
# sensitivity, which grows with the force as the contact patch widens on the fingertip.
def draw(numbers: dict):
    """Calibration curve and sensitivity against the force."""
    rows = numbers["calibration"]
    f = np.array([r.force_N for r in rows])
    p = np.array([r.pressure_Pa for r in rows]) / 1e3
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8), layout="constrained")
    left.plot(f, p, "o-", label="model")
    left.plot(f, np.polyval(np.polyfit(f, p, 1), f), "--", color="0.5", label="least-squares line")
    left.plot([numbers["reading"].force_N], [numbers["reading"].pressure_Pa / 1e3], "s", color="tab:red",
              label=f"a reading of {READING}")
    left.set_xlabel("force F (N)")
    left.set_ylabel("pressure P (kPa)")
    left.legend()
    right.plot(f, [r.sensitivity_kPa_per_N for r in rows], "o-", label="along the calibration")
    right.plot([0.0], [numbers["at_rest"]], "*", ms=14, color="tab:red", label="at rest, by reciprocity")
    right.set_xlabel("force F (N)")
    right.set_ylabel("sensitivity dP/dF (kPa/N)")
    right.legend()
    for ax in (left, right):
        ax.grid(alpha=0.3)
    fig.suptitle(f"air-filled sensor under an 8 mm fingertip: linearity {numbers['linearity']:.2g} % of full scale")
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
