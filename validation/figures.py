"""The report's figures as data: panels of named series, the paper's axes and symbols.

A ``Figure`` is what gets drawn (``draw.py``) and what goes into its CSV, so
every plotted number is in the CSV. Solvers are told apart by line style and
marker (``STYLES``), cases by colour.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .convergence import FORCE as CONVERGENCE_FORCE
from .convergence import observed_order
from .plan import RANGE_FRACTION

__all__ = ["Series", "Panel", "Figure", "figures", "convergence_figure", "STYLES"]

#: solver -> matplotlib style: line style, marker, marker face
STYLES = {
    "shooting": dict(linestyle="-", marker="", linewidth=1.6),
    "FEM P1": dict(linestyle="none", marker="o", markerfacecolor="none", markersize=7),
    "FEM P2": dict(linestyle="none", marker="x", markersize=6),
    "analytical": dict(linestyle="--", marker="", linewidth=1.3),
    "theory": dict(linestyle="--", marker="", linewidth=0.9),
}
_PROFILE_MARKERS = 21  # FE nodes shown per profile
_NEAR = 1.0  # Fhat range of the paper's figures 3 and 5


@dataclasses.dataclass(frozen=True)
class Series:
    label: str
    solver: str  # a key of STYLES, or "convergence"
    x: np.ndarray
    y: np.ndarray
    color: int = 0  # index into the colour cycle


@dataclasses.dataclass(frozen=True)
class Panel:
    title: str
    xlabel: str
    ylabel: str
    series: tuple
    log: str = ""  # axes on a log scale: "", "x" or "xy"
    equal: bool = False
    marks: tuple = ()  # (x, y, text) annotations: a vertical line at x, a horizontal at y
    limits: tuple | None = None  # ((x0, x1), (y0, y1))
    legend: bool = True


@dataclasses.dataclass(frozen=True)
class Figure:
    name: str
    caption: str
    panels: tuple


def _short(case) -> str:
    return case.name if case.sample is None else f"sample {case.sample}, Phat_I = {case.pressure_hat:.3g}"


def _curve_series(results, key, cases, analytical, xkey="force", top=None):
    """Shooting for ``cases``, FE markers where computed, analytical for the cases in ``analytical``."""
    series = []
    for color, case in enumerate(cases):
        curves = results.curves[results.cases.index(case)]
        keep = [s for s in curves.shooting if top is None or s.force <= top]
        series.append(Series(f"{_short(case)}: shooting", "shooting",
                             np.array([getattr(s, xkey) for s in keep]), np.array([getattr(s, key) for s in keep]),
                             color))
        if case in analytical:
            pairs = [a for a in curves.analytical if a is not None and (top is None or a.force <= top) and a.force > 0]
            series.append(Series(f"{_short(case)}: analytical", "analytical",
                                 np.array([getattr(a, xkey) for a in pairs]),
                                 np.array([getattr(a, key) for a in pairs]), color))
        for run in (r for r in results.fem if r.case == case and len(r.states) > 1):
            states = [s for s in run.states if top is None or s.force <= top]
            series.append(Series(f"{_short(case)}: FEM P{run.order}", f"FEM P{run.order}",
                                 np.array([getattr(s, xkey) for s in states]),
                                 np.array([getattr(s, key) for s in states]), color))
    return tuple(series)


def _profiles(results, head, force):
    curves = results.curves[results.cases.index(head)]
    k = int(np.argmin(np.abs(curves.forces - force)))
    shot, ana = curves.shooting[k], curves.analytical[k]
    series = [Series("shooting", "shooting", shot.profile.rho, shot.profile.eta)]
    if ana is not None:
        series.append(Series("analytical", "analytical", ana.profile.rho, ana.profile.eta))
    for run in (r for r in results.fem if r.case == head):
        for state in run.states:
            if state.force == shot.force:
                pick = np.linspace(0, len(state.profile.r) - 1, _PROFILE_MARKERS).round().astype(int)
                series.append(Series(f"FEM P{run.order}", f"FEM P{run.order}", state.profile.rho[pick],
                                     state.profile.eta[pick]))
    return shot.force, tuple(series)


def convergence_figure(results) -> Figure:
    """Error against element size, one panel per quantity, observed and theoretical orders in the legend,
    and the theory's slopes 2 and 4 drawn a third below the finest point of the fitted P1 and P2 series."""
    from .convergence import EXPECTED

    panels = []
    for study, quantity, title in (("inflation", "stretch_pole", "inflation: pole stretch lambda_0"),
                                   ("compression", "height", f"compression, Fhat = {CONVERGENCE_FORCE}: height H"),
                                   ("compression", "contact_radius", f"compression, Fhat = {CONVERGENCE_FORCE}: a_c")):
        series, slopes = [], []
        for seq in results.sequences:
            if seq.study == study:
                errors = seq.errors(quantity)
                p = observed_order(seq.sizes, errors)
                theory = EXPECTED[(study, seq.order, seq.mesh)][quantity][0]
                color = 2 * (seq.order - 1) + (seq.mesh == "uniform")
                series.append(Series(f"P{seq.order} {seq.mesh}: order {p:.2f} (theory {theory:g})", "convergence",
                                     seq.sizes, errors, color))
                if seq.mesh == "fitted":
                    h = np.array([seq.sizes[0], seq.sizes[-1]])
                    slope = 2 * seq.order
                    slopes.append(Series(f"slope {slope} (theory, P{seq.order} fitted)", "theory", h,
                                         errors[-1] / 3 * (h / h[-1]) ** slope, color))
        panels.append(Panel(title, "largest element size h", "|FEM / shooting - 1|", tuple(series + slopes),
                            log="xy"))
    return Figure("convergence", "Mesh convergence of the FE model against the shooting reference (headline case): "
                  "fitted = the default meshes graded towards the axis and, in compression, the edge-fitted contact; "
                  "uniform = uniform meshes and, in compression, the penalty plate. Observed orders fitted by least "
                  "squares (np.polyfit) on log(error) vs log(h); dashed: the theory's slopes.", tuple(panels))


def figures(results, head) -> list[Figure]:
    """The paper's figs 2-5 and the convergence study, from a run's results."""
    out = []
    panels = []
    top_eta = results.curves[results.cases.index(head)].shooting[0].inflated.height
    limits = ((-0.02, 1.05), (-0.02, 1.1 * top_eta))
    for letter, force in (("a", 0.0), ("b", 0.19)):
        f, series = _profiles(results, head, force)
        panels.append(Panel(f"({letter}) F/(P_I pi R^2) = {f:.3g}", "rho / R", "eta / R", series, equal=True,
                            limits=limits))
    out.append(Figure("fig2", f"Fig. 2: profiles of {head.label}, inflated (a) and compressed (b); FE nodes "
                      f"subsampled to {_PROFILE_MARKERS} markers.", tuple(panels)))
    curves = results.curves[results.cases.index(head)]
    ordered = [head] + [c for c in results.cases if c != head]
    fhat = "F / (P_I pi R^2)"
    design = (1.0 / results.design.pressure_coefficient, results.design.height_ratio,
              f"section 6: Fhat = 1/{results.design.pressure_coefficient:g}, H / H_0 = {results.design.height_ratio:g}")
    for name, key, ylabel, caption, marks, log in (
            ("fig3a", "contact_area", "A_c / (pi R^2)", "Fig. 3a: contact area fraction", (), "x"),
            ("fig3b", "height_ratio", "H / H_0", "Fig. 3b: normalised height", (design,), "x"),
            ("fig5", "pressure_ratio", "P / P_I", "Fig. 5: pressure rise", (), "xy")):
        near = Panel(f"(a) F/(P_I pi R^2) <= {_NEAR:g}", fhat, ylabel,
                     _curve_series(results, key, ordered, (head,), top=_NEAR), marks=marks, legend=False)
        full = Panel(f"(b) to {RANGE_FRACTION:g} of the end of each case's range", fhat, ylabel,
                     _curve_series(results, key, ordered, (head,)), log=log, marks=marks)
        out.append(Figure(name, f"{caption} against the force: the shooting solver for every case, the FE model "
                          "(markers) where computed, the analytical model for the headline case; (a) the paper's "
                          f"range, (b) the whole range (the headline case's ends at Fhat = {curves.force_end:.3g}).",
                          (near, full)))
    four = [c for c in results.cases if "fig4" in c.tags]
    series = _curve_series(results, "height", four, four, xkey="pressure_ratio")
    out.append(Figure("fig4", "Fig. 4: height H/R against the pressure rise P/P_I for the four samples of Table 1 "
                      "at the same P_I, to near the end of each range (log scale in P/P_I).",
                      (Panel("", "P / P_I", "H / R", series, log="x"),)))
    if results.sequences:
        out.append(convergence_figure(results))
    return out
