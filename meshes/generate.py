"""Node sets of 1-D meshes of the Lagrangian radius r in [0, 1].

Every function returns a sorted float array of node coordinates, strictly
increasing, with the first node exactly 0.0 and the last exactly 1.0.

``uniform(n)``
    n equal elements, h = 1/n.
``graded(n, towards=t, ratio=q)``
    geometric grading, finest at r = t. Towards an end (t = 0 or 1) the n
    element sizes form a geometric sequence h_k = h_0 g^k with common factor
    g = q^(1/(n-1)), so ``ratio`` q is exactly largest / smallest element size.
    Towards an interior point the interval is split at t into [0, t] and
    [t, 1], with m = round(n t) (kept within 1 .. n-1) and n - m elements,
    and each side is graded towards t with the same ratio q (a side of one
    element is uniform). Element counts proportional to the side lengths make
    the two elements next to t nearly equal; t is a node.
``refined(n, at=a, width=w, factor=f)``
    the uniform mesh of n elements (h = 1/n), with the band |r - a| <= w
    meshed at the finer size h/f. The band edges a - w, a + w (clipped to
    [0, 1]) and a itself are nodes; each of the (up to four) pieces between
    them is split uniformly into ceil(length / size) elements, so every element
    within the band is at most h/f long and every other at most h. The total
    is about n (1 + 2 w (f - 1)) elements. The element size jumps by about f
    at the band edges: 1-D Lagrange elements have no shape quality to lose,
    and the error is governed by the largest element, so no transition zone
    is added. A coarse piece shorter than one fine element is merged into the
    band, so that no sliver element appears next to r = 0 or r = 1.
``polar(n, power=p)``
    n elements graded algebraically towards the axis r = 0: the nodes are
    r_k = s^p (1 + (p - 1)(1 - s)) at s = k/n. Near the axis r ~ p s^p, so the
    elements shrink like (r)^(1 - 1/p) / n towards it; at the clamp dr/ds = 1,
    so the last elements are 1/n long as on the uniform mesh, and the largest is
    max_s dr/ds / n (1.33/n for p = 2, 1.51/n for p = 2.5, 1.69/n for p = 3).
    The axis is a coordinate singularity of the axisymmetric weak form: the
    pole stretch (a derivative there) converges at O(h^2) on uniform meshes
    and regains the order of the energy on these.
"""

from __future__ import annotations

import math
import operator

import numpy as np

from pocket.core.errors import InputError
from pocket.core.inputs import check_finite

__all__ = ["graded", "polar", "refined", "uniform"]


def _count(n, name="n") -> int:
    try:
        if isinstance(n, bool):
            raise TypeError
        value = operator.index(n)
    except TypeError:
        raise InputError(f"{name} = {n!r}, but a mesh needs an integer number of elements >= 1") from None
    if value < 1:
        raise InputError(f"{name} = {n!r}, but a mesh needs an integer number of elements >= 1")
    return value


def _split(length: float, count: int) -> np.ndarray:
    """Nodes of ``count`` equal pieces of [0, length], both ends exact."""
    nodes = np.linspace(0.0, length, count + 1)
    nodes[-1] = length
    return nodes


def _geometric(count: int, ratio: float) -> np.ndarray:
    """Nodes on [0, 1], finest at 0, largest/smallest element = ratio, ends exact."""
    if count == 1 or ratio == 1.0:
        return _split(1.0, count)
    growth = ratio ** (1.0 / (count - 1))
    sizes = growth ** np.arange(count)
    nodes = np.concatenate(([0.0], np.cumsum(sizes) / sizes.sum()))
    nodes[-1] = 1.0
    return nodes


def uniform(n) -> np.ndarray:
    """Nodes of ``n`` equal elements on [0, 1]."""
    return _split(1.0, _count(n))


def graded(n, *, towards=1.0, ratio=10.0) -> np.ndarray:
    """Nodes of ``n`` elements graded geometrically, finest at r = ``towards``.

    ``ratio`` (>= 1) is the largest over the smallest element size (on each
    side of an interior ``towards``); ratio = 1 gives the uniform mesh.
    """
    n = _count(n)
    towards = check_finite("towards", towards)
    ratio = check_finite("ratio", ratio)
    if not 0.0 <= towards <= 1.0:
        raise InputError(f"towards = {towards!r}, but it must lie in [0, 1]")
    if ratio < 1.0:
        raise InputError(f"ratio = {ratio!r}, but the largest/smallest element size ratio must be >= 1")
    if towards == 0.0:
        return _geometric(n, ratio)
    if towards == 1.0:
        return 1.0 - _geometric(n, ratio)[::-1]
    if n < 2:
        raise InputError(f"n = {n}, but grading towards the interior point {towards!r} needs n >= 2")
    m = min(max(round(n * towards), 1), n - 1)
    left = towards * (1.0 - _geometric(m, ratio)[::-1])
    right = towards + (1.0 - towards) * _geometric(n - m, ratio)
    left[-1] = towards
    right[-1] = 1.0
    return np.concatenate((left, right[1:]))


def refined(n, *, at, width=0.05, factor=8.0) -> np.ndarray:
    """Nodes of a uniform ``n``-element mesh refined ``factor`` times within ``width`` of ``at``."""
    n = _count(n)
    at = check_finite("at", at)
    width = check_finite("width", width)
    factor = check_finite("factor", factor)
    if not 0.0 < at < 1.0:
        raise InputError(f"at = {at!r}, but the refinement point must lie inside (0, 1)")
    if width <= 0.0:
        raise InputError(f"width = {width!r}, but the refined band needs width > 0")
    if factor < 1.0:
        raise InputError(f"factor = {factor!r}, but the refinement factor must be >= 1")
    coarse, fine = 1.0 / n, 1.0 / (n * factor)
    low, high = max(at - width, 0.0), min(at + width, 1.0)
    if low < fine:
        low = 0.0
    if high > 1.0 - fine:
        high = 1.0
    breaks = [0.0, low, at, high, 1.0]
    sizes = [coarse, fine, fine, coarse]
    pieces = [np.array([0.0])]
    for start, stop, size in zip(breaks[:-1], breaks[1:], sizes, strict=True):
        if stop > start:
            count = max(math.ceil((stop - start) / size * (1.0 - 1e-12)), 1)
            piece = start + _split(stop - start, count)
            piece[-1] = stop
            pieces.append(piece[1:])
    return np.concatenate(pieces)


def polar(n, *, power=2.5) -> np.ndarray:
    """Nodes of ``n`` elements graded algebraically towards the axis with exponent ``power`` (>= 1)."""
    n = _count(n)
    power = check_finite("power", power)
    if power < 1.0:
        raise InputError(f"power = {power!r}, but the grading exponent must be >= 1")
    s = _split(1.0, n)
    nodes = s**power * (1.0 + (power - 1.0) * (1.0 - s))
    nodes[0], nodes[-1] = 0.0, 1.0
    return nodes
