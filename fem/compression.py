"""Step 2, compression at fixed volume V_I: plate-height and plate-force control.

First contact: force control is singular without contact (the plate height is
then undetermined), so the plate is lowered from the pole height H0 under
height control, monitoring the reaction F, until F passes the target; then
``steps.land`` solves under force control. Further forces follow under force
control, each step seeded by the last (``continuation.follow``).

Contact: penalty kappa on the gap, with an augmented-Lagrangian (Uzawa) option.
With multiplier field l at the quadrature points, the plate pressure is
p_N = <l + kappa (eta - h)>_+; after a converged Newton solve, l <- p_N and the
solve is repeated until the penetration max(eta - h) is below ``PENETRATION``.
At a fixed point eta = h wherever p_N > 0: the penetration of the pure
penalty, about Phat lambda_c^2 / kappa, is removed.
"""

from __future__ import annotations

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from .continuation import follow
from .model import Control, Model, full, multiplier_update, penetration
from .newton import Tolerances
from .post import plate_force
from .steps import land, solve

__all__ = ["press_to_force", "press_to_height", "force_path", "augment"]

PENETRATION = 1e-9  # target of the Uzawa loop, in units of R
MAX_UPDATES = 30
SETTLED = 1e-7
LOWEST = 0.02  # the height path stops at this fraction of H0


def _at(y: np.ndarray, h: float) -> np.ndarray:
    return np.concatenate([y[:-1], [h]])


def _onto_plate(model: Model, y: np.ndarray) -> np.ndarray:
    """The guess y with eta clipped to the plate (plus the penalty's P/kappa).

    A predictor that crosses the plate starts Newton on the wrong active set,
    which then grows a few quadrature points per iteration.
    """
    u = full(model, y)
    eta = model.basis.nodal_dofs[1].tolist() + model.basis.interior_dofs[1:2].ravel().tolist()
    u[eta] = np.minimum(u[eta], y[-1] + y[-2] / model.penalty)
    return np.concatenate([u[model.free], y[-2:]])


def press_to_height(model: Model, y0, volume, height, lam, tol: Tolerances):
    """From a state y0 (plate at y0[-1]) lower the plate to ``height``; (y, iterations)."""
    total = 0

    def along(h, guess):
        return solve(model, Control(volume=volume, height=h), _onto_plate(model, _at(guess, h)), lam, tol)

    y = y0
    for _, y, iterations in follow(along, y0, y0[-1], height, first_step=0.05, name="plate height h/R"):
        total += iterations
    return y, total


def press_to_force(model: Model, y0, volume, force, lam, tol: Tolerances):
    """From the inflated state y0 lower the plate until the reaction is ``force``."""
    h0 = float(y0[-1])
    y0 = np.concatenate([y0[:-1], [h0]])

    def along(h, guess):
        return solve(model, Control(volume=volume, height=h), _onto_plate(model, _at(guess, h)), lam, tol)

    def at_target(guess):
        return solve(model, Control(volume=volume, height=None, force=force), _onto_plate(model, guess), lam, tol)

    def f(y):
        return plate_force(model, y, lam)

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


def force_path(model: Model, y0, volume, force, lam, tol: Tolerances):
    """From a contact state y0 at its force, follow force control to ``force``."""

    def along(f, guess):
        return solve(model, Control(volume=volume, height=None, force=f), _onto_plate(model, guess), lam, tol)

    total, y = 0, y0
    for _, y, iterations in follow(along, y0, plate_force(model, y0, lam), force, name="plate force F/(E T R)"):
        total += iterations
    return y, total


def augment(model: Model, y, control: Control, lam, tol: Tolerances):
    """Uzawa updates of the multiplier until the penetration is gone; (y, lam, iterations).

    Stops when the penetration at every quadrature point is below PENETRATION,
    or when the sheet's pole is on the plate (|eta(0) - h| < PENETRATION) and an
    update changes P and h by less than SETTLED (relative), or after
    MAX_UPDATES with the pole on the plate. What then remains is inside the
    element that holds the contact edge, where a polynomial cannot be both flat
    and curved and weakly active quadrature points make Uzawa slow: it is below
    the discretization error there, and reported as ``penetration``.
    """
    total, pole = 0, np.inf
    for _ in range(MAX_UPDATES):
        if penetration(model, y) <= PENETRATION:
            return y, lam, total
        lam = multiplier_update(model, y, lam)
        before = y[-2:]
        y, iterations = solve(model, control, y, lam, tol)
        total += iterations
        pole = abs(full(model, y)[model.basis.nodal_dofs[1][0]] - y[-1])
        if pole <= PENETRATION and np.all(np.abs(y[-2:] / before - 1.0) <= SETTLED):
            return y, lam, total
    if pole <= PENETRATION:
        return y, lam, total
    raise ConvergenceError(
        f"augmented Lagrangian: the pole is {pole:.3e} R off the plate after {MAX_UPDATES}"
        f" updates (penalty {model.penalty:.3g})",
        load=float(y[-1]),
        iterations=total,
        residual=pole,
    )
