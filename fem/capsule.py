r"""The closed capsule: a spherical membrane inflated, then squeezed between two parallel plates.

The reference surface is ``pocket.core.geometries.CAPSULE``: by symmetry only the upper half is solved, its
meridian the quarter circle S in [0, pi/2] (r0 = sin S, z0 = cos S), meshed in r = S / c on [0, 1]
(c = pi/2; ``kernel`` derives the forms). The unknowns and equations are ``model``'s: rho(0) = 0 and
eta(1) = 0 are prescribed (the pole on the axis, the equator on the plane of symmetry), rho(1) is free
(the equator moves out); the pressure is the multiplier of the upper half's volume, half the capsule's,
and the plate's force is the reaction on the upper half's contact zone: the force on each plate.

Inflation. The inflated capsule is a sphere of uniform equibiaxial stretch lambda (docs: theory, section 12),

    Phat = 2 t(lambda) / lambda = 2 w_1(lambda, lambda) / lambda^2,     V = 4/3 pi lambda^3,

t = T_1 / (E T) at (lambda, lambda). ``sphere_stretch`` solves it on the first branch: from the unstressed
sphere (lambda = 1, or 1 / lambda_p for a sheet prestretched by lambda_p), Phat(lambda) is followed up in
steps of 1 % and the first step past the target is refined by Brent's method; a fall on the way is the
balloon's pressure maximum (``OutOfRangeError``: volume control passes it), and the path stops at the pole
stretch ``STRETCH_LIMIT``. That sphere, interpolated (rho = lambda sin S, eta = lambda cos S), is
Newton's start under pressure control; the finite elements then settle on their own discrete sphere, within
the discretisation error of the closed form. At Phat = 0 the capsule is the unstressed reference sphere, its
nodes where the reference puts them (no tension: Newton's pressure and increments would have nothing to be
measured against).

Compression: the disc's edge-fitted contact (``fitted``, ``curves``) with the contact zone [0, a] on
``model.flat`` elements (the flat zone is not uniform on a sphere: its stretches vary like S^2), closed by
tangent contact at the edge; the states are ``capsulestates``'.

The end of the range. Nothing like the pocket's clamp ends it. Where the pole's stretch under the plate falls
below that of the unstressed rubber (1 / lambda_p, at a low Phat_I or with a yielding gas) the patch's tension is
compressive: such states are returned flagged wrinkled (``pocket.core.states``), as the shooting solver's are. As
the force rises the slack can spread to the contact edge, where the meridional tension T_1 then vanishes and the
free part would leave the plate with the unbounded curvature P / T_1: no membrane state lies beyond
(``pocket.core.errors.CAPSULE_EDGE``, the end the shooting solver quotes). The free part's vertical balance keeps
T_1 positive everywhere off the plate but at the edge, so the edge is what is watched: every converged state's T_1
there, from the contact zone's flux (``post.edge_tension``), must be positive, else the step is outside the model
(``steps.check_edge``, an ``OutOfRangeError``). The discrete states go on past the end, their edge compressive;
the continuation (``continuation``) cuts the step that lands there down to its smallest and quotes the end between
the last force (or plate height) it solved and the nearest beyond it it tried, on the default mesh within a few
1e-6 of the shooting solver's end. Under the plate a compressive tension is a slack patch, not an end.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from pocket.core.errors import (
    STRETCH_LIMIT,
    OutOfRangeError,
    above_pressure_maximum,
    past_stretch_limit,
)

from .geometry import node_radii, place
from .material import Law
from .model import FREE, Control, Model
from .newton import Tolerances
from .steps import solve

__all__ = ["STEP", "inflate", "inflate_volume", "sphere", "sphere_pressure", "sphere_stretch"]

#: the relative step in lambda of the march along the closed form's first branch
STEP = 0.01


def sphere_pressure(law: Law, stretch) -> np.ndarray:
    """Phat = 2 w_1(lambda, lambda) / lambda^2 of the sphere of uniform stretch ``stretch`` (any shape)."""
    stretch = np.asarray(stretch, dtype=float)
    return 2.0 * law.derivatives(stretch, stretch)[0] / stretch**2


def sphere_stretch(law: Law, pressure: float) -> float:
    """lambda of the inflated sphere at ``pressure`` on the first branch (module docstring)."""
    low = 1.0 / law.prestretch
    if pressure <= 0.0:
        return low
    asked = f"Phat = {pressure!r}"
    lam, last = low, 0.0
    while lam < STRETCH_LIMIT:
        step = lam * (1.0 + STEP)
        value = float(sphere_pressure(law, step))
        if not math.isfinite(value):  # past a locking rubber's domain, where its pressure diverged
            raise past_stretch_limit(asked)
        if value >= pressure:
            return float(brentq(lambda s: float(sphere_pressure(law, s)) - pressure, lam, step, xtol=1e-15,
                                rtol=1e-15))
        if value < last:
            peak = minimize_scalar(lambda s: -float(sphere_pressure(law, s)), bounds=(lam / (1 + STEP), step),
                                   method="bounded", options={"xatol": 1e-12})
            stretch = float(peak.x)
            raise above_pressure_maximum(pressure, -float(peak.fun), 4.0 / 3.0 * np.pi * stretch**3,
                                         f"the capsule's stretch lambda = {stretch:.6g}, {law.label}")
        lam, last = step, value
    raise past_stretch_limit(asked)


def sphere(model: Model, stretch: float, pressure: float) -> np.ndarray:
    """FREE unknowns of the sphere of uniform ``stretch`` at ``pressure``, interpolated at the nodes."""
    arc = model.geometry.length * node_radii(place(model.xi, model.ref), model.ref)
    u = np.column_stack([stretch * np.sin(arc), stretch * np.cos(arc)]).ravel()
    u[0], u[-1] = 0.0, 0.0
    return np.concatenate([u, [pressure]])


def inflate(model: Model, pressure: float, tol: Tolerances) -> tuple[np.ndarray, int]:
    """The inflated capsule at ``pressure`` (Phat >= 0); (FREE unknowns, Newton iterations)."""
    stretch = sphere_stretch(model.law, pressure)
    start = sphere(model, stretch, pressure)
    if pressure == 0.0:  # the unstressed sphere: no tension, nothing for Newton to resolve (module docstring)
        return start, 0
    return solve(model, FREE, Control(pressure=pressure), start, tol)


def inflate_volume(model: Model, volume: float, tol: Tolerances) -> tuple[np.ndarray, int]:
    """The inflated capsule of whole volume ``volume`` (V / R^3); (FREE unknowns, Newton iterations)."""
    stretch = (0.75 * volume / np.pi) ** (1.0 / 3.0)
    if stretch > STRETCH_LIMIT:
        raise past_stretch_limit(f"volume = {volume!r}")
    pressure = float(sphere_pressure(model.law, stretch))
    if not math.isfinite(pressure):
        raise OutOfRangeError(f"volume = {volume!r} is not reached before the rubber locks ({model.law.label}: "
                              f"the sphere's stretch {stretch:.6g} is past its domain)")
    return solve(model, FREE, Control(volume=0.5 * volume), sphere(model, stretch, pressure), tol)
