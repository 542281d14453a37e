"""Step 2, compression at fixed volume by a flat frictionless plate.

Contact zone (0 <= r <= a): the sheet lies flat on the plate; tangential
equilibrium with no friction and regularity at the axis leave the uniform
equibiaxial stretch rho = lambda_c r, lambda_1 = lambda_2 = lambda_c (the normal
load is carried by the plate). At the contact edge the tension T_1 and the
position are continuous and the meridian is horizontal (a smooth plate cannot
exert a line force), so the free part a <= r <= 1 starts from
rho = lambda_c a, psi = 0, lambda_1 = lambda_c and is integrated to the clamp.

Unknowns (q, lambda_c) with q = P/P_I. The force fixes the contact radius:
F = P A_c with A_c = pi (lambda_c a)^2 gives Fhat = q (lambda_c a)^2, so
a = sqrt(Fhat / q) / lambda_c. Residuals: rho(1) - 1 (clamp) and V/V_I - 1
(fixed fluid volume), where V = -pi int rho^2 eta' dr is carried by the free
part alone (eta' = 0 on the contact zone). They are solved by MINPACK's hybrid
method (``scipy.optimize.root``), each force seeded by the last (continuation),
with the force step halved on failure.

The model holds while the free meridian stays above the clamp plane and does
not fold (psi in (0, pi)); past that a force is reported out of range.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import root

from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError
from pocket.core.inputs import check_alpha, check_force, check_positive
from pocket.core.states import CompressedState, InflatedState

from .inflation import inflate
from .integrator import OK
from .shots import profile_from_steps, shot_edge

__all__ = ["compress", "compression_curve"]

_FAIL = 10.0  # residual returned for a shot that does not reach the clamp
_TOL = 1e-12  # residual accepted at convergence (volume fraction and clamp radius)
_MAX_HALVINGS = 12


def _residual(x, force, inflated, alpha, rtol):
    q, lc = x
    if not (q > 0.0 and lc > 0.0):
        return np.array([_FAIL, _FAIL])
    a = np.sqrt(force / q) / lc
    if not a < 1.0:
        return np.array([_FAIL, _FAIL])
    p = 3.0 * (1.0 + alpha) * inflated.pressure * q
    status, y, _ = shot_edge(lc, a, alpha, p, rtol)
    if status != OK:
        return np.array([_FAIL, _FAIL])
    return np.array([y[0] - 1.0, y[4] / inflated.volume - 1.0])


def _solve(force, seed, inflated, alpha, rtol):
    """Newton-like solve for (q, lambda_c) at one force; returns x or None."""
    sol = root(_residual, seed, args=(force, inflated, alpha, rtol), method="hybr",
               options=dict(xtol=1e-14))
    res = _residual(sol.x, force, inflated, alpha, rtol)
    return sol.x if np.max(np.abs(res)) < _TOL else None


def _state(force, x, inflated, alpha, rtol):
    q, lc = x
    a = np.sqrt(force / q) / lc
    p = 3.0 * (1.0 + alpha) * inflated.pressure * q
    status, y, _ = shot_edge(lc, a, alpha, p, rtol)
    _, _, steps = shot_edge(lc, a, alpha, p, rtol, store=20000)
    profile = profile_from_steps(steps, alpha, lc, contact_radius=a)
    free = ~profile.contact
    if status != OK or np.any(profile.eta[free][:-1] <= 0.0) or np.any(steps[1:, 3] <= 0.0):
        raise OutOfRangeError(
            f"force = {force:.6g} is beyond the model's range: the free part of the sheet "
            "reaches the clamp plane"
        )
    height = -y[1]
    return CompressedState(
        alpha=alpha,
        pressure_initial=inflated.pressure,
        force=force,
        pressure=inflated.pressure * q,
        pressure_ratio=q,
        contact_area=(lc * a) ** 2,
        contact_radius=a,
        stretch_contact=lc,
        height=height,
        height_ratio=height / inflated.height,
        volume=y[4],
        profile=profile,
        inflated=inflated,
        solver="shooting",
    )


def _uncompressed(inflated: InflatedState) -> CompressedState:
    """Fhat = 0: the inflated state itself, seen as a compressed state with no contact."""
    return CompressedState(
        alpha=inflated.alpha, pressure_initial=inflated.pressure, force=0.0,
        pressure=inflated.pressure, pressure_ratio=1.0, contact_area=0.0, contact_radius=0.0,
        stretch_contact=inflated.stretch_pole, height=inflated.height, height_ratio=1.0,
        volume=inflated.volume, profile=inflated.profile, inflated=inflated, solver="shooting",
    )


def _continue(f_from, x_from, f_to, inflated, alpha, rtol):
    """Solve at f_to starting from the solution x_from at f_from, halving the step on failure."""
    f, x = f_from, x_from
    step = f_to - f_from
    halvings = 0
    while f < f_to:
        f_try = min(f + step, f_to)
        x_try = _solve(f_try, x, inflated, alpha, rtol)
        if x_try is None:
            halvings += 1
            if halvings > _MAX_HALVINGS:
                raise OutOfRangeError(
                    f"force = {f_to:.6g} is beyond the model's range: no compressed state past "
                    f"force = {f:.6g} (the free part folds onto the clamp plane or the solve fails)"
                ) if f > 0.0 else ConvergenceError(
                    f"compression failed to start from the inflated state towards force = {f_to:.6g}",
                    load=f, iterations=halvings)
            step /= 2.0
            continue
        f, x = f_try, x_try
    return x


def compression_curve(alpha, pressure_initial, forces, *, rtol=1e-10) -> list[CompressedState]:
    """Compress at each force Fhat = F/(P_I pi R^2) of ``forces`` (any order), by continuation.

    Returns the states in the order of ``forces``. Raises OutOfRangeError for a force past
    the model's range, InputError for invalid input.
    """
    alpha = check_alpha(alpha)
    pressure_initial = check_positive("pressure", pressure_initial)
    forces = [check_force(f) for f in np.atleast_1d(np.asarray(forces, dtype=float))]
    if not forces:
        raise InputError("no force given")
    inflated = inflate(alpha, pressure_initial, rtol=rtol)
    states = {}
    f_prev, x_prev = 0.0, np.array([1.0, inflated.stretch_pole])
    for f in sorted(set(forces)):
        if f == 0.0:
            states[f] = _uncompressed(inflated)
            continue
        x_prev = _continue(f_prev, x_prev, f, inflated, alpha, rtol)
        f_prev = f
        states[f] = _state(f, x_prev, inflated, alpha, rtol)
    return [states[f] for f in forces]


def compress(alpha, pressure_initial, force, *, rtol=1e-10) -> CompressedState:
    """Compress the pocket inflated at Phat_I = ``pressure_initial`` by force Fhat."""
    return compression_curve(alpha, pressure_initial, [force], rtol=rtol)[0]
