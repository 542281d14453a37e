"""Inverse problems on the dimensionless model: the load that gives a target value.

Both inflation and compression are monotone in their load on the model's first
branch: the inflated height H0/R and volume grow with Phat_I; under compression
the pressure ratio P/P_I grows with Fhat while the height H/R and H/H0 fall.
So each inverse problem is one scalar root, bracketed and then solved by
Brent's method on the forward solver:

- ``pressure_for_height``: Phat_I with inflate(material, Phat_I).height = H0/R;
- ``force_where``: Fhat with compress(material, Phat_I, Fhat).<key> = target;
- ``pressure_for_sheet``: Phat_I with compress(material, Phat_I, c / Phat_I).<key> = target, a sheet of
  known thickness T pressed by a known force F (``design``), so that Fhat = F / (P_I pi R^2) = c / Phat_I,
  c = F / (pi R E T).

The bracket starts at load 0, where the value is known (height 0, a capsule's its radius; the
uncompressed state). For a force, a solver that knows the end of its range
(``range_end``, an optional entry point: ``pocket.core.solver``) gives the top of
the bracket directly. Each function takes the solver's record (``pocket.core.solver.Solver``) and
gets its entry points from it (``pocket.apps.solvers.entry``). Otherwise an upper load doubles until the sign changes; a
forward solve that is out of the model's range there (OutOfRangeError: past a
pressure maximum, or the free part reaching the clamp plane) ends the doubling:
the range edge is then bisected. A target the model does not reach inside its
range is an OutOfRangeError, never an extrapolation. A solver that fails
(ConvergenceError) is not a range edge: the error propagates.

scipy is imported on first use: the command line imports this module to build
its parser, and every ``pocket`` command would otherwise pay for it.
"""

from __future__ import annotations

import math

from pocket.core.errors import OutOfRangeError
from pocket.core.solver import Solver

from .solvers import entry

__all__ = ["force_where", "pressure_for_height", "pressure_for_sheet", "range_end"]

_XTOL, _RTOL = 1e-15, 1e-13  # the forward solvers resolve their values to ~1e-10
_EDGE = 1e-9  # relative width at which the range edge is located
_WIDEST = 2.0**16  # how far a bracket in Phat_I may grow from its start, each way (a factor ~6.6e4)


def _bracket(fun, start, what, reached):
    """[lo, hi] with fun(lo) < 0 <= fun(hi), lo from 0 (fun(0) < 0), doubling from ``start``."""
    lo, hi = 0.0, start
    while True:
        try:
            if fun(hi) >= 0.0:
                return lo, hi
        except OutOfRangeError:
            break
        lo, hi = hi, 2.0 * hi
    while hi - lo > _EDGE * hi:  # bisect the edge of the range between lo (inside) and hi (outside)
        mid = 0.5 * (lo + hi)
        try:
            if fun(mid) >= 0.0:
                return lo, mid
        except OutOfRangeError:
            hi = mid
            continue
        lo = mid
    raise OutOfRangeError(f"{what} is beyond the model's range (it reaches {reached(lo):.10g} at its edge)")


def pressure_for_height(solver: Solver, material, height, **options) -> float:
    """Phat_I at which the inflated height H0/R is ``height`` (first branch), by ``solver``'s ``inflate``.

    The bracket starts at Phat_I = 0, where the height is the undeformed surface's pole height (0 for the flat
    pocket; R for a capsule, given as ``options["geometry"]``, whose pole height above its equator is lambda R): a
    height below it is an OutOfRangeError, the height itself Phat_I = 0."""

    from scipy.optimize import brentq

    from pocket.core.geometries import as_geometry
    from pocket.core.smallstrain import height_constant

    inflate = entry(solver, "inflate", f"an initial height H0/R = {height:.10g}")
    geometry = as_geometry(options.get("geometry"))
    rest = float(geometry.height(0.0))  # the undeformed pole's height
    if height <= rest:
        if height == rest:
            return 0.0
        raise OutOfRangeError(f"initial height H0/R = {height:.10g} is below the undeformed {geometry.name}'s "
                              f"({rest:.10g}): no inflation pressure P_I >= 0 gives it")

    def miss(p):
        return inflate(material, p, **options).height - height if p > 0.0 else rest - height

    # the small-strain Phat_I: the pocket's model, or a sphere's Phat = 4 (lambda - 1) with H0/R = lambda
    guess = (height / height_constant()) ** 3 if rest == 0.0 else 4.0 * (height - rest)
    lo, hi = _bracket(miss, guess, f"initial height H0/R = {height:.10g}",
                      lambda p: inflate(material, p, **options).height)
    return brentq(miss, lo, hi, xtol=_XTOL, rtol=_RTOL)


def force_where(solver: Solver, material, pressure_initial, key, target, *, increasing, **options) -> float:
    """Fhat at which the compressed state's ``key`` equals ``target``, by ``solver``'s ``compress``.

    ``increasing``: whether ``key`` grows with the force (``pressure_ratio``) or
    falls (``height``, ``height_ratio``). A target on the wrong side of the
    uncompressed value, or past the model's range, is an OutOfRangeError.
    """
    from scipy.optimize import brentq

    sign = 1.0 if increasing else -1.0
    compress = entry(solver, "compress", f"a compressed state of {key} = {target:.10g}")

    def value(f):
        return getattr(compress(material, pressure_initial, f, **options), key)

    start = value(0.0)
    if target == start:
        return 0.0
    if sign * (target - start) < 0.0:
        side = "below" if increasing else "above"
        raise OutOfRangeError(f"{key} = {target:.10g} is {side} its value with no force ({start:.10g})")

    def miss(f):
        return sign * (value(f) - target) if f > 0.0 else sign * (start - target)

    end = _own_end(solver, material, pressure_initial, options)
    if end is None or math.isinf(end):  # no end known, or none at all (a capsule pressed by a liquid)
        lo, hi = _bracket(miss, 0.1, f"{key} = {target:.10g}", value)
    elif miss(end) < 0.0:
        raise OutOfRangeError(f"{key} = {target:.10g} is beyond the model's range (it reaches {value(end):.10g} "
                              f"at its edge, force = {end:.10g})")
    else:
        lo, hi = 0.0, end
    return brentq(miss, lo, hi, xtol=_XTOL, rtol=_RTOL)


def pressure_for_sheet(solver: Solver, material, per_pressure, key, target, *, what=None, **options) -> float:
    """Phat_I at which ``solver``'s compress(material, Phat_I, ``per_pressure`` / Phat_I).<key> equals ``target``
    (``key``: ``height_ratio`` H/H0 or ``height`` H/R, both growing with Phat_I on this path); ``what`` names
    the target in messages (by default ``key = target``).

    Along it a higher pressure is both a stiffer pocket and a smaller Fhat, so the pressed height and its
    ratio to the inflated one grow with Phat_I (the design's tests check it). The model's range bounds the
    path on both sides: at a low Phat_I the force presses the free part onto the clamp plane (a state
    below every target), at a high one there may be no inflated state (above every target). The bracket
    doubles or halves from Phat_I = 5.7 ``per_pressure`` (Fhat = 1/5.7, the paper's rule), then closes on
    the range's edge until both its ends are states; a target past the edge is an OutOfRangeError. So is
    one not reached within a factor ``_WIDEST`` of the start: as Phat_I falls at fixed Phat_I Fhat, H/H0
    tends to a limit above 0 (about 0.53 for alpha = 0.3 and the section 6 button's F / (pi R E T)), so a
    low target may lie below every state of the path.
    """
    from scipy.optimize import brentq

    compress = entry(solver, "compress", f"a compressed state of {key} = {target:.10g}")
    inflate = entry(solver, "inflate", f"a compressed state of {key} = {target:.10g}")

    def miss(p):
        try:
            return getattr(compress(material, p, per_pressure / p, **options), key) - target
        except OutOfRangeError:
            try:
                inflate(material, p, **{k: v for k, v in options.items() if k not in ("fluid", "indenter")})
            except OutOfRangeError:
                return math.inf  # no inflated state so high: above every target
            return -math.inf  # pressed past the end of the range: below every target

    lo, hi = _sheet_bracket(miss, 5.7 * per_pressure, what or f"{key} = {target:.10g}", target)
    return brentq(miss, lo, hi, xtol=_XTOL, rtol=_RTOL)


def _sheet_bracket(miss, start, what, target) -> tuple[float, float]:
    """[lo, hi] with finite miss(lo) < 0 <= miss(hi), miss growing, from ``start`` (``pressure_for_sheet``)."""
    lo = hi = start
    low = high = miss(start)
    while not (low < 0.0 <= high and lo < hi):
        if high < 0.0:
            if hi > start * _WIDEST:
                raise OutOfRangeError(f"{what} is not reached on this sheet: it is {high + target:.10g} at "
                                      f"Phat_I = {hi:.6g}, {_WIDEST:g} times the paper's rule's")
            lo, low, hi = hi, high, 2.0 * hi
            high = miss(hi)
        else:
            if lo < start / _WIDEST:  # Phat_I -> 0 at fixed Phat_I Fhat tends to a limit, not to the range's end
                raise OutOfRangeError(f"{what} is not reached on this sheet: it is still {low + target:.10g} at "
                                      f"Phat_I = {lo:.6g}, 1/{_WIDEST:g} of the paper's rule's")
            hi, high, lo = lo, low, 0.5 * lo
            low = miss(lo)
    while not (math.isfinite(low) and math.isfinite(high)):  # close on the range's edge
        if hi - lo <= _EDGE * hi:
            side = "its compression range (the free part reaching the clamp plane)" if math.isinf(low) else \
                "its inflated states"
            raise OutOfRangeError(f"{what} is beyond the model's range: the pocket reaches the end of {side} at "
                                  f"Phat_I = {lo:.10g} first")
        mid = 0.5 * (lo + hi)
        value = miss(mid)
        lo, low, hi, high = (mid, value, hi, high) if value < 0.0 else (lo, low, mid, value)
    return lo, hi


def _own_end(solver: Solver, material, pressure_initial, options):
    """The solver's own ``range_end`` (an entry point its record may list), or None if it has none."""
    if not solver.serves("range_end"):
        return None
    return entry(solver, "range_end", "the end of the compression range")(material, pressure_initial, **options)


def range_end(solver: Solver, material, pressure_initial, *, below=None, width=_EDGE, **options) -> float:
    """The end of the model's compression range in Fhat (where the free part reaches the
    clamp plane); the value is inside the range.

    ``options`` go to the solver (a shooting ``rtol`` among them). A solver with its own
    ``range_end`` gives it (``width`` is then not used: the solver states its own tolerance).
    Otherwise the end is located by bisection to the relative width ``width``,
    first bracketed by doubling from Fhat = 1 (up to 1e4). With ``below``: ``below`` itself if
    the model has a compressed state there, else the end below it.
    """
    end = _own_end(solver, material, pressure_initial, options)
    if end is not None:
        return end if below is None else min(below, end)
    compress = entry(solver, "compress", "the end of the compression range")

    def inside(f):
        try:
            compress(material, pressure_initial, f, **options)
        except OutOfRangeError:
            return False
        return True

    if below is not None:
        if inside(below):
            return below
        lo, hi = 0.0, below
    else:
        lo, hi = 0.0, 1.0
        while inside(hi):
            lo, hi = hi, 2.0 * hi
            if hi > 1e4:
                raise OutOfRangeError(f"no end of the compression range found below Fhat = {hi:g}")
    while hi - lo > width * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if inside(mid) else (lo, mid)
    return lo
