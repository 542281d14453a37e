"""The indenter's lower surface as a VTK dataset, so that ParaView shows it pressing the sheet.

The surface is z = h + z(rho) (``pocket.core.indenters``), revolved about the axis like the sheet
(``pocket.apps.vtk.revolve``), h the height of the indenter's lowest point: a compressed state's ``height``
(units R). Its meridian is sampled at ``RINGS`` radii rho_k = reach sin(pi k / (2 (RINGS - 1))), denser
towards the rim where a sphere steepens, out to ``reach``: the flat plate is a disc of radius ``reach``
(``write_series`` takes ``PLATE_MARGIN`` times the widest point of the sheet in the series, so the disc
covers the pocket), a sphere is drawn to its equator or ``reach``, a profile to its last radius or
``reach``. Every step of a series has the same points, only their height changes.

Field data: ``height`` (h, units R), ``indenter_code`` (the kind's position in
``pocket.core.indenters.KINDS``) and each numeric parameter (a sphere's ``radius``, units R).
"""

from __future__ import annotations

import meshio
import numpy as np

from pocket.core.indenters import KINDS, Indenter

from .revolve import revolve

__all__ = ["PLATE_MARGIN", "RINGS", "indenter_mesh", "reach_of"]

#: radii on the indenter's meridian
RINGS = 41
#: the plate's disc is this many times wider than the widest point of the sheet
PLATE_MARGIN = 1.25


def reach_of(profiles) -> float:
    """How far out to draw an indenter over the sheets ``profiles`` (``pocket.core.states.Profile``): the
    margin times the widest radius of any (at least the clamp radius 1), units R."""
    return PLATE_MARGIN * max(1.0, *(float(np.max(p.rho)) for p in profiles))


def _extent(indenter: Indenter, reach: float) -> float:
    """The largest radius at which the indenter's surface exists, up to ``reach``."""
    if indenter.kind == "sphere":
        return min(reach, indenter.number("radius"))
    if "shape" in dict(indenter.params):
        return min(reach, indenter.shape().extent)
    return reach


def indenter_mesh(indenter: Indenter, height: float, reach: float, *, segments: int = 64) -> meshio.Mesh:
    """The lower surface of ``indenter`` with its lowest point at ``height`` (units R) out to ``reach`` (units R),
    revolved with ``segments`` points per ring, with its field data (module docstring)."""
    rho = _extent(indenter, reach) * np.sin(0.5 * np.pi * np.linspace(0.0, 1.0, RINGS))
    rho[-1] = _extent(indenter, reach)  # sin(pi/2) is 1 only to rounding
    eta = height + indenter.height(rho)
    surface = revolve(rho, eta, segments)
    fields = {"height": np.array([float(height)]),
              "indenter_code": np.array([float(tuple(KINDS).index(indenter.kind))])}
    fields.update({name: np.array([value]) for name, value in indenter.params if isinstance(value, float)})
    return meshio.Mesh(surface.points, surface.cells, field_data=fields)
