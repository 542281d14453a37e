"""Step 2 on a fixed mesh with a penalty plate: plate-height and plate-force control.

The unknowns and equations are ``model``'s PENALTY ones (y = [U, P, h]). This
is the unfitted method, kept to compare with the edge-fitted one (``fitted``):
the contact edge falls inside an element, where a polynomial cannot be both
flat and curved.

First contact: force control is singular without contact (the plate height is
then undetermined), so the plate is lowered from the pole height H0 under
height control, monitoring the reaction F, until F passes the target; then
``steps.land`` solves under force control. Further forces follow under force
control, each step seeded by the last (``continuation.follow``). The fluid is
``fill``, the volume row's ``model.Control``, extended by each control.

Contact: penalty kappa on the gap, with an augmented-Lagrangian (Uzawa) option.
With multiplier field l at the quadrature points, the plate pressure is
p_N = <l + kappa (eta - h)>_+; after a converged Newton solve, l <- p_N and the
solve is repeated until the penetration max(eta - h) is below ``PENETRATION``.
At a fixed point eta = h wherever p_N > 0: the penetration of the pure
penalty, about Phat lambda_c^2 / kappa, is removed, except in the element that
holds the edge (``augment``); the loop then stops once P and h settle to
``SETTLED``, the floor of this method.

Stiffening (``_solve``). The residual is only piecewise smooth: a quadrature
point entering contact adds 2 pi kappa <eta - h>_+ r to its row, a kink of
slope kappa (in units E T / R^2, against membrane stiffnesses of order T_1,
below one). Newton's backtracking (``newton``) accepts a step only if ||R||
falls, so from a point just off the plate (gap g < 0, closing at the rate d
along the step) it accepts about g / d and no more: the step that brings
the next point into contact shrinks like 1/kappa, below the line search's
2^-8, and a solve whose contact set must grow by several points stalls
(measured: at the paper's Phat_I from 0.02 to 0.33 and Fhat = 0.19, 11 of 66
solves on uniform P1/P2 meshes of 32-128 elements fail, most after one to
three iterations; more halvings only trade the stall for a crawl of one
point per iteration). At a soft penalty the kinks are gentle and Newton
crosses them; raising kappa then moves the state by O(P / kappa) and the
contact edge by a fraction of a quadrature spacing. So a solve that fails
at kappa is repeated at kappa 10^-j (j = 1 .. SOFTENINGS, the first that
converges) and followed back up to kappa in log kappa (``continuation.follow``,
which cuts its steps). The state returned is the Newton solution at kappa
itself, to the same tolerances: the detour changes how it is reached, not
what it is.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from .continuation import follow
from .model import PENALTY, Control, Model, fields, plate_force
from .newton import Tolerances
from .spherepenalty import gap
from .steps import land, solve

__all__ = [
    "augment",
    "contact_area_active",
    "contact_zone_active",
    "force_path",
    "multiplier_update",
    "penetration",
    "press_to_force",
    "press_to_height",
]

PENETRATION = 1e-9  # target of the Uzawa loop, in units of R
MAX_UPDATES = 30
SETTLED = 1e-7
LOWEST = 0.02  # the height path stops at this fraction of H0
SOFTENINGS = 7  # a failed solve is retried at penalties down to kappa 10^-SOFTENINGS


def _at(model: Model, y: np.ndarray, h: float) -> np.ndarray:
    out = y.copy()
    out[model.dofs + 1] = h
    return out


def _onto_plate(model: Model, y: np.ndarray) -> np.ndarray:
    """The guess y with eta clipped to the plate (plus the penalty's P/kappa).

    A predictor that crosses the plate starts Newton on the wrong active set,
    which then grows a few quadrature points per iteration.
    """
    out = y.copy()
    n = model.dofs
    lift = 0.0 if model.obstacle is None else np.nan_to_num(model.obstacle.height(y[0:n:2]), nan=np.inf)
    out[1:n:2] = np.minimum(out[1:n:2], y[n + 1] + lift + y[n] / model.penalty)
    return out


def _solve_at(model: Model, penalty: float, control, guess, lam, tol):
    """``steps.solve`` with the plate's penalty ``penalty`` (units E T / R^2); (y, iterations)."""
    model = replace(model, penalty=penalty)
    return solve(model, PENALTY, control, _onto_plate(model, guess), tol, lam)


def _solve(model, control, guess, lam, tol):
    """The state at ``model.penalty`` under ``control`` from ``guess``: Newton, and if that fails
    stiffening from a softer penalty (module docstring); (y, iterations)."""
    try:
        return _solve_at(model, model.penalty, control, guess, lam, tol)
    except ConvergenceError as err:
        first = err
    total = first.iterations
    for j in range(1, SOFTENINGS + 1):
        soft = model.penalty * 10.0**-j
        try:
            y, iterations = _solve_at(model, soft, control, guess, lam, tol)
            break
        except ConvergenceError as err:
            total += err.iterations
        except OutOfRangeError:  # a state at a softer penalty is not the one asked for: try softer
            pass
    else:
        raise ConvergenceError(f"{first}; the same solve at every penalty down to kappa = {soft:.3g} failed too",
                               load=first.load, iterations=total, residual=first.residual) from first
    total += iterations

    def along(log_kappa, start):
        return _solve_at(model, np.exp(log_kappa), control, start, lam, tol)

    try:
        for _, y, iterations in follow(along, y, np.log(soft), np.log(model.penalty), name="log(kappa)",
                                       show=np.exp):
            total += iterations
    except ConvergenceError as err:
        raise ConvergenceError(f"{first}; stiffening from the penalty kappa = {soft:.3g} failed: {err}",
                               load=first.load, iterations=total, residual=err.residual) from err
    return y, total


def press_to_height(model: Model, y0, fill: Control, height, lam, tol: Tolerances):
    """From a state y0 (plate at y0's h) lower the plate to ``height``; (y, iterations)."""
    total = 0

    def along(h, guess):
        return _solve(model, replace(fill, height=h), _at(model, guess, h), lam, tol)

    y = y0
    for _, y, iterations in follow(along, y0, y0[model.dofs + 1], height, first_step=0.05,
                                   name="plate height h/R"):
        total += iterations
    return y, total


def press_to_force(model: Model, y0, fill: Control, force, lam, tol: Tolerances):
    """From the inflated state y0 (plate touching the pole) lower the plate until the reaction is ``force``."""
    h0 = float(y0[model.dofs + 1])

    def along(h, guess):
        return _solve(model, replace(fill, height=h), _at(model, guess, h), lam, tol)

    def at_target(guess):
        return _solve(model, replace(fill, force=force), guess, lam, tol)

    def f(y):
        return plate_force(model, y, PENALTY, lam)

    total, previous = 0, (h0, y0)
    for h, y, iterations in follow(along, y0, h0, LOWEST * h0, first_step=0.05, name="plate height h/R"):
        total += iterations
        if f(y) >= force:
            y, iterations = land(along, at_target, previous, (h, y), f, force)
            return y, total + iterations
        previous = (h, y)
    raise OutOfRangeError(
        f"plate force {force:.6g} (units E T R) not reached with the plate down to {LOWEST} H0"
    )


def force_path(model: Model, y0, fill: Control, force, lam, tol: Tolerances):
    """From a contact state y0 at its force, follow force control to ``force``."""

    def along(f, guess):
        return _solve(model, replace(fill, force=f), guess, lam, tol)

    total, y = 0, y0
    start = plate_force(model, y0, PENALTY, lam)
    for _, y, iterations in follow(along, y0, start, force, name="plate force F/(E T R)"):
        total += iterations
    return y, total


def _gap(model: Model, y: np.ndarray) -> np.ndarray:
    """eta - h at the quadrature points (eta - h - z(rho) under a curved indenter: ``spherepenalty``)."""
    w = fields(model, y, PENALTY)
    if model.obstacle is not None:
        return gap(model.obstacle, w.rho, w.eta, y[model.dofs + 1])
    return w.eta - y[model.dofs + 1]


def penetration(model: Model, y: np.ndarray) -> float:
    """Largest eta - h at the quadrature points, where contact is imposed (0 if none)."""
    return max(0.0, float(_gap(model, y).max()))


def multiplier_update(model: Model, y: np.ndarray, lam) -> np.ndarray:
    """Augmented-Lagrangian (Uzawa) update: lam <- <lam + kappa (eta - h)>_+ at the quadrature points."""
    return np.maximum(lam + model.penalty * _gap(model, y), 0.0)


def contact_area_active(model: Model, y: np.ndarray, lam) -> float:
    """Deformed area of the active set, 2 pi int chi rho rho' dr (edge resolved to O(h))."""
    w = fields(model, y, PENALTY)
    chi = lam + model.penalty * _gap(model, y) > 0.0
    return float(np.sum(2 * np.pi * chi * w.rho * w.drho * w.lengths[:, None] * model.ref.weights))


def contact_zone_active(model: Model, y: np.ndarray, lam) -> tuple[float, float]:
    """(curved area 2 pi int chi rho |x'| dr (units R^2), the largest r of an active point): the contact zone
    under a curved indenter, to O(h)."""
    w = fields(model, y, PENALTY)
    chi = lam + model.penalty * _gap(model, y) > 0.0
    area = float(np.sum(2 * np.pi * chi * w.rho * w.l1 * w.lengths[:, None] * model.ref.weights))
    return area, float(w.r[chi].max()) if chi.any() else 0.0


def augment(model: Model, y, control: Control, lam, tol: Tolerances):
    """Uzawa updates of the multiplier until the penetration is gone; (y, lam, iterations).

    Stops when the penetration at every quadrature point is below PENETRATION, or
    when an update changes P and h by less than SETTLED (relative), or after
    MAX_UPDATES. What then remains sits in the element that holds the contact
    edge, where a polynomial cannot be both flat and curved: there the discrete
    constraint has no exact solution and Uzawa creeps (the multiplier of a point
    that cannot close its gap grows by kappa times the gap per update). It is
    reported as ``penetration`` and ``penetration_pole``, never hidden.
    """
    total, n = 0, model.dofs
    for _ in range(MAX_UPDATES):
        if penetration(model, y) <= PENETRATION:
            break
        lam = multiplier_update(model, y, lam)
        before = y[n:].copy()
        y, iterations = _solve(model, control, y, lam, tol)
        total += iterations
        if np.all(np.abs(y[n:] / before - 1.0) <= SETTLED):
            break
    return y, lam, total
