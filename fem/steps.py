"""Shared solving steps: one controlled solve, the starting dome, landing on a target.

``solve`` is Newton on the bordered system followed by the range check of
a free part below the clamp plane (eta < 0) is outside the membrane model.

``land`` finds the state where a monitored quantity f(y) (the pressure along a
volume path, the plate force along a height path) equals a target, given two
converged states bracketing it: Newton under target control from the linear
interpolation, and if that fails, bisection of the bracket under the path's
own control until it succeeds. Interpolating two distant converged states can
give a slack meridian (|x'| < 1 near the clamp: no tension, a soft mode and a
wild Newton step), so a converged endpoint is also tried as the guess.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from pocket.core import smallstrain
from pocket.core.errors import ConvergenceError, OutOfRangeError

from .model import NO_PLATE, Control, Model, full, jacobian, residual
from .newton import Tolerances, newton

__all__ = ["solve", "dome", "land"]

_ETA_FLOOR = -1e-12  # round-off below the clamp plane is not a range violation


def solve(
    model: Model, control: Control, guess: np.ndarray, lam, tol: Tolerances
) -> tuple[np.ndarray, int]:
    """Newton under ``control`` from ``guess``; (y, iterations)."""
    y, iterations = newton(
        lambda z: residual(model, z, control, lam),
        lambda z: jacobian(model, z, control, lam),
        guess,
        tol,
    )
    eta = full(model, y)[model.basis.nodal_dofs[1][:-1]]
    if eta.min() < _ETA_FLOOR:
        raise OutOfRangeError(
            f"the free part of the sheet comes down to the clamp plane (min eta/R = {eta.min():.3g}"
            f" at Phat = {y[-2]:.6g}): outside the membrane model"
        )
    return y, iterations


def dome(model: Model, pressure: float) -> np.ndarray:
    """The small-strain dome of the paper's eqs (14)-(15), (18) at ``pressure``.

    lambda_0 - 1 = (Phat / (4 sqrt 6))^(2/3), rho = r (lambda_0 - (lambda_0 - 1) r^2),
    eta = sqrt(3 (lambda_0 - 1) / 2) (1 - r^2).
    """
    e = smallstrain.pole_strain(pressure)
    r = model.basis.doflocs[0]
    u = np.where(np.arange(model.basis.N) % 2 == 0, r * (1 + e - e * r**2), np.sqrt(1.5 * e) * (1 - r**2))
    return np.concatenate([u[model.free], [pressure, NO_PLATE]])


def land(
    along: Callable[[float, np.ndarray], tuple[np.ndarray, int]],
    at_target: Callable[[np.ndarray], tuple[np.ndarray, int]],
    a: tuple[float, np.ndarray],
    b: tuple[float, np.ndarray],
    f: Callable[[np.ndarray], float],
    target: float,
    max_bisections: int = 30,
) -> tuple[np.ndarray, int]:
    """The state with f = target between a = (s_a, y_a) and b = (s_b, y_b).

    f(y_a) < target <= f(y_b); ``along(s, guess)`` solves at path parameter s,
    ``at_target(guess)`` under target control. Returns (y, iterations).
    """
    total = 0
    for _ in range(max_bisections):
        (s_a, y_a), (s_b, y_b) = a, b
        theta = (target - f(y_a)) / (f(y_b) - f(y_a))
        nearer = y_a if theta < 0.5 else y_b
        for guess in (y_a + theta * (y_b - y_a), nearer):
            try:
                y, iterations = at_target(guess)
                return y, total + iterations
            except ConvergenceError as err:
                last = err
        s_m = 0.5 * (s_a + s_b)
        y_m, iterations = along(s_m, nearer)
        total += iterations
        a, b = ((s_m, y_m), b) if f(y_m) < target else (a, (s_m, y_m))
    raise ConvergenceError(
        f"could not land on the target {target:.6g} after {max_bisections} bisections: {last}",
        load=target,
        iterations=last.iterations,
        residual=last.residual,
    )
