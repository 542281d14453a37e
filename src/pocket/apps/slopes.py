"""Compression curves with their slopes d(value)/d(Fhat), by finite differences.

At each force f the slope of a state's value v (``height``, ``pressure_ratio``)
is the central difference (v(f + h) - v(f - h)) / (2 h), with h = 1e-4 max(f, 0.01):
truncation error ~ h^2 v''' / 6, about 1e-10 relative, and round-off ~ delta / h
from the solver's resolution delta ~ 1e-11, about 1e-6 relative. Where f < h
(the unloaded pocket) it is the one-sided second-order difference
(-3 v(f) + 4 v(f + h) - v(f + 2 h)) / (2 h). All the forces go to the solver in
one continuation (``compression_curve``).
"""

from __future__ import annotations

import numpy as np

from pocket.core.solver import Solver

from .solvers import entry

__all__ = ["curve_with_slopes"]

_STEP = 1e-4  # relative finite-difference step (see the module docstring)


def _stencil(f):
    h = _STEP * max(f, 0.01)
    if f >= h:
        return h, (f - h, f + h), (-0.5, 0.5)
    return h, (f + h, f + 2.0 * h), (2.0, -0.5)  # plus -1.5 v(f)


def curve_with_slopes(solver: Solver, material, pressure_initial, forces, keys, **options):
    """States at ``forces`` (Fhat) and {key: array of d key / d Fhat} for each of ``keys``, by ``solver``'s
    ``compression_curve`` (its record)."""
    forces = [float(f) for f in forces]
    stencils = [_stencil(f) for f in forces]
    points = sorted(set(forces) | {x for _, xs, _ in stencils for x in xs})
    curve = entry(solver, "compression_curve", "the slopes of a compression curve")
    states = dict(zip(points, curve(material, pressure_initial, points, **options), strict=True))
    slopes = {}
    for key in keys:
        out = []
        for f, (h, xs, weights) in zip(forces, stencils, strict=True):
            centre = -1.5 * getattr(states[f], key) if xs[0] > f else 0.0
            out.append((centre + sum(w * getattr(states[x], key) for x, w in zip(xs, weights, strict=True))) / h)
        slopes[key] = np.array(out)
    return [states[f] for f in forces], slopes
