r"""The mesh of the sheet's cross-section: r in [0, 1] by z in [-t/2, t/2] (units R; t = T/R).

The mid-surface of the flat sheet is the membrane's clamp plane z = 0, so that the solid's heights
are measured from the same plane as the membrane's. Quadrilaterals, a tensor product of the radial
nodes and ``layers`` layers through the thickness (graded towards both surfaces). Along the radius
the nodes are

    r_i = 1 - (1 - i / n)^q,    i = 0 .. n,

graded towards the clamp r = 1 with q = ``CLAMP_GRADING``: the sheet bends there over a
boundary layer a few thicknesses wide (the membrane's slope jumps to the clamp's), where the
elements are q / n^q long instead of 1 / n (the pole needs no grading: the solid has no
singular stretch there).

The clamp's corners. Where the clamped face r = 1 meets the free surfaces the strain is singular.
The sheet leaves the clamp bent upwards within about one thickness (past the vertical when the
pocket is more than a hemisphere), so the upper surface beside the corner lies on the inside of
that bend. Resolved by elements much shorter than the thickness, that surface folds: on the way
to Fhat = 3 of a Mooney-Rivlin pocket (alpha = 0.3, Phat_I = 0.3, T/R = 0.0125) meshed with
corner elements 0.16 T long, the upper surface's node beside the corner had sunk 0.05 T below
the corner, det F in the corner element spread over 0.19 to 2.9 at its quadrature points, and
from Fhat = 2.35 on Newton, with the contact's active set fixed, cycled there with period two
(steps of 1e-5 R that did not fall, whatever the force step); free inflation, without the plate,
stalled alike (Phat = 1.26; at 0.84 with corner elements 0.15 T long and high). A smooth discrete
surface cannot follow a fold, nor a crease, which a rubber surface compressed past a stretch of
about 0.65 forms (Hong, Zhao and Suo, Appl. Phys. Lett. 95, 111901, 2009). The elements at the
clamp are therefore ``corner`` T long (the solver's option; T/2 without the clamp's upper jaw, the default
``pocket.solid.DEFAULT_CORNER`` with it) whatever the radial elements and the layers, and the
next two grow by ``CORNER_GROWTH``, so that refining along the radius leaves the corners' mesh:
a regularisation at the thickness' scale, at which the real clamp's jaws (rounded, not rigid)
regularise the sheet too. With it the same pocket reaches Fhat = 3 and free inflation Phat = 2, and
on 64 x 4 elements, and on the default 24 x 4 with the contact edge followed, the pocket without the clamp's
upper jaw (``jaw``) goes on to Fhat = 5.43, where the corner element folds in turn: the discrete
path turns there, in force and in height, and Newton stops (``newton``). Corner elements 1 T long take it to
Fhat = 7.41, 1.5 and 2 T past Fhat = 9; they change P/P_I at Fhat = 5 by 2.7e-3 and 4.6e-3 (from 0.5 T), more
than the solid's difference from the membrane there (1.9e-3; at Fhat = 1 7e-4, against their 5e-4 and 1.5e-3).
The membrane, which has no thickness, sees none of this; doubling the corner elements' length
changes V by 4e-4 and H0 by 1.3e-4 (relative), a few percent of the membrane's own difference
from the solid (``tests/test_solid_clamp.py``). With the jaw (the default, its edge T/2) the upper surface
wraps the edge instead of folding, the range goes on past Fhat = 9, and the corner's elements, no longer a
regularisation but a mesh of the edge's radius, change the headline pocket's V by 1e-6 from T/2 to T/4
(``tests/test_solid_clamp.py``); the default, T/4, spans the edge with two elements.

The jaw's wrap zone. Wrapped round the edge, the sheet presses the jaw's side face too and leaves it a little
further out: on the headline pocket the upper surface lies on the jaw over about 0.6 to 1.2 T from the clamp,
longer than the edge's radius. Elements that grow from the corner's length straight away cut that zone
across: the zone's end, where the sheet lifts off, fell inside an element 0.56 T long (from 0.63 to 1.19 T on
24 elements), its discrete place jumped from node to node as the mesh changed, and P/P_I moved erratically with
the radial elements, by 5e-5 and more (-6.3e-5 on 24 elements, +1.8e-6 on 56, -5.1e-5
on 60, against 128, at Fhat = 0.4 of the headline pocket). The elements therefore keep the corner's length over
``WRAP`` thicknesses from the clamp before they grow: the headline pocket's curve (Fhat 0.1 to 1) then moves
by 1e-6 from 24 to 256 elements, and by 6e-4 at Fhat = 0.4 from the former meshes' answer, which all of them
shared.
"""

from __future__ import annotations

import numpy as np
from skfem import MeshQuad

from pocket.core.geometries import DISC, Geometry

__all__ = ["CLAMP_GRADING", "WRAP", "corner_nodes", "radial_nodes", "section"]

#: grading exponent of the radial nodes towards the clamp
CLAMP_GRADING = 1.5
#: growth of the elements' lengths away from the clamp's corners
CORNER_GROWTH = 1.5
#: the length from the clamp (in thicknesses) over which the elements keep the corner's length: the jaw's wrap
#: zone (module docstring), where the upper surface lies on the jaw's edge and side face (to ~1.2 T)
WRAP = 1.5


def radial_nodes(elements: int, grading: float = CLAMP_GRADING) -> np.ndarray:
    """The radial nodes (elements + 1,), from 0 to 1, graded towards 1."""
    s = np.linspace(0.0, 1.0, elements + 1)
    r = 1.0 - (1.0 - s) ** grading
    r[0], r[-1] = 0.0, 1.0
    return r


def heights(thickness: float, layers: int) -> np.ndarray:
    """The heights of the layers' interfaces (layers + 1,), graded towards both surfaces."""
    return 0.5 * thickness * np.sin(0.5 * np.pi * np.linspace(-1.0, 1.0, layers + 1))


def _spacing(r: np.ndarray, x: float) -> float:
    """The length of the element of the nodes ``r`` that holds x."""
    k = int(np.clip(np.searchsorted(r, x), 1, r.size - 1))
    return float(r[k] - r[k - 1])


def corner_nodes(r: np.ndarray, smallest: float, uniform: float = 0.0) -> np.ndarray:
    """The radial nodes ``r`` with a cluster at the clamp: elements ``smallest`` long from r = 1 until they span
    ``uniform`` (at least one), then each ``CORNER_GROWTH`` times longer until one is twice ``smallest`` (these
    do not depend on ``r``), then longer or shorter by that ratio until they are within a factor
    sqrt(``CORNER_GROWTH``) of ``r``'s elements where the cluster ends; the nodes of ``r`` within half an element
    of the cluster dropped. The cluster stops where its next element would leave less than twice its length to
    the axis (thick sheets).

    Examples
    --------
    Elements 0.05 long over 0.1 from the clamp, then growing by 1.5 up to the 0.25-long elements of ``r``:

    >>> import numpy as np
    >>> np.round(corner_nodes(np.linspace(0.0, 1.0, 5), 0.05, 0.1), 6).tolist()
    [0.0, 0.25, 0.54375, 0.7125, 0.825, 0.9, 0.95, 1.0]
    """
    steps = [smallest]

    def room(step):
        return 1.0 - sum(steps) - step > 2.0 * step

    while sum(steps) < uniform * (1.0 - 1e-9) and room(smallest):
        steps.append(smallest)
    while steps[-1] < 2.0 * smallest and room(CORNER_GROWTH * steps[-1]):
        steps.append(CORNER_GROWTH * steps[-1])
    ratio = CORNER_GROWTH if _spacing(r, 1.0 - sum(steps)) > steps[-1] else 1.0 / CORNER_GROWTH
    while room(ratio * steps[-1]):
        mismatch = _spacing(r, 1.0 - sum(steps)) / steps[-1]
        if mismatch ** np.sign(ratio - 1.0) < np.sqrt(CORNER_GROWTH):
            break
        steps.append(ratio * steps[-1])
    end = 1.0 - sum(steps)
    bulk = r[r < end - 0.5 * _spacing(r, end)]
    return np.concatenate([bulk, 1.0 - np.cumsum(steps)[::-1], [1.0]])


def section(thickness: float, elements: int, layers: int, corner: float, grading: float = CLAMP_GRADING,
            geometry: Geometry = DISC) -> MeshQuad:
    """The quadrilateral mesh of [0, 1] x [-t/2, t/2], t = ``thickness`` (T/R), with the boundaries
    ``left`` (the axis), ``right`` (the clamp), ``bottom`` (wetted by the fluid) and ``top``: the undeformed
    sheet about the reference surface ``geometry`` (the flat clamped disc, whose radius r0(S) is its arc length
    S; the only one ``api.GEOMETRIES`` poses), its radial nodes at r0 of the arc lengths graded as above, the
    clamp's corner elements ``corner`` thicknesses long over the jaw's wrap zone (``WRAP`` thicknesses)."""
    z = heights(thickness, layers)
    r = geometry.radius(corner_nodes(radial_nodes(elements, grading), corner * thickness, WRAP * thickness))
    return MeshQuad.init_tensor(r, z).with_defaults()
