"""Step 2, compression: the inflated pocket pressed by a frictionless indenter (the flat plate or a sphere,
``contact``; "the plate" below) at fixed fluid.

The fluid row holds the volume the fluid takes at its pressure (``fluids.Fluid.volume_ratio``:
V_I for a liquid, the polytropic law for a gas sealed at P_I); the plate touches the upper
surface's nodes of the active set (``newton.contact``). The first contact is the pole's node with
the plate at the inflated pole's height and no force. Forces are reached in steps of at most
``MAX_FORCE_STEP`` (Fhat), each seeded by the state before it, halved when Newton or the active
set fails; a height target in steps of the plate's travel likewise. Every state on the way is checked
against the end of the range (``rangeend``): a load past it is refused, naming the end. A march whose step
fails however short (below ``MIN_FRACTION`` of the first) stops with a ConvergenceError naming the last
force solved (and the height, under height control), the shortest step tried and Newton's reason: where the
discrete path turns at the clamp's upper corner (``newton``), that force is the turn's to the march's
smallest step.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.fluids import Fluid

from .contact import PLATE_SURFACE, Surface
from .contact import force as force_of
from .equations import Control
from .jaw import Jaw, first
from .model import Model
from .newton import SWEEP_TOL, contact
from .rangeend import margins, past_end

__all__ = ["MAX_FORCE_STEP", "first_contact", "fluid_control", "to_force", "to_height"]

#: the largest force step (Fhat)
MAX_FORCE_STEP = 0.25
#: the plate's first travel, in thicknesses, under height control (``to_force``)
FIRST_TRAVEL = 0.05
#: the largest travel of one step under height control, in thicknesses
MAX_TRAVEL = 1.0
#: the smallest step, as a fraction of the first, before the path is declared lost
MIN_FRACTION = 1e-3


def fluid_control(model: Model, fluid: Fluid, pressure_initial: float, volume_initial: float) -> Control:
    """The fluid's row: V(p_f) = V_I (V / V_I)(Phat), Phat = p_f / (3 t), and its slope dV/dp_f =
    -V / (gamma (Phat + Phat_atm) 3 t) (zero for a liquid)."""
    scale = 3.0 * model.thickness

    def volume(pf):
        ratio = fluid.volume_ratio(pf / scale, pressure_initial)
        slope = 0.0 if not fluid.is_gas else -ratio / (fluid.gamma * (pf / scale + fluid.ambient)) / scale
        return volume_initial * ratio, volume_initial * slope

    return Control(volume=volume)


def first_contact(model: Model, y_inflated: np.ndarray, fill: Control, surface: Surface = PLATE_SURFACE,
                  jaw: Jaw | None = None) -> tuple[np.ndarray, Control]:
    """The inflated state touched by the indenter ``surface`` (default the flat plate) at its pole, its lowest
    point there: its height and a zero force inserted after the fluid's pressure (before the multipliers of the
    clamp's upper ``jaw``, if given, whose active set is the nodes on it: ``jaw.first``)."""
    height = 0.5 * model.thickness + y_inflated[model.top_z[0]]
    y = np.concatenate([y_inflated[:model.size + 1], [height, 0.0], y_inflated[model.size + 1:]])
    jaw = None if jaw is None else first(model, y, jaw, SWEEP_TOL)
    return y, dataclasses.replace(fill, active=np.array([0]), force=0.0, surface=surface, jaw=jaw)


def _march(model, y, control, key, target, step, tol, unit, largest=None):
    """From the state y of ``control``, the state at ``control.<key> = target``: the first step ``step``, each
    next 1.5 times the last that converged, at most ``largest`` (default ``step``), halved when one fails. A
    state past the end of the range (``rangeend.margins``) stops the march: the end is located between it and
    the state before, and a ``target`` past it refused (``rangeend.past_end``; ``unit`` the force of Fhat = 1)."""
    value, total, first = getattr(control, key), 0, step
    largest = step if largest is None else largest
    while value < target if target > value else value > target:
        delta = np.sign(target - value) * min(step, abs(target - value))
        try:
            new, new_control, iterations = contact(model, y, dataclasses.replace(control, **{key: value + delta}),
                                                   tol)
        except (ConvergenceError, OutOfRangeError) as err:
            step *= 0.5
            if step >= MIN_FRACTION * first:
                continue
            if isinstance(err, OutOfRangeError):  # the contact leaves the indenter's surface however short the step
                raise past_end(model, (value, y, control), (value + delta, None), key, target, unit, tol) from err
            raise _stopped(model, y, control, key, value, value + delta, unit, err) from err
        margin = margins(model, new, new_control)
        if min(margin.values()) <= 0.0:
            raise past_end(model, (value, y, control), (value + delta, margin), key, target, unit, tol)
        y, control, value, total = new, new_control, value + delta, total + iterations
        step = min(largest, 1.5 * step)
    return y, control, total


def _stopped(model, y, control, key, reached, tried, unit, err: ConvergenceError) -> ConvergenceError:
    """The error of a march whose steps beyond ``key`` = ``reached`` (the state y of ``control``) all failed, the
    shortest to ``tried``: where it stopped (the force there in Fhat, ``unit`` the force of Fhat = 1) and why."""
    force = force_of(model, control.surface, y, np.asarray(control.active)) / unit
    if key == "force":
        where = f"Fhat = {force:.6g} (each step beyond failed, the shortest to Fhat = {tried / unit:.6g})"
    else:
        where = (f"height = {reached:.6g} R, Fhat = {force:.6g} (each step beyond failed, the shortest to "
                 f"height = {tried:.6g} R)")
    return ConvergenceError(f"the solid stopped at {where}: {err}", load=force, iterations=err.iterations,
                            residual=err.residual)


def to_force(model: Model, y: np.ndarray, control: Control, force: float, unit: float, tol: float):
    """The state at the plate force ``force`` (mu_0 R^2) from the state y of ``control`` (force control);
    ``unit`` is the force of Fhat = 1. (y, control, Newton iterations).

    From the first contact (no force yet) the plate is first pressed by ``FIRST_TRAVEL`` thicknesses
    under height control: a force on the pole's node alone is a point load on a continuum, whose
    indentation has no bound, and Newton on it fails; a travel spreads it over the nodes it reaches."""
    total = 0
    if control.force == 0.0:
        travel = FIRST_TRAVEL * model.thickness
        y, control, total = to_height(model, y, control, float(y[model.size + 1]) - travel, unit, tol)
        pushed = force_of(model, control.surface, y, np.asarray(control.active))
        control = dataclasses.replace(control, height=None, force=pushed)
    y, control, iterations = _march(model, y, control, "force", force, MAX_FORCE_STEP * unit, tol, unit)
    return y, control, total + iterations


def to_height(model: Model, y: np.ndarray, control: Control, height: float, unit: float, tol: float):
    """The state with the plate at ``height`` (R) from the state y of ``control`` (``unit`` the force of
    Fhat = 1, for a refusal past the end of the range: ``_march``): first the control turned
    to the plate's height where it is, then the height marched from a first step of ``FIRST_TRAVEL``
    thicknesses (the first travel in one step: in ten, the 10-force headline curve took 136 Newton iterations,
    in one 110, to the same states), growing to at most ``MAX_TRAVEL`` thicknesses (about the travel of a
    force step of ``MAX_FORCE_STEP`` near Fhat = 1 on the headline pocket; held at the first step, a travel
    of 12 T took 240 steps)."""
    start = float(y[model.size + 1])
    control = dataclasses.replace(control, force=None, height=start)
    first = min(abs(start - height), FIRST_TRAVEL * model.thickness) + 1e-12
    return _march(model, y, control, "height", height, first, tol, unit,
                  largest=max(first, MAX_TRAVEL * model.thickness))
