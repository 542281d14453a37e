r"""A capsule's states deep in its compression: the second branch of a low P_I, and the uninflated capsule.

Pressed from the touch, a capsule at a low inflation pressure reaches the end of its first branch early: the
patch under a plate is compressed towards its edge by a strain of the order of the compression, only the
inflation's tension keeps it taut, and where the meridional tension at the contact edge vanishes the free membrane
would leave the plate with unbounded curvature (``pocket.core.errors.CAPSULE_EDGE``; at Phat_I = 0.01, neo-Hookean,
a liquid, at a compression of 5.6 %). Deeper, the states resume: the free membrane's tension grows like the
square of the compression (the fluid must be enclosed by a larger area) until it holds the edge again. An
uninflated capsule (P_I = 0) has only that second branch: the neo-Hookean one filled with a liquid from a
compression of about 21 %, its patch compressive at the pole (flagged wrinkled) down to about 52 %, taut beyond.

No load stepping from the touch reaches the second branch. It is reached from an inflated capsule whose branch
has no end, at a fixed plate height, by lowering the sealed fluid to the target's:

1. at Phat_I = ``ANCHOR`` the capsule is pressed from the touch to the plate height H_d = min(H, ``DEEP``);
2. at that height the initial pressure is stepped (``continuation.follow``) from ``ANCHOR`` to the target P_I, the
   fluid at each step the one sealed in the capsule inflated there (a liquid: the finite elements' own inflated
   volume; a gas: its polytropic law sealed at that P_I);
3. the plate is moved, at the target P_I, to the height or the force asked.

The step 3 that would pass the branch's start (the edge's tension vanishing: ``steps.check_edge``) is cut down to
the continuation's smallest step and quotes the start between the last height (or force) it solved and the nearest
beyond it tried (``pocket.core.errors.capsule_gap``).

The neo-Hookean liquid's branch has no end from Phat_I ~ 0.02 up, hence ``ANCHOR`` = 0.1, five times that; and at
``DEEP`` = 0.5 (a compression of 50 % of R) the uninflated neo-Hookean capsule's edge tension is 0.046 E T, about
twenty times its value where the branch starts. A soft gas (a low ambient pressure: the squeeze raises its pressure
less) may start its deep branch below ``DEEP``: where the edge's tension vanishes on the way down in P_I, the
height is halved, down to ``DEEPEST`` (at P_I = 0, neo-Hookean, Phat_atm = 0.5, isothermal, the branch starts at
H = 0.416). A rubber or gas for which it still fails says where (the anchor's range end, or the continuation's last
initial pressure).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from pocket.core.errors import CAPSULE_EDGE, OutOfRangeError, capsule_gap
from pocket.core.fluids import Fluid
from pocket.core.indenters import Indenter

from . import capsule, capsulestates, fitted, inflation
from .continuation import follow
from .gas import sealed
from .model import FITTED, Control, Model
from .newton import Tolerances
from .steps import solve

__all__ = ["ANCHOR", "DEEP", "DEEPEST", "filled", "to_force", "to_height"]

ANCHOR = 0.1  # Phat_I of the capsule the descent starts from (module docstring)
DEEP = 0.5  # H/R: the plate height the fluid is lowered at (module docstring)
DEEPEST = 0.125  # ... and the lowest it is halved to, where the deep branch starts below it (``_deep``)


def filled(model: Model, pressure_initial: float, fluid: Fluid, indenter: Indenter,
           tol: Tolerances) -> tuple[np.ndarray, object, Control]:
    """The capsule inflated at Phat_I = ``pressure_initial`` with ``fluid`` sealed in it: (its FREE unknowns, its
    ``InflatedState``, the volume row's ``Control`` of the upper half)."""
    y_i, iterations = inflation.inflated_at(model, pressure_initial, tol, capsule.inflate)
    state = capsulestates.inflated(model, y_i, iterations, pressure=pressure_initial)
    return y_i, state, Control(volume=0.5 * state.volume, gas=sealed(fluid, pressure_initial), indenter=indenter)


def _lowered(model: Model, pressure_initial: float, fluid: Fluid, indenter: Indenter, height: float,
             tol: Tolerances) -> tuple[np.ndarray, int]:
    """Steps 1 and 2 (module docstring): the FITTED state at the target Phat_I with the plate at ``height``."""
    y_a, _, fill = filled(model, ANCHOR, fluid, indenter, tol)
    y, total = fitted.first_contact(model, y_a, fill, fitted.A_FIRST / 4, tol)
    y, iterations = fitted.height_path(model, y, fill, height, tol)
    total += iterations

    def along(p_i, guess):
        return solve(model, FITTED, replace(filled(model, p_i, fluid, indenter, tol)[2], height=height), guess, tol)

    for _, y, iterations in follow(along, y, ANCHOR, pressure_initial, name="initial pressure Phat_I"):
        total += iterations
    return y, total


def _deep(model: Model, pressure_initial: float, fluid: Fluid, indenter: Indenter, height: float,
          tol: Tolerances) -> tuple[np.ndarray, int, float]:
    """``_lowered`` at ``height``, or, where the edge's tension vanishes on the way (a soft gas, whose pressure the
    squeeze raises less, starts its deep branch below ``DEEP``), at half the height, down to ``DEEPEST``; (y,
    iterations, the height it reached the target at)."""
    while True:
        try:
            return (*_lowered(model, pressure_initial, fluid, indenter, height, tol), height)
        except OutOfRangeError:
            if height <= DEEPEST:
                raise
            height = max(DEEPEST, 0.5 * height)


def to_height(model: Model, pressure_initial: float, fill: Control, height: float, tol: Tolerances,
              asked: str, end: str | None = None) -> tuple[np.ndarray, int]:
    """The FITTED state at the plate height ``height`` reached deep (module docstring); (y, iterations).

    ``fill``: the target's volume row (its fluid and indenter). ``asked`` names the load in a refusal and ``end``
    quotes the end of the branch from the touch (None at P_I = 0): a height above the deep branch's start is the
    ``OutOfRangeError`` of ``capsule_gap``."""
    fluid = Fluid() if fill.gas is None else fill.gas.fluid
    y, total, deep = _deep(model, pressure_initial, fluid, fill.indenter, min(height, DEEP), tol)
    if height > deep:
        y, iterations = _raised(lambda: fitted.height_path(model, y, fill, height, tol), asked, end)
        total += iterations
    return y, total


def to_force(model: Model, pressure_initial: float, fill: Control, force: float, tol: Tolerances, asked: str,
             end: str | None = None, unit: float = 1.0) -> tuple[np.ndarray, int]:
    """The FITTED state at the plate force ``force`` (units E T R) reached deep; as ``to_height`` (``unit``: the
    force in messages is F / unit)."""
    fluid = Fluid() if fill.gas is None else fill.gas.fluid
    y, total, _ = _deep(model, pressure_initial, fluid, fill.indenter, DEEP, tol)
    y, iterations = _raised(lambda: fitted.force_path(model, y, fill, force, tol, unit), asked, end)
    return y, total + iterations


def _raised(path, asked: str, end: str | None):
    """``path()``, its refusal past the deep branch's start (the edge's tension vanishing) worded by
    ``capsule_gap``."""
    try:
        return path()
    except OutOfRangeError as err:
        if err.end is None or CAPSULE_EDGE not in str(err):
            raise
        raise capsule_gap(asked, err.end, end) from err
