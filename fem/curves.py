"""Compression curves: the forces of a curve solved in turn, each from the states before it.

Edge-fitted contact. The first force goes through first contact and a force
path (``fitted``). Each later force F_k is solved under force control in one
Newton solve from a predictor, the extrapolation in sigma = sqrt(F) through
the last states (linear through two, quadratic through three: sigma is the
natural parameter, the contact radius grows about linearly in it). All
states share the reference mesh, so their unknown vectors extrapolate
directly. If that solve fails or leaves the model, the force is reached by
stepping (``fitted.force_path``) from the last state, which cuts its steps.
The states are built by ``results`` (``capsulestates`` on the capsule: the
caller says which).
A force below ``fitted.SMALLEST_FORCE`` is not attempted (``ConvergenceError``
saying why): the plate's balance at the edge would be lost in round-off.

Penalty contact. The plate is lowered to the first force under height
control, then each force follows under force control, with
augmented-Lagrangian updates after each (``penalty``).

The fluid enters as ``fill``, the volume row's ``model.Control`` (V_I, and a
gas sealed at P_I, or none for a liquid), which every control of step 2 extends.
``progress(done, total)``, if given, is called after each force. A force
whose solve fails is named in the ``ConvergenceError`` (``_at_force``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from . import fitted, penalty, results
from .model import FITTED, PENALTY, Control, Model
from .newton import Tolerances
from .steps import solve

__all__ = ["fitted_curve", "fitted_height", "penalty_curve", "penalty_height", "predict"]


def predict(history: list[tuple[float, np.ndarray]], sigma: float) -> np.ndarray:
    """Extrapolation through the last (up to three) (sigma, y) of ``history`` to ``sigma`` (Lagrange)."""
    points = history[-3:]
    knots = [s for s, _ in points]
    if len(set(knots)) < len(knots):
        return points[-1][1]
    out = np.zeros_like(points[-1][1])
    for i, (s_i, y_i) in enumerate(points):
        weight = np.prod([(sigma - s_j) / (s_i - s_j) for j, s_j in enumerate(knots) if j != i])
        out += weight * y_i
    return out


def _at_force(fhat: float, err: ConvergenceError) -> ConvergenceError:
    """``err`` saying the force Fhat it was solving for."""
    return ConvergenceError(f"compression at Fhat = {fhat!r}: {err}", load=err.load, iterations=err.iterations,
                            residual=err.residual)


def _first_radius(model: Model, inflated, fhat: float) -> float:
    return min(fitted.A_FIRST, 0.5 * np.sqrt(fhat) / inflated.stretch_pole)


def _next_fitted(model, history, fill, force, tol, unit):
    sigma = np.sqrt(force)
    try:
        return solve(model, FITTED, replace(fill, force=force), predict(history, sigma), tol)
    except (ConvergenceError, OutOfRangeError) as err:
        y, iterations = fitted.force_path(model, history[-1][1], fill, force, tol, unit)
        return y, iterations + err.iterations if isinstance(err, ConvergenceError) else iterations


def fitted_curve(model: Model, y_i: np.ndarray, inflated, fill: Control, forces, tol: Tolerances,
                 progress=None, builder=results, deeper=None) -> list:
    """Compressed states (edge-fitted contact) at the forces Fhat, from the inflated unknowns y_i; ``builder``: the
    module that builds them (``results``; ``capsulestates`` on the capsule). ``deeper(force, fhat, end)``, if given:
    (y, iterations) of a force (units E T R) past the ``end`` of the branch the stepping followed (the end its
    refusal quotes), on another branch (a capsule's, ``descent``); the states after it follow that branch."""
    p_i, states = inflated.pressure, []
    history: list[tuple[float, np.ndarray]] = []  # (sqrt(force), unknowns) of the states solved
    for k, fhat in enumerate(forces):
        if fhat == 0.0:
            states.append(builder.uncompressed(inflated, fill, FITTED))
        else:
            if fhat < fitted.SMALLEST_FORCE:
                raise ConvergenceError(
                    f"force = {fhat!r} is below the smallest force the edge-fitted finite elements resolve "
                    f"({fitted.SMALLEST_FORCE:g}): the plate's balance is lost in round-off (the shooting solver "
                    "resolves it)")
            force = fhat * np.pi * p_i
            try:
                if not history:
                    a0 = _first_radius(model, inflated, fhat)
                    y, iterations = fitted.first_contact(model, y_i, fill, a0, tol)
                    y, more = fitted.force_path(model, y, fill, force, tol, np.pi * p_i)
                    iterations += more
                else:
                    y, iterations = _next_fitted(model, history, fill, force, tol, np.pi * p_i)
            except ConvergenceError as err:
                raise _at_force(fhat, err) from err
            except OutOfRangeError as err:
                if deeper is None or err.end is None:
                    raise
                y, iterations = deeper(force, fhat, err.end)
                history.clear()  # the states of the branch left behind do not extrapolate to this one
            history.append((np.sqrt(force), y))
            states.append(builder.fitted_state(model, y, iterations, inflated, fill, fhat, tol))
        if progress is not None:
            progress(k + 1, len(forces))
    return states


def fitted_height(model: Model, y_i: np.ndarray, inflated, fill: Control, height: float, tol: Tolerances,
                  builder=results):
    """The compressed state (edge-fitted contact) with the plate at ``height``; ``builder`` as for ``fitted_curve``."""
    y, iterations = fitted.first_contact(model, y_i, fill, fitted.A_FIRST / 4, tol)
    y, more = fitted.height_path(model, y, fill, height, tol)
    fhat = fitted.plate_force_of(model, y) / (np.pi * inflated.pressure)
    return builder.fitted_state(model, y, iterations + more, inflated, fill, fhat, tol)


def _touching(model: Model, y_i: np.ndarray, inflated) -> np.ndarray:
    """PENALTY unknowns of the inflated state with the plate touching the pole."""
    return np.concatenate([y_i, [inflated.height]])


def penalty_curve(model: Model, y_i: np.ndarray, inflated, fill: Control, forces, tol: Tolerances, augmented: bool,
                  progress=None) -> list:
    """Compressed states (penalty contact) at the forces Fhat."""
    p_i = inflated.pressure
    lam = np.zeros((model.elements, model.ref.t.size))
    states, y, in_contact = [], _touching(model, y_i, inflated), False
    for k, fhat in enumerate(forces):
        if fhat == 0.0:
            states.append(results.uncompressed(inflated, fill, PENALTY))
        else:
            force = fhat * np.pi * p_i
            try:
                if in_contact:
                    y, iterations = penalty.force_path(model, y, fill, force, lam, tol)
                else:
                    y, iterations = penalty.press_to_force(model, _touching(model, y_i, inflated), fill, force,
                                                           lam, tol)
                if augmented:
                    y, lam, more = penalty.augment(model, y, replace(fill, force=force), lam, tol)
                    iterations += more
            except ConvergenceError as err:
                raise _at_force(fhat, err) from err
            states.append(results.penalty_state(model, y, lam, iterations, inflated, fill, fhat, tol))
            in_contact = True
        if progress is not None:
            progress(k + 1, len(forces))
    return states


def penalty_height(model: Model, y_i: np.ndarray, inflated, fill: Control, height: float, tol: Tolerances,
                   augmented: bool):
    """The compressed state (penalty contact) with the plate at ``height``."""
    lam = np.zeros((model.elements, model.ref.t.size))
    y, iterations = penalty.press_to_height(model, _touching(model, y_i, inflated), fill, height,
                                            lam, tol)
    if augmented:
        y, lam, more = penalty.augment(model, y, replace(fill, height=height), lam, tol)
        iterations += more
    return results.penalty_state(model, y, lam, iterations, inflated, fill, None, tol)
