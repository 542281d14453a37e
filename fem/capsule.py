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

The end of the range (``slack_end``). Nothing like the pocket's clamp ends it; but as the plates close, the
contact patch's stretch at the pole can fall to that of the unstressed rubber, lambda_0 = 1 / lambda_p, where its
tension vanishes (T_1 = T_2 = 0): beyond, the membrane would wrinkle under the plate, outside membrane theory.
Between a state whose pole's stretch is within 2 % of 1 / lambda_p and the one below it (the first from a fifth
of its sigma = sqrt(F)) the pole's stretch is watched in steps of 5 % in sigma (``within_range``: it may dip below
1 / lambda_p and rise again, as a prestretched capsule's does); where it has fallen to 1 / lambda_p the force is
located by Brent's method between the last two steps (each state solved from the nearer known ones; to 1e-12 of
sigma, so that the end quoted is the same, to its ten digits, whatever force was asked), and the force asked is
``OutOfRangeError`` naming it. A dip narrower than a step can be missed.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from pocket.core.errors import (
    STRETCH_LIMIT,
    ConvergenceError,
    OutOfRangeError,
    above_pressure_maximum,
    beyond_range,
    past_stretch_limit,
)

from . import fitted
from .geometry import node_radii, place
from .material import Law
from .model import FITTED, FREE, Control, Model
from .newton import Tolerances
from .post import pole_stretch
from .steps import solve

__all__ = ["SLACK_PATCH", "STEP", "inflate", "inflate_volume", "slack_end", "sphere", "sphere_pressure",
           "sphere_stretch", "within_range"]

#: the relative step in lambda of the march along the closed form's first branch
STEP = 0.01
#: what happens at the end of a capsule's range (module docstring)
SLACK_PATCH = ("the contact patch's tension vanishes at the pole (T_1 = T_2 = 0): the membrane would wrinkle under "
               "the plate, outside membrane theory")
#: the relative tolerance in sigma = sqrt(F) to which the end is located
END_XTOL = 1e-12
#: the steps in sigma = sqrt(F) in which the pole's stretch is watched between two states (``within_range``)
SAMPLE = 0.05
#: where that watch starts, relative to the first state's sigma (the pole's stretch falls from the inflated one)
FIRST = 0.2
#: how near the unstressed stretch (lambda_0 - 1 / lambda_p) a state's pole must be for the watch to run: the
#: pole's stretch moves by a few per cent over a whole range (measured 3.5 % from Fhat 0 to 3 for a liquid and a
#: gas, prestretched or not), so a dip to the end between two states farther from it is not expected
WATCH = 0.02


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


def _slack(model: Model, y: np.ndarray) -> float:
    """lambda_0 - 1 / lambda_p of the FITTED state y: where it is not positive, the patch is slack at the pole."""
    return pole_stretch(model, y, FITTED) - 1.0 / model.law.prestretch


class _Path:
    """The FITTED states of one capsule along the force, solved on demand in sigma = sqrt(F), each from the
    interpolation of the two nearest known."""

    def __init__(self, model: Model, fill: Control, tol: Tolerances, known: list):
        self.model, self.fill, self.tol, self.known = model, fill, tol, list(known)

    def at(self, sigma: float) -> np.ndarray:
        (s0, y0), *others = sorted(self.known, key=lambda item: abs(item[0] - sigma))
        s1, y1 = next((item for item in others if item[0] != s0), (s0, y0))
        guess = y0 if s1 == s0 else y0 + (sigma - s0) / (s1 - s0) * (y1 - y0)
        try:
            y, _ = solve(self.model, FITTED, dataclasses.replace(self.fill, force=sigma**2), guess, self.tol)
        except (ConvergenceError, OutOfRangeError):
            y, _ = fitted.force_path(self.model, y0, self.fill, sigma**2, self.tol)
        self.known.append((sigma, y))
        return y


def _sigma(model: Model, y: np.ndarray) -> float:
    return float(np.sqrt(fitted.plate_force_of(model, y)))


def slack_end(path: _Path, below: float, above: float) -> float:
    """The plate force F (units E T R) where the pole's stretch falls to 1 / lambda_p (module docstring), between
    sigma = sqrt(F) ``below`` (taut) and ``above`` (slack), both known to ``path``."""
    return float(brentq(lambda sigma: _slack(path.model, path.at(sigma)), below, above, xtol=END_XTOL * above,
                        rtol=END_XTOL)) ** 2


def _taut(model: Model, y_i: np.ndarray, fill: Control, tol: Tolerances, sigma: float) -> tuple[float, np.ndarray]:
    """(sigma, the FITTED state there) at ``sigma`` = sqrt(F), or at a smaller one by factors ``FIRST`` where the
    patch is slack there (as F -> 0 the pole's stretch tends to the inflated sphere's, above 1 / lambda_p)."""
    for _ in range(8):
        first, _ = fitted.first_contact(model, y_i, fill, min(fitted.A_FIRST, 0.5 * sigma), tol)
        low, _ = fitted.force_path(model, first, fill, sigma**2, tol)
        if _slack(model, low) > 0.0:
            return _sigma(model, low), low
        sigma *= FIRST
    raise ConvergenceError(f"the capsule's contact patch is slack at the pole down to the force F/(E T R) = "
                           f"{sigma**2 / FIRST**2:.3g}: no taut state to locate the end of its range from")


def within_range(model: Model, y_i: np.ndarray, fill: Control, tol: Tolerances, unit: float, y: np.ndarray,
                 history: list, asked: str) -> None:
    """OutOfRangeError if the FITTED state ``y`` (asked as ``asked``) lies past the end of the range (module
    docstring), quoting the end as Fhat (the force over ``unit`` = pi Phat_I); ``history``: the (sigma, y) of the
    states solved before it. The pole's stretch is watched from the nearest state below ``y`` (or, with none, one at
    ``FIRST`` of its sigma, solved from the inflated ``y_i``) in steps of ``SAMPLE`` in sigma."""
    top, slack = _sigma(model, y), _slack(model, y)
    if slack > WATCH:
        return
    lower = [item for item in history if item[0] < top]
    start = max(lower, key=lambda item: item[0]) if lower else _taut(model, y_i, fill, tol, FIRST * top)
    path = _Path(model, fill, tol, [start, (top, y)])
    count = int(np.ceil(np.log(top / start[0]) / np.log1p(SAMPLE)))
    previous = start[0]
    for sigma in [*start[0] * (top / start[0]) ** (np.arange(1, count) / count), top]:
        state = y if sigma == top else path.at(sigma)
        if _slack(model, state) <= 0.0:
            end = slack_end(path, previous, sigma) / unit
            raise beyond_range(asked, f"force = {end:.10g} ({model.law.label}, capsule)", SLACK_PATCH)
        previous = sigma
