"""The figures beyond the paper: its pocket filled with a gas, and other rubber laws.

- ``fluids``: the pockets tagged "fluids" (one sheet at one P_I, filled with a
  liquid, with air compressed slowly, gamma = 1, and fast, gamma = 1.4): the
  contact area A_c/(pi R^2) and the pressure ratio P/P_I against the force, each to
  0.95 of the end of its range. A gas is compressed too, so at moderate force its
  pressure rises less than the liquid's; near the end of the range the liquid's
  fixed volume stretches the contact zone more, its contact area is larger and its
  pressure F / A_c lower than the gas's (the curves cross).
- ``laws``: the pockets of the other laws beside the headline pocket: the height
  H/H0 and the pressure ratio P/P_I against the force (log scale: their ranges end
  between Fhat = 4 and 52).

Both draw the shooting solver as lines and the FE model as markers where computed,
like the paper's figures (``figures``).
"""

from __future__ import annotations

import numpy as np

from .plan import RANGE_FRACTION
from .plotdata import Figure, Panel, Series, curve_series, paper_pockets, pocket_colors, pocket_label
from .suite import headline, on_plate

__all__ = ["other_figures"]

_FHAT = "F / (P_I pi R^2)"


def _difference(results, liquid, pockets) -> tuple:
    """Series of (P/P_I)_gas / (P/P_I)_liquid - 1 against Fhat for each gas of ``pockets``, the liquid's
    curve interpolated (cubic spline through its shooting states) at the gas's forces inside its range."""
    from scipy.interpolate import CubicSpline

    ref = results.curves_of(liquid).reference
    spline = CubicSpline([s.force for s in ref], [s.pressure_ratio for s in ref])
    out, colors = [], pocket_colors(results.pockets)
    for pocket in (p for p in pockets if p.case.fluid.is_gas):
        states = [s for s in results.curves_of(pocket).reference if 0.0 < s.force <= ref[-1].force]
        forces = np.array([s.force for s in states])
        out.append(Series(f"{pocket.case.label}: shooting", "shooting", forces,
                          np.array([s.pressure_ratio for s in states]) / spline(forces) - 1.0, colors[pocket],
                          pocket_label(pocket)))
    return tuple(out)


def _fluids(results, pockets) -> Figure:
    panels = [Panel(f"({letter}) {title}", _FHAT, ylabel, curve_series(results, key, pockets, ()), log="x")
              for letter, key, ylabel, title in (("a", "contact_area", "A_c / (pi R^2)", "contact area"),
                                                 ("b", "pressure_ratio", "P / P_I", "pressure ratio"))]
    liquid = next((p for p in pockets if not p.case.fluid.is_gas), None)
    if liquid is not None:
        panels.append(Panel("(c) the gas against the liquid", _FHAT, "(P / P_I)_gas / (P / P_I)_liquid - 1",
                            _difference(results, liquid, pockets), log="x", marks=((None, 0.0, ""),)))
    return Figure("fluids", f"A liquid and a gas in one pocket ({pocket_label(pockets[0])}; air at the ambient "
                  "pressure of the cases, compressed slowly (gamma = 1) and fast (gamma = 1.4)): contact area (a) "
                  f"and pressure ratio P/P_I (b) against the force, each to {RANGE_FRACTION:g} of the end of its "
                  "range; "
                  "lines: shooting, markers: the FE model; (c) the gas's pressure ratio over the liquid's at the same "
                  "force, minus 1 (A_c = F / P, so the contact areas differ by the inverse ratio). The gas is "
                  "compressed as well: at moderate force its pressure rises less; near the end of the range the "
                  "liquid, held at its volume, stretches the contact zone more, so its contact area is larger and "
                  "its pressure F / A_c lower: the curves cross.", tuple(panels))


def _laws(results, pockets) -> Figure:
    panels = tuple(Panel(f"({letter}) {title}", _FHAT, ylabel, curve_series(results, key, pockets, ()), log=log)
                   for letter, key, ylabel, title, log in (("a", "height_ratio", "H / H_0", "height", "x"),
                                                           ("b", "pressure_ratio", "P / P_I", "pressure ratio", "xy")))
    return Figure("laws", "Other rubber laws beside the headline pocket (the paper's Mooney-Rivlin silicone): "
                  f"height (a) and pressure ratio P/P_I (b) against the force, each to {RANGE_FRACTION:g} of the "
                  "end of its range (log scales); lines: shooting, markers: the FE model.", panels)


def other_figures(results) -> list[Figure]:
    """The ``fluids`` figure if the cases tag pockets "fluids", the ``laws`` figure if they hold another
    law (module docstring)."""
    out = []
    head = headline(results.pockets)
    fluids = [p for p in results.pockets if "fluids" in p.case.tags]
    if fluids:
        out.append(_fluids(results, fluids))
    others = [p for p in results.pockets
              if p.case.material.law != "mooney-rivlin" and not p.case.fluid.is_gas and on_plate(p)]
    if others:
        main = [head] if head in paper_pockets(results.pockets) else []
        out.append(_laws(results, main + others))
    return out
