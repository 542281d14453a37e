"""The section "The solid's own error": the convergence of ``pocket.solid`` with its mesh, on the paper's samples.

The solid measures the membrane's modelling error (``thickness``), so its numbers are worth only as much as they are
converged. Each studied sample of the paper (Table 1: Mooney-Rivlin C1 = 160 kPa, C2 = 47 kPa, R = 20 mm, a liquid)
is inflated to ``PRESSURE_KPA`` and pressed by the plate at ``FORCES`` (small contacts: the contact edge is the
solid's least resolved output), and solved on meshes refined along one axis at a time, each halving the element
size of the one before: along the radius (the elements), through the thickness (the layers) and at the clamp's corner
(the corner elements' length, a fraction of T: ``pocket.solid.mesh``), the others at the solid's defaults. The last
is not a discretisation error like the others: the corner is singular, the answer depends on the length at which it
is regularised, and the study measures by how much.

Of each quantity q (the inflated V and H0; at each force P/P_I, A_c and the contact edge's Lagrangian radius a_c),
with the three finest meshes of an axis q_4h, q_2h, q_h: the observed order p = log2((q_4h - q_2h) / (q_2h - q_h))
and Richardson's extrapolation q* = q_h + (q_h - q_2h) / (2^p - 1) (``convergence.richardson``; none where the
differences do not shrink: no asymptotic range yet). The default mesh's error along that axis is then
|q_default / q* - 1| (for a_c, |q_default - q*| in units of R); without q*, its distance from the finest mesh plus
the finest mesh's own last change (|q_2h / q_h - 1|): the error cannot be certified smaller than that. The checks
hold the default mesh to ``TARGETS``: the contact area to 0.5 % and the contact radius to 1e-3 R along each axis;
the other quantities are informational.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from .convergence import richardson
from .plotdata import Figure, Panel, Series
from .thickness import posed
from .verdicts import Check

__all__ = ["AXES", "COMPARISON", "FORCES", "PRESSURE_KPA", "TARGETS", "Study", "checks", "figure", "meshes", "rows",
           "solve", "studies"]

#: the inflation pressure of every studied sample (kPa), and the forces Fhat it is pressed at
PRESSURE_KPA = 5.0
FORCES = (0.08, 0.16, 0.32)
#: the quantities: of the inflated sheet, then at each force
INFLATION = ("V", "H0")
COMPRESSION = ("P/P_I", "A_c", "a_c")
#: quantities measured in units of R (their error absolute, not relative)
ABSOLUTE = ("a_c",)
#: the default mesh's largest accepted error along an axis, by quantity (the others: informational)
TARGETS = {"A_c": 5e-3, "a_c": 1e-3}
#: the refined axes
AXES = ("radial", "through the thickness", "at the clamp's corner")
COMPARISON = "solid: mesh convergence"


def meshes(axis: str, counts) -> tuple[tuple[int, int, float], ...]:
    """The meshes (elements, layers, corner) of ``axis`` with the element or layer ``counts`` (or the corner
    elements' lengths in thicknesses), the others at the solid's defaults."""
    from pocket import solid

    default, k = (solid.DEFAULT_ELEMENTS, solid.DEFAULT_LAYERS, solid.DEFAULT_CORNER), AXES.index(axis)
    return tuple((*default[:k], value, *default[k + 1:]) for value in counts)


def solve(number: int, pressure_kpa: float, forces: tuple[float, ...], elements: int, layers: int, corner: float):
    """((quantity, force or None) -> value, seconds): sample ``number`` at ``pressure_kpa`` pressed at ``forces``
    (Fhat) by the solid on the mesh (``elements``, ``layers``, the clamp's corner elements ``corner`` T long)."""
    from pocket import solid

    material, phat, t = posed(number, pressure_kpa)
    start = time.perf_counter()
    states = solid.compression_curve(material, phat, forces, thickness_ratio=t, elements=elements, layers=layers,
                                     corner=corner)
    seconds = time.perf_counter() - start
    out: dict[tuple[str, float | None], float] = {("V", None): states[0].inflated.volume,
                                                  ("H0", None): states[0].inflated.height}
    for force, state in zip(forces, states, strict=True):
        out["P/P_I", force] = state.pressure_ratio
        out["A_c", force] = state.contact_area
        out["a_c", force] = state.contact_radius
    return out, seconds


@dataclasses.dataclass(frozen=True)
class Study:
    """One sample refined along one ``axis``: its ``meshes`` (elements, layers, corner), coarse to fine, the ``values``
    ((quantity, force) -> value) and ``seconds`` on each, and the solid's ``default`` mesh among them."""

    sample: int
    thickness_ratio: float
    pressure_kpa: float
    forces: tuple[float, ...]
    axis: str
    meshes: tuple[tuple[int, int, float], ...]
    values: tuple[dict, ...]
    seconds: tuple[float, ...]
    default: tuple[int, int, float]

    def quantities(self):
        """(quantity, force): the inflated sheet's (force None), then each force's."""
        yield from ((q, None) for q in INFLATION)
        yield from ((q, f) for f in self.forces for q in COMPRESSION)

    @property
    def counts(self) -> np.ndarray:
        """The refined count of each mesh: elements along the radius, layers, or 1 / the corner's length."""
        k = AXES.index(self.axis)
        return np.array([m[k] if k < 2 else 1.0 / m[k] for m in self.meshes])

    def series(self, key) -> np.ndarray:
        """The values of ``key`` on each mesh, coarse to fine."""
        return np.array([v[key] for v in self.values])

    def estimate(self, key) -> tuple[float, float, float] | None:
        """(q*, |q* - q_h|, p) from the three finest meshes (module docstring), or None."""
        if len(self.meshes) < 3:
            return None
        return richardson(1.0 / self.counts, self.series(key))

    def error(self, key, value: float, reference: float) -> float:
        """|value / reference - 1|, or |value - reference| for a length in units of R (``ABSOLUTE``)."""
        return abs(value - reference) if key[0] in ABSOLUTE else abs(value / reference - 1.0)

    def default_error(self, key) -> tuple[float, bool]:
        """(the default mesh's error along the axis, whether it is against q*): its distance from q*, or where the
        differences do not shrink (no q*), its distance from the finest mesh plus the finest mesh's own last change
        (module docstring)."""
        value, found = self.default_value(key), self.estimate(key)
        if found:
            return self.error(key, value, found[0]), True
        finest, before = self.values[-1][key], self.values[-2][key]
        return self.error(key, value, finest) + self.error(key, before, finest), False

    def default_value(self, key) -> float:
        """``key`` on the solid's default mesh."""
        return self.values[self.meshes.index(self.default)][key]

    def reference(self, key) -> float:
        """q* where it exists, else the finest mesh's value: what the default is measured against."""
        found = self.estimate(key)
        return found[0] if found else self.values[-1][key]


def studies(numbers, pressure_kpa, forces, counts, done) -> list[Study]:
    """The studies of the samples ``numbers`` along each axis (``counts``: the radial elements, the layers and the
    corner's lengths of the refinements) from ``done``: (number, elements, layers, corner) -> the ``solve`` of that
    mesh."""
    from pocket import solid

    out = []
    for number in numbers:
        t = posed(number, pressure_kpa)[2]
        for axis, values in zip(AXES, counts, strict=True):
            grid = meshes(axis, values)
            solved = [done[(number, *m)] for m in grid]
            out.append(Study(number, t, pressure_kpa, tuple(forces), axis, grid, tuple(s[0] for s in solved),
                             tuple(s[1] for s in solved),
                             (solid.DEFAULT_ELEMENTS, solid.DEFAULT_LAYERS, solid.DEFAULT_CORNER)))
    return out


def _where(study: Study, force) -> str:
    return (f"P_I = {study.pressure_kpa:g} kPa, refined {study.axis}, "
            + ("inflated" if force is None else f"F/(P_I pi R^2) = {force:g}"))


def checks(found) -> list[Check]:
    """The default mesh's error of each quantity along each axis: held to ``TARGETS``, else informational."""
    out = []
    for study in found:
        for key in study.quantities():
            error, _ = study.default_error(key)
            tolerance = TARGETS.get(key[0])
            verdict = "info" if tolerance is None else "pass" if error <= tolerance else "fail"
            out.append(Check(f"sample {study.sample}", COMPARISON, "inflation" if key[1] is None else "compression",
                             key[0], _where(study, key[1]), float(study.default_value(key)),
                             float(study.reference(key)), float(error), tolerance, verdict))
    return out


def rows(found) -> tuple[list, list]:
    """(header, rows): every quantity of every study, its values on each mesh, order, extrapolation and the default
    mesh's error."""
    header = ["sample", "T/R", "P_I (kPa)", "refined", "meshes (elements x layers, corner / T)", "quantity",
              "F/(P_I pi R^2)", "values", "observed order", "extrapolated", "default mesh's error"]
    out = []
    for study in found:
        grid = ", ".join(f"{e}x{n} {c:g}" for e, n, c in study.meshes)
        for key in study.quantities():
            estimate = study.estimate(key)
            error, against = study.default_error(key)
            unit = " R" if key[0] in ABSOLUTE else ""
            out.append([study.sample, f"{study.thickness_ratio:g}", f"{study.pressure_kpa:g}", study.axis, grid, key[0],
                        "" if key[1] is None else f"{key[1]:g}",
                        ", ".join(f"{v:.8g}" for v in study.series(key)),
                        f"{estimate[2]:.2f}" if estimate else "(not yet asymptotic)",
                        f"{estimate[0]:.8g}" if estimate else "",
                        f"{error:.2e}{unit}" + ("" if against else " (to the finest mesh plus its last change)")])
    return header, out


def figure(found) -> Figure:
    """|q / q* - 1| against the refined count, log-log: a panel per sample and axis, a line per quantity at the
    smallest force (and the inflated V), where q* exists."""
    panels = []
    for study in found:
        series = []
        for k, key in enumerate([("V", None), *((q, study.forces[0]) for q in COMPRESSION)]):
            estimate = study.estimate(key)
            if estimate is None:
                continue
            errors = np.array([study.error(key, v, estimate[0]) for v in study.series(key)])
            keep = errors > 0.0
            label = key[0] if key[1] is None else f"{key[0]} at Fhat = {key[1]:g}"
            series.append(Series(f"{label} (p = {estimate[2]:.2f})", "convergence", study.counts[keep].astype(float),
                                 errors[keep], k))
        if series:
            what = ("elements along the radius", "layers through the thickness",
                    "T / (the corner elements' length)")[AXES.index(study.axis)]
            panels.append(Panel(f"sample {study.sample} (T/R = {study.thickness_ratio:g}), refined {study.axis}", what,
                                "|q / q* - 1| (a_c: |q - q*| / R)", tuple(series), log="xy"))
    return Figure("solid_convergence", "The solid's convergence with its mesh: each quantity's distance from its "
                  "Richardson extrapolation q* against the number of elements along the refined axis, the other at "
                  f"the default; the paper's samples at P_I = {found[0].pressure_kpa:g} kPa, the contact quantities "
                  f"at the smallest force F/(P_I pi R^2) = {found[0].forces[0]:g}. p: the observed order from the "
                  "three finest meshes.", tuple(panels))

