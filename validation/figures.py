"""The report's figures as data: panels of named series, the paper's axes and symbols.

A ``Figure`` is what gets drawn (``draw.py``) and what goes into its CSV, so
every plotted number is in the CSV. Solvers are told apart by line style and
marker (``STYLES``, one legend), pockets by colour (a second legend, the
pockets' labels), one colour per pocket in every figure (``pocket_colors``).
The headline pocket is drawn first as a broad dark line, the others as thin
coloured lines over it, so that a curve lying on the headline's (sample 1 at
5 kPa, Phat_I 0.322, against 0.31) still shows inside it; each thin line
carries dots of its colour at places staggered from pocket to pocket
(``Series.layer``), so that two curves lying on each other (sample 2 at 5 kPa
and the neo-Hookean pocket) both show.

Log axes leave out the points at 0 (the inflated pocket, F = 0), which a log
scale cannot place (``without_zeros``); the captions say so.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.apps.design import PAPER_FORCE_FACTOR

from .convergence import FORCE as CONVERGENCE_FORCE
from .convergence import observed_order
from .plan import RANGE_FRACTION
from .suite import headline, on_plate

__all__ = ["Series", "Panel", "Figure", "figures", "convergence_figure", "curve_series", "paper_pockets", "STYLES",
           "pocket_label", "pocket_colors", "solver_key", "without_zeros", "NO_ZERO"]

#: solver column label -> matplotlib style: line style, marker, marker face
STYLES = {
    "shooting": dict(linestyle="-", marker="", linewidth=1.4),
    "FEM P1": dict(linestyle="none", marker="o", markerfacecolor="none", markersize=7),
    "FEM P2": dict(linestyle="none", marker="x", markersize=6),
    "analytical": dict(linestyle="--", marker="", linewidth=1.3),
    "theory": dict(linestyle="--", marker="", linewidth=0.9),
    "residual": dict(linestyle=":", marker="o", markersize=4, linewidth=0.8),
}
#: solver column label -> how a caption names its style
#: the solvers a curve figure may show, in legend order
STYLES_OF_CURVES = ("shooting", "analytical", "FEM P1", "FEM P2")
_STYLE_NAMES = {"shooting": "solid lines", "analytical": "dashed lines", "FEM P1": "open circles",
                "FEM P2": "crosses"}
#: what a caption says of the points a log axis leaves out
NO_ZERO = "The log axes leave out F = 0 (the inflated pocket), which a log scale cannot place."
_PROFILE_MARKERS = 21  # FE nodes shown per profile
_NEAR = 1.0  # Fhat range of the paper's figures 3 and 5


@dataclasses.dataclass(frozen=True)
class Series:
    """One plotted line. ``group`` names the pocket (the colour legend; "" for none); ``emphasis``
    marks the headline pocket, drawn broad and dark beneath the others; ``layer`` staggers the dots of
    a thin pocket line (its place among the figure's pockets)."""

    label: str
    solver: str  # a key of STYLES, or "convergence"
    x: np.ndarray
    y: np.ndarray
    color: int = 0  # index into the colour cycle
    group: str = ""
    emphasis: bool = False
    layer: int = 0


@dataclasses.dataclass(frozen=True)
class Panel:
    title: str
    xlabel: str
    ylabel: str
    series: tuple
    log: str = ""  # axes on a log scale: "", "x" or "xy"
    equal: bool = False
    marks: tuple = ()  # (x, y, text) annotations: a vertical line at x, a horizontal at y (None: none), the text
    limits: tuple | None = None  # ((x0, x1), (y0, y1))
    legend: bool = True


@dataclasses.dataclass(frozen=True)
class Figure:
    name: str
    caption: str
    panels: tuple


def pocket_label(pocket) -> str:
    """The pocket's label with its Phat_I: what the legends show."""
    return f"{pocket.case.label} (Phat_I = {pocket.pressure_initial:.3g})"


def pocket_colors(pockets) -> dict:
    """pocket -> index into the colour cycle: every pocket of a run but the headline (drawn dark), in file
    order, so that a pocket has one colour in every figure."""
    head = headline(pockets)
    return {p: k for k, p in enumerate(p for p in pockets if p != head)}


def solver_key(solvers) -> str:
    """How a caption names the styles of ``solvers`` (STYLES keys): "solid lines: shooting, ..."."""
    return ", ".join(f"{_STYLE_NAMES[s]}: {'the ' if s == 'analytical' else ''}{s}"
                     + (" model" if s == "analytical" else "") for s in solvers)


def without_zeros(figure: Figure) -> Figure:
    """``figure`` with the points at 0 or below left out of its log axes (a log scale would clip them to its
    edge and draw a false plateau from there); NO_ZERO added to the caption if any was left out."""
    panels, dropped = [], False
    for panel in figure.panels:
        series = []
        for s in panel.series:
            keep = np.ones(len(s.x), dtype=bool)
            if "x" in panel.log:
                keep &= np.asarray(s.x) > 0
            if "y" in panel.log:
                keep &= np.asarray(s.y) > 0
            dropped |= not keep.all()
            series.append(dataclasses.replace(s, x=np.asarray(s.x)[keep], y=np.asarray(s.y)[keep]))
        panels.append(dataclasses.replace(panel, series=tuple(series)))
    caption = f"{figure.caption} {NO_ZERO}" if dropped else figure.caption
    return dataclasses.replace(figure, caption=caption, panels=tuple(panels))


def _values(states, key):
    return np.array([getattr(s, key) for s in states])


def curve_series(results, key, pockets, approximate, xkey="force", top=None):
    """The reference for ``pockets``, solver columns (markers) where computed, the approximate model
    for the pockets in ``approximate``; the headline pocket first, emphasised."""
    head = headline(results.pockets)
    colors = pocket_colors(results.pockets)
    series = []
    for layer, pocket in enumerate(pockets):
        curves, group, emphasis = results.curves_of(pocket), pocket_label(pocket), pocket == head
        color = colors.get(pocket, 0)
        name = f"{pocket.case.label}: "

        def add(solver, states, name=name, color=color, group=group, emphasis=emphasis, layer=layer):
            states = [s for s in states if top is None or s.force <= top]
            series.append(Series(name + solver, solver, _values(states, xkey), _values(states, key), color,
                                 group, emphasis, layer))

        add("shooting", curves.reference)
        if pocket in approximate:
            add("analytical", [a for a in curves.approximate if a is not None and a.force > 0])
        for run in (r for r in results.columns if r.pocket == pocket and len(r.states) > 1):
            add(run.column.label, run.states)
    return tuple(series)


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


def figures(results) -> list[Figure]:
    """The paper's figs 2-5, the other rubbers' and the gases' figures (``others``), the fingertips'
    (``fingertips``), the identification's (``identification``), the membrane's against the solid
    (``thickness``) and the convergence study, from a run's results."""
    from .fingertips import fingertip_figures
    from .identification import figure as identification_figure
    from .others import other_figures
    from .thickness import figure as thickness_figure

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
    out += [against["fig3a"], against["fig3b"], _fig4(results), against["fig5"]]
    out += other_figures(results) + fingertip_figures(results)
    if results.fits:
        out.append(identification_figure(results.fits))
    if results.thicknesses:
        out.append(thickness_figure(results.thicknesses))
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


def _fig4(results) -> Figure:
    four = [p for p in results.pockets if "fig4" in p.case.tags]
    series = curve_series(results, "height", four, four, xkey="pressure_ratio")
    return Figure("fig4", "Fig. 4: height H/R against the pressure ratio P/P_I for the four samples of Table 1 "
                  f"at the same P_I, each to {RANGE_FRACTION:g} of the end of its range (log scale in P/P_I); "
                  f"{solver_key(STYLES_OF_CURVES)} (the FE model where computed).",
                  (Panel("", "P / P_I", "H / R", series, log="x"),))


def paper_pockets(pockets) -> list:
    """The pockets of the paper's model: a Mooney-Rivlin rubber filled with a liquid, pressed by the plate."""
    return [p for p in pockets if p.case.material.law == "mooney-rivlin" and not p.case.fluid.is_gas and on_plate(p)]
