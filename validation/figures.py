"""The report's figures, in the report's order: the paper's figures 2-5, then each section's.

Each figure is built from a run's results in the vocabulary of ``plotdata`` (panels of named series);
the sections beyond the paper's (``others``, ``fingertips``, ``identification``, ``thickness``,
``capsulereport``) build
their own, and ``figures`` lists them all.
"""

from __future__ import annotations

import numpy as np

from pocket.apps.design import PAPER_FORCE_FACTOR

from .capsulereport import figure as capsule_figure
from .convergence import EXPECTED, observed_order
from .convergence import FORCE as CONVERGENCE_FORCE
from .fingertips import fingertip_figures
from .identification import figure as identification_figure
from .others import other_figures
from .plan import RANGE_FRACTION
from .plotdata import (
    STYLES_OF_CURVES,
    Figure,
    Panel,
    Series,
    curve_series,
    paper_pockets,
    pocket_label,
    solver_key,
    without_zeros,
)
from .solidstudy import figure as solid_study_figure
from .suite import headline
from .thickness import figure as thickness_figure

__all__ = ["convergence_figure", "figures"]

_PROFILE_MARKERS = 21  # FE nodes shown per profile
_NEAR = 1.0  # Fhat range of the paper's figures 3 and 5


def _profiles(results, head, force):
    curves = results.curves_of(head)
    k = int(np.argmin(np.abs(curves.forces - force)))
    shot, ana = curves.reference[k], curves.approximate[k]
    series = [Series("shooting", "shooting", shot.profile.rho, shot.profile.eta)]
    if ana is not None:
        series.append(Series("analytical", "analytical", ana.profile.rho, ana.profile.eta))
    for run in (r for r in results.columns if r.pocket == head):
        for state in run.states:
            if state.force == shot.force:
                pick = np.linspace(0, len(state.profile.r) - 1, _PROFILE_MARKERS).round().astype(int)
                series.append(Series(run.column.label, run.column.label, state.profile.rho[pick],
                                     state.profile.eta[pick]))
    return shot.force, tuple(series)


def convergence_figure(results) -> Figure:
    """Error against element size, one panel per quantity, observed and theoretical orders in the legend,
    and the theory's slopes 2 and 4 drawn a third below the finest point of the fitted P1 and P2 series."""
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


def figures(results) -> list[Figure]:
    """The paper's figs 2-5, the other rubbers' and the gases' figures (``others``), the fingertips'
    (``fingertips``), the identification's (``identification``), the membrane's against the solid
    (``thickness``), the solid's convergence (``solidstudy``), the capsules' (``capsulereport``) and the
    convergence study, from a run's results."""
    head = headline(results.pockets)
    curves = results.curves_of(head)
    out = []
    panels = []
    limits = ((-0.02, 1.05), (-0.02, 1.1 * curves.reference[0].inflated.height))
    for letter, force in (("a", 0.0), ("b", 0.19)):
        f, series = _profiles(results, head, force)
        panels.append(Panel(f"({letter}) F/(P_I pi R^2) = {f:.3g}", "rho / R", "eta / R", series, equal=True,
                            limits=limits))
    out.append(Figure("fig2", f"Fig. 2: profiles of {pocket_label(head)}, inflated (a) and compressed (b); FE "
                      f"nodes subsampled to {_PROFILE_MARKERS} markers.", tuple(panels)))
    against = _against_force(results)
    four = [p for p in results.pockets if "fig4" in p.case.tags]  # the samples of Table 1 (none: no figure)
    out += [against["fig3a"], against["fig3b"], *([_fig4(results, four)] if four else []), against["fig5"]]
    out += other_figures(results) + fingertip_figures(results)
    if results.fits:
        out.append(identification_figure(results.fits))
    if results.thicknesses:
        out.append(thickness_figure(results.thicknesses))
    if results.solid_studies:
        out.append(solid_study_figure(results.solid_studies))
    if results.capsules:
        out.append(capsule_figure(results.capsules, results.uninflated))
    if results.sequences:
        out.append(convergence_figure(results))
    return [without_zeros(f) for f in out]


def _against_force(results) -> dict:
    """The paper's figs 3a, 3b and 5 by name: a quantity of every pocket of its rubber and fluid against the
    force, (a) in the paper's range, (b) to RANGE_FRACTION of the end of each pocket's range."""
    head = headline(results.pockets)
    ordered = [head] + [p for p in paper_pockets(results.pockets) if p != head]
    fhat = "F / (P_I pi R^2)"
    h = results.button.height_ratio
    design = (1.0 / PAPER_FORCE_FACTOR, h, f"section 6: F/(P_I pi R^2) = 1/{PAPER_FORCE_FACTOR:g}, H / H_0 = {h:g}")
    end = results.curves_of(head).force_end
    out = {}
    for name, key, ylabel, caption, marks, log in (
            ("fig3a", "contact_area", "A_c / (pi R^2)", "Fig. 3a: contact area fraction", (), "x"),
            ("fig3b", "height_ratio", "H / H_0", "Fig. 3b: normalised height", (design,), "x"),
            ("fig5", "pressure_ratio", "P / P_I", "Fig. 5: pressure ratio P/P_I", (), "xy")):
        near = Panel(f"(a) F/(P_I pi R^2) <= {_NEAR:g}", fhat, ylabel,
                     curve_series(results, key, ordered, (head,), top=_NEAR), marks=marks)
        full = Panel(f"(b) each pocket to {RANGE_FRACTION:g} of the end of its range", fhat, ylabel,
                     curve_series(results, key, ordered, (head,)), log=log, marks=marks)
        out[name] = Figure(name, f"{caption} against the force: the shooting solver for every pocket of the "
                           "paper's rubber and fluid (Mooney-Rivlin, a liquid), the FE "
                           "model (markers) where computed, the analytical model for the headline pocket (the "
                           f"broad dark line); (a) the paper's range, (b) each pocket to {RANGE_FRACTION:g} of the "
                           "end of its range (where the free part of the sheet would reach the clamp plane; the "
                           f"headline's ends at F/(P_I pi R^2) = {end:.3g}).", (near, full))
    return out


def _fig4(results, four) -> Figure:
    series = curve_series(results, "height", four, four, xkey="pressure_ratio")
    return Figure("fig4", "Fig. 4: height H/R against the pressure ratio P/P_I for the four samples of Table 1 "
                  f"at the same P_I, each to {RANGE_FRACTION:g} of the end of its range (log scale in P/P_I); "
                  f"{solver_key(STYLES_OF_CURVES)} (the FE model where computed).",
                  (Panel("", "P / P_I", "H / R", series, log="x"),))
