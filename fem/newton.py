"""Newton's method on the bordered system, with a backtracking line search on the residual norm.

Each iteration linearises at the current point (``linearize(y) -> (R, system)``),
solves system . dy = -R (``banded.Bordered``) and takes the largest step
1, 1/2, 1/4, ... that lowers ||R||_2 by the Armijo factor (1 - 1e-4 step): the
system is a saddle point (the pressure is a multiplier), so the energy is not
a merit function. The trial point is linearised whole, so an accepted step
costs one assembly. Near the solution the full step is accepted and the
residual falls quadratically (``Result.residuals`` keeps the sequence).

Converged when both ||R||_inf and ||dy / scales||_inf are below the
tolerances: the rows are dimensionless (nodal forces of order one or less;
the control rows relative), the increments are measured against ``scales``,
the size of what each unknown resolves (``steps.solve``: the height of the
sheet for eta, its radial displacement for rho, P for the pressure), so that
a state of the small-strain regime, Phat down to 1e-8, is resolved as well
as a large one. On very fine meshes round-off leaves a residual floor that can sit
slightly above ``residual``, and the increments of a small-strain state one
above ``increment``: a residual that has stopped falling, within 1e3 of
``residual``, with an increment within 1e3 of ``increment``, also counts.
So does, with an increment below ``increment``, a residual within NOISE of
the change that perturbing every unknown by four units in its last place
makes (``_noise``): no stored state can do better. That floor is the
stiffness times the unknowns' round-off, and grows past 1e3 ``residual``
when the rows are stiff (a rubber near its locking stretch on the small
elements by the contact edge: measured 1e-7 for Gent with Jm = 1 at
Phat = 50); it is evaluated only when the increment has converged and the
residual has not.
Failure raises ``ConvergenceError`` with the iteration count and the last
residual; the caller says what load it was solving for.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from pocket.core.errors import ConvergenceError

from .banded import SingularSystem

__all__ = ["FLOOR", "NOISE", "ULPS", "Result", "Tolerances", "border_noise", "newton"]

FLOOR = 1e3  # a residual this many tolerances above the target can be round-off
NOISE = 10.0  # a residual within this factor of the unknowns' round-off (``_noise``) is at the floor
ULPS = 4.0  # the units in the last place the unknowns' round-off is measured in


@dataclasses.dataclass(frozen=True)
class Tolerances:
    """Absolute tolerances on ||R||_inf and ||dy||_inf, and iteration limits."""

    residual: float = 1e-10
    increment: float = 1e-10
    max_iterations: int = 25
    max_halvings: int = 8


@dataclasses.dataclass(frozen=True)
class Result:
    """The solution y, the iterations spent, and ||R||_inf before each iteration."""

    y: np.ndarray
    iterations: int
    residuals: tuple[float, ...]


def _finite(*arrays) -> bool:
    return all(np.all(np.isfinite(a)) for a in arrays)


def newton(linearize: Callable, y0: np.ndarray, tol: Tolerances = Tolerances(),
           increment: Callable | None = None, scales: np.ndarray | float = 1.0) -> Result:
    """Solve R(y) = 0 from y0.

    ``linearize(y)`` returns (R(y), system) with ``system.solve(-R)`` giving dy;
    ``increment(y, dx, ds)`` assembles dy from the solver's (nodal, scalar) parts;
    ``scales``: what the increments are measured against (module docstring).
    """
    with np.errstate(all="ignore"):  # overflow and invalid values are caught as non-finite numbers
        return _iterate(linearize, np.array(y0, dtype=float), tol, increment, scales)


def _iterate(linearize, y, tol, increment, scales) -> Result:
    r, system = linearize(y)
    history, r_prev, k = [], np.inf, 0
    for k in range(1, tol.max_iterations + 1):
        if not _finite(r):
            break
        r_max = float(np.abs(r).max())
        history.append(r_max)
        try:
            dy = increment(y, *system.solve(-r[: system.B.shape[0]], -r[system.B.shape[0]:]))
        except SingularSystem:
            break
        if not _finite(dy):
            break
        step_size = float(np.abs(dy / scales).max())
        converged = step_size <= tol.increment and r_max <= tol.residual
        floor = r_max >= 0.1 * r_prev and r_max <= FLOOR * tol.residual and step_size <= FLOOR * tol.increment
        if not (converged or floor) and step_size <= tol.increment:
            floor = r_max <= NOISE * _noise(linearize, y, r)  # the system is spent: only dy is used below
        if converged or floor:
            return Result(y + dy, k, tuple(history))
        r_prev = r_max
        merit, step = np.linalg.norm(r), 1.0
        for _ in range(tol.max_halvings + 1):
            trial = y + step * dy
            r_trial, system_trial = linearize(trial)
            if _finite(r_trial) and np.linalg.norm(r_trial) <= (1.0 - 1e-4 * step) * merit:
                break
            step *= 0.5
        else:
            if r_max > FLOOR * tol.residual:
                break
            trial = y + dy  # at round-off level the merit need not decrease
            r_trial, system_trial = linearize(trial)
        y, r, system = trial, r_trial, system_trial
    res = float(np.abs(r).max()) if _finite(r) else float("nan")
    raise ConvergenceError(f"Newton failed after {k} iterations, residual {res:.3e}", iterations=k, residual=res)


def _noise(linearize: Callable, y: np.ndarray, r: np.ndarray) -> float:
    """max |R(y') - R(y)| with y' = y (1 +- ULPS eps), the signs alternating: the residual's round-off floor."""
    signs = np.where(np.arange(y.size) % 2 == 0, 1.0, -1.0)
    r_near, _ = linearize(y * (1.0 + ULPS * np.finfo(float).eps * signs))
    return float(np.abs(r_near - r).max()) if _finite(r_near) else np.inf


def border_noise(system, y: np.ndarray) -> np.ndarray:
    """ULPS eps (|C| |U| + |D| |s|): the most each border row of the bordered ``system`` (C (m, N), D (m, m), at
    y = [U, s]) moves when every unknown moves by ULPS units in its last place, whatever their signs (the
    worst case of ``_noise``, row by row, to first order)."""
    n = system.C.shape[1]
    u, s = np.abs(y[:n]), np.abs(y[n:])
    return ULPS * np.finfo(float).eps * (np.abs(system.C) @ u + np.abs(system.D) @ s)
