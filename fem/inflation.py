"""Step 1, inflation: from a small dome to a given pressure or volume.

Start: the small-strain dome (``steps.dome``) at Phat_0 = min(Phat, 1e-3),
polished by Newton under pressure control; the flat sheet is never used (its
tangent is singular).

Volume target: load stepping in log V under volume control, which passes
pressure maxima.

Pressure target: the same volume path, monitoring P. When P reaches the
target, ``steps.land`` solves under pressure control from the bracketing
states. If P falls before reaching it, the path has passed a pressure maximum
(neo-Hookean-like alpha): a golden-section search in V locates it; a target
above it has no state on the first branch (``OutOfRangeError``), one below it
is landed on the rising side. A maximum can hide inside one step: for alpha
just below the value where the maximum disappears, P(V) has a dip so shallow and
narrow (alpha = 0.0547: Phat 0.73277 at V/R^3 = 8.2, 0.73246 at 12, back to
0.73277 by 16) that the states on either side of it both rise. A local maximum
flattens the path first, so where the slope dP/dlog V of a step falls below
``FLATTENING`` times the step's before it, or its slope d log P / d log V below
``FLAT``, ``SUBSTEPS`` states are solved inside it and watched like the others
(``_states``); without that the path would pass the dip and return a state of
the second rising branch. Nearer the alpha where the dip vanishes (0.05544) it is
narrower than a substep (alpha = 0.05542: 1.4e-9 of P deep): where the
substeps all rise, the least slope among them is located by golden sections on the
slope over ``SLOPE_STEP`` (``_least_slope``), and a negative one is a fall.

A rubber that locks (Gent) stops the volume path at its locking stretch
(``steps.near_locking``): a volume target past it is ``OutOfRangeError``.

Every path stops at the pole stretch ``STRETCH_LIMIT`` (``pocket.core.errors``), as the shooting
solver's marches do: a pressure or volume reached only past it, or not by it, is the one
``OutOfRangeError`` both solvers give (``past_stretch_limit``), checked on the state the path
lands on too. The path's range in log V (``LOG_V_RANGE``) is wide enough that it ends there first.

Remembered: ``inflated_at`` solves a pressure target once per (law, mesh, reference surface, Phat, tolerances)
among the last ``REMEMBERED`` asked in the process. Every entry point starts from the
inflated state, and the applications call them many times on one pocket (a design's or a
sensor's inverse problem once per bracket step, a case file's checks and curve): the
inflation was 60 % of a one-force compression. The solve is deterministic, so a remembered
state is the one a fresh solve gives, bit for bit.
"""

from __future__ import annotations

import collections
import itertools

import numpy as np

from pocket.core.errors import STRETCH_LIMIT, ConvergenceError, above_pressure_maximum, past_stretch_limit

from .continuation import follow
from .model import FREE, Control, Model, forms
from .newton import Tolerances
from .post import pole_stretch
from .steps import dome, land, near_locking, solve

__all__ = ["REMEMBERED", "forget", "inflated_at", "to_pressure", "to_volume", "volume"]

#: inflated states ``inflated_at`` remembers (at most 8 (2 N + 3) floats each, N the nodal dofs)
REMEMBERED = 8
_SOLVED: collections.OrderedDict = collections.OrderedDict()

P_START = 1e-3
#: how far past the start volume (V/R^3 ~ 0.1 at Phat_0 = 1e-3) a pressure target is sought: far past the
#: pole stretch STRETCH_LIMIT, where the path stops (V/R^3 ~ 5e5 there for alpha = 0.0573)
LOG_V_RANGE = np.log(1e12)
#: the path's first, largest and smallest steps in log V
_FIRST_STEP, _MAX_STEP, _MIN_STEP = 0.05 * np.log(1e6), 0.1 * np.log(1e6), 1e-5 * np.log(1e6)
#: a step whose slope dP/dlog V is below this fraction of the step's before it is searched for a maximum
#: inside it (a rubber without one flattens by a few per cent a step; at a maximum the slope goes to 0)
FLATTENING = 0.25
#: ... or where its slope d log P / d log V is below this (it is 3 at small strain, 1/3 at large stretch)
FLAT = 0.03
#: the states solved inside such a step
SUBSTEPS = 8
#: the step in log V of the slope d log P / d log V where it is least inside such a step (``_least_slope``)
SLOPE_STEP = 1e-4
_GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0


def _start(model: Model, pressure: float, tol: Tolerances):
    """The first state, at a small pressure from the small-strain dome; (y, iterations)."""
    p0 = min(pressure, P_START)
    try:
        return solve(model, FREE, Control(pressure=p0), dome(model, p0), tol)
    except ConvergenceError as err:
        raise ConvergenceError(f"the first state, from the small-strain dome at Phat = {p0:.6g}, did not "
                               f"converge: {err}", load=p0, iterations=err.iterations,
                               residual=err.residual) from err


def to_volume(model: Model, target: float, tol: Tolerances) -> tuple[np.ndarray, int]:
    """Inflated state of volume ``target``; (y, Newton iterations)."""
    y, total = _start(model, P_START, tol)

    def along(log_v, guess):
        return solve(model, FREE, Control(volume=np.exp(log_v)), guess, tol)

    try:
        for _, y, iterations in follow(along, y, np.log(volume(model, y)), np.log(target), name="log(V/R^3)"):
            total += iterations
            _within_limit(model, y, f"volume = {target!r}")
    except ConvergenceError as err:
        near_locking(model, y, FREE, err, f"volume = {target!r}", bounded=True)
        raise
    return y, total


def to_pressure(model: Model, target: float, tol: Tolerances) -> tuple[np.ndarray, int]:
    """Inflated state at pressure ``target`` on the first branch; (y, Newton iterations)."""
    y, total = _start(model, target, tol)
    if target <= P_START:
        return y, total

    def along(log_v, guess):
        return solve(model, FREE, Control(volume=np.exp(log_v)), guess, tol)

    def at_target(guess):
        return solve(model, FREE, Control(pressure=target), guess, tol)

    log_v0 = np.log(volume(model, y))
    path = [(log_v0, y)]
    what = f"Phat = {target!r}"
    try:
        for log_v, y, iterations in _states(along, y, log_v0):
            total += iterations
            if y[-1] >= target:
                y, iterations = land(along, at_target, path[-1], (log_v, y), _pressure, target)
                return _within_limit(model, y, what), total + iterations
            if y[-1] < path[-1][1][-1] and len(path) >= 2:
                peak, iterations = _pressure_peak(along, path[-2], path[-1], (log_v, y))
                total += iterations
                if peak[1][-1] < target:
                    raise above_pressure_maximum(target, peak[1][-1], float(np.exp(peak[0])), model.law.label)
                y, iterations = land(along, at_target, path[-2], peak, _pressure, target)
                return _within_limit(model, y, what), total + iterations
            _within_limit(model, y, what)
            path.append((log_v, y))
    except ConvergenceError as err:
        near_locking(model, path[-1][1], FREE, err, f"Phat = {target:.6g}", bounded=False)
        raise
    raise ConvergenceError(f"the volume path to {what} ended at V/R^3 = {np.exp(log_v):.4g} before the pole "
                           f"stretch {STRETCH_LIMIT:g}", load=float(np.exp(log_v)))


def _within_limit(model: Model, y: np.ndarray, what: str) -> np.ndarray:
    """``y``, a state on the way to (or at) the target ``what``, if its pole stretch is within ``STRETCH_LIMIT``;
    else the refusal every solver gives."""
    if pole_stretch(model, y, FREE) > STRETCH_LIMIT:
        raise past_stretch_limit(what)
    return y


def _states(along, y, log_v0):
    """(log V, y, Newton iterations) along the volume path from ``y`` at log V = ``log_v0`` to
    ``LOG_V_RANGE`` past it, with the states of ``_inside`` more where a step flattens (module docstring)."""
    last: list[tuple[float, np.ndarray]] = [(log_v0, y)]
    for log_v, y, iterations in follow(along, y, log_v0, log_v0 + LOG_V_RANGE, name="log(V/R^3)",
                                       first_step=_FIRST_STEP / LOG_V_RANGE, max_step=_MAX_STEP / LOG_V_RANGE,
                                       min_step=_MIN_STEP / LOG_V_RANGE):
        if len(last) == 2:
            (s_a, y_a), (s_m, y_m) = last
            before, now = (y_m[-1] - y_a[-1]) / (s_m - s_a), (y[-1] - y_m[-1]) / (log_v - s_m)
            if 0.0 <= now < max(FLATTENING * before, FLAT * y[-1]):
                yield from _inside(along, (s_m, y_m), log_v)
        yield log_v, y, iterations
        last = [*last, (log_v, y)][-2:]


def _inside(along, start, stop):
    """(log V, y, iterations) of ``SUBSTEPS`` states from ``start`` = (log V, y) to log V = ``stop``, and, where
    they all rise but the least slope d log P / d log V near them is negative (a maximum narrower than a substep,
    ``_least_slope``), up to the two states about that slope instead, the second below the first."""
    states, guess = [], start[1]
    for s in np.linspace(start[0], stop, SUBSTEPS + 2)[1:-1]:
        guess, k = along(s, guess)
        states.append((s, guess, k))
    chain = [start, *[(s, y) for s, y, _ in states]]
    if all(b[1][-1] >= a[1][-1] for a, b in itertools.pairwise(chain)):
        s, slope, pair = _least_slope(along, chain)
        if slope < 0.0:
            states = [state for state in states if state[0] < s] + pair
    yield from states


def _least_slope(along, chain):
    """(log V, the slope d log P / d log V there, the states at log V and log V + ``SLOPE_STEP`` as
    (log V, y, iterations)) where the slope is least, near the least of the slopes between the states
    (log V, y) of ``chain``: golden sections on the slope over ``SLOPE_STEP``, each state by Newton from the
    nearest one of ``chain``."""
    slopes = [np.log(b[1][-1] / a[1][-1]) / (b[0] - a[0]) for a, b in itertools.pairwise(chain)]
    k = int(np.argmin(slopes))
    lo, hi = chain[max(k - 1, 0)][0], chain[min(k + 2, len(chain) - 1)][0]
    pairs = {}

    def minus_slope(s):
        y, k = along(s, min(chain, key=lambda item: abs(item[0] - s))[1])
        y_up, k_up = along(s + SLOPE_STEP, y)
        pairs[s] = [(s, y, k), (s + SLOPE_STEP, y_up, k_up)]
        return -np.log(y_up[-1] / y[-1]) / SLOPE_STEP

    s, minus = _golden_maximum(minus_slope, lo, hi, SLOPE_STEP)
    return s, -minus, pairs[s]


def inflated_at(model: Model, target: float, tol: Tolerances, solve=None) -> tuple[np.ndarray, int]:
    """``solve(model, target, tol)`` (default ``to_pressure``; the capsule's: ``pocket.fem.capsule.inflate``), solved
    once per (law, mesh, reference surface, target, tol) among the last ``REMEMBERED`` asked (module docstring); (y,
    Newton iterations of its solve), y a copy of its own.

    A target with no state is not remembered: its error is raised again by a fresh solve.
    """
    law = model.law
    key = (law.code, law.params.tobytes(), law.jm, model.xi.tobytes(), model.order, model.geometry, float(target),
           tol)
    if key in _SOLVED:
        _SOLVED.move_to_end(key)
        y, iterations = _SOLVED[key]
    else:
        y, iterations = _SOLVED[key] = (to_pressure if solve is None else solve)(model, target, tol)
        while len(_SOLVED) > REMEMBERED:
            _SOLVED.popitem(last=False)
    return y.copy(), iterations


def forget() -> None:
    """Forget every remembered inflation: the next ``inflated_at`` of any pocket solves it again."""
    _SOLVED.clear()


def _pressure(y: np.ndarray) -> float:
    return float(y[-1])


def volume(model: Model, y: np.ndarray) -> float:
    """V(x) of the FREE state y."""
    return forms(model, y, FREE).volume


def _reach(along, known, s):
    """The state at log V = s: Newton from the nearest known state, else stepping from it; (y, iterations)."""
    s_near, y_near = min(known, key=lambda item: abs(item[0] - s))
    try:
        return along(s, y_near)
    except ConvergenceError:
        total, y = 0, y_near
        for _, y, iterations in follow(along, y_near, s_near, s, name="log(V/R^3)"):
            total += iterations
        return y, total


def _pressure_peak(along, a, m, b, rtol: float = 1e-7):
    """Golden-section search for max P(log V) in [a, b], P(m) >= P(a), P(b).

    Returns ((log V, y) at the peak, iterations).
    """
    known, counts = [a, m, b], []

    def pressure(s):
        y, k = _reach(along, known, s)
        known.append((s, y))
        counts.append(k)
        return y[-1]

    _golden_maximum(pressure, a[0], b[0], rtol)
    return max(known[1:], key=lambda item: item[1][-1]), sum(counts)


def _golden_maximum(f, lo: float, hi: float, xtol: float) -> tuple[float, float]:
    """(x, f(x)) at a local maximum of ``f`` on [lo, hi], located to within ``xtol`` by golden sections."""
    x1, x2 = hi - _GOLDEN * (hi - lo), lo + _GOLDEN * (hi - lo)
    f1, f2 = f(x1), f(x2)
    while hi - lo > xtol:
        if f1 >= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - _GOLDEN * (hi - lo)
            f1 = f(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + _GOLDEN * (hi - lo)
            f2 = f(x2)
    return (x1, f1) if f1 >= f2 else (x2, f2)
