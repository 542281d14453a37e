"""Step 1, inflation: from the flat sheet, under volume control, to a given volume or pressure.

The flat sheet is the start (the solid's tangent there is regular: it bends). The path is followed
in log V under volume control (the pressure is the multiplier, so pressure maxima pass), from
``V_START`` in steps of at most ``MAX_RATIO`` in V, each seeded by the secant through the two
states before it and halved when Newton fails. A pressure target is bracketed on this path and
landed on under pressure control from the interpolated bracket (narrowed under volume control if Newton
fails from there); a pressure that falls before
reaching the target has passed its maximum: the target has no state on the first branch
(OutOfRangeError).
"""

from __future__ import annotations

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from .equations import Control
from .jaw import Jaw, candidates
from .model import Model
from .newton import contact, solve

__all__ = ["MAX_RATIO", "V_START", "to_pressure", "to_volume"]

#: the first volume (units R^3), solved from the flat sheet
V_START = 1e-2
#: largest volume ratio of one step
MAX_RATIO = 2.0
#: the shortest step (a ratio 1 + MIN_STEP) before the path is declared lost
MIN_STEP = 1e-3
#: the largest volume a pressure target is sought at (a sheet stretched ~10 times)
V_MAX = 1e3
#: landings on a pressure target before giving up (``_land``)
MAX_LANDINGS = 12
#: Newton's tolerance on the path's states (units R): they only seed the next, and the state returned is
#: solved to the caller's tolerance from the last (a step below 1e-3 R leaves an error ~1e-6 R)
PATH_TOL = 1e-3


def _volume(v: float, jaw: Jaw | None = None) -> Control:
    return Control(volume=lambda pf: (v, 0.0), jaw=jaw)


def _solve(model: Model, y: np.ndarray, control: Control, tol: float) -> tuple[np.ndarray, Control, int]:
    """Newton on ``control``; with the clamp's upper jaw, its active set settled too (``newton.contact``)."""
    if control.jaw is None:
        y, iterations = solve(model, y, control, tol)
        return y, control, iterations
    return contact(model, y, control, tol)


def _path(model: Model, target_volume: float, tol: float, jaw: Jaw | None = None):
    """States along log V up to ``target_volume``, solved to ``PATH_TOL``; yields (V, y, iterations, the jaw
    with its active set)."""
    tol = max(tol, PATH_TOL)
    y = np.zeros(model.size + 1 + (0 if jaw is None else candidates(model).size))
    v0 = min(V_START, target_volume)
    y, control, iterations = _solve(model, y, _volume(v0, jaw), tol)
    yield v0, y, iterations, control.jaw
    log_v, previous, log_step = np.log(v0), None, np.log(MAX_RATIO)
    while log_v < np.log(target_volume):
        step = min(log_step, np.log(target_volume) - log_v)
        guess = y if previous is None else y + (y - previous[1]) * step / (log_v - previous[0])
        try:
            new, control, iterations = _solve(model, guess, _volume(np.exp(log_v + step), control.jaw), tol)
        except ConvergenceError:
            log_step = 0.5 * step
            if log_step < MIN_STEP:
                raise
            continue
        previous, y, log_v = (log_v, y), new, log_v + step
        log_step = min(np.log(MAX_RATIO), 1.5 * step)
        yield np.exp(log_v), y, iterations, control.jaw


def to_volume(model: Model, volume: float, tol: float, jaw: Jaw | None = None) -> tuple[np.ndarray, int]:
    """The inflated state of cavity volume ``volume`` (R^3), against the clamp's upper ``jaw`` if given (``jaw``:
    its multipliers end y); (y, Newton iterations)."""
    total = 0
    for _, y, iterations, jaw in _path(model, volume, tol, jaw):
        total += iterations
    y, _, iterations = _solve(model, y, _volume(volume, jaw), tol)
    return y, total + iterations


def to_pressure(model: Model, pressure: float, tol: float, jaw: Jaw | None = None) -> tuple[np.ndarray, int]:
    """The inflated state at the fluid pressure ``pressure`` (units mu_0) on the first branch, against the clamp's
    upper ``jaw`` if given (``jaw``: its multipliers end y); (y, iterations)."""
    total, before = 0, None
    for v, y, iterations, jaw in _path(model, V_MAX, tol, jaw):
        total += iterations
        pf = y[model.size]
        if pf >= pressure:
            if before is None:
                y, _, iterations = _solve(model, y, Control(pressure=pressure, jaw=jaw), tol)
                return y, total + iterations
            y, iterations = _land(model, pressure, before, (v, y), tol, jaw)
            return y, total + iterations
        if before is not None and pf < before[1][model.size]:
            raise OutOfRangeError(f"the solid's pressure has a maximum below Phat-equivalent {pressure:.6g} mu_0 "
                                  f"(it falls past V/R^3 = {before[0]:.4g}): no inflated state on the first branch")
        before = (v, y)
    raise OutOfRangeError(f"the fluid pressure {pressure:.6g} mu_0 is not reached by V/R^3 = {V_MAX:g}")


def _land(model: Model, pressure: float, low, high, tol: float, jaw: Jaw | None) -> tuple[np.ndarray, int]:
    """The state at ``pressure`` between the path's states ``low`` = (V, y) below it and ``high`` above, under
    pressure control from their interpolation at the pressure; if Newton fails from there (a corner element
    turned inside out on the way: the bracket spans the jaw's first contact, say), the bracket is narrowed under
    volume control at the interpolated volume (regula falsi in V; each state solved from the state below, the
    volume step halved while Newton fails) and the landing tried again, ``MAX_LANDINGS`` times in all;
    (y, iterations)."""
    total, size, attempts = 0, model.size, 0
    while True:
        w = (pressure - low[1][size]) / (high[1][size] - low[1][size])
        guess = low[1] + w * (high[1] - low[1])
        try:
            y, _, iterations = _solve(model, guess, Control(pressure=pressure, jaw=jaw), tol)
            return y, total + iterations
        except ConvergenceError:
            attempts += 1
            if attempts == MAX_LANDINGS:
                raise
        v = low[0] + w * (high[0] - low[0])
        while True:  # from the converged state below, its volume step halved until Newton converges
            try:
                y, control, iterations = _solve(model, low[1], _volume(v, jaw), max(tol, PATH_TOL))
                break
            except ConvergenceError:
                v = 0.5 * (low[0] + v)
                if v - low[0] < MIN_STEP * low[0]:
                    raise
        total, jaw = total + iterations, control.jaw
        low, high = ((v, y), high) if y[size] < pressure else (low, (v, y))
