"""The figures of the pockets pressed by a sphere (a fingertip) rather than the flat plate.

- ``fingertips``: the headline pocket pressed by the plate and by the spheres of the
  cases that share its sheet, fluid and P_I: (a) the force against the travel
  (H_0 - H)/R, H the indenter's lowest point above the clamp plane, (b) the pressure
  rise P/P_I against the force.
- ``contact_pressure``: the contact pressure p_c/P along the contact zone of every
  pocket pressed by a sphere, at F/(P_I pi R^2) = ``CONTACT_FORCE`` (the nearest force of
  its curve), against the deformed radius rho/R (a) and against rho/rho_c (b), rho_c
  the deformed contact radius. On a sphere of radius R_s, p_c = P + (T_1 + T_2)/R_s > P.

Each figure is left out when the cases hold no pocket for it.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .plan import RANGE_FRACTION
from .plotdata import Figure, Panel, Series, curve_series, pocket_colors, pocket_label, solver_key
from .suite import headline, on_plate

__all__ = ["CONTACT_FORCE", "fingertip_figures", "fingertip_pockets", "sphere_pockets"]

#: F/(P_I pi R^2) of the contact-pressure figure (a force of the plans' FE columns under a sphere)
CONTACT_FORCE = 0.5
_MARKERS = 15  # FE nodes shown per contact zone
_FHAT = "F / (P_I pi R^2)"


def sphere_pockets(pockets) -> list:
    """The pockets pressed by a curved indenter, in file order."""
    return [p for p in pockets if not on_plate(p)]


def fingertip_pockets(pockets) -> list:
    """The headline pocket (pressed by the plate) and the pockets pressed by a curved indenter that share
    its sheet, fluid and P_I, by the indenter's radius."""
    head = headline(pockets)
    same = [p for p in sphere_pockets(pockets) if p.case.material == head.case.material
            and p.case.fluid == head.case.fluid and p.pressure_initial == head.pressure_initial]
    return [head, *sorted(same, key=lambda p: p.case.indenter.numbers()["radius"])]


def _travel_series(results, pockets) -> tuple:
    """Fhat against the travel (H_0 - H)/R: the reference as lines, the FE columns as markers."""
    head, colors = headline(results.pockets), pocket_colors(results.pockets)
    series = []
    for layer, pocket in enumerate(pockets):
        runs = [("shooting", results.curves_of(pocket).reference)]
        runs += [(r.column.label, r.states) for r in results.columns if r.pocket == pocket and len(r.states) > 1]
        for solver, states in runs:
            travel = np.array([s.inflated.height - s.height for s in states])
            series.append(Series(f"{pocket.case.label}: {solver}", solver, travel, np.array([s.force for s in states]),
                                 colors.get(pocket, 0), pocket_label(pocket), pocket == head, layer))
    return tuple(series)


def _fingertips(results, pockets) -> Figure:
    panels = (Panel("(a) force against travel", "(H_0 - H) / R", _FHAT, _travel_series(results, pockets)),
              Panel("(b) pressure rise", _FHAT, "P / P_I", curve_series(results, "pressure_ratio", pockets, ()),
                    log="xy"))
    radii = ", ".join(f"{p.case.indenter.columns(p.case.radius)['indenter_radius_m'] * 1e3:g}" for p in pockets[1:])
    return Figure("fingertips", f"A fingertip, not a plate: {pocket_label(pockets[0])} pressed by the flat plate "
                  f"(the broad dark line) and by spheres of radius R_s = {radii} mm, each to {RANGE_FRACTION:g} of "
                  "the end of its range; (a) the force against the travel H_0 - H (H: the indenter's lowest point "
                  "above the clamp plane, H_0 the inflated pocket's height), (b) the pressure ratio P/P_I against "
                  f"the force (log scales). {solver_key(('shooting', 'FEM P2'))} (the FE model where computed; "
                  "P1 only under the plate). At the same force a smaller sphere travels further and raises the "
                  "pressure a little more; the larger the sphere, the nearer its curves to the plate's.", panels)


def _contact_series(results, pockets, scaled: bool) -> tuple:
    """p_c/P along the contact zone at the force nearest CONTACT_FORCE: against rho/R, or rho/rho_c if
    ``scaled``; the reference as lines, the FE columns as markers at that same force."""
    colors = pocket_colors(results.pockets)
    series = []
    for layer, pocket in enumerate(pockets):
        curves = results.curves_of(pocket)
        shot = curves.reference[int(np.argmin(np.abs(curves.forces - CONTACT_FORCE)))]
        runs: list[tuple[str, Any, int | None]] = [("shooting", shot, None)]
        runs += [(r.column.label, s, _MARKERS) for r in results.columns if r.pocket == pocket
                 for s in r.states if s.force == shot.force]
        for solver, state, markers in runs:
            zone = np.isfinite(state.contact_pressure)
            rho = state.profile.rho[zone] / (state.contact_radius_deformed if scaled else 1.0)
            ratio = state.contact_pressure[zone] / state.pressure
            if markers is not None:
                pick = np.unique(np.linspace(0, len(rho) - 1, markers).round().astype(int))
                rho, ratio = rho[pick], ratio[pick]
            series.append(Series(f"{pocket.case.label}: {solver} at Fhat = {shot.force:.3g}", solver, rho, ratio,
                                 colors.get(pocket, 0), pocket_label(pocket), False, layer))
    return tuple(series)


def _contact_pressure(results, pockets) -> Figure:
    panels = (Panel("(a) along the deformed radius", "rho / R", "p_c / P", _contact_series(results, pockets, False)),
              Panel("(b) scaled by the contact radius", "rho / rho_c", "p_c / P",
                    _contact_series(results, pockets, True)))
    return Figure("contact_pressure", "The contact pressure p_c over the fluid pressure P along the contact zone "
                  f"of every pocket pressed by a sphere, at F/(P_I pi R^2) = {CONTACT_FORCE:g} (the nearest force "
                  "of its curve): (a) against the deformed radius rho, (b) against rho over the deformed contact "
                  "radius rho_c. On the sphere the sheet's tensions add (T_1 + T_2)/R_s to P, so p_c/P > 1, "
                  "largest at the pole and falling to the contact edge. "
                  f"{solver_key(('shooting', 'FEM P2'))} (the FE nodes in contact, subsampled to {_MARKERS}).",
                  panels)


def fingertip_figures(results) -> list[Figure]:
    """The ``fingertips`` and ``contact_pressure`` figures, each if the cases hold pockets for it (module
    docstring)."""
    out = []
    tips = fingertip_pockets(results.pockets)
    if len(tips) > 1:
        out.append(_fingertips(results, tips))
    spheres = sphere_pockets(results.pockets)
    if spheres:
        out.append(_contact_pressure(results, spheres))
    return out
