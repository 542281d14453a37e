"""Profiles resampled on given Lagrangian radii, piecewise on either side of the contact edge.

A solver samples a state's meridian (``pocket.core.states.Profile``) at radii of
its own: the shooting solver at its adaptive integration steps, a different
count at every force; the FE model at its nodes. A time series for ParaView
needs one set of points at every step (its temporal interpolation and point
tracking pair points by index), so ``series_radii`` gives one set for a series
and ``resample`` puts each profile on it.

The meridian is smooth on each side of the contact edge a_c (the largest
Lagrangian radius in contact) but not across it: the curvature jumps from 0 in
the flat zone to P/T_1 in the free part. So the contact zone r <= a_c and the
free part r >= a_c are interpolated separately, each field (rho, eta, the
stretches and tensions) by a not-a-knot cubic spline through the solver's
points on that side: fourth-order accurate in the solver's spacing on each
side, exact on the flat zone (rho = lambda_c r, eta = H, constant stretches and
tensions are cubics), and the kink stays at a_c. ``series_radii`` puts a point
at the contact edge of every state of the series, so each step has one exactly
at its own edge, and ``contact`` is exactly r <= a_c.
"""

from __future__ import annotations

import numpy as np

from pocket.core.errors import InputError
from pocket.core.states import Profile

__all__ = ["contact_edge", "resample", "series_radii"]

_FIELDS = ("rho", "eta", "stretch_1", "stretch_2", "tension_1", "tension_2")
_MERGE = 1e-9  # relative distance below which an equally spaced radius gives way to a contact edge


def contact_edge(profile) -> float | None:
    """The Lagrangian contact radius a_c: the largest r in contact (None: no contact)."""
    touching = np.asarray(profile.contact, dtype=bool)
    return float(np.asarray(profile.r)[touching].max()) if touching.any() else None


def _spline(r, values, at) -> np.ndarray:
    """``values`` at ``at`` by a not-a-knot cubic spline through (r, values); one point is a constant."""
    from scipy.interpolate import CubicSpline

    if len(r) == 1:
        return np.full(len(at), values[0], dtype=float)
    return CubicSpline(r, values)(at)


def _check(r, at) -> None:
    if at.ndim != 1 or at.size < 2 or np.any(np.diff(at) <= 0.0) or at[0] < r[0] or at[-1] > r[-1]:
        raise InputError(f"radii must be at least 2 increasing values in [{r[0]!r}, {r[-1]!r}], got {at.size} "
                         f"from {at.min()!r} to {at.max()!r}" if at.size else "radii is empty")


def resample(profile, radii) -> Profile:
    """``profile`` at the Lagrangian radii ``radii``, shape (m,), increasing, within the profile's span."""
    r = np.asarray(profile.r, dtype=float)
    at = np.asarray(radii, dtype=float)
    _check(r, at)
    once = np.concatenate(([True], np.diff(r) > 0.0))  # a radius given twice (a solver's seam) counts once
    r = r[once]
    edge = contact_edge(profile)
    inside = np.zeros(at.size, bool) if edge is None else at <= edge
    sides = [(~inside, r >= (r[0] if edge is None else edge))]
    if edge is not None:
        sides.append((inside, r <= edge))
    out = {}
    for name in _FIELDS:
        values = np.asarray(getattr(profile, name), dtype=float)[once]
        field = np.empty(at.size)
        for wanted, given in sides:
            if wanted.any():
                field[wanted] = _spline(r[given], values[given], at[wanted])
        out[name] = field
    return Profile(r=at.copy(), contact=inside, **out)


def series_radii(profiles, points: int) -> np.ndarray:
    """One set of Lagrangian radii for a series of profiles: ``points`` equally spaced over the span every
    profile covers, plus each profile's contact edge (an edge within 1e-9 of the span of an equally spaced
    radius replaces it, so that no two points nearly coincide)."""
    low, high = max(float(p.r[0]) for p in profiles), min(float(p.r[-1]) for p in profiles)
    edges = np.unique([e for e in map(contact_edge, profiles) if e is not None and low <= e <= high])
    grid = np.linspace(low, high, points)
    if edges.size:
        near = np.abs(grid[:, None] - edges[None, :]).min(axis=1) <= _MERGE * (high - low)
        near[[0, -1]] = False  # the span's ends stay
        grid = grid[~near]
    return np.unique(np.concatenate((grid, edges)))
