"""Step 2 under a curved indenter: first contact, then force or height control (``obstacle``'s equations).

As for the flat plate (``fitted``, ``curves``): the first state is solved at a small prescribed
contact radius a_0 (force control is singular at a = 0), from the inflated meridian seen on the
fitted mesh with the zone r < a_0 laid on the surface, h = eta_I(a_0) - z(rho_I(a_0)); a failure
halves a_0. The load is then stepped (``continuation.follow``) in sigma = sqrt(F) or in h; each
later force of a curve is one Newton solve from the extrapolation through the states before it
(``curves.predict``), stepping from the last state if that fails or leaves the model.

A sphere's surface ends at its equator, where its slope diverges: a path that gives up with the
contact edge within EQUATOR of it has met the end of the model's range (the sheet would wrap past
the equator), an ``OutOfRangeError`` quoting the last force (or height) reached.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from . import results, wrapstates
from .continuation import follow
from .curves import predict
from .fitted import A_FIRST, SMALLEST_FORCE
from .geometry import contact_elements, evaluate, node_radii, place
from .model import Control, Model
from .newton import Tolerances
from .obstacle import conform, reaction, solve
from .surfaces import surface

__all__ = ["at_height", "curve", "first_contact", "first_radius", "force_path", "height_path", "touch"]

_HALVINGS = 6
#: a path that gives up with its contact edge within this fraction of the surface's reach has met
#: a sphere's equator, where the zone's slope z' diverges (measured: rho_c/R_s = 0.99993 converges)
EQUATOR = 1e-3


def touch(model: Model, inflated: np.ndarray, fill: Control, a: float) -> np.ndarray:
    """WRAPPED unknowns at contact radius ``a`` from the inflated (FREE) unknowns."""
    ref, k = model.ref, contact_elements(model.elements)
    surf = surface(fill.indenter)
    points = node_radii(place(model.xi, ref, a, k), ref)
    u = evaluate(place(model.xi, ref), ref, inflated[: model.dofs], points).ravel()
    e = 2 * ref.order * k
    h = float(u[e + 1] - surf.height(u[e]))
    u[0] = 0.0
    return conform(model, np.concatenate([u, [inflated[model.dofs], h, a]]), surf)


def first_contact(model: Model, inflated: np.ndarray, fill: Control, a: float,
                  tol: Tolerances) -> tuple[np.ndarray, int]:
    """The contact state at radius ``a`` (or a halved one) from the inflated state; (y, iterations)."""
    total, first = 0, a
    for _ in range(_HALVINGS + 1):
        try:
            y, iterations = solve(model, replace(fill, radius=a), touch(model, inflated, fill, a), tol)
            return y, total + iterations
        except (ConvergenceError, OutOfRangeError) as err:  # a first contact out of range is a step too long
            total += getattr(err, "iterations", 0)
            last = err
            a *= 0.5
    raise ConvergenceError(f"first contact with the {fill.indenter.name}: Newton failed at every contact radius "
                           f"from a/R = {first:.3g} down to {2 * a:.3g}: {last}", load=a, iterations=total,
                           residual=getattr(last, "residual", float("nan")))


def first_radius(inflated, fill: Control, largest: float) -> float:
    """The first contact radius: ``largest``, and at most a quarter of the surface's reach seen from the
    inflated pole (the zone's radius, about lambda_0 a, then stays well inside the cap)."""
    return min(largest, 0.25 * surface(fill.indenter).reach / inflated.stretch_pole)


def force_path(model: Model, y0: np.ndarray, fill: Control, force: float, tol: Tolerances, unit: float):
    """From a WRAPPED state y0 to the indenter force ``force`` (units E T R), stepping in sqrt(F);
    (y, iterations). ``unit``: the force in messages is F / unit (pi Phat_I gives Fhat)."""

    def along(sigma, guess):
        return solve(model, replace(fill, force=sigma**2), guess, tol)

    surf = surface(fill.indenter)
    start = np.sqrt(reaction(model, y0, surf))
    total, y = 0, y0
    try:
        for _, y, iterations in follow(along, y0, start, np.sqrt(force), name="force", show=lambda s: s**2 / unit):
            total += iterations
    except ConvergenceError as err:
        reached = reaction(model, y, surf) / unit
        _at_equator(model, y, surf, err, f"force = {force / unit:.6g}", f"force = {reached:.6g}")
        raise
    return y, total


def _at_equator(model: Model, y: np.ndarray, surf, err: ConvergenceError, target: str, reached: str) -> None:
    """Raise OutOfRangeError from ``err`` if the last state y of a path that gave up has its contact edge
    within EQUATOR of the surface's reach: the sheet wraps past a sphere's equator there (module docstring)."""
    rho_c = float(y[2 * model.order * contact_elements(model.elements)])
    if rho_c > (1.0 - EQUATOR) * surf.reach:
        raise OutOfRangeError(f"{target} is beyond the model's range, which ends near {reached}: there the sheet "
                              f"wraps past {surf.end} (rho_c/R = {rho_c:.6f} of its {surf.reach:.6g}, at the last "
                              "state reached), outside the model") from err


def height_path(model: Model, y0: np.ndarray, fill: Control, height: float, tol: Tolerances):
    """From a WRAPPED state y0 to the indenter height ``height`` (units R); (y, iterations)."""

    def along(h, guess):
        return solve(model, replace(fill, height=h), guess, tol)

    total, y = 0, y0
    try:
        for _, y, iterations in follow(along, y0, float(y0[model.dofs + 1]), height, name="indenter height h/R"):
            total += iterations
    except ConvergenceError as err:
        _at_equator(model, y, surface(fill.indenter), err, f"indenter height h/R = {height:.6g}",
                    f"h/R = {y[model.dofs + 1]:.6g}")
        raise
    return y, total


def _at_force(fhat: float, err: ConvergenceError) -> ConvergenceError:
    return ConvergenceError(f"compression at Fhat = {fhat!r}: {err}", load=err.load, iterations=err.iterations,
                            residual=err.residual)


def curve(model: Model, y_i: np.ndarray, inflated, fill: Control, forces, tol: Tolerances, progress=None) -> list:
    """Compressed states under the curved indenter of ``fill`` at the forces Fhat, from the inflated
    unknowns y_i (``curves.fitted_curve``'s rules, the smallest force included)."""
    unit = np.pi * inflated.pressure
    states: list = []
    history: list[tuple[float, np.ndarray]] = []
    for k, fhat in enumerate(forces):
        if fhat == 0.0:
            states.append(results.uncompressed(inflated, fill, "fitted"))
        else:
            if fhat < SMALLEST_FORCE:
                raise ConvergenceError(
                    f"force = {fhat!r} is below the smallest force the edge-fitted finite elements resolve "
                    f"({SMALLEST_FORCE:g}): the indenter's balance is lost in round-off")
            force = fhat * unit
            state = None  # the state at fhat, once known
            try:
                if not history:
                    y, iterations = first_contact(model, y_i, fill, first_radius(inflated, fill, min(
                        A_FIRST, 0.5 * np.sqrt(fhat) / inflated.stretch_pole)), tol)
                    y, more = force_path(model, y, fill, force, tol, unit)
                    iterations += more
                else:
                    try:
                        y, iterations = solve(model, replace(fill, force=force), predict(history, np.sqrt(force)),
                                              tol)
                        state = wrapstates.state(model, y, iterations, inflated, fill, fhat, tol)
                        _same_branch(state, states[-1])
                    except (ConvergenceError, OutOfRangeError):
                        state = None
                        y, iterations = force_path(model, history[-1][1], fill, force, tol, unit)
            except ConvergenceError as err:
                raise _at_force(fhat, err) from err
            history.append((np.sqrt(force), y))
            states.append(state or wrapstates.state(model, y, iterations, inflated, fill, fhat, tol))
        if progress is not None:
            progress(k + 1, len(forces))
    return states


def _same_branch(state, before) -> None:
    """A ConvergenceError if ``state``, solved in one jump from the curve's predictor, is wrinkled where the
    state ``before`` it on the curve was not: Newton then found a spurious root (measured: Mooney-Rivlin in
    a gas under a sphere of radius 2R, Fhat 0.3 to 1 on 256 elements, a/R 0.48345 against shooting's
    0.48391 and T_1 = -0.64 E T beside the edge), which the stepped path from ``before`` does not."""
    if state.wrinkled and not before.wrinkled:
        raise ConvergenceError(f"the jump to Fhat = {state.force!r} found a wrinkled state from an unwrinkled one")


def at_height(model: Model, y_i: np.ndarray, inflated, fill: Control, height: float, tol: Tolerances):
    """The compressed state with the indenter's lowest point at ``height``."""
    y, iterations = first_contact(model, y_i, fill, first_radius(inflated, fill, A_FIRST / 4), tol)
    y, more = height_path(model, y, fill, height, tol)
    fhat = reaction(model, y, surface(fill.indenter)) / (np.pi * inflated.pressure)
    return wrapstates.state(model, y, iterations + more, inflated, fill, fhat, tol)
