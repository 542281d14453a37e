"""A small dense nonlinear solver for the shooting unknowns (2 or 3 of them), without scipy.

Damped Newton with a forward-difference Jacobian and Broyden's update between
differences (Dennis & Schnabel, Numerical Methods for Unconstrained Optimization and
Nonlinear Equations, 1983, ch. 6 and 8):

- the step solves J dx = -f; it is halved until the residual's max-norm falls by
  the factor 1 - 1e-4 lambda (lambda the step fraction taken), or the trial point
  lies where the residual is defined (``fun`` returns None outside the model's domain,
  e.g. a shot that does not reach the clamp);
- J starts as the caller's (the last solve's, in a continuation) or as differences (or
  as the caller's ``derivative``, a cheaper Jacobian where a problem has one),
  gets Broyden's rank-one update after each step that halves the residual, and is
  recomputed by differences after a slower step or when a step with an updated J
  fails to decrease the residual;
- it stops when max |f| <= ``tol`` (the caller scales f so that this is a relative
  accuracy), or, given a ``floor`` above ``tol``, when no step along a freshly differenced
  Newton direction decreases a residual already below ``floor`` (the residual's noise,
  which no step can reduce), and reports failure (never an exception) with what it
  reached, so the caller can cut its load step or say where it failed.

``tests/test_shooting_newton.py`` checks it against scipy's ``root(method="hybr")``
on standard hard problems (Rosenbrock, Powell's badly scaled function, Freudenstein
and Roth's spurious minimum).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

__all__ = ["Solution", "difference_steps", "differences", "solve"]

_ARMIJO = 1e-4
_MIN_FRACTION = 2.0**-12
_SLOW = 0.5  # a step that reduces max |f| by less than this factor ends Broyden's updates
_STEP = 1e-7  # relative difference step: about the square root of the residuals' noise (rtol ~ 1e-10 and up)


@dataclasses.dataclass(frozen=True)
class Solution:
    """The outcome of ``solve``: ``x`` and ``f`` at the last accepted point, the Jacobian there
    (for the next solve of a continuation), evaluations of ``fun``, and why it stopped."""

    x: np.ndarray
    f: np.ndarray | None
    jacobian: np.ndarray | None
    evaluations: int
    success: bool
    message: str

    @property
    def residual(self) -> float:
        """max |f| at ``x`` (inf if ``fun`` was undefined there)."""
        return float(np.max(np.abs(self.f))) if self.f is not None else float("inf")


def difference_steps(x, step=_STEP) -> np.ndarray:
    """The forward-difference steps of the unknowns x: ``step`` max(|x_j|, 1) each, shape (n,)."""
    return step * np.maximum(np.abs(x), 1.0)


def differences(fun, x, f, step=_STEP):
    """Forward-difference Jacobian of ``fun`` at ``x`` (shape (n, n)), or None where undefined.

    Each column steps x_j by ``difference_steps`` towards the side where ``fun`` is defined.
    """
    n = x.size
    jac = np.empty((n, n))
    for j, h in enumerate(difference_steps(x, step)):
        for sign in (1.0, -1.0):
            xj = x.copy()
            xj[j] += sign * h
            fj = fun(xj)
            if fj is not None:
                jac[:, j] = (fj - f) / (sign * h)
                break
        else:
            return None
    return jac


def solve(fun: Callable[[np.ndarray], np.ndarray | None], x0, *, tol: float, jacobian=None,
          max_iterations=30, floor=None, derivative=None) -> Solution:
    """Solve fun(x) = 0 from ``x0`` (shape (n,)) to max |fun(x)| <= ``tol``, or to a stall below
    ``floor`` (module docstring). ``derivative``: None, or ``derivative(x, f)``, the Jacobian at x, where fun(x) = f
    (or None), used where a fresh one is due instead of ``differences``."""
    count = [0]

    def call(x):
        count[0] += 1
        return fun(x)

    def result(x, f, jac, success, message):
        return Solution(x=x, f=f, jacobian=jac, evaluations=count[0], success=success, message=message)

    x = np.array(x0, dtype=float)
    f = call(x)
    if f is None:
        return result(x, None, None, False, "the starting point is outside the domain")
    jac = None if jacobian is None else np.array(jacobian, dtype=float)
    fresh = False  # whether jac is a difference Jacobian at x
    for _ in range(max_iterations):
        norm = np.max(np.abs(f))
        if norm <= tol:
            return result(x, f, jac, True, "converged")
        if jac is None:
            jac, fresh = None if derivative is None else derivative(x, f), True
            jac = differences(call, x, f) if jac is None else jac
            if jac is None:
                return result(x, f, None, False, "the residual is undefined next to the point")
        try:
            dx = np.linalg.solve(jac, -f)
        except np.linalg.LinAlgError:
            dx = None
        step = _line_search(call, x, dx, norm) if dx is not None and np.all(np.isfinite(dx)) else None
        if step is None:
            if fresh and floor is not None and norm <= floor:
                return result(x, f, jac, True, f"at the residual's noise (max |f| = {norm:.3g})")
            if fresh:
                return result(x, f, jac, False, "no step decreases the residual (max |f| "
                                                f"= {norm:.3g}) along the Newton direction")
            jac = None  # an updated Jacobian misled the step: difference it afresh and retry
            continue
        x_new, f_new = step
        s, y = x_new - x, f_new - f
        # Broyden's ("good") update; on slow progress the Jacobian is stale: difference it afresh at the new point
        jac = jac + np.outer(y - jac @ s, s) / (s @ s) if np.max(np.abs(f_new)) <= _SLOW * norm else None
        x, f, fresh = x_new, f_new, False
    return result(x, f, jac, np.max(np.abs(f)) <= tol, f"{max_iterations} iterations")


def _line_search(call, x, dx, norm):
    """(x + lambda dx, f there) for the first lambda = 1, 1/2, ... that decreases max |f| enough."""
    fraction = 1.0
    while fraction >= _MIN_FRACTION:
        trial = x + fraction * dx
        f = call(trial)
        if f is not None and np.all(np.isfinite(f)) and np.max(np.abs(f)) <= (1.0 - _ARMIJO * fraction) * norm:
            return trial, f
        fraction *= 0.5
    return None
