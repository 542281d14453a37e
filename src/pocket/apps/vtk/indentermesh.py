"""The indenter's lower surface as a VTK dataset, so that ParaView shows it pressing the sheet.

The surface is z = h + z(rho) (``pocket.core.indenters``), revolved about the axis like the sheet
(``pocket.apps.vtk.revolve``), h the height of the indenter's lowest point: a compressed state's ``height``
(units R). Its meridian is the indenter's own (``Indenter.meridian``) at ``RINGS`` radii, denser towards the
rim where a sphere steepens, out to its reach or ``reach``, whichever is nearer: the flat plate is a disc of
radius ``reach`` (``write_series`` takes ``PLATE_MARGIN`` times the widest point of the sheet in the series, so
the disc covers the pocket), a sphere is drawn to its equator or ``reach``, a profile to its last radius or
``reach``. Every step of a series has the same points, only their height changes.

A capsule is pressed between two plates, symmetric about its equatorial plane z = c (``mirror``): the mesh then
holds both, the upper one's lowest point at h and its mirror image through that plane, the lower plate's
highest point at 2 c - h (its cells after the upper one's, the same in number).

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


def indenter_mesh(indenter: Indenter, height: float, reach: float, *, segments: int = 64,
                  mirror: float | None = None) -> meshio.Mesh:
    """The lower surface of ``indenter`` with its lowest point at ``height`` (units R) out to ``reach`` (units R),
    revolved with ``segments`` points per ring, with its field data (module docstring); with ``mirror``, the
    height of a plane of mirror symmetry (a capsule's equatorial plane, units R), its mirror image too."""
    rho, z = indenter.meridian(reach, RINGS)
    surface = revolve(rho, height + z, segments)
    points, cells = surface.points, surface.cells
    if mirror is not None:
        image = points * np.array([1.0, 1.0, -1.0]) + np.array([0.0, 0.0, 2.0 * mirror])
        cells = [*cells, *((kind, block + len(points)) for kind, block in cells)]
        points = np.vstack((points, image))
    fields = {"height": np.array([float(height)]),
              "indenter_code": np.array([float(tuple(INDENTERS).index(indenter.name))])}
    fields.update({name: np.array([value]) for name, value in indenter.numbers().items()})
    return meshio.Mesh(points, cells, field_data=fields)
