"""Shared solving steps: one controlled solve, the starting dome, landing on a target, locking.

``solve`` is Newton on the bordered system (``model``, ``newton``) followed by
the range check (``check_range``), which says where a converged state is
outside the membrane model (``OutOfRangeError``).

A clamped sheet: a free part below the clamp plane. Under pressure the free
meridian is convex, so as the plate comes down it first reaches the clamp
plane at the clamp itself, where its tangent turns horizontal (the force where
that happens ends the model's range); past it the meridian dips below the
plane and comes up to the clamp. The check is therefore the sign of the
tangent's vertical component at the clamp, t_eta(1) = (R_eta - pi P) /
|(R_rho, R_eta - pi P)| from the clamp reaction (``post``: a flux, accurate
like the energy), positive meaning outside; and, for safety, eta < 0 at any
node other than the clamp.

A meridian ending on a plane of symmetry (the capsule), pressed by the plate
(FITTED): a meridional tension at the contact edge that is not positive
(``check_edge``). The free part's vertical balance, cut at a circle of radius
rho, 2 pi rho T_1 sin(psi) = pi P (rho^2 - rho(a)^2) (F = pi P rho(a)^2),
makes T_1 positive wherever the free meridian rises outwards (0 < psi < pi,
rho > rho(a)); only at the edge, where both sides vanish, can it fall to 0,
and as it does the free part leaves the plate with the unbounded curvature
P / T_1: the end of the range (``pocket.core.errors.CAPSULE_EDGE``, where the
shooting solver ends it too). The discrete states go on past it, their edge
compressive, so the check is the edge's T_1 from the contact zone's flux
(``post.edge_tension``: the quadrature points of the first free element, which
cannot resolve that corner, swing negative well inside the range); under the
plate a compressive tension is a slack patch, flagged wrinkled, not checked.

``land`` finds the state where a monitored quantity f(y) (the pressure along a
volume path) equals a target, given two converged states bracketing it: Newton
under target control from the linear interpolation, and if that fails,
bisection of the bracket under the path's own control until it succeeds.
Interpolating two distant converged states can give a slack meridian (|x'| < 1
near the clamp: no tension, a soft mode and a wild Newton step), so a
converged endpoint is also tried as the guess.

``near_locking``: a rubber whose energy exists only below a locking stretch
(Gent: I1 - 3 < Jm) returns NaN derivatives past it, so a load step that
would cross it fails and is cut (``continuation``); a load path that gives up
with its last state within LOCKING of locking (1 - (I1 - 3)/Jm at a quadrature
point) has met the end of the rubber's domain. For a target of the geometry
(a volume, a plate height), which locking bounds, that is OutOfRangeError;
for a pressure or a force, which diverge at locking and so are never past it,
a ConvergenceError that says how near locking it stopped.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from pocket.core import smallstrain
from pocket.core.errors import CAPSULE_EDGE, CLAMP_PLANE, ConvergenceError, OutOfRangeError
from pocket.core.geometries import Symmetry

from .geometry import node_radii, place
from .model import FITTED, FREE, Control, Model, conform, edge, fields, linearize, placement
from .newton import Tolerances, newton
from .post import edge_tension, reaction

__all__ = ["LOCKING", "check_clamp", "check_edge", "check_range", "dome", "increment", "land", "near_locking",
           "scales", "solve"]

_ETA_FLOOR = -1e-12  # round-off below the clamp plane is not a range violation
_SLOPE_FLOOR = 1e-12  # nor a tangent at the clamp rising by round-off
_TINY = 1e-300  # a scale is never zero
#: lock margin 1 - (I1 - 3)/Jm below which a load path that gave up has met the rubber's locking
LOCKING = 1e-2


def increment(model: Model, mode: str) -> Callable:
    """dy from the linear solve's (nodal, scalar) parts: the tied dofs move with the plate (FITTED)."""
    tied = model.tied() if mode == FITTED else None

    def join(y, x, s):
        if tied is not None:
            x = x.copy()
            x[tied] = s[1]
        return np.concatenate([x, s])

    return join


def solve(model: Model, mode: str, control: Control, guess: np.ndarray, tol: Tolerances,
          multiplier=0.0) -> tuple[np.ndarray, int]:
    """Newton under ``control`` from ``guess`` (its prescribed dofs reset: ``model.conform``); (y, iterations).

    OutOfRangeError if the state is outside the membrane model (``check_range``)."""
    guess = conform(model, guess, mode)
    if mode == FITTED or control.force is not None:
        control = dataclasses.replace(control, scale=_plate_scale(model, guess, mode, control))
    result = newton(lambda z: linearize(model, z, mode, control, multiplier), guess, tol, increment(model, mode),
                    scales(model, guess, mode))
    check_range(model, result.y, mode, multiplier)
    return result.y, result.iterations


def check_range(model: Model, y: np.ndarray, mode: str, multiplier=0.0) -> None:
    """OutOfRangeError if the state y is outside the membrane model (module docstring): ``check_clamp`` on a clamped
    sheet, ``check_edge`` on a meridian ending on a plane of symmetry pressed by the plate (FITTED)."""
    if not isinstance(model.geometry.end, Symmetry):
        check_clamp(model, y, mode, multiplier)
    elif mode == FITTED:
        check_edge(model, y)


def check_edge(model: Model, y: np.ndarray) -> None:
    """OutOfRangeError if the meridional tension at the contact edge of the FITTED state y is not positive (module
    docstring). A NaN (a degenerate edge, rho(a) <= 0) is left to the states' own checks (``ConvergenceError``)."""
    tension = edge_tension(model, y)
    if tension <= 0.0:
        raise OutOfRangeError(f"{CAPSULE_EDGE} (T_1 = {tension:.3g} E T at the contact edge of the finite elements' "
                              f"state, at Phat = {y[model.dofs]:.6g})")


def check_clamp(model: Model, y: np.ndarray, mode: str, multiplier=0.0) -> None:
    """OutOfRangeError if the free part of the state y comes below the clamp plane (module docstring). A meridian
    that ends on a plane of symmetry (the capsule's equator) has no clamp to come below: nothing to check."""
    if isinstance(model.geometry.end, Symmetry):
        return
    rows = reaction(model, y, mode, multiplier)
    rise = rows[-1] - np.pi * y[model.dofs]  # 2 pi T1 t_eta at the clamp
    slope = rise / np.hypot(rows[-2], rise)
    eta = y[1: model.dofs - 2: 2]
    if slope > _SLOPE_FLOOR or eta.min() < _ETA_FLOOR:
        raise OutOfRangeError(
            f"{CLAMP_PLANE} (its tangent at the clamp rises at {slope:.3g}, min eta/R = {eta.min():.3g}, "
            f"at Phat = {y[model.dofs]:.6g}), outside the membrane model"
        )


def scales(model: Model, y: np.ndarray, mode: str) -> np.ndarray:
    """What each unknown's increment is measured against: eta and h the sheet's height, rho its
    largest radial displacement, P itself, a one (Newton's tolerance is relative to these)."""
    n = model.dofs
    radii = node_radii(placement(model, y, mode), model.ref)
    rho, eta = y[0:n:2], y[1:n:2]
    out = np.ones_like(y)
    out[0:n:2] = max(float(np.abs(rho - radii).max()), _TINY)
    out[1:n:2] = max(float(np.abs(eta).max()), _TINY)
    out[n] = max(abs(float(y[n])), _TINY)
    if mode != FREE:
        out[n + 1] = out[1]
    return out


def _plate_scale(model: Model, y: np.ndarray, mode: str, control: Control) -> float:
    """The plate force the plate rows are measured against: the target, or pi P rho(a)^2 of the guess."""
    if control.force is not None:
        return control.force
    return float(np.pi * y[model.dofs] * y[edge(model)] ** 2)


def dome(model: Model, pressure: float) -> np.ndarray:
    """The small-strain dome of the paper's eqs (14)-(15), (18) at ``pressure`` (FREE unknowns).

    lambda_0 - 1 = (Phat / (4 sqrt 6))^(2/3), rho = r (lambda_0 - (lambda_0 - 1) r^2),
    eta = sqrt(3 (lambda_0 - 1) / 2) (1 - r^2).

    A prestretched sheet is taut: where it gives the smaller strain, the dome is the paraboloid of its
    tension N_0 = n_0 E T, eta = H (1 - r^2) with H = Phat / (4 n_0), and the same radial form with
    lambda_0 - 1 = 0.7 H^2 (linear in-plane elasticity about the prestressed sheet,
    ``pocket.shooting.inflation``).
    """
    e = smallstrain.pole_strain(pressure)
    height = np.sqrt(1.5 * e)
    if model.law.prestretch != 1.0:
        taut = pressure / (4.0 * model.law.flat_tension)
        if 0.7 * taut * taut < e:
            e, height = 0.7 * taut * taut, taut
    r = node_radii(place(model.xi, model.ref), model.ref)
    u = np.column_stack([r * (1 + e - e * r**2), height * (1 - r**2)]).ravel()
    return np.concatenate([u, [pressure]])


def land(
    along: Callable[[float, np.ndarray], tuple[np.ndarray, int]],
    at_target: Callable[[np.ndarray], tuple[np.ndarray, int]],
    a: tuple[float, np.ndarray],
    b: tuple[float, np.ndarray],
    f: Callable[[np.ndarray], float],
    target: float,
    max_bisections: int = 30,
) -> tuple[np.ndarray, int]:
    """The state with f = target between a = (s_a, y_a) and b = (s_b, y_b).

    f(y_a) < target <= f(y_b); ``along(s, guess)`` solves at path parameter s,
    ``at_target(guess)`` under target control. Returns (y, iterations).
    """
    total = 0
    for _ in range(max_bisections):
        (s_a, y_a), (s_b, y_b) = a, b
        theta = (target - f(y_a)) / (f(y_b) - f(y_a))
        nearer = y_a if theta < 0.5 else y_b
        for guess in (y_a + theta * (y_b - y_a), nearer):
            try:
                y, iterations = at_target(guess)
                return y, total + iterations
            except ConvergenceError as err:
                last = err
        s_m = 0.5 * (s_a + s_b)
        y_m, iterations = along(s_m, nearer)
        total += iterations
        a, b = ((s_m, y_m), b) if f(y_m) < target else (a, (s_m, y_m))
    raise ConvergenceError(
        f"could not land on the target {target:.6g} after {max_bisections} bisections: {last}",
        load=target,
        iterations=last.iterations,
        residual=last.residual,
    )





def near_locking(model: Model, y: np.ndarray, mode: str, err: ConvergenceError, target: str, bounded: bool) -> None:
    """Raise, from ``err``, the failure of a load path towards ``target`` whose last state ``y`` is within
    LOCKING of the rubber's locking: OutOfRangeError if locking bounds the target (``bounded``), else a
    ConvergenceError saying so (module docstring). Returns if the state is not near locking."""
    w = fields(model, y, mode)
    margin = model.law.lock_margin(w.l1, w.l2)
    if not margin < LOCKING:
        return
    where = (f"the sheet is within {margin:.2g} of the rubber's locking (1 - (I1 - 3)/Jm, {model.law.label}) at "
             f"the last state reached")
    if bounded:
        raise OutOfRangeError(f"{target} is not reached before the rubber locks: {where}") from err
    raise ConvergenceError(f"{err} ({where})", load=err.load, iterations=err.iterations, residual=err.residual) from err
