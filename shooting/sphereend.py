r"""The end of the compression range under a sphere: the largest force the pocket's first branch carries.

Four things end the model as the sphere presses further (``pocket.shooting.sphere``; under a user's
profile, ``pocket.shooting.profile``, the same four with the equator replaced by the profile's end: its
last radius, or where its slope turns vertical):

- the sheet would wrap past the sphere's equator (phi_c = pi/2): its lower cap ends there, and the
  contact zone's shot stops (``integrator.FOLD``, psi = -pi/2);
- the free sheet would reach the clamp plane: psi(1) = pi, as under the plate
  (``pocket.shooting.rangeend``); shots may turn past pi, so this margin is smooth across it;
- the sphere's lowest point, and the sheet's pole on it, would reach the clamp plane (h = 0): a small
  sphere pushed deep, whose cap dips below the clamp before the free sheet does;
- the free sheet would touch the sphere outside the contact zone. For a sphere this cannot come
  first: the free sheet leaves the edge tangent to the sphere and, while it rises (psi < 0), normal
  equilibrium turns it down (psi' = lambda_1 (p - t2 sin(psi) / rho) / t1 > 0) while the sphere's
  surface turns up, so the gap grows; once it descends it is below the contact edge and the sphere
  above it. It is watched all the same, in every state the search solves.

The end, computed. From a state at a small force, the force is continued with steps doubled after each
success (each state solved by ``newton`` from a secant prediction) while every margin
(``SphereProblem.margins``: pi/2 - phi_c, pi - psi(1), h, the smallest gap) stays positive; a step whose
state does not solve or breaks a margin is halved, until it is below ``_RTOL`` of the force. The end is
then the last force solved, within that relative width, and its reason the margin nearest to zero
there (scaled: the angles by pi/2 and pi, the height and the gap by the inflated dome's height). A
search that stalls with every margin above ``_NEAR`` is no end of the model but a solver failure
(ConvergenceError). A force
that grows past ``_FORCE_MAX`` without an end (a rubber that locks) leaves the range without end
(inf). A force maximum before either end (a fold) is not sought under a sphere. Computed once per
pocket and indenter (``rangeend.end_of`` caches it).
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.errors import CLAMP_PLANE, ConvergenceError

from . import newton
from .rangeend import End

__all__ = ["end_of_sphere"]

_START_FORCE = 1e-2  # the first state (halved until it solves)
_RTOL = 1e-10  # relative width of the force bracket at the end
_NEAR = 1e-3  # scaled margin below which a stalled search has reached an end of the model
_FORCE_MAX = 1e6  # force beyond which the range has no end


def _solve(problem, force, guess, jacobian=None):
    """newton.Solution at ``force`` from ``guess``, or None if it fails."""
    sol = newton.solve(lambda x: problem.residual(x, force), guess, tol=problem.residual_tol,
                       floor=problem.residual_floor, jacobian=jacobian)
    return sol if sol.success and problem.close(sol.x, guess, guess) else None


def _scaled(problem, margins) -> dict[str, float]:
    """The margins in comparable units (``problem.scales``: the angles by pi/2 and pi, the lengths by the
    inflated height)."""
    return {key: value / problem.scales[key] for key, value in margins.items()}


def _first(problem, seed):
    """A solved (force, x, margins) to start from: ``seed`` if given, else a small force."""
    if seed is not None and seed[0] > 0.0:
        return seed[0], np.asarray(seed[1]), _scaled(problem, problem.margins(*seed))
    force = _START_FORCE
    for _ in range(30):
        sol = _solve(problem, force, problem.start())
        if sol is not None:
            margins = _scaled(problem, problem.margins(force, sol.x))
            if min(margins.values()) > 0.0:
                return force, sol.x, margins
        force /= 2.0
    raise ConvergenceError(f"range end ({problem.label}): no compressed state found at small forces down to "
                           f"Fhat = {force:.3g}", load=force)


def end_of_sphere(problem, seed=None) -> End:
    """The ``End`` of the sphere's ``problem`` (module docstring); ``seed``: a solved (force, x) or None."""
    force, x, margins = _first(problem, seed)
    previous, step, jacobian = None, force, None
    while step >= _RTOL * force:
        if force > _FORCE_MAX:
            return End(force=math.inf, angle=math.pi - margins[CLAMP_PLANE] * math.pi, fold=False, path=(),
                       locks=True, reason="")
        target = force + step
        guess = x if previous is None else x + step * (x - previous[1]) / (force - previous[0])
        sol = _solve(problem, target, guess, jacobian)
        trial = _scaled(problem, problem.margins(target, sol.x)) if sol is not None else None
        if trial is None or min(trial.values()) <= 0.0:
            step, jacobian = 0.5 * step, None
            continue
        previous, force, x, margins, jacobian = (force, x), target, sol.x, trial, sol.jacobian
        step *= 2.0
    reason = min(margins, key=margins.get)
    if margins[reason] > _NEAR:
        raise ConvergenceError(f"range end ({problem.label}): the continuation in the force stalled at Fhat = "
                               f"{force:.10g}, short of every end of the model (scaled margins "
                               + ", ".join(f"{k}: {v:.3g}" for k, v in margins.items()) + ")", load=force)
    return End(force=float(force), angle=math.pi - margins[CLAMP_PLANE] * math.pi, fold=False, path=(),
               reason=reason)
