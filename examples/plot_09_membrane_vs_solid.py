"""
How thick is too thick: the membrane against the solid
======================================================

The paper's model, like pocket's membrane solvers, gives the sheet no thickness. ``pocket.solid`` solves
the same pocket with the sheet's cross-section as an axisymmetric incompressible solid (clamped through
its thickness, the fluid on its lower surface, the plate on its upper one), so its difference from the
membrane is the membrane's own error. This example first takes the thickest sample of Bouremel et al.,
"Compression of pressurised elastic pockets" (Table 1): a 1.6 mm silicone sheet (Mooney-Rivlin,
C1 = 160 kPa, C2 = 47 kPa) over a 20 mm radius, T/R = 0.08, filled with a liquid at 5 kPa and pressed
by a flat plate, and prints both answers in physical units with the membrane's error, membrane / solid
- 1. Then it inflates the paper's pocket at several thickness ratios to show how that error falls with
T/R.

Heights: the membrane's surface is the sheet's mid-surface; the plate meets the upper surface, half the
thinned thickness (lambda_3 T / 2, lambda_3 = 1 / (lambda_1 lambda_2)) higher. The table gives the
membrane's mid-surface height plus that half thickness, the membrane's best answer to what the plate
sees.

Run it as a script: ``python examples/plot_09_membrane_vs_solid.py``.
"""

# %%
# ``sample(4)`` is the paper's sample as a case in physical units; its rubber in units of mu_0 and
# Phat_I = P_I R / (E T) are what both solvers take. The solid also takes the thickness ratio T/R and
# its mesh: ``elements`` along the radius, ``layers`` through the thickness (its default, 24 by 4, for
# sample 4; a coarser one for the thickness sweep below, whose volume error it gives to a few percent of
# itself). Its clamp holds the sheet between two plates, the upper one's edge rounded to half a thickness
# (``clamp_radius``, in thicknesses): the real clamp, which the membrane, hinged at r = R, does not see.
import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting, solid
from pocket.apps.cases import sample

PRESSURE = 5e3  # Pa: P_I
FORCES = (0.5, 1.0, 2.0)  # N
ALPHA, PHAT = 47 / 160, 0.31  # the paper's pocket of the thickness sweep: C2/C1, Phat_I
RATIOS = (0.01, 0.02, 0.04, 0.08)  # T/R of the thickness sweep
SWEEP_MESH = {"elements": 32, "layers": 2}  # the solid's mesh in the thickness sweep


def _upper(state, thickness_ratio):
    """The upper surface's pole height of a membrane state (units R): mid-surface + lambda_3 T / 2."""
    return state.height + 0.5 * thickness_ratio / (state.profile.stretch_1[0] * state.profile.stretch_2[0])


def _row(table, load, name, unit, membrane, continuum):
    """Print a row of the table and keep its numbers in ``table[load, name]``."""
    print(f"  {name:<34} {membrane:>12.5g} {continuum:>12.5g} {unit:<4} {membrane / continuum - 1.0:>+10.2%}")
    table[load, name] = (membrane, continuum)


# %%
# Sample 4 both ways. The membrane's volume is under its mid-surface, the solid's under its lower
# surface, where the fluid is: the main part of the difference, of the order of T/R.
def main() -> dict:
    """Solve sample 4 both ways and print the table, then the thickness sweep; returns what it printed,
    unrounded: ``{"table": {(load, row name): (membrane, solid)}, "sweep": {T/R: (membrane, solid) inflated
    volumes V/R^3}, "states": (membrane states, solid states) of sample 4}``, the load the force in N (None: the
    inflated sheet), each number in the printed row's unit."""
    case = sample(4)
    radius, t = case.radius, case.thickness / case.radius
    phat = PRESSURE * radius / (case.modulus * case.thickness)
    fhats = [f / (PRESSURE * np.pi * radius**2) for f in FORCES]
    material = case.material.scaled()
    membrane = shooting.compression_curve(material, phat, fhats)
    continuum = solid.compression_curve(material, phat, fhats, thickness_ratio=t)
    m0, s0 = membrane[0].inflated, continuum[0].inflated
    mm, ml = radius * 1e3, radius**3 * 1e6
    print(f"sample 4: T = {case.thickness * 1e3:g} mm, R = {mm:g} mm (T/R = {t:g}), P_I = {PRESSURE / 1e3:g} kPa "
          f"(Phat_I = {phat:.4g}), a liquid")
    print(f"  {'':<34} {'membrane':>12} {'solid':>12} {'':<4} {'error':>10}")
    table: dict = {}
    _row(table, None, "fluid volume", "mL", m0.volume * ml, s0.volume * ml)
    _row(table, None, "pole height, mid-surface", "mm", m0.height * mm, s0.extra["height_mid"] * mm)
    _row(table, None, "pole height, upper surface", "mm", _upper(m0, t) * mm, s0.height * mm)
    for force, m, s in zip(FORCES, membrane, continuum, strict=True):
        print(f" pressed by the plate with {force:g} N:")
        _row(table, force, "pressure", "kPa", m.pressure * PRESSURE / phat / 1e3, s.pressure * PRESSURE / phat / 1e3)
        _row(table, force, "plate height (upper surface)", "mm", _upper(m, t) * mm, s.height * mm)
        _row(table, force, "contact area", "mm^2", m.contact_area * np.pi * mm**2, s.contact_area * np.pi * mm**2)
    sweep = thickness_sweep()
    return {"table": table, "sweep": sweep, "states": (membrane, continuum)}


# %%
# The thickness sweep: the paper's pocket inflated to Phat_I = 0.31 as a membrane and as solids of
# T/R from 0.01 to 0.08. As T/R -> 0 the solid must tend to the membrane, and at first order: the
# volume error divided by T/R settles to a constant, and the slope of log(error) against log(T/R),
# fitted by least squares, is the observed order.
def thickness_sweep() -> dict:
    """The inflated volumes V/R^3 of the membrane and of the solid at each of RATIOS, printed with the
    observed order of their difference: ``{T/R: (membrane, solid)}``."""
    membrane = shooting.inflate(ALPHA, PHAT).volume
    sweep = {t: (membrane, solid.inflate(ALPHA, PHAT, thickness_ratio=t, **SWEEP_MESH).volume) for t in RATIOS}
    print(f"the paper's pocket inflated to Phat_I = {PHAT}: membrane V/R^3 = {membrane:.6f}")
    print(f"  {'T/R':>6} {'solid V/R^3':>12} {'membrane / solid - 1':>21} {'error / (T/R)':>14}")
    for t, (m, s) in sweep.items():
        print(f"  {t:>6g} {s:>12.6f} {m / s - 1:>+21.4%} {(m / s - 1) / t:>14.4f}")
    errors = [m / s - 1 for m, s in sweep.values()]
    print(f"  observed order in T/R: {np.polyfit(np.log(RATIOS), np.log(errors), 1)[0]:.3f}")
    return sweep


# %%
# The figure: both sheets' cross-sections (mm), inflated and pressed at the largest force, and the
# volume error of the thickness sweep against T/R.
def draw(numbers: dict):
    """Sample 4's sheets, inflated (a) and pressed at the largest force (b): the solid's mid-surface, and the
    membrane's with its thinned thickness lambda_3 T drawn about it; (c) the sweep's volume error."""
    membrane, continuum = numbers["states"]
    case = sample(4)
    t, radius = case.thickness / case.radius, case.radius
    fig, axes = plt.subplot_mosaic([["a", "c"], ["b", "c"]], figsize=(11, 5.5), layout="constrained",
                                   width_ratios=[2, 1])
    mm = radius * 1e3
    for key, (title, m, s) in zip("ab", (("(a) inflated", membrane[0].inflated, continuum[0].inflated),
                                         (f"(b) pressed with {FORCES[-1]:g} N", membrane[-1], continuum[-1])),
                                  strict=True):
        ax, p = axes[key], m.profile
        half = 0.5 * t / (p.stretch_1 * p.stretch_2)  # lambda_3 T / 2
        ds, de = np.gradient(p.rho, p.r), np.gradient(p.eta, p.r)
        nr, nz = -de / np.hypot(ds, de), ds / np.hypot(ds, de)  # the upward normal
        for sign in (1.0, -1.0):
            ax.plot((p.rho + sign * half * nr) * mm, (p.eta + sign * half * nz) * mm, color="tab:blue",
                    linewidth=0.8, linestyle="--", label=r"membrane $\pm \lambda_3 T/2$" if sign > 0 else None)
        ax.plot(p.rho * mm, p.eta * mm, color="tab:blue", linewidth=1.5, label="membrane (mid-surface)")
        ax.plot(s.profile.rho * mm, s.profile.eta * mm, color="tab:red", linewidth=1.5, label="solid (mid-surface)")
        if hasattr(s, "contact_area"):
            ax.axhline(s.height * mm, color="0.3", linewidth=2.0, label="plate (on the solid)")
        ax.set_title(title, fontsize=10)
        ax.set_ylabel("height (mm)")
        ax.set_aspect("equal")
        ax.legend(fontsize=7, loc="lower left")
    axes["b"].set_xlabel("radius (mm)")
    ratios = np.array(list(numbers["sweep"]))
    errors = np.array([m / s - 1 for m, s in numbers["sweep"].values()])
    axes["c"].loglog(ratios, errors, "o-", label="membrane / solid - 1, volume")
    axes["c"].loglog(ratios, ratios, ":", color="0.5", label="T/R")
    axes["c"].set_xticks(ratios, [f"{t:g}" for t in ratios], minor=False)
    axes["c"].set_xticks([], minor=True)
    axes["c"].set_xlabel("T/R")
    axes["c"].set_title(f"(c) the paper's pocket inflated, Phat_I = {PHAT}", fontsize=10)
    axes["c"].legend(fontsize=8)
    axes["c"].grid(alpha=0.3, which="both")
    fig.suptitle(f"Sample 4 (T/R = {t:g}) at {PRESSURE / 1e3:g} kPa: membrane against solid", fontsize=10)
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
