"""Step 2 on the edge-fitted mesh: first contact, then plate-force or plate-height control.

The unknowns and equations are ``model``'s FITTED ones: the contact radius a
is a Newton unknown, closed by tangent contact, and the first element is the
flat contact zone (``geometry``).

First contact. At a = 0 the contact zone is empty and force control is
singular (F ~ a^2). Contact-radius control is regular there, so the first
state is solved at a small prescribed a_0 = min(A_FIRST, a_F / 2), where
a_F = sqrt(Fhat) / lambda_0 is the contact radius of the target force if the
pressure stayed P_I and the contact zone kept the pole stretch. Its guess is
the inflated state seen on the fitted mesh (``touch``): the inflated meridian
evaluated at the moved nodes, with the cap r < a_0 flattened onto the plate at
h = eta_I(a_0). A failure halves a_0.

Then the load is stepped (``continuation.follow``) under force control in
sigma = sqrt(F), in which the contact radius grows about linearly (F = P pi
rho(a)^2), or under height control in h; each step starts from the secant
extrapolation of the last two states, which the fitted mesh makes accurate
(the edge node moves with the edge, so the nodal values are smooth in the load).

The fluid is ``fill``: the volume row's ``model.Control`` (V_I and, for a gas,
its polytropic law), which each control here extends with its own target. A
path that gives up close to the rubber's locking says so (``steps.near_locking``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from .continuation import follow
from .geometry import evaluate, node_radii, place
from .model import FITTED, Control, Model, edge
from .newton import Tolerances
from .steps import near_locking, solve

__all__ = ["A_FIRST", "SMALLEST_FORCE", "first_contact", "force_path", "height_path", "plate_force_of", "touch"]

A_FIRST = 0.05  # largest contact radius of the first contact state
#: smallest force Fhat solved: below it the plate's balance, a difference of nodal forces of the
#: first free element, is lost in their round-off (measured: 1e-8 fails on fine meshes at Phat_I = 1.5)
SMALLEST_FORCE = 1e-7
_HALVINGS = 6


def touch(model: Model, inflated: np.ndarray, a: float) -> np.ndarray:
    """FITTED unknowns at contact radius ``a`` from the inflated (FREE) unknowns."""
    ref = model.ref
    points = node_radii(place(model.xi, ref, a, model.flat), ref)
    u = evaluate(place(model.xi, ref), ref, inflated[: model.dofs], points).ravel()
    h = float(u[edge(model) + 1])  # eta at the edge node
    u[model.tied()] = h
    u[0] = 0.0
    return np.concatenate([u, [inflated[model.dofs], h, a]])


def plate_force_of(model: Model, y: np.ndarray) -> float:
    """F = pi P rho(a)^2 (units E T R), the plate force of a converged FITTED state."""
    return float(np.pi * y[model.dofs] * y[edge(model)] ** 2)


def first_contact(model: Model, inflated: np.ndarray, fill: Control, a: float,
                  tol: Tolerances) -> tuple[np.ndarray, int]:
    """The contact state at radius ``a`` (or a halved one) from the inflated state; (y, iterations)."""
    total, first = 0, a
    for _ in range(_HALVINGS + 1):
        try:
            y, iterations = solve(model, FITTED, replace(fill, radius=a), touch(model, inflated, a), tol)
            return y, total + iterations
        except ConvergenceError as err:
            total += err.iterations
            last = err
            a *= 0.5
    raise ConvergenceError(f"first contact: Newton failed at every contact radius from a/R = {first:.3g} down to "
                           f"{2 * a:.3g}: {last}", load=a, iterations=total, residual=last.residual)


def force_path(model: Model, y0: np.ndarray, fill: Control, force: float, tol: Tolerances, unit: float = 1.0):
    """From a FITTED state y0 to the plate force ``force`` (units E T R), stepping in sqrt(F); (y, iterations).

    ``unit``: the force in messages is F / unit (pi Phat_I gives Fhat). If the stepping stalls at a
    maximum of the force (a limit point: past it the pocket has no state on this branch, for some
    alpha < 0 before the free part reaches the clamp plane), that is ``OutOfRangeError``.
    """

    def along(sigma, guess):
        return solve(model, FITTED, replace(fill, force=sigma**2), guess, tol)

    name = "force" if unit != 1.0 else "plate force F/(E T R)"
    total, y = 0, y0
    try:
        for _, y, iterations in follow(along, y0, np.sqrt(plate_force_of(model, y0)), np.sqrt(force), name=name,
                                       show=lambda sigma: sigma**2 / unit):
            total += iterations
    except ConvergenceError as err:
        near_locking(model, y, FITTED, err, f"{name} = {force / unit:.6g}", bounded=False)
        peak = _force_peak(model, y, fill, tol)
        if peak is None:
            raise
        raise OutOfRangeError(f"the plate force has a maximum, {name} = {peak / unit:.6g}, before the target "
                              f"{force / unit:.6g}: no compressed state on the first branch above it") from err
    return y, total


def _force_peak(model: Model, y: np.ndarray, fill: Control, tol: Tolerances, steps: int = 4) -> float | None:
    """The plate force's maximum if plate-height control, stepping down from y by 1e-3 of its height,
    finds the force falling within ``steps`` steps; None if it keeps rising or a step fails."""
    height, best = float(y[model.dofs + 1]), plate_force_of(model, y)
    for k in range(1, steps + 1):
        try:
            y, _ = solve(model, FITTED, replace(fill, height=height * (1.0 - 1e-3 * k)), y, tol)
        except (ConvergenceError, OutOfRangeError):
            return None
        force = plate_force_of(model, y)
        if force < best:
            return best
        best = force
    return None


def height_path(model: Model, y0: np.ndarray, fill: Control, height: float, tol: Tolerances):
    """From a FITTED state y0 to the plate height ``height`` (units R); (y, iterations)."""

    def along(h, guess):
        return solve(model, FITTED, replace(fill, height=h), guess, tol)

    total, y = 0, y0
    try:
        for _, y, iterations in follow(along, y0, float(y0[model.dofs + 1]), height, name="plate height h/R"):
            total += iterations
    except ConvergenceError as err:
        near_locking(model, y, FITTED, err, f"plate height h/R = {height:.6g}", bounded=True)
        raise
    return y, total
