r"""The mesh of the sheet's cross-section: r in [0, 1] by z in [-t/2, t/2] (units R; t = T/R).

The mid-surface of the flat sheet is the membrane's clamp plane z = 0, so that the solid's heights
are measured from the same plane as the membrane's. Quadrilaterals, a tensor product of the radial
nodes and ``layers`` equal layers through the thickness. Along the radius the nodes are

    r_i = 1 - (1 - i / n)^q,    i = 0 .. n,

graded towards the clamp r = 1 with q = ``CLAMP_GRADING``: the sheet bends there over a
boundary layer a few thicknesses wide (the membrane's slope jumps to the clamp's), where the
elements are q / n^q long instead of 1 / n (the pole needs no grading: the solid has no
singular stretch there).
"""

from __future__ import annotations

import numpy as np
from skfem import MeshQuad

__all__ = ["section", "radial_nodes", "CLAMP_GRADING"]

#: grading exponent of the radial nodes towards the clamp
CLAMP_GRADING = 1.5
#: growth of the elements' lengths away from the clamp's corners
CORNER_GROWTH = 1.5


def radial_nodes(elements: int, grading: float = CLAMP_GRADING) -> np.ndarray:
    """The radial nodes (elements + 1,), from 0 to 1, graded towards 1."""
    s = np.linspace(0.0, 1.0, elements + 1)
    r = 1.0 - (1.0 - s) ** grading
    r[0], r[-1] = 0.0, 1.0
    return r


def heights(thickness: float, layers: int) -> np.ndarray:
    """The heights of the layers' interfaces (layers + 1,), graded towards both surfaces."""
    return 0.5 * thickness * np.sin(0.5 * np.pi * np.linspace(-1.0, 1.0, layers + 1))


def corner_nodes(r: np.ndarray, smallest: float) -> np.ndarray:
    """The radial nodes ``r`` with a geometric cluster towards the clamp: from an element ``smallest`` long at
    r = 1, each ``CORNER_GROWTH`` times longer, until they are as long as the last element of ``r``."""
    edge = r[-1] - r[-2]
    steps = smallest * CORNER_GROWTH ** np.arange(int(np.ceil(np.log(edge / smallest) / np.log(CORNER_GROWTH))))
    cluster = 1.0 - np.cumsum(steps)
    bulk = r[r < cluster[-1] - 0.5 * edge] if cluster.size else r[:-1]
    return np.concatenate([bulk, cluster[::-1], [1.0]])


def section(thickness: float, elements: int, layers: int, grading: float = CLAMP_GRADING) -> MeshQuad:
    """The quadrilateral mesh of [0, 1] x [-t/2, t/2], t = ``thickness`` (T/R), with the boundaries
    ``left`` (the axis), ``right`` (the clamp), ``bottom`` (wetted by the fluid) and ``top``."""
    z = heights(thickness, layers)
    r = corner_nodes(radial_nodes(elements, grading), z[1] - z[0])
    return MeshQuad.init_tensor(r, z).with_defaults()
