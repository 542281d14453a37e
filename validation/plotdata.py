"""The vocabulary of the report's figures: panels of named series, their styles, colours and labels.

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
from typing import Any

import numpy as np

from .suite import headline, on_plate

__all__ = [
    "NO_ZERO",
    "STYLES",
    "STYLES_OF_CURVES",
    "Figure",
    "Panel",
    "Series",
    "curve_series",
    "paper_pockets",
    "pocket_colors",
    "pocket_label",
    "solver_key",
    "without_zeros",
]

#: solver column label -> matplotlib style: line style, marker, marker face
STYLES: dict[str, dict[str, Any]] = {
    "shooting": dict(linestyle="-", marker="", linewidth=1.4),
    "FEM P1": dict(linestyle="none", marker="o", markerfacecolor="none", markersize=7),
    "FEM P2": dict(linestyle="none", marker="x", markersize=6),
    "analytical": dict(linestyle="--", marker="", linewidth=1.3),
    "theory": dict(linestyle="--", marker="", linewidth=0.9),
    "residual": dict(linestyle=":", marker="o", markersize=4, linewidth=0.8),
}
#: the solvers a curve figure may show, in legend order
STYLES_OF_CURVES = ("shooting", "analytical", "FEM P1", "FEM P2")
#: solver column label -> how a caption names its style
_STYLE_NAMES = {"shooting": "solid lines", "analytical": "dashed lines", "FEM P1": "open circles",
                "FEM P2": "crosses"}
#: what a caption says of the points a log axis leaves out
NO_ZERO = "The log axes leave out F = 0 (the inflated pocket), which a log scale cannot place."


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


def paper_pockets(pockets) -> list:
    """The pockets of the paper's model: a Mooney-Rivlin rubber filled with a liquid, pressed by the plate."""
    return [p for p in pockets if p.case.material.law == "mooney-rivlin" and not p.case.fluid.is_gas and on_plate(p)]
