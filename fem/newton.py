"""Newton's method with a backtracking line search on the residual norm.

Converged when both the residual and the Newton increment are small in the
max norm (absolute: the unknowns and the nodal forces are dimensionless, of
order one or less). On fine meshes the residual has a round-off floor that can
sit slightly above ``residual``: a tiny increment with a residual that has
stopped falling (and is below 1e3 ``residual``) also counts as converged.
The merit function for the line search is ||R||_2: the bordered system is a
saddle point (the pressure is a multiplier), so the energy is not a merit
function. Failure raises ``ConvergenceError`` with the iteration count and the
last residual; the caller adds the load level.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np
import scipy.sparse.linalg as spla

from pocket.core.errors import ConvergenceError

__all__ = ["Tolerances", "newton"]


@dataclasses.dataclass(frozen=True)
class Tolerances:
    """Absolute tolerances on ||R||_inf and ||dy||_inf, and iteration limits."""

    residual: float = 1e-10
    increment: float = 1e-10
    max_iterations: int = 25
    max_halvings: int = 8


def newton(
    residual: Callable[[np.ndarray], np.ndarray],
    jacobian: Callable[[np.ndarray], object],
    y0: np.ndarray,
    tol: Tolerances = Tolerances(),
) -> tuple[np.ndarray, int]:
    """Solve residual(y) = 0 from y0; return (y, iterations)."""
    y = np.array(y0, dtype=float)
    r = residual(y)
    r_prev = np.inf
    for k in range(1, tol.max_iterations + 1):
        if not np.all(np.isfinite(r)):
            break
        dy = spla.spsolve(jacobian(y), -r)
        if not np.all(np.isfinite(dy)):
            break
        step_size, r_max = np.abs(dy).max(), np.abs(r).max()
        if step_size <= tol.increment and r_max <= tol.residual:
            return y + dy, k
        floor = r_max >= 0.1 * r_prev and r_max <= 1e3 * tol.residual
        if step_size <= tol.increment and floor:
            return y + dy, k  # a round-off floor above tol.residual: nothing left to gain
        r_prev = r_max
        merit = np.linalg.norm(r)
        step = 1.0
        for _ in range(tol.max_halvings + 1):
            trial = y + step * dy
            r_trial = residual(trial)
            if np.linalg.norm(r_trial) <= (1.0 - 1e-4 * step) * merit:
                break
            step *= 0.5
        else:
            if np.abs(r).max() > tol.residual:
                break
            trial = y + dy  # at round-off level the merit need not decrease
            r_trial = residual(trial)
        y, r = trial, r_trial
    res = float(np.abs(r).max()) if np.all(np.isfinite(r)) else float("nan")
    raise ConvergenceError(
        f"Newton failed after {k} iterations, residual {res:.3e}", iterations=k, residual=res
    )
