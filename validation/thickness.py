"""The section "How thick is too thick": the membrane against the solid for the paper's four samples.

Both membrane solvers and the paper model the sheet as a surface without thickness. ``pocket.solid``
solves its cross-section as an incompressible solid (the same rubber, the clamp through the thickness,
the fluid on the lower surface, the plate on the upper one), so the difference between the two is the
membrane's own modelling error, first order in T/R. Here the paper's four samples of Table 1 (T = 0.25,
0.5, 0.8, 1.6 mm on R = 20 mm: T/R = 0.0125 to 0.08, Mooney-Rivlin C1 = 160 kPa, C2 = 47 kPa, a liquid)
are inflated to each pressure P_I of the plan and pressed by the plate at its forces Fhat, by the shooting
solver (the membrane) and the solid at its default mesh. The error of a quantity is membrane / solid - 1
(the solid taken as the continuum it approximates). The solid's own mesh error is small beside these
differences except in the contact area, its least resolved output: at Fhat = 0.2 (the smallest contact),
128 elements along the radius (the default: 64) move A_c by 0.8 % for sample 1 at 2 kPa, and for sample 4
by 0.7 % at 5 kPa and 6 % at 2 kPa (there, with 8 layers, the membrane's error goes from 118 % to 105 %).

Which heights are compared: the membrane's surface is the sheet's mid-surface, whose heights are the
solid's ``height_mid``; a plate or a laser meets the upper surface, lambda_3 T / 2 above the mid-surface at
the pole (lambda_3 = 1 / (lambda_1 lambda_2), the sheet's thinned thickness over T). The rows "upper
surface" compare the membrane's mid-surface height plus that half thickness with the solid's upper surface:
the membrane's best answer to what the plate measures. The volume is the fluid's, under the lower surface,
for the solid, and under the mid-surface for the membrane: for an incompressible sheet the two differ at
second order only (the offset surface's volume gained by thinning is exactly the reference plane's T / 2
lower: int lambda_3 dA_deformed = pi R^2), so the membrane's V is its best first-order answer too. The
row "V (membrane's lower surface)" shows it: the membrane's volume under its lower surface
(``pocket.core.offset``) removes a fraction of order T/R of the membrane's volume error, which comes from
the clamp, where the solid bends over a few thicknesses and the membrane's slope jumps.

The verdict: where the membrane is within ``LIMIT`` (1 %) of the solid, per quantity and sample. The
checks are informational: a model's error is a fact about the model, not a tolerance of the software.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from pocket.apps.cases import SAMPLES, sample

from .plotdata import Figure, Panel, Series
from .verdicts import Check

__all__ = [
    "COMPARISON",
    "LIMIT",
    "QUANTITIES",
    "Comparison",
    "checks",
    "compare",
    "figure",
    "posed",
    "rows",
    "slopes",
    "verdict",
]

#: the error a user may accept from the membrane: the report says where it holds
LIMIT = 0.01
#: the compared quantities: inflation first, then at each force
INFLATION = ("V", "V (membrane's lower surface)", "H0 (mid-surface)", "H0 (upper surface)")
COMPRESSION = ("P/P_I", "H/H0 (mid-surface)", "H/H0 (upper surface)", "A_c")
QUANTITIES = INFLATION + COMPRESSION
#: the comparison name of its checks
COMPARISON = "membrane (shooting) vs solid"


@dataclasses.dataclass(frozen=True)
class Comparison:
    """One sample at one pressure: its number, T/R, P_I (kPa), Phat_I, the forces Fhat compressed to, and
    ``values``: (quantity, Fhat or None) -> (membrane, solid); ``seconds`` of the solid's solve."""

    sample: int
    thickness_ratio: float
    pressure_kpa: float
    pressure: float
    forces: tuple[float, ...]
    values: dict
    seconds: float

    @property
    def label(self) -> str:
        return f"sample {self.sample} (T/R = {self.thickness_ratio:g}) at {self.pressure_kpa:g} kPa"

    def error(self, quantity: str, force=None) -> float:
        """membrane / solid - 1 of ``quantity`` (at the force Fhat ``force``; None for the inflated pocket)."""
        membrane, solid = self.values[quantity, force]
        return membrane / solid - 1.0


def _half_thickness(state, t: float) -> float:
    """lambda_3 t / 2 at the pole of a membrane state (units R): the upper surface above the mid-surface."""
    return 0.5 * t / (state.profile.stretch_1[0] * state.profile.stretch_2[0])


def posed(number: int, pressure_kpa: float):
    """(the rubber in units of its mu_0, Phat_I, T/R) of sample ``number`` inflated to ``pressure_kpa``."""
    case = sample(number)
    phat = pressure_kpa * 1e3 * case.radius / (case.modulus * case.thickness)
    return case.material.scaled(), phat, case.thickness / case.radius


def compare(number: int, pressure_kpa: float, forces: tuple[float, ...]) -> Comparison:
    """Sample ``number`` inflated to ``pressure_kpa`` and pressed at ``forces`` (Fhat), by the membrane and the
    solid (module docstring)."""
    from pocket import shooting, solid

    material, phat, t = posed(number, pressure_kpa)
    membrane = shooting.compression_curve(material, phat, forces)
    start = time.perf_counter()
    continuum = solid.compression_curve(material, phat, forces, thickness_ratio=t)
    seconds = time.perf_counter() - start
    m0, s0 = membrane[0].inflated, continuum[0].inflated
    m_top0 = m0.height + _half_thickness(m0, t)
    values: dict[tuple[str, float | None], tuple[float, float]] = {("V", None): (m0.volume, s0.volume),
              ("V (membrane's lower surface)", None): (m0.volume_lower(t), s0.volume),
              ("H0 (mid-surface)", None): (m0.height, float(s0.extra["height_mid"])),
              ("H0 (upper surface)", None): (m_top0, s0.height)}
    for f, m, s in zip(forces, membrane, continuum, strict=True):
        values["P/P_I", f] = (m.pressure_ratio, s.pressure_ratio)
        values["H/H0 (mid-surface)", f] = (m.height_ratio, float(s.extra["height_mid"]) / float(s0.extra["height_mid"]))
        values["H/H0 (upper surface)", f] = ((m.height + _half_thickness(m, t)) / m_top0, s.height_ratio)
        values["A_c", f] = (m.contact_area, s.contact_area)
    return Comparison(number, t, pressure_kpa, phat, tuple(forces), values, seconds)


def _keys(c: Comparison):
    yield from ((q, None) for q in INFLATION)
    yield from ((q, f) for f in c.forces for q in COMPRESSION)


def _where(c: Comparison, force) -> str:
    return (f"P_I = {c.pressure_kpa:g} kPa (Phat_I = {c.pressure:.4g}), "
            + ("inflated" if force is None else f"F/(P_I pi R^2) = {force:g}"))


def checks(comparisons) -> list[Check]:
    """Every compared quantity, informational: the membrane's value against the solid's."""
    out = []
    for c in comparisons:
        for quantity, force in _keys(c):
            membrane, solid = c.values[quantity, force]
            out.append(Check(f"sample {c.sample}", COMPARISON, "inflation" if force is None else "compression",
                             quantity, _where(c, force), float(membrane), float(solid),
                             abs(c.error(quantity, force)), None, "info"))
    return out


def rows(comparisons) -> tuple[list, list]:
    """(header, rows): each sample, pressure, force and quantity with the membrane's and the solid's values."""
    header = ["sample", "T/R", "P_I (kPa)", "F/(P_I pi R^2)", "quantity", "membrane", "solid", "membrane / solid - 1",
              f"within {LIMIT:.0%}"]
    out = []
    for c in comparisons:
        for quantity, force in _keys(c):
            membrane, solid = c.values[quantity, force]
            error = c.error(quantity, force)
            out.append([c.sample, f"{c.thickness_ratio:g}", f"{c.pressure_kpa:g}",
                        "" if force is None else f"{force:g}", quantity, f"{membrane:.6g}", f"{solid:.6g}",
                        f"{error:+.2e}", "yes" if abs(error) <= LIMIT else "no"])
    return header, out


def _worst(comparisons, quantity) -> dict:
    """sample -> the largest |error| of ``quantity`` over its pressures and forces."""
    out: dict = {}
    for c in comparisons:
        forces = [None] if quantity in INFLATION else c.forces
        worst = max(abs(c.error(quantity, f)) for f in forces)
        out[c.sample] = max(out.get(c.sample, 0.0), worst)
    return out


def slopes(comparisons) -> dict:
    """quantity -> the slope of log(largest |error|) against log(T/R) over the samples (np.polyfit): the
    order in T/R of the membrane's error across the four samples (each at its own Phat_I)."""
    ratio = {c.sample: c.thickness_ratio for c in comparisons}
    out = {}
    for quantity in QUANTITIES:
        worst = _worst(comparisons, quantity)
        numbers = sorted(n for n in worst if worst[n] > 0.0)
        if len(numbers) >= 2:
            out[quantity] = float(np.polyfit(np.log([ratio[n] for n in numbers]),
                                             np.log([worst[n] for n in numbers]), 1)[0])
    return out


def verdict(comparisons) -> list[str]:
    """One sentence per quantity: the samples where the membrane is within LIMIT of the solid, and those where
    it is not (the largest error of each)."""
    out = []
    for quantity in QUANTITIES:
        worst = _worst(comparisons, quantity)
        within = [n for n in sorted(worst) if worst[n] <= LIMIT]
        beyond = [n for n in sorted(worst) if worst[n] > LIMIT]
        text = f"{quantity}: "
        text += (f"within {LIMIT:.0%} for sample{'s' if len(within) > 1 else ''} {', '.join(map(str, within))}"
                 if within else f"within {LIMIT:.0%} for no sample")
        if beyond:
            text += "; not for " + ", ".join(f"sample {n} ({worst[n]:.1%})" for n in beyond)
        out.append(text + f" (largest error {max(worst.values()):.2%}).")
    return out


def figure(comparisons) -> Figure:
    """The largest |membrane / solid - 1| of each quantity against T/R (log-log), inflation (a) and
    compression (b), with the 1 % line and a slope-1 guide."""
    ratios = np.array(sorted({c.thickness_ratio for c in comparisons}))
    ratio = {c.sample: c.thickness_ratio for c in comparisons}
    panels = []
    for letter, names, what in (("a", INFLATION, "inflated"), ("b", COMPRESSION, "compressed, worst over the forces")):
        series = []
        for k, quantity in enumerate(names):
            worst = _worst(comparisons, quantity)
            numbers = sorted(worst)
            series.append(Series(quantity, "residual", np.array([ratio[n] for n in numbers]),
                                 np.array([worst[n] for n in numbers]), k))
        top = max(s.y.max() for s in series)
        series.append(Series("slope 1 (first order in T/R)", "theory", ratios, 0.5 * top * ratios / ratios[-1], 9))
        panels.append(Panel(f"({letter}) {what}", "T / R", "|membrane / solid - 1|", tuple(series), log="xy",
                            marks=((None, LIMIT, f"{LIMIT:.0%}"),)))
    pressures = ", ".join(f"{p:g}" for p in sorted({c.pressure_kpa for c in comparisons}))
    forces = ", ".join(f"{f:g}" for f in comparisons[0].forces)
    return Figure("thickness", "The membrane's own error: the largest |membrane / solid - 1| over P_I = "
                  f"{pressures} kPa for the paper's four samples (T = {', '.join(SAMPLES.values())} on R = 20 mm), "
                  f"(a) inflated, (b) pressed by the plate at F/(P_I pi R^2) = {forces}; the solid "
                  "(pocket.solid, an incompressible axisymmetric solid of the sheet's cross-section) is the "
                  "reference. Heights 'mid-surface' compare like with like; 'upper surface' adds lambda_3 T / 2 to "
                  "the membrane (what a plate meets); the membrane's lower-surface volume lies on its V. Dotted "
                  "horizontal line: 1 %; dashed: a slope-1 guide.",
                  tuple(panels))
