"""A meridian revolved about the z axis into a surface of quads (triangles at a pole on the axis).

Point (i, j) of ring i lies at (rho_i cos t_j, rho_i sin t_j, eta_i), t_j = 2 pi j / segments; the quads
(i, j), (i+1, j), (i+1, j+1), (i, j+1) wrap around in j, their normal (meridian tangent) x (hoop tangent).
A meridian that starts on the axis (rho_0 = 0) has its first ring collapsed to one point, and its first band
made of triangles (pole, (1, j), (1, j+1)); one that also ends on the axis (a closed capsule's whole meridian,
from pole to pole) has its last ring collapsed too, and its last band made of triangles ((m, j), end, (m, j+1)),
m the last ring: the surface is closed.
"""

from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["Revolved", "revolve"]


@dataclasses.dataclass(frozen=True)
class Revolved:
    """``points`` (m, 3) and meshio ``cells``; ``source`` (m,) the meridian index of each point and ``hoop`` (m,)
    its ring position j, for copying per-point data around the rings."""

    points: np.ndarray
    cells: list
    source: np.ndarray
    hoop: np.ndarray
    cos: np.ndarray
    sin: np.ndarray


def revolve(rho, eta, segments: int) -> Revolved:
    """The meridian (``rho``, ``eta``), float arrays of shape (n,), revolved with ``segments`` points per ring."""
    rho, eta = np.asarray(rho, dtype=float), np.asarray(eta, dtype=float)
    pole = rho[0] == 0.0
    tail = len(rho) > 2 and rho[-1] == 0.0  # the meridian ends on the axis too: a closed surface
    angle = 2.0 * np.pi * np.arange(segments) / segments
    cos, sin = np.cos(angle), np.sin(angle)
    rings = np.arange(1 if pole else 0, len(rho) - (1 if tail else 0))  # meridian index of each ring
    x, y = np.outer(rho[rings], cos).ravel(), np.outer(rho[rings], sin).ravel()
    points = np.column_stack((x, y, np.repeat(eta[rings], segments)))
    source = np.repeat(rings, segments)
    hoop = np.tile(np.arange(segments), len(rings))
    if pole:
        points = np.vstack(([[0.0, 0.0, eta[0]]], points))
        source, hoop = np.concatenate(([0], source)), np.concatenate(([0], hoop))
    first = 1 if pole else 0  # index of the first point of ring 0

    def at(ring, j):
        return first + ring * segments + j % segments

    j = np.arange(segments)
    band = np.arange(len(rings) - 1)[:, None]
    quads = np.stack((at(band, j), at(band + 1, j), at(band + 1, j + 1), at(band, j + 1)), axis=-1)
    cells = [("quad", quads.reshape(-1, 4))] if len(rings) > 1 else []
    if pole:
        cells.insert(0, ("triangle", np.column_stack((np.zeros(segments, int), at(0, j), at(0, j + 1)))))
    if tail:
        end = len(points)
        points = np.vstack((points, [[0.0, 0.0, eta[-1]]]))
        source, hoop = np.concatenate((source, [len(rho) - 1])), np.concatenate((hoop, [0]))
        last = len(rings) - 1
        cells.append(("triangle", np.column_stack((at(last, j), np.full(segments, end), at(last, j + 1)))))
    return Revolved(points, cells, source, hoop, cos, sin)
