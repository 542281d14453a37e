"""The indenter's lower surface as a VTK dataset, so that ParaView shows it pressing the sheet.

The surface is z = h + z(rho) (``pocket.core.indenters``), revolved about the axis like the sheet
(``pocket.apps.vtk.revolve``), h the height of the indenter's lowest point: a compressed state's ``height``
(units R). Its meridian is the indenter's own (``Indenter.meridian``) at ``RINGS`` radii, denser towards the
rim where a sphere steepens, out to its reach or ``reach``, whichever is nearer: the flat plate is a disc of
radius ``reach`` (``write_series`` takes ``PLATE_MARGIN`` times the widest point of the sheet in the series, so
the disc covers the pocket), a sphere is drawn to its equator or ``reach``, a profile to its last radius or
``reach``. Every step of a series has the same points, only their height changes.

Field data: ``height`` (h, units R), ``indenter_code`` (the indenter's position in
``pocket.core.indenters.INDENTERS``) and each numeric parameter (``Indenter.numbers``: a sphere's ``radius``,
units R).
"""

from __future__ import annotations

import meshio
import numpy as np

from pocket.core.indenters import INDENTERS, Indenter

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


def indenter_mesh(indenter: Indenter, height: float, reach: float, *, segments: int = 64) -> meshio.Mesh:
    """The lower surface of ``indenter`` with its lowest point at ``height`` (units R) out to ``reach`` (units R),
    revolved with ``segments`` points per ring, with its field data (module docstring)."""
    rho, z = indenter.meridian(reach, RINGS)
    surface = revolve(rho, height + z, segments)
    fields = {"height": np.array([float(height)]),
              "indenter_code": np.array([float(tuple(INDENTERS).index(indenter.name))])}
    fields.update({name: np.array([value]) for name, value in indenter.numbers().items()})
    return meshio.Mesh(surface.points, surface.cells, field_data=fields)
