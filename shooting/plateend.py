r"""The end of the compression range under the flat plate: the largest force the pocket's first branch carries.

What happens there. The free meridian leaves the contact edge horizontally
(psi = 0) and turns down and outward, then (past psi = pi/2) inward to the clamp.
Its height falls while 0 < psi < pi, so its lowest point is the clamp as long as
psi stays below pi. Normal equilibrium, psi' = lambda_1 (p - t2 sin(psi)/rho)/t1,
gives psi' = lambda_1 p / t1 > 0 wherever psi = 0 or pi: psi cannot come back to 0,
and it cannot touch pi from below inside (a, 1) without crossing it. So as the
force grows, the first point of the free part to reach the clamp plane is the
clamp itself, where the meridian then arrives horizontally, moving inward:
psi(1) = pi. Beyond, the meridian would run below the clamp plane and come back
up to the clamp: outside the model (the substrate is in the way). There the
clamp carries no vertical force (T_1 sin(psi(1)) = 0), so the plate carries all of
P pi R^2: Fhat = P/P_I, and by F = P A_c the deformed contact area is pi R^2
exactly, a check independent of how the end was found.

The clamp angle theta = psi(1) rises along the branch from its inflated value.
For alpha >= 0 (every case measured) the force rises with it up to theta = pi.
For some alpha < 0 (softening under large hoop stretch; e.g. alpha = -0.5 at
Phat_I = 0.1) the force reaches a maximum (a fold) before theta = pi: past that
force the branch carries no state under force control. A rubber that locks (Gent,
I1 - 3 < Jm) and is inflated close to its locking stretch may have no end at all:
as the force grows the pressure grows without bound while the stretches approach
the locking limit and the clamp angle a limit below pi (measured: Jm = 3, Phat_I = 2,
psi(1) -> 2.955 with Fhat -> infinity). The continuation in theta then stalls
below that angle with the contact zone within 1 % of locking: the range has no end
(``range_end`` is inf), and forces so large that the stretches come within the
solver's precision of locking fail as ConvergenceErrors that say so.

The end, defined and computed. Fhat_end is the largest force on the branch for
psi(1) in [theta_inflated, pi]: the force at psi(1) = pi, or the force maximum
before it. It is found by continuation in theta, the clamp angle, from a state
at a small force, solving at each step the augmented shooting system: unknowns
(q, e, Fhat), residuals (rho(1) - 1)/s_0, V/V_I - 1 and psi(1) - theta
(``PlateProblem.residual``), by Newton from a secant prediction, with steps of at
most 1/8 of the way. The last step lands exactly on theta = pi, and Fhat there is
the end, unless the force fell on the way: then the maximum of Fhat(theta) is
located by golden sections on the steps around it. Shots from the contact edge
may turn past pi (``shots.PSI_MAX_EDGE``), so the residuals are smooth at pi.

Tolerance. The end is computed once per (rubber, Phat_I, rtol, fluid) and cached (``pocket.shooting.end``). Its error
is that of the shots (``tests/test_shooting_rangeend.py`` measures it under rtol
refinement). A force up to and including the returned number is inside the range
and solves; any force above it is outside, however close: the decision is the
comparison with this one number, so it is the same whatever force was asked. The
branch computed on the way is kept, and ``solve_on_branch`` uses it for forces
near a fold, where continuation in the force cannot go.
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.errors import ConvergenceError

from . import brent, newton
from .end import End, end_of

__all__ = ["plate_end", "solve_on_branch"]

_START_FORCE = 1e-2  # the first state of the continuation in theta (halved if it does not solve)
_MIN_STEP = 1e-6  # smallest step in theta (rad) before the continuation gives up
_FOLD_XTOL = 1e-7  # width in theta to which a force maximum is located (the force to ~1e-14)
_LOCKING = 1e-2  # lock margin 1 - (I1 - 3)/Jm of the contact zone below which a stalled continuation is locking


def _first_state(problem, seed):
    """A solved (force, x) to start from: ``seed`` if given, else a small force solved from the inflated state."""
    if seed is not None and seed[0] > 0.0:
        return seed
    force = _START_FORCE
    for _ in range(20):
        sol = newton.solve(lambda x, f=force: problem.residual(x, f), problem.start(), tol=problem.residual_tol,
                           floor=problem.residual_floor)
        if sol.success:
            return force, sol.x
        force /= 2.0
    raise ConvergenceError(f"range end: no compressed state found at small forces down to Fhat = {force:.3g} "
                           f"({sol.message})", load=force, residual=sol.residual)


def _at_angle(problem, theta, path, jacobian=None):
    """newton.Solution of the augmented system at clamp angle ``theta``, seeded from ``path``
    (linear through its two points nearest to theta), or None if it fails or jumps branch."""
    near = sorted(path, key=lambda point: abs(point[0] - theta))[:2]
    guess = near[0][1]
    if len(near) > 1 and near[0][0] != near[1][0]:
        (t0, z0), (t1, z1) = near
        guess = z0 + (theta - t0) * (z1 - z0) / (t1 - t0)
    sol = newton.solve(lambda v: problem.residual(v[:2], v[2], theta), guess, tol=problem.residual_tol,
                       floor=problem.residual_floor, jacobian=jacobian)
    return sol if sol.success and problem.close(sol.x, guess, near[0][1]) else None


def _fold(problem, path, k):
    """The force maximum between path[k - 2] and path[k]: End(fold=True)."""
    lo, hi = path[max(k - 2, 0)][0], path[k][0]

    def force(theta):
        sol = _at_angle(problem, theta, path)
        return -math.inf if sol is None else sol.x[2]

    theta, peak = brent.maximum(force, lo, hi, xtol=_FOLD_XTOL)
    if not math.isfinite(peak):
        raise ConvergenceError(f"range end: no state solves near the force maximum at psi(1) in [{lo:.6g}, {hi:.6g}]")
    z = _at_angle(problem, theta, path).x
    branch = (*tuple(p for p in path if p[0] < theta), (theta, z))
    return End(force=float(peak), angle=float(theta), fold=True, path=branch)


def plate_end(problem, seed) -> End:
    """The ``End`` of the plate's ``problem`` (module docstring; ``PlateProblem.end``), from the solved ``seed``."""
    force, x = _first_state(problem, seed)
    theta = problem.clamp_angle(x, force)
    path = [(theta, np.array([x[0], x[1], force]))]
    step_max = (math.pi - theta) / 8.0
    step, jacobian = 0.5 * step_max, None
    while theta < math.pi:
        target = min(theta + step, math.pi)
        sol = _at_angle(problem, target, path[-2:], jacobian)
        if sol is None:
            step, jacobian = 0.5 * step, None
            if step < _MIN_STEP:
                lc = problem.stretch(path[-1][1][1])
                if problem.law.lock_margin(lc, lc) < _LOCKING:
                    return End(force=math.inf, angle=theta, fold=False, path=tuple(path), locks=True)
                raise ConvergenceError(f"range end: the continuation in the clamp angle stalled at psi(1) = "
                                       f"{theta:.10g} (Fhat = {path[-1][1][2]:.10g})", load=path[-1][1][2])
            continue
        theta, jacobian = target, sol.jacobian
        path.append((theta, sol.x))
        if path[-1][1][2] < path[-2][1][2]:
            return _fold(problem, path, len(path) - 1)
        step = min(1.5 * step, step_max)
    return End(force=float(path[-1][1][2]), angle=math.pi, fold=False, path=tuple(path))


def solve_on_branch(problem, force: float):
    """Unknowns x = (q, e) of the state at ``force`` (<= the end) found on the branch by the clamp
    angle: Brent's method on theta of Fhat(theta) - force, each Fhat(theta) an augmented solve.
    For forces near a fold, where continuation in the force stalls. None if it fails."""
    end = end_of(problem)
    path = list(end.path)
    forces = [z[2] for _, z in path]
    k = next((i for i, f in enumerate(forces) if f >= force), None)
    if k is None or k == 0:
        return None if k is None or forces[0] != force else path[0][1][:2]

    def miss(theta):
        sol = _at_angle(problem, theta, path)
        if sol is None:
            raise ConvergenceError(f"compression at force = {force!r}: no state at clamp angle {theta:.10g}")
        return sol.x[2] - force

    theta = brent.root(miss, path[k - 1][0], path[k][0], fa=forces[k - 1] - force, fb=forces[k] - force,
                       rtol=1e-14)
    return _at_angle(problem, theta, path).x[:2]
