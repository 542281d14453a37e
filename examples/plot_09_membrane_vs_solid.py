"""Is a membrane good enough for a 1.6 mm sheet? The membrane against the solid for the paper's sample 4.

The thickest sample of Bouremel et al., "Compression of pressurised elastic pockets" (Table 1): a 1.6 mm
silicone sheet (Mooney-Rivlin, C1 = 160 kPa, C2 = 47 kPa) clamped over a 20 mm radius, T/R = 0.08, filled
with a liquid at 5 kPa and pressed by a flat plate. The script solves it twice: as a membrane (the shooting
solver: a surface without thickness, the paper's model) and as a solid (``pocket.solid``: the sheet's
cross-section as an incompressible solid, clamped through its thickness, the liquid on its lower surface
and the plate on its upper one). It prints each answer in physical units with the membrane's error,
membrane / solid - 1, and draws both sheets, inflated and pressed at the largest force.

Heights: the membrane's surface is the sheet's mid-surface; the plate meets the upper surface, half the
thinned thickness (lambda_3 T / 2, lambda_3 = 1 / (lambda_1 lambda_2)) higher. The table gives the
membrane's mid-surface height plus that half thickness, the membrane's best answer to what the plate sees.

    python examples/membrane_error.py [OUTPUT_FOLDER]      (default: membrane-error)
"""

import pathlib
import sys

import numpy as np

from pocket import shooting, solid
from pocket.apps.cases import sample

PRESSURE = 5e3  # Pa: P_I
FORCES = (0.5, 1.0, 2.0)  # N


def _upper(state, thickness_ratio):
    """The upper surface's pole height of a membrane state (units R): mid-surface + lambda_3 T / 2."""
    return state.height + 0.5 * thickness_ratio / (state.profile.stretch_1[0] * state.profile.stretch_2[0])


def _row(table, load, name, unit, membrane, continuum):
    """Print a row of the table and keep its numbers in ``table[load, name]``."""
    print(f"  {name:<34} {membrane:>12.5g} {continuum:>12.5g} {unit:<4} {membrane / continuum - 1.0:>+10.2%}")
    table[load, name] = (membrane, continuum)


def main(out: pathlib.Path) -> dict:
    """Solve sample 4 both ways, print the table, draw the figure into ``out``; returns what it printed,
    unrounded: ``{"table": {(load, row name): (membrane, solid)}, "figure": its path}``, the load the force in
    N (None: the inflated sheet), each number in the printed row's unit."""
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
    figure = draw(out, membrane, continuum, t, radius)
    print(f"wrote {figure}")
    return {"table": table, "figure": figure}


def draw(out: pathlib.Path, membrane, continuum, t: float, radius: float) -> pathlib.Path:
    """Both sheets' cross-sections (mm), inflated (a) and pressed at the largest force (b): the solid's
    mid-surface, and the membrane's with its thinned thickness lambda_3 T drawn about it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    mm = radius * 1e3
    for ax, (title, m, s) in zip(axes, (("(a) inflated", membrane[0].inflated, continuum[0].inflated),
                                        (f"(b) pressed with {FORCES[-1]:g} N", membrane[-1], continuum[-1])),
                                 strict=True):
        p = m.profile
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
        ax.set_title(title)
        ax.set_ylabel("height (mm)")
        ax.set_aspect("equal")
        ax.legend(fontsize=7, loc="lower left")
    axes[-1].set_xlabel("radius (mm)")
    fig.suptitle(f"Sample 4 (T/R = {t:g}) at {PRESSURE / 1e3:g} kPa: membrane against solid", fontsize=10)
    fig.tight_layout()
    out.mkdir(parents=True, exist_ok=True)
    path = out / "membrane_error.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "membrane-error"))
