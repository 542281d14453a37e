r"""The end of the compression range under a curved indenter: the largest force the pocket's first branch carries.

Four things end the model as the indenter presses further (``pocket.shooting.surface``; the words of each
are its problem's ``END``, ``POLE`` and ``TOUCH``):

- the sheet would wrap past the end of the surface: a sphere's equator (phi_c = pi/2), where its lower cap
  ends and the contact zone's shot stops (``integrator.FOLD``, psi = -pi/2); a profile's last radius, or
  where its slope turns vertical (``Surface.end_margin``);
- the free sheet would reach the clamp plane: psi(1) = pi, as under the plate
  (``pocket.shooting.plateend``); shots may turn past pi, so this margin is smooth across it;
- the indenter's lowest point, and the sheet's pole on it, would reach the clamp plane (h = 0): a small
  sphere pushed deep, whose cap dips below the clamp before the free sheet does;
- the free sheet would touch the indenter outside the contact zone. For a convex surface this cannot come
  first: the free sheet leaves the edge tangent to the surface and, while it rises (psi < 0), normal
  equilibrium turns it down (psi' = lambda_1 (p - t2 sin(psi) / rho) / t1 > 0) while the convex
  surface turns up, so the gap grows; once it descends it is below the contact edge and the surface
  above it. It is watched all the same, in every state the search solves: a state with the free sheet
  inside the indenter is outside the model. Its margin is not the smallest gap, which is zero at the
  contact edge by tangency in every state, but that gap only where it is negative (else inf), so that
  the tangency is not mistaken for an end.

A force maximum (a fold) may come first, as under the plate (``pocket.shooting.plateend``: e.g. a
softening Mooney-Rivlin rubber, alpha = -0.5 at Phat_I = 0.1): past it the continuation in the force
stalls with every margin well inside the model. The branch is then continued in the indenter's height
h, which keeps falling through the fold: unknowns z = (x, Fhat), the force-controlled residuals and
(h(z) - h)/H0, steps in h growing from ``_FOLD_STEP`` H0. Once the force falls, its maximum over h is
located by golden sections (``brent.maximum``) to ``_FOLD_XTOL`` in h (the force, flat there, to its
square), and the end is that maximum (``End.fold``), with the branch in h kept as ``End.path`` for
``on_branch``: forces near the fold, where continuation in the force cannot go, are solved by Brent's
method on h of Fhat(h) - Fhat.

The end, computed. From a state at a small force, the force is continued with steps doubled after each
success (each state solved by ``newton`` from a secant prediction) while every margin
(``SurfaceProblem.margins``: the surface's end margin, pi - psi(1), h, the smallest gap) stays positive; a step whose
state does not solve or breaks a margin is halved, until it is below ``_RTOL`` of the force. The end is
then the last force solved, within that relative width, and its reason the margin nearest to zero
there (scaled: the end margin by the surface's scale, the clamp angle by pi, the height and the gap by the
inflated dome's height). A
search that stalls with every margin above ``_NEAR`` has met a fold (below) or, if none is found, a
solver failure (ConvergenceError). A force that grows past ``_FORCE_MAX`` without an end (a rubber that
locks) leaves the range without end (inf). Computed once per pocket and indenter (``end.end_of``
caches it).
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.errors import CLAMP_PLANE, ConvergenceError

from . import brent, newton
from .end import End, end_of

__all__ = ["end_of_surface", "on_branch"]

_START_FORCE = 1e-2  # the first state (halved until it solves)
_RTOL = 1e-10  # relative width of the force bracket at the end
_NEAR = 1e-3  # scaled margin below which a stalled search has reached an end of the model
_FORCE_MAX = 1e6  # force beyond which the range has no end
_FOLD_STEP = 1e-4  # first step in the height past a stall, relative to the inflated height
_FOLD_STEPS = 200  # steps in the height before a stall is declared no fold
_FOLD_XTOL = 1e-7  # width in h/H0 to which a force maximum is located (the force to ~1e-14)


def _solve(problem, force, guess, jacobian=None):
    """newton.Solution at ``force`` from ``guess``, or None if it fails."""
    sol = newton.solve(lambda x: problem.residual(x, force), guess, tol=problem.residual_tol,
                       floor=problem.residual_floor, jacobian=jacobian)
    return sol if sol.success and problem.close(sol.x, guess, guess) else None


def _scaled(problem, margins) -> dict[str, float]:
    """The margins in comparable units (``problem.scales``: the end margin by the surface's scale, the clamp
    angle by pi, the lengths by the inflated height)."""
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


def end_of_surface(problem, seed=None) -> End:
    """The ``End`` of the curved indenter's ``problem`` (module docstring); ``seed``: a solved (force, x) or None."""
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
        fold = _fold(problem, force, x)
        if fold is not None:
            return fold
        raise ConvergenceError(f"range end ({problem.label}): the continuation in the force stalled at Fhat = "
                               f"{force:.10g}, short of every end of the model and of a force maximum (scaled margins "
                               + ", ".join(f"{k}: {v:.3g}" for k, v in margins.items()) + ")", load=force)
    return End(force=float(force), angle=math.pi - margins[CLAMP_PLANE] * math.pi, fold=False, path=(),
               reason=reason)


def _height(problem, z) -> float:
    """The indenter's height h (units R) of the state z = (x, Fhat)."""
    return -float(problem.shoot(z[:-1], z[-1])[1][1])


def _at_height(problem, height, path, jacobian=None):
    """newton.Solution z = (x, Fhat) of the state with the indenter at ``height``, seeded linearly from the two
    points of ``path`` ((h, z)) nearest to it; None if it fails or breaks a margin."""
    near = sorted(path, key=lambda point: abs(point[0] - height))[:2]
    guess = near[0][1]
    if len(near) > 1 and near[0][0] != near[1][0]:
        (h0, z0), (h1, z1) = near
        guess = z0 + (height - h0) * (z1 - z0) / (h1 - h0)
    scale = problem.inflated.height

    def residual(z):
        out = problem.residual(z[:-1], z[-1])
        return None if out is None else np.append(out, (_height(problem, z) - height) / scale)

    sol = newton.solve(residual, guess, tol=problem.residual_tol, floor=problem.residual_floor, jacobian=jacobian)
    if not (sol.success and problem.close(sol.x, guess, near[0][1])):
        return None
    return sol if min(problem.margins(sol.x[-1], sol.x[:-1]).values()) > 0.0 else None


def _fold(problem, force, x) -> End | None:
    """The force maximum on the branch past the stalled state (``force``, x), by continuation in the height
    (module docstring); None if the force does not fall within ``_FOLD_STEPS`` steps."""
    z = np.array([*x, force])
    path = [(_height(problem, z), z)]
    step, jacobian = _FOLD_STEP * problem.inflated.height, None
    for _ in range(_FOLD_STEPS):
        target = path[-1][0] - step
        sol = _at_height(problem, target, path[-2:], jacobian)
        if sol is None:
            step, jacobian = 0.5 * step, None
            if step < _FOLD_XTOL * problem.inflated.height:
                return None
            continue
        path.append((target, sol.x))
        jacobian = sol.jacobian
        if sol.x[-1] < path[-2][1][-1]:
            return _peak(problem, path)
        step *= 1.5
    return None


def _peak(problem, path) -> End:
    """The End at the force maximum between path[-3] (or path[0]) and path[-1], whose force fell."""
    lo, hi = path[-1][0], path[max(len(path) - 3, 0)][0]

    def force(h):
        sol = _at_height(problem, h, path)
        return -math.inf if sol is None else sol.x[-1]

    height, peak = brent.maximum(force, lo, hi, xtol=_FOLD_XTOL * problem.inflated.height)
    if not math.isfinite(peak):
        raise ConvergenceError(f"range end ({problem.label}): no state solves near the force maximum at h in "
                               f"[{lo:.6g}, {hi:.6g}]")
    z = _at_height(problem, height, path).x
    branch = (*tuple(p for p in path if p[0] > height), (height, z))
    return End(force=float(peak), angle=problem.clamp_angle(z[:-1], z[-1]), fold=True, path=branch)


def on_branch(problem, force):
    """Unknowns x at ``force`` found on the branch past the force-continuation's reach, by the height: Brent's
    method on h of Fhat(h) - ``force`` between the two points of the end's branch that bracket it (its
    height path ends at the fold). None if there is no such bracket or a solve fails."""
    path = end_of(problem).path
    forces = [z[-1] for _, z in path]
    k = next((i for i, f in enumerate(forces) if f >= force), None)
    if k is None or k == 0:
        return None if k is None or forces[0] != force else path[0][1][:-1]

    def miss(h):
        sol = _at_height(problem, h, path)
        if sol is None:
            raise ConvergenceError(f"compression at force = {force!r} ({problem.label}): no state with the "
                                   f"indenter at h = {h:.10g}", load=force)
        return sol.x[-1] - force

    height = brent.root(miss, path[k - 1][0], path[k][0], fa=forces[k - 1] - force, fb=forces[k] - force,
                        rtol=1e-14)
    return _at_height(problem, height, path).x[:-1]
