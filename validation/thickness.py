"""The section "How thick is too thick": the membrane against the solid for the paper's four samples.

Both membrane solvers and the paper model the sheet as a surface without thickness. ``pocket.solid``
solves its cross-section as an incompressible solid (the same rubber, the clamp through the thickness,
the fluid on the lower surface, the plate on the upper one), so the difference between the two is the
membrane's own modelling error, first order in T/R. Here the paper's four samples of Table 1 (T = 0.25,
0.5, 0.8, 1.6 mm on R = 20 mm: T/R = 0.0125 to 0.08, Mooney-Rivlin C1 = 160 kPa, C2 = 47 kPa, a liquid)
are inflated to each pressure P_I of the plan and pressed by the plate at its forces Fhat, by the shooting
solver (the membrane) and the solid at its default mesh. The error of a quantity is membrane / solid - 1
(the solid taken as the continuum it approximates). Beside each error stands the solid's own: the same curve
solved again on ``REFINED`` (twice the elements along the radius and through the thickness, the clamp's
corner elements half as long), and the error's change, |membrane / refined - membrane / solid|, is the
uncertainty the solid's mesh puts on it (for a first-order quantity about its size, for a second-order one a
third of it: an honest bound either way, not a tolerance).

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
from pocket.solid import DEFAULT_CORNER, DEFAULT_ELEMENTS, DEFAULT_LAYERS

from pocket.apps.cases import SAMPLES, sample

from .plotdata import Figure, Panel, Series
from .verdicts import Check

__all__ = [
    "COMPARISON",
    "LIMIT",
    "QUANTITIES",
    "REFINED",
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
#: the solid's mesh refined along all three of its axes at once: its change is the solid's own uncertainty
REFINED: dict = {"elements": 2 * DEFAULT_ELEMENTS, "layers": 2 * DEFAULT_LAYERS, "corner": 0.5 * DEFAULT_CORNER}


@dataclasses.dataclass(frozen=True)
class Comparison:
    """One sample at one pressure: its number, T/R, P_I (kPa), Phat_I, the forces Fhat compressed to, and
    ``values``: (quantity, Fhat or None) -> (membrane, solid); ``seconds`` of the solid's solves; ``refined``: the
    same keys -> the solid's value on the mesh ``REFINED`` (empty: not solved there)."""

    sample: int
    thickness_ratio: float
    pressure_kpa: float
    pressure: float
    forces: tuple[float, ...]
    values: dict
    seconds: float
    refined: dict = dataclasses.field(default_factory=dict)

    @property
    def label(self) -> str:
        return f"sample {self.sample} (T/R = {self.thickness_ratio:g}) at {self.pressure_kpa:g} kPa"

    def error(self, quantity: str, force=None) -> float:
        """membrane / solid - 1 of ``quantity`` (at the force Fhat ``force``; None for the inflated pocket)."""
        membrane, solid = self.values[quantity, force]
        return membrane / solid - 1.0

    def uncertainty(self, quantity: str, force=None) -> float:
        """|membrane / refined - membrane / solid| of ``quantity``: the solid's mesh's share of ``error`` (nan
        without the refined solve)."""
        if (quantity, force) not in self.refined:
            return float("nan")
        membrane, solid = self.values[quantity, force]
        return abs(membrane / self.refined[quantity, force] - membrane / solid)


def _half_thickness(state, t: float) -> float:
    """lambda_3 t / 2 at the pole of a membrane state (units R): the upper surface above the mid-surface."""
    return 0.5 * t / (state.profile.stretch_1[0] * state.profile.stretch_2[0])


def posed(number: int, pressure_kpa: float):
    """(the rubber in units of its mu_0, Phat_I, T/R) of sample ``number`` inflated to ``pressure_kpa``."""
    case = sample(number)
    phat = pressure_kpa * 1e3 * case.radius / (case.modulus * case.thickness)
    return case.material.scaled(), phat, case.thickness / case.radius


def _solid_values(states, forces) -> dict:
    """(quantity, Fhat or None) -> the solid's value, of a solid compression curve ``states`` at ``forces``."""
    s0 = states[0].inflated
    out = {("V", None): s0.volume, ("V (membrane's lower surface)", None): s0.volume,
           ("H0 (mid-surface)", None): float(s0.extra["height_mid"]), ("H0 (upper surface)", None): s0.height}
    for f, s in zip(forces, states, strict=True):
        out["P/P_I", f] = s.pressure_ratio
        out["H/H0 (mid-surface)", f] = float(s.extra["height_mid"]) / float(s0.extra["height_mid"])
        out["H/H0 (upper surface)", f] = s.height_ratio
        out["A_c", f] = s.contact_area
    return out


def compare(number: int, pressure_kpa: float, forces: tuple[float, ...], refine: bool = False) -> Comparison:
    """Sample ``number`` inflated to ``pressure_kpa`` and pressed at ``forces`` (Fhat), by the membrane and the
    solid at its default mesh, and (``refine``) the solid again on ``REFINED`` (module docstring)."""
    from pocket import shooting, solid

    material, phat, t = posed(number, pressure_kpa)
    membrane = shooting.compression_curve(material, phat, forces)
    start = time.perf_counter()
    continuum = _solid_values(solid.compression_curve(material, phat, forces, thickness_ratio=t), forces)
    refined = (_solid_values(solid.compression_curve(material, phat, forces, thickness_ratio=t, **REFINED), forces)
               if refine else {})
    seconds = time.perf_counter() - start
    m0 = membrane[0].inflated
    m_top0 = m0.height + _half_thickness(m0, t)
    values: dict[tuple[str, float | None], tuple[float, float]] = {
        ("V", None): (m0.volume, continuum["V", None]),
        ("V (membrane's lower surface)", None): (m0.volume_lower(t), continuum["V", None]),
        ("H0 (mid-surface)", None): (m0.height, continuum["H0 (mid-surface)", None]),
        ("H0 (upper surface)", None): (m_top0, continuum["H0 (upper surface)", None])}
    for f, m in zip(forces, membrane, strict=True):
        values["P/P_I", f] = (m.pressure_ratio, continuum["P/P_I", f])
        values["H/H0 (mid-surface)", f] = (m.height_ratio, continuum["H/H0 (mid-surface)", f])
        values["H/H0 (upper surface)", f] = ((m.height + _half_thickness(m, t)) / m_top0,
                                             continuum["H/H0 (upper surface)", f])
        values["A_c", f] = (m.contact_area, continuum["A_c", f])
    return Comparison(number, t, pressure_kpa, phat, tuple(forces), values, seconds, refined)


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
              "+/- (solid's mesh)", f"within {LIMIT:.0%}"]
    out = []
    for c in comparisons:
        for quantity, force in _keys(c):
            membrane, solid = c.values[quantity, force]
            error = c.error(quantity, force)
            out.append([c.sample, f"{c.thickness_ratio:g}", f"{c.pressure_kpa:g}",
                        "" if force is None else f"{force:g}", quantity, f"{membrane:.6g}", f"{solid:.6g}",
                        f"{error:+.2e}", _uncertainty_cell(c.uncertainty(quantity, force)),
                        "yes" if abs(error) <= LIMIT else "no"])
    return header, out


def _uncertainty_cell(uncertainty: float) -> str:
    """The table's cell of an error's uncertainty: '-' where the solid was not solved on the refined mesh."""
    return "-" if np.isnan(uncertainty) else f"{uncertainty:.1e}"


def _worst(comparisons, quantity) -> dict:
    """sample -> the largest |error| of ``quantity`` over its pressures and forces."""
    return {n: e for n, (e, _) in _worst_with_uncertainty(comparisons, quantity).items()}


def _worst_with_uncertainty(comparisons, quantity) -> dict:
    """sample -> (the largest |error| of ``quantity`` over its pressures and forces, that error's uncertainty)."""
    out: dict = {}
    for c in comparisons:
        for f in [None] if quantity in INFLATION else c.forces:
            error = abs(c.error(quantity, f))
            if error >= out.get(c.sample, (-1.0, 0.0))[0]:
                out[c.sample] = (error, c.uncertainty(quantity, f))
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


def _stated(error: float, uncertainty: float) -> str:
    """An error in percent with the solid's uncertainty beside it, if known."""
    return f"{error:.2%}" + ("" if np.isnan(uncertainty) else f" +/- {100.0 * uncertainty:.1g}% (the solid's mesh)")


def verdict(comparisons) -> list[str]:
    """One sentence per quantity: the samples where the membrane is within LIMIT of the solid, and those where
    it is not (the largest error of each, with the solid's own uncertainty beside it)."""
    out = []
    for quantity in QUANTITIES:
        worst = _worst_with_uncertainty(comparisons, quantity)
        within = [n for n in sorted(worst) if worst[n][0] <= LIMIT]
        beyond = [n for n in sorted(worst) if worst[n][0] > LIMIT]
        text = f"{quantity}: "
        text += (f"within {LIMIT:.0%} for sample{'s' if len(within) > 1 else ''} {', '.join(map(str, within))}"
                 if within else f"within {LIMIT:.0%} for no sample")
        if beyond:
            text += "; not for " + ", ".join(f"sample {n} ({worst[n][0]:.1%})" for n in beyond)
        largest = max(worst.values())
        out.append(text + f" (largest error {_stated(*largest)}).")
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
