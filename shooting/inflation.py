"""Step 1, inflation: find the pole stretch lambda_0 = 1 + s such that lambda_2(1) = 1.

Pressure control (the paper's step 1). At a fixed pressure p, a shot from the
pole with strain s lands at rho(1) = 1 + m(s). Below the first-branch root the
pressure is too high for that stretch: the meridian lands inside the clamp
(m < 0) or curls back before reaching it (the shot stops: axis, fold, vanishing
tension). So s is marched up from below the small-strain estimate (the Hencky
regime, ``pocket.core.smallstrain``) by a factor 1.25 until m >= 0, and the root
is found by Brent's method in that bracket (relative to s, so that Phat = 1e-6,
s ~ 2e-5, is resolved as well as Phat = 1).

The march may overstep the first branch: near a pressure maximum (alpha near 0
or below) m(s) > 0 only on a short interval, and above the maximum nowhere. The
march gives up as soon as it sees that (m falls, or a shot fails after one
landed), and the robust path takes over: march the first-branch pressure p(s)
(a root in p of m at fixed s, ``pressure_of_stretch``) until it passes the target,
or locate its maximum by golden sections and report that no first-branch state
exists above it (``OutOfRangeError`` naming the maximum). For alpha < 0 the pole
tension (1 - l^-6)(1 + alpha l^2) vanishes at l^2 = -1/alpha: p(s) exists only
below, and the maximum lies there.

Volume control (``inflate_volume``) brackets V(s) the same way, on the first
branch p = p(s); the volume grows through pressure maxima, so it reaches states
pressure control cannot.

A shot that fails for numerical reasons (too many steps) is a ConvergenceError, and
so is a final shot that does not land on the clamp: only the bracketing reads a
shot that stops early as "too much pressure for this stretch".
"""

from __future__ import annotations

import math

from pocket.core import smallstrain
from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.inputs import check_alpha, check_positive
from pocket.core.states import InflatedState

from . import brent
from .integrator import OK, STATUS, STEPS
from .shots import Tolerance, profile_from_steps, shot_pole

__all__ = ["inflate", "inflate_volume", "pressure_of_stretch"]

_GROWTH = 1.25  # ratio of successive s = lambda_0 - 1 in the marches
_S_MAX = 20.0  # s beyond which the marches give up
_S_RTOL = 1e-13  # relative accuracy of the root in s
_P_RTOL = 1e-14  # relative accuracy of the pressure p(s)
_PEAK_RTOL = 1e-9  # relative width in s to which a pressure maximum is located (its value to ~1e-18)


def _tolerance(rtol, strain):
    """Integration tolerances for a dome of pole strain ~ ``strain`` (``Tolerance.scaled``)."""
    return Tolerance.scaled(rtol, math.sqrt(1.5 * strain), 0.25 * math.pi * math.sqrt(6.0 * strain))


def _landing(s, alpha, p, tol, what):
    """rho(1) - 1 of the shot from pole strain s at pressure p, or None if it stops before the clamp."""
    status, y, _ = shot_pole(1.0 + s, alpha, p, tol)
    if status == STEPS:
        raise ConvergenceError(f"inflation ({what}): the shot from lambda_0 = {1 + s:.12g} took too many steps",
                               load=1.0 + s)
    return y[0] - 1.0 if status == OK else None


def _signed(value):
    """A landing as a sign for bracketing: a shot that stopped early had too much pressure (-1)."""
    return -1.0 if value is None else value


def pressure_of_stretch(l0, alpha, *, rtol=1e-10, tol=None) -> float | None:
    """The pressure p (units 2 C1 T / R) at which the shot from pole stretch ``l0`` lands on rho(1) = 1.

    None if there is none: for alpha < 0 past l0^2 = -1/alpha the pole tension vanishes.
    """
    s = l0 - 1.0
    tol = _tolerance(rtol, s) if tol is None else tol
    if (1.0 - l0**-6) * (1.0 + alpha * l0 * l0) <= 0.0:
        return None
    what = f"p(lambda_0 = {l0:.12g})"
    hi = 3.0 * (1.0 + alpha) * 4.0 * math.sqrt(6.0) * s**1.5 * 2.0
    f_hi = _signed(_landing(s, alpha, hi, tol, what))
    while f_hi >= 0.0:
        hi *= 2.0
        if hi > 1e6:
            raise ConvergenceError(f"inflation: no pressure up to 1e6 closes the shot from lambda_0 = {l0!r}",
                                   load=l0)
        f_hi = _signed(_landing(s, alpha, hi, tol, what))
    return brent.root(lambda p: _signed(_landing(s, alpha, p, tol, what)), 0.0, hi, fa=s, fb=f_hi,
                      rtol=_P_RTOL)


def _march(fun, s):
    """Fast path: s up by _GROWTH from below the root until fun(s) >= 0 (fun None where a shot stops).

    Returns (s_lo, f_lo, s_hi, f_hi) bracketing a sign change, or None if the march oversteps.
    """
    f = fun(s)
    while f is not None and f >= 0.0:
        s /= _GROWTH**4
        f = fun(s)
    landed = False
    while s < _S_MAX:
        s_new = s * _GROWTH
        f_new = fun(s_new)
        if f_new is not None and f_new >= 0.0:
            return s, _signed(f), s_new, f_new
        if landed and (f_new is None or f_new < f):  # past a maximum of m: the root may lie behind
            return None
        landed = landed or f_new is not None
        s, f = s_new, f_new
    return None


def _first_branch(phat, target, s, alpha, what):
    """Robust path: s_lo < s_hi with phat(s_lo) < target <= phat(s_hi) on the first branch.

    ``phat(s)`` is the first-branch value (pressure or volume), None where there is none;
    the march starts below ``s`` and below a tenth of the equibiaxial limit of alpha < 0,
    so that it starts on the rising part of the first branch.
    Raises OutOfRangeError when phat has a maximum below ``target``.
    """
    if alpha < 0.0:
        s = min(s, 0.1 * (1.0 / math.sqrt(-alpha) - 1.0))
    history = [(s, phat(s))]
    while history[-1][1] is None or history[-1][1] >= target:
        s /= _GROWTH**4
        history = [(s, phat(s))]
    while True:
        s *= _GROWTH
        if s > _S_MAX:
            raise OutOfRangeError(f"{what} = {target:.6g} is not reached for lambda_0 up to {1 + _S_MAX:g}")
        value = phat(s)
        if value is not None and value >= target:
            return history[-1][0], s
        if value is None or value < history[-1][1]:
            lo = history[-2][0] if len(history) > 1 else history[0][0]
            peak_s, peak = brent.maximum(lambda x: _minus_inf(phat(x)), lo, s, xtol=_PEAK_RTOL * s)
            if peak < target:
                raise OutOfRangeError(
                    f"no inflated state on the first branch: {what} = {target:.6g} is above "
                    f"its maximum {peak:.6g} (reached at lambda_0 = {1 + peak_s:.6g})"
                )
            return lo, peak_s
        history.append((s, value))


def _minus_inf(value):
    return -math.inf if value is None else value


def _state(l0, alpha, p, tol, what, **echo):
    """The state at the root: scalars from the same shot as the root finder, the profile from a
    finer-stepped shot of the same problem; ``echo`` the inputs as given (pressure or volume)."""
    status, y, _ = shot_pole(l0, alpha, p, tol)
    miss = y[0] - 1.0
    if status != OK or abs(miss) > 1e-8 * (l0 - 1.0) + 1e-13:
        raise ConvergenceError(f"inflation ({what}): the final shot from lambda_0 = {l0:.12g} "
                               f"{STATUS[status]}, rho(1) - 1 = {miss:.3g}", load=l0, residual=miss)
    _, _, steps = shot_pole(l0, alpha, p, tol, store=20000)
    scalars = dict(alpha=alpha, pressure=p / (3.0 * (1.0 + alpha)), stretch_pole=l0, height=-y[1], volume=y[4],
                   stretch_clamp=y[3])
    return InflatedState(**{**scalars, **echo}, profile=profile_from_steps(steps, alpha, l0), solver="shooting")


def inflate(alpha, pressure, *, rtol=1e-10) -> InflatedState:
    """Inflate at pressure Phat = P R / (E T) (pressure control, first branch).

    alpha: C2/C1 (> -1). pressure: Phat (> 0). rtol: ODE tolerance.
    Raises OutOfRangeError if Phat exceeds the first-branch maximum of Phat(V).
    """
    alpha = check_alpha(alpha)
    pressure = check_positive("pressure", pressure)
    p = 3.0 * (1.0 + alpha) * pressure
    s_est = smallstrain.pole_strain(pressure)
    tol = _tolerance(rtol, s_est)
    what = f"Phat = {pressure!r}"

    def miss(s):
        return _landing(s, alpha, p, tol, what)

    bracket = _march(miss, s_est)
    if bracket is None:
        def phat(s):
            value = pressure_of_stretch(1.0 + s, alpha, tol=tol)
            return None if value is None else value / (3.0 * (1.0 + alpha))

        lo, hi = _first_branch(phat, pressure, s_est, alpha, "pressure")
        bracket = lo, _signed(miss(lo)), hi, _signed(miss(hi))
    s_lo, f_lo, s_hi, f_hi = bracket
    s = brent.root(lambda x: _signed(miss(x)), s_lo, s_hi, fa=f_lo, fb=f_hi, rtol=_S_RTOL)
    return _state(1.0 + s, alpha, p, tol, what, pressure=pressure)


def inflate_volume(alpha, volume, *, rtol=1e-10) -> InflatedState:
    """Inflate to enclosed volume V / R^3 (volume control, passes pressure maxima)."""
    alpha = check_alpha(alpha)
    volume = check_positive("volume", volume)
    s_est = smallstrain.strain_of_volume(volume)
    tol = _tolerance(rtol, s_est)
    what = f"V = {volume!r}"

    def volume_of(s):
        p = pressure_of_stretch(1.0 + s, alpha, tol=tol)
        if p is None:
            return None
        status, y, _ = shot_pole(1.0 + s, alpha, p, tol)
        if status != OK:
            raise ConvergenceError(f"inflation ({what}): the shot from lambda_0 = {1 + s:.12g} at its pressure "
                                   f"{STATUS[status]}", load=1.0 + s)
        return y[4]

    lo, hi = _first_branch(volume_of, volume, s_est, alpha, "volume")
    s = brent.root(lambda x: volume_of(x) - volume, lo, hi, rtol=_S_RTOL)
    p = pressure_of_stretch(1.0 + s, alpha, tol=tol)
    return _state(1.0 + s, alpha, p, tol, what, volume=volume)
