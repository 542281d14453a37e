"""Step 1, inflation: find the pole stretch lambda_0 such that lambda_2(1) = 1.

Pressure control (the paper's step 1). For a given lambda_0, the clamp radius
rho(1) falls from lambda_0 (> 1, at p = 0) as p rises, so ``pressure_of_stretch``
finds the pressure p(lambda_0) with rho(1) = 1 by a bracketing root finder
(brentq). Along the first branch p(lambda_0) rises from 0; for alpha near 0 it
reaches a maximum and falls (DESIGN.md). ``inflate`` marches lambda_0 upward from
below the small-strain estimate until p(lambda_0) passes the target; if p falls
first, it locates the maximum and, above it, reports that no inflated state
exists on the first branch. The final lambda_0 is then found at fixed pressure
by brentq inside that bracket (rho(1) - 1 changes sign there), which is the
paper's formulation with a robust root finder instead of fixed bisections.

Volume control (``inflate_volume``) brackets V(lambda_0) the same way; the
volume grows through pressure maxima, so it reaches states pressure control cannot.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from pocket.core import smallstrain
from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.inputs import check_alpha, check_positive
from pocket.core.states import InflatedState

from .integrator import OK, STATUS
from .shots import profile_from_steps, shot_pole

__all__ = ["inflate", "inflate_volume", "pressure_of_stretch"]

_GROWTH = 1.25  # ratio of successive lambda_0 - 1 in the march
_S_MAX = 20.0  # lambda_0 - 1 beyond which we give up the march
_XTOL = dict(xtol=1e-15, rtol=1e-14, maxiter=200)


def _miss(l0, alpha, p, rtol):
    """rho(1) - 1 for a shot from the pole; -1 when the meridian curls back first."""
    status, y, _ = shot_pole(l0, alpha, p, rtol)
    return y[0] - 1.0 if status == OK else -1.0


def pressure_of_stretch(l0, alpha, *, rtol=1e-10):
    """The pressure p (units 2 C1 T / R) at which the shot from pole stretch l0 lands on rho(1) = 1."""
    s = l0 - 1.0
    hi = 3.0 * (1.0 + alpha) * 4.0 * np.sqrt(6.0) * s**1.5 * 2.0
    while _miss(l0, alpha, hi, rtol) > 0.0:
        hi *= 2.0
        if hi > 1e6:
            raise ConvergenceError(f"no pressure closes the shot from lambda_0 = {l0}", load=l0)
    return brentq(lambda p: _miss(l0, alpha, p, rtol), 0.0, hi, **_XTOL)


def _volume(l0, alpha, rtol):
    p = pressure_of_stretch(l0, alpha, rtol=rtol)
    status, y, _ = shot_pole(l0, alpha, p, rtol)
    return y[4]


def _bracket(fun, target, s_start, what):
    """March s = lambda_0 - 1 up from below s_start until fun(1 + s) >= target.

    Returns (s_lo, s_hi) with fun below/above target, on the first branch. Raises
    OutOfRangeError when fun has a maximum below the target.
    """
    s = s_start
    while fun(1.0 + s) >= target:
        s /= _GROWTH**4
    history = [(s, fun(1.0 + s))]
    while history[-1][1] < target:
        s *= _GROWTH
        if s > _S_MAX:
            raise OutOfRangeError(f"{what} = {target:.6g} not reached for lambda_0 up to {1 + _S_MAX}")
        history.append((s, fun(1.0 + s)))
        if history[-1][1] < history[-2][1]:
            lo = history[-3][0] if len(history) > 2 else history[0][0]
            peak = minimize_scalar(lambda x: -fun(1.0 + x), bounds=(lo, s), method="bounded",
                                   options=dict(xatol=1e-12 * s))
            if -peak.fun < target:
                raise OutOfRangeError(
                    f"no inflated state on the first branch: {what} = {target:.6g} is above "
                    f"its maximum {-peak.fun:.6g} (reached at lambda_0 = {1 + peak.x:.6g})"
                )
            return lo, peak.x
    return history[-2][0], history[-1][0]


def _state(l0, alpha, p, rtol, how):
    """The state at the root: scalars from the same shot as the root finder, the
    profile from a finer-stepped shot of the same problem."""
    status, y, _ = shot_pole(l0, alpha, p, rtol)
    if status != OK or abs(y[0] - 1.0) > 1e-9:
        raise ConvergenceError(f"inflation ({how}): final shot {STATUS[status]}, rho(1) - 1 = {y[0] - 1:.3g}")
    _, _, steps = shot_pole(l0, alpha, p, rtol, store=20000)
    return InflatedState(
        alpha=alpha,
        pressure=p / (3.0 * (1.0 + alpha)),
        stretch_pole=l0,
        height=-y[1],
        volume=y[4],
        stretch_clamp=y[3],
        profile=profile_from_steps(steps, alpha, l0),
        solver="shooting",
    )


def inflate(alpha, pressure, *, rtol=1e-10) -> InflatedState:
    """Inflate at pressure Phat = P R / (E T) (pressure control, first branch).

    alpha: C2/C1 (> -1). pressure: Phat (> 0). rtol: ODE tolerance.
    Raises OutOfRangeError if Phat exceeds the first-branch maximum of Phat(V).
    """
    alpha = check_alpha(alpha)
    pressure = check_positive("pressure", pressure)
    p = 3.0 * (1.0 + alpha) * pressure
    s_est = smallstrain.pole_strain(pressure)

    def phat(l0):
        return pressure_of_stretch(l0, alpha, rtol=rtol) / (3.0 * (1.0 + alpha))

    s_lo, s_hi = _bracket(phat, pressure, s_est, "pressure")
    l0 = brentq(lambda s: _miss(s, alpha, p, rtol), 1.0 + s_lo, 1.0 + s_hi, **_XTOL)
    return _state(l0, alpha, p, rtol, f"Phat = {pressure}")


def inflate_volume(alpha, volume, *, rtol=1e-10) -> InflatedState:
    """Inflate to enclosed volume V / R^3 (volume control, passes pressure maxima)."""
    alpha = check_alpha(alpha)
    volume = check_positive("volume", volume)
    s_est = smallstrain.strain_of_volume(volume)

    s_lo, s_hi = _bracket(lambda l0: _volume(l0, alpha, rtol), volume, s_est, "volume")
    l0 = brentq(lambda s: _volume(s, alpha, rtol) - volume, 1.0 + s_lo, 1.0 + s_hi, **_XTOL)
    p = pressure_of_stretch(l0, alpha, rtol=rtol)
    return _state(l0, alpha, p, rtol, f"V = {volume}")
