"""The section "Identifying a rubber from its bulge test": each law fitted to data of the other solver.

For each law of the plan (``Plan.fits``: a law and its number of terms), a known rubber (the truth: the
law's example, or the Ogden rubber ``OGDEN_ONE`` or ``OGDEN_TWO``) is inflated by the P2 finite-element
model at its default mesh to ``POINTS`` pressures Phat from ``LOW`` to ``HIGH`` (pole stretches to ~1.6
for these rubbers), on a sheet of thickness ``THICKNESS`` and clamp radius ``RADIUS``; ``pocket fit``'s
library (``pocket.apps.fit``, the shooting solver as its model) fits the law to those pole heights,
noise-free. The truth is the exact answer: each parameter comes back to the two solvers' difference
(``fem_p2``: ~1e-10) times the fit's conditioning, so within ``TOLERANCES["fit"]`` (its reason there).
The parameters of an Ogden rubber of several terms are not unique (Ogden, Saccomandi and Sgura, 2004):
what its fit must give is mu_0 and the curve (every datum to the tolerance); its parameters are reported.
The figure shows the data, the fitted curves and the residuals.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.apps.fit.data import Dataset
from pocket.apps.fit.leastsquares import fit
from pocket.apps.fit.model import Setup
from pocket.core.materials import LAWS, Material, check

from .plotdata import Figure, Panel, Series
from .verdicts import TOLERANCES, Check

__all__ = [
    "HIGH",
    "LOW",
    "OGDEN_ONE",
    "OGDEN_TWO",
    "POINTS",
    "RADIUS",
    "THICKNESS",
    "Identification",
    "checks",
    "describe",
    "figure",
    "identify",
    "rows",
    "truth_of",
]

RADIUS, THICKNESS = 0.02, 1e-3  # the sheet (m)
POINTS, LOW, HIGH = 10, 0.06, 0.6  # pressures Phat of the bulge test
_CURVE = 40  # points of each fitted curve in the figure
#: the one-term Ogden rubber (Pa): not the neo-Hookean exponent 2
OGDEN_ONE = {"mu": [200e3], "exponents": [3.0]}
#: the two-term Ogden rubber (Pa): a soft term and a stiff one
OGDEN_TWO = {"mu": [150e3, 10e3], "exponents": [2.0, 5.0]}
TOLERANCE = TOLERANCES["fit"][0]


@dataclasses.dataclass(frozen=True)
class Identification:
    """One law's fit: the ``truth`` and ``fitted`` rubbers (Pa), the data (``pressures`` Phat, ``heights`` H/R),
    the fitted keys' ``names``, ``values`` and ``errors`` (standard errors), the ``residuals`` (model/data - 1),
    the fitted ``curve`` (Phat, H/R), the ``warnings``, solver ``calls`` and ``seconds``."""

    truth: Material
    fitted: Material
    pressures: np.ndarray
    heights: np.ndarray
    names: tuple[str, ...]
    values: np.ndarray
    errors: np.ndarray
    residuals: np.ndarray
    curve: tuple[np.ndarray, np.ndarray]
    warnings: tuple[str, ...]
    calls: int
    seconds: float

    @property
    def label(self) -> str:
        terms = len(self.truth["mu"]) if self.truth.law == "ogden" else 0
        return f"{self.truth.law} ({terms} terms)" if terms > 1 else self.truth.law


def truth_of(law: str, terms: int) -> Material:
    """The rubber whose data a law is fitted to (module docstring)."""
    if law == "ogden":
        return check("ogden", {1: OGDEN_ONE, 2: OGDEN_TWO}.get(terms, dict(LAWS[law].example)))
    return check(law, dict(LAWS[law].example))


def identify(law: str, terms: int) -> Identification:
    """Fit ``law`` with ``terms`` terms to the FE bulge test of its truth (module docstring)."""
    from pocket import fem, shooting

    truth = truth_of(law, terms)
    tension = 3.0 * truth.mu0 * THICKNESS
    phats = np.linspace(LOW, HIGH, POINTS)
    heights = np.array([fem.inflate(truth.scaled(), p).height for p in phats])
    data = Dataset("inflation", phats * tension / RADIUS, {"height": heights * RADIUS}, None, "FE bulge test")
    result = fit(Setup((data,), RADIUS, THICKNESS), law, terms=terms)
    dense = np.linspace(LOW / 4.0, HIGH, _CURVE)
    scale = result.material.mu0 * 3.0 * THICKNESS / tension  # the fitted tension scale over the truth's
    curve = shooting.inflation_curve(result.material.scaled(), list(dense / scale))
    s = result.statistics
    return Identification(truth, result.material, phats, heights, s.names, s.values, s.standard_errors,
                          result.residuals, (dense, np.array([c.height for c in curve])), s.warnings, result.calls,
                          result.seconds)


def _truth(f: Identification, name: str) -> float:
    """The truth's value of the fitted key ``name``; Ogden's terms matched by the order of their exponents (the
    energy is a sum over terms: their order is arbitrary)."""
    if "[" not in name:
        return f.truth[name]
    base, k = name[:-1].split("[")
    fitted, truth = np.argsort(f.fitted["exponents"]), np.argsort(f.truth["exponents"])
    return f.truth[base][int(truth[list(fitted).index(int(k))])]


def checks(fits) -> list[Check]:
    """Each fitted parameter against the truth (Ogden's: reported), mu_0 and the curve's largest residual."""
    out = []
    for f in fits:
        where = f"{POINTS} FE pole heights, Phat {LOW:g} to {HIGH:g}"
        for name, value in zip(f.names, f.values, strict=True):
            truth = _truth(f, name)
            error = abs(value / truth - 1.0)
            tolerance = None if f.truth.law == "ogden" and len(f.truth["mu"]) > 1 else TOLERANCE
            out.append(Check(f.label, "fit to FE data vs the truth", "identification", name, where, float(value),
                             float(truth), error, tolerance, "info" if tolerance is None else
                             "pass" if error <= tolerance else "fail"))
        error = abs(f.fitted.mu0 / f.truth.mu0 - 1.0)
        out.append(Check(f.label, "fit to FE data vs the truth", "identification", "mu_0", where, f.fitted.mu0,
                         f.truth.mu0, error, TOLERANCE, "pass" if error <= TOLERANCE else "fail"))
        worst = float(np.max(np.abs(f.residuals)))
        out.append(Check(f.label, "fit to FE data vs the truth", "identification", "curve (largest |model/data - 1|)",
                         where, worst, 0.0, worst, TOLERANCE, "pass" if worst <= TOLERANCE else "fail"))
    return out


def rows(fits) -> tuple[list, list]:
    """(header, rows) of the section's table: every check of ``checks`` with the fit's standard error."""
    header = ["law", "quantity", "truth", "fitted", "standard error", "relative error", "tolerance", "verdict"]
    out = []
    for f in fits:
        errors = dict(zip(f.names, f.errors, strict=True))
        for c in checks([f]):
            se = errors.get(c.quantity)
            out.append([c.case, c.quantity, f"{c.reference:.10g}", f"{c.value:.10g}",
                        "" if se is None else f"{se:.2g}", f"{c.error:.2g}",
                        "" if c.tolerance is None else f"{c.tolerance:g}", c.verdict])
    return header, out


def describe(fits) -> str:
    """The truths of ``fits`` in words (Pa): what the section's text quotes."""
    return "; ".join(f"{f.label}: " + ", ".join(f"{n} = {v}" for n, v in f.truth.describe().items() if n != "material")
                     for f in fits)


def figure(fits) -> Figure:
    """The data, the fitted curves (a) and the residuals (b) of every law's fit."""
    # colours are laws here, not pockets: no series names a pocket (``Series.group``), so each panel has its legend
    data = tuple(Series(f"{f.label}: FE data", "FEM P2", f.pressures, f.heights, k) for k, f in enumerate(fits))
    curves = tuple(Series(f"{f.label}: fitted (shooting)", "shooting", f.curve[0], f.curve[1], k)
                   for k, f in enumerate(fits))
    residuals = tuple(Series(f"{f.label}", "residual", f.pressures, f.residuals, k) for k, f in enumerate(fits))
    return Figure("identification", f"Identifying a rubber from its bulge test: each law fitted by the shooting "
                  f"model to {POINTS} noise-free pole heights of a known rubber computed by the P2 FE model (the "
                  "truth: each law's example, Ogden's its own; colours are laws); (a) the data (crosses) and the "
                  "fitted curves (solid lines), (b) the residuals, model/data - 1 (the two solvers' difference, of "
                  "the order of 1e-9).",
                  (Panel("(a) bulge test: pole height against pressure", "Phat = P R / (E T)", "H_0 / R",
                         data + curves),
                   Panel("(b) residuals", "Phat = P R / (E T)", "model / data - 1", residuals)))
