"""
Your own indenter, read from a CSV table
========================================

An indenter need not be a plate or a sphere: any convex body of revolution, flat on the axis, can press
the pocket. Its lower surface is given as a table of heights z against the radius, in a CSV file with
the units in its header, as a spreadsheet or a measurement would give it. This example writes such a
table for a paraboloid tip (z = rho^2 / (2 R_t), R_t = 8 mm, to 12 mm from the axis) into a temporary
folder, reads it back as a ``Profile`` indenter, presses the paper's pocket with it and compares it with
the sphere of the same tip radius.

Run it as a script: ``python examples/plot_04_profile_indenter.py``.
"""

# %%
# ``read_csv`` reads the table and divides its lengths by the clamp radius (the model's unit). The
# table is interpolated by a cubic spline in rho^2, which keeps the profile flat on the axis; a
# paraboloid is linear in rho^2, so the spline reproduces it exactly.
import pathlib
import tempfile

import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting
from pocket.core.indenters import Profile, Sphere
from pocket.core.profiles import read_csv

RADIUS, TIP, REACH, ROWS = 0.020, 0.008, 0.012, 13  # m: clamp radius, tip radius, the table's last radius; rows
ALPHA, PRESSURE = 47 / 160, 0.31  # the paper's pocket: C2/C1, Phat_I
FORCES = (0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0)  # Fhat


def write_table(path: pathlib.Path) -> None:
    """The paraboloid tip as a CSV table in millimetres."""
    rho = np.linspace(0.0, REACH, ROWS)
    path.write_text("radius [mm],height [mm]\n" + "".join(f"{r * 1e3:.6g},{r * r / (2 * TIP) * 1e3:.6g}\n"
                                                          for r in rho))


# %%
# On a curved indenter the contact pressure exceeds the fluid's, so F = P A_c no longer holds. The
# force follows instead from the equilibrium of the sheet in contact, cut at the contact edge (radius
# rho_c in the deformed sheet, where the sheet leaves the indenter at the angle theta_c of its slope):
# the fluid pushes it up with P pi rho_c^2, the rest of the sheet pulls it up with its meridional
# tension, 2 pi rho_c T_1 sin(theta_c), and the indenter pushes it down with F. The script checks that
# balance on every state (in the model's units, Fhat = (Phat rho_c^2 + 2 rho_c T_1 sin theta_c) / Phat_I).
def free_body_force(state) -> float:
    """Fhat from the contact cap's equilibrium: the fluid's pressure and the tension at the contact edge."""
    rho_c = state.contact_radius_deformed
    slope = float(state.indenter.slope(rho_c))
    tension = float(np.interp(rho_c, state.profile.rho, state.profile.tension_1))
    return (state.pressure * rho_c**2 + 2 * rho_c * tension * slope / np.hypot(1.0, slope)) / state.pressure_initial


def main(out: pathlib.Path) -> dict:
    """Write the table into ``out``, press the pocket with it and with the sphere, print both; returns
    ``{"profile": [state, ...], "sphere": [state, ...]}`` at ``FORCES``."""
    table = out / "tip.csv"
    write_table(table)
    tip = Profile(read_csv(table, RADIUS))
    states = {"profile": shooting.compression_curve(ALPHA, PRESSURE, FORCES, indenter=tip),
              "sphere": shooting.compression_curve(ALPHA, PRESSURE, FORCES, indenter=Sphere(TIP / RADIUS))}
    print(f"{table.name}: {ROWS} rows, a paraboloid of tip radius {TIP * 1e3:g} mm to {REACH * 1e3:g} mm from the axis")
    print(f"{'Fhat':>5} {'P/P_I paraboloid':>17} {'P/P_I sphere':>13} {'rho_c/R':>8} {'p_c pole/P':>11} "
          f"{'free body / Fhat - 1':>21}")
    for p, s in zip(states["profile"], states["sphere"], strict=True):
        print(f"{p.force:>5.2f} {p.pressure_ratio:>17.6f} {s.pressure_ratio:>13.6f} {p.contact_radius_deformed:>8.4f} "
              f"{p.contact_pressure_pole / p.pressure:>11.4f} {free_body_force(p) / p.force - 1:>+21.1e}")
    return states


# %%
# The figure: the pressure rise under both tips, and the sheet's profile at the largest force with the
# indenter's surface. They share their tip curvature, so they press alike while the contact is small;
# further out the paraboloid is flatter than the sphere, which sinks deeper into the dome: the pressure
# rises less under the paraboloid.
def draw(states: dict):
    """P/P_I against the force, and the deformed profiles at the largest force."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.8), layout="constrained")
    for name, curve in states.items():
        left.plot([s.force for s in curve], [s.pressure_ratio for s in curve], "o-", label=name)
        last = curve[-1]
        line, = right.plot(last.profile.rho, last.profile.eta, label=f"sheet under the {name}")
        rho = np.linspace(0.0, min(last.indenter.reach, 0.8), 200)
        right.plot(rho, last.height + last.indenter.height(rho), ":", color=line.get_color())
    left.set_xlabel(r"$F/(P_I \pi R^2)$")
    left.set_ylabel("$P/P_I$")
    left.legend()
    right.set_xlabel(r"$\rho/R$")
    right.set_ylabel(r"$\eta/R$")
    right.set_aspect("equal")
    right.legend(fontsize=8)
    right.set_title(f"at Fhat = {FORCES[-1]:g} (dotted: the indenters)", fontsize=10)
    for ax in (left, right):
        ax.grid(alpha=0.3)
    return fig


# %%
# Run it; the table lives in a temporary folder that is removed at the end.
if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        draw(main(pathlib.Path(folder)))
    plt.show()
