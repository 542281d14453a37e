"""Scalar root finding and maximisation on a bracket, without scipy (its import costs half a second).

``root`` is Brent's method (Brent 1973, ch. 4) as scipy's ``brentq`` implements it
(``scipy/optimize/Zeros/brentq.c``): inverse quadratic interpolation or secant
steps while they shrink the bracket fast enough, bisection otherwise, so that it
never needs more than about (log2 of the bracket over the tolerance)^2 evaluations
and converges superlinearly on smooth functions. ``maximum`` is a golden-section
search (Kiefer 1953): slower than Brent's parabolic variant but it needs no
smoothness, and it only runs on the error path of inflation (locating a pressure
maximum to report it). ``tests/test_shooting_brent.py`` checks both against scipy's
``brentq`` and ``minimize_scalar`` on hard cases.
"""

from __future__ import annotations

import math
from collections.abc import Callable

__all__ = ["BracketError", "maximum", "root"]

_GOLDEN = 0.5 * (3.0 - math.sqrt(5.0))  # 0.381966..., the golden-section fraction


class BracketError(ValueError):
    """f(a) and f(b) do not differ in sign, or the search ran out of iterations."""


def root(f: Callable[[float], float], a: float, b: float, *, fa=None, fb=None, xtol=1e-300, rtol=4e-16,
         maxiter=200) -> float:
    """A root of ``f`` in [a, b] where f(a) f(b) <= 0, to |x - root| <= xtol + rtol |x|.

    ``fa``, ``fb``: f(a), f(b) if already known (saves evaluations). Raises
    BracketError if the signs are equal or ``maxiter`` evaluations do not suffice.
    """
    xpre, xcur = float(a), float(b)
    fpre = f(xpre) if fa is None else fa
    fcur = f(xcur) if fb is None else fb
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise BracketError(f"f({a!r}) = {fpre!r} and f({b!r}) = {fcur!r} have the same sign")
    xblk = fblk = spre = scur = 0.0
    for _ in range(maxiter):
        if fpre != 0.0 and fcur != 0.0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):  # keep the best point in xcur
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = 0.5 * (xtol + rtol * abs(xcur))
        sbis = 0.5 * (xblk - xcur)
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            try:
                if xpre == xblk:  # secant
                    stry = -fcur * (xcur - xpre) / (fcur - fpre)
                else:  # inverse quadratic interpolation
                    dpre = (fpre - fcur) / (xpre - xcur)
                    dblk = (fblk - fcur) / (xblk - xcur)
                    stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            except ZeroDivisionError:  # C's inf or nan: the test below then bisects, as scipy does
                stry = math.inf
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else math.copysign(delta, sbis)
        fcur = f(xcur)
    raise BracketError(f"no convergence in {maxiter} evaluations (bracket [{xcur!r}, {xblk!r}])")


def maximum(f: Callable[[float], float], a: float, b: float, *, xtol: float) -> tuple[float, float]:
    """(x, f(x)) at a local maximum of ``f`` on [a, b], located to within ``xtol`` by golden sections.

    If ``f`` is unimodal on [a, b] this is its maximum there (an endpoint if f is monotone).
    """
    x1 = a + _GOLDEN * (b - a)
    x2 = b - _GOLDEN * (b - a)
    f1, f2 = f(x1), f(x2)
    while b - a > xtol:
        if f1 >= f2:
            b, x2, f2 = x2, x1, f1
            x1 = a + _GOLDEN * (b - a)
            f1 = f(x1)
        else:
            a, x1, f1 = x1, x2, f2
            x2 = b - _GOLDEN * (b - a)
            f2 = f(x2)
    return (x1, f1) if f1 >= f2 else (x2, f2)
