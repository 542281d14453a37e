"""Step 2 under a curved indenter: first contact, then force or height control (``obstacle``'s equations).

As for the flat plate (``fitted``, ``curves``): the first state is solved at a small prescribed
contact radius a_0 (force control is singular at a = 0), from the inflated meridian seen on the
fitted mesh with the zone r < a_0 laid on the surface, h = eta_I(a_0) - z(rho_I(a_0)); a failure
halves a_0. The load is then stepped (``continuation.follow``) in sigma = sqrt(F) or in h; each
later force of a curve is one Newton solve from the extrapolation through the states before it
(``curves.predict``), stepping from the last state if that fails or leaves the model.
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

__all__ = ["touch", "first_contact", "force_path", "height_path", "curve", "at_height"]

_HALVINGS = 6


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
        except ConvergenceError as err:
            total += err.iterations
            last = err
            a *= 0.5
    raise ConvergenceError(f"first contact with the {fill.indenter.kind}: Newton failed at every contact radius "
                           f"from a/R = {first:.3g} down to {2 * a:.3g}: {last}", load=a, iterations=total,
                           residual=last.residual)


def force_path(model: Model, y0: np.ndarray, fill: Control, force: float, tol: Tolerances, unit: float):
    """From a WRAPPED state y0 to the indenter force ``force`` (units E T R), stepping in sqrt(F);
    (y, iterations). ``unit``: the force in messages is F / unit (pi Phat_I gives Fhat)."""

    def along(sigma, guess):
        return solve(model, replace(fill, force=sigma**2), guess, tol)

    start = np.sqrt(reaction(model, y0, surface(fill.indenter)))
    total, y = 0, y0
    for _, y, iterations in follow(along, y0, start, np.sqrt(force), name="force", show=lambda s: s**2 / unit):
        total += iterations
    return y, total


def height_path(model: Model, y0: np.ndarray, fill: Control, height: float, tol: Tolerances):
    """From a WRAPPED state y0 to the indenter height ``height`` (units R); (y, iterations)."""

    def along(h, guess):
        return solve(model, replace(fill, height=h), guess, tol)

    total, y = 0, y0
    for _, y, iterations in follow(along, y0, float(y0[model.dofs + 1]), height, name="indenter height h/R"):
        total += iterations
    return y, total


def _at_force(fhat: float, err: ConvergenceError) -> ConvergenceError:
    return ConvergenceError(f"compression at Fhat = {fhat!r}: {err}", load=err.load, iterations=err.iterations,
                            residual=err.residual)


def curve(model: Model, y_i: np.ndarray, inflated, fill: Control, forces, tol: Tolerances, progress=None) -> list:
    """Compressed states under the curved indenter of ``fill`` at the forces Fhat, from the inflated
    unknowns y_i (``curves.fitted_curve``'s rules, the smallest force included)."""
    unit = np.pi * inflated.pressure
    states, history = [], []
    for k, fhat in enumerate(forces):
        if fhat == 0.0:
            states.append(results.uncompressed(inflated, fill, "fitted"))
        else:
            if fhat < SMALLEST_FORCE:
                raise ConvergenceError(
                    f"force = {fhat!r} is below the smallest force the edge-fitted finite elements resolve "
                    f"({SMALLEST_FORCE:g}): the indenter's balance is lost in round-off")
            force = fhat * unit
            try:
                if not history:
                    a0 = min(A_FIRST, 0.5 * np.sqrt(fhat) / inflated.stretch_pole)
                    y, iterations = first_contact(model, y_i, fill, a0, tol)
                    y, more = force_path(model, y, fill, force, tol, unit)
                    iterations += more
                else:
                    try:
                        y, iterations = solve(model, replace(fill, force=force), predict(history, np.sqrt(force)),
                                              tol)
                    except (ConvergenceError, OutOfRangeError):
                        y, iterations = force_path(model, history[-1][1], fill, force, tol, unit)
            except ConvergenceError as err:
                raise _at_force(fhat, err) from err
            history.append((np.sqrt(force), y))
            states.append(wrapstates.state(model, y, iterations, inflated, fill, fhat))
        if progress is not None:
            progress(k + 1, len(forces))
    return states


def at_height(model: Model, y_i: np.ndarray, inflated, fill: Control, height: float, tol: Tolerances):
    """The compressed state with the indenter's lowest point at ``height``."""
    y, iterations = first_contact(model, y_i, fill, A_FIRST / 4, tol)
    y, more = height_path(model, y, fill, height, tol)
    fhat = reaction(model, y, surface(fill.indenter)) / (np.pi * inflated.pressure)
    return wrapstates.state(model, y, iterations + more, inflated, fill, fhat)
