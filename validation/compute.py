"""The solves of a validation run, as functions of plain data (run in worker processes).

``reference(pocket, plan)``: the reference column (shooting) and the approximate one
(the analytical model, the flat plate's only: None under a curved indenter) on a grid
of forces from 0 to near the end of the reference model's range, found by ``pocket.apps.inverse.range_end``: the
largest Fhat with a compressed state (past it the free part of the sheet
reaches the clamp plane).
``column_curve(pocket, column, forces)``: a solver column's curve (the FE columns).
Each solver is reached through its record (``pocket.apps.solvers.entry``)
with the column's options, the pocket's rubber (``Pocket.material``) and its fluid
(``Pocket.fluid_options``: a gas's Phat_atm). Every function returns frozen dataclasses
(picklable) and draws nothing.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.apps.inverse import range_end as model_range_end
from pocket.apps.physical import Pocket
from pocket.apps.solvers import entry, record
from pocket.core.errors import OutOfRangeError
from pocket.core.states import CompressedState

from .failures import located
from .plan import APPROXIMATE, RANGE_FRACTION, REFERENCE, Column, Plan
from .suite import on_plate

__all__ = [
    "DESIGN_FORCES",
    "RANGE_RTOL",
    "ColumnCurve",
    "Curves",
    "column_curve",
    "fem_forces",
    "force_grid",
    "range_end",
    "reference",
]

#: forces always on the grid: fig 2 (0.19) and the section 6 design reading (1/5.7)
DESIGN_FORCES = (0.19, 1.0 / 5.7)
_SMALL_FORCES = (0.005, 0.01, 0.02, 0.05)  # where the analytical model is expected to hold
_PAPER_FORCES = tuple(np.linspace(0.1, 1.0, 10))  # the range of the paper's figs 3 and 5
#: relative width to which the end of the range is located (the curves stop at 0.95 of it)
RANGE_RTOL = 1e-3


@dataclasses.dataclass(frozen=True)
class Curves:
    """Reference and approximate compression curves of one pocket (index 0: Fhat = 0).

    ``approximate`` holds None where a force is past the approximate model's own range, and at every force
    of a pocket pressed by a curved indenter (the paper's model is the flat plate's).
    """

    pocket: Pocket
    force_end: float
    forces: np.ndarray
    reference: tuple[CompressedState, ...]
    approximate: tuple[CompressedState | None, ...]


@dataclasses.dataclass(frozen=True)
class ColumnCurve:
    """The compression curve of one pocket by one solver column."""

    pocket: Pocket
    column: Column
    states: tuple[CompressedState, ...]


def range_end(pocket: Pocket, column: Column = REFERENCE, *, width: float = RANGE_RTOL) -> float:
    """The end of ``column``'s compression range in Fhat (a lower bound): the solver's own, or bisected to
    the relative ``width`` for a solver without one."""
    end = model_range_end(record(column.solver), pocket.material, pocket.pressure_initial, width=width,
                          **column.kwargs(), **pocket.fluid_options())
    if not math.isfinite(end):  # a Gent rubber that locks before the sheet reaches the clamp plane
        raise OutOfRangeError(f"{pocket.case.name}: its compression range has no end (the rubber locks first), "
                              "and the suite runs each curve to a fraction of that end: choose a pocket whose "
                              "range ends")
    return end


def force_grid(force_end: float, points: int, extra=()) -> np.ndarray:
    """Sorted forces to RANGE_FRACTION * force_end: ``points`` linearly and ``points`` geometrically
    spaced (from 0.005: ranges differ 20-fold between cases), the small, the paper's and the design forces."""
    top = RANGE_FRACTION * force_end
    grid = np.concatenate((np.linspace(0.0, top, points), np.geomspace(0.005, top, points), _SMALL_FORCES,
                           _PAPER_FORCES, DESIGN_FORCES, list(extra)))
    return np.unique(grid[grid <= top])


def fem_forces(plan_forces, force_end: float) -> list[float]:
    """A plan's FE forces with None replaced by RANGE_FRACTION * force_end, and those past it left out
    (a pocket whose range ends early)."""
    top = RANGE_FRACTION * force_end
    return [top if f is None else float(f) for f in plan_forces if f is None or f <= top]


def _pointwise(pocket, column, forces):
    """``column``'s state at each force, None past its own range."""
    compress = entry(column.solver, "compress", f"the {column.label} column")
    options = {**column.kwargs(), **pocket.fluid_options()}
    out = []
    for force in forces:
        try:
            out.append(compress(pocket.material, pocket.pressure_initial, float(force), **options))
        except OutOfRangeError:
            out.append(None)
    return tuple(out)


def reference(pocket: Pocket, plan: Plan) -> Curves:
    """Reference and approximate curves of ``pocket`` on the plan's grid (plus its FE forces)."""
    with located(pocket.case.name, "end of the compression range (shooting)", _mesh(REFERENCE),
                 "Fhat bisected to the end of the range"):
        end = range_end(pocket)
    forces = force_grid(end, plan.curve_points, fem_forces(plan.fem_forces_of(pocket), end))
    states = column_curve(pocket, REFERENCE, forces).states
    approximate = (None,) * len(forces)
    if on_plate(pocket):
        with located(pocket.case.name, "analytical column", _mesh(APPROXIMATE), _forces(forces)):
            approximate = _pointwise(pocket, APPROXIMATE, forces)
    return Curves(pocket=pocket, force_end=end, forces=forces, reference=states, approximate=approximate)


def _mesh(column: Column) -> str:
    """The mesh a column solves on, in words."""
    if column.solver != "fem":
        return f"no mesh ({column.solver})"
    options = column.kwargs()
    mesh = options.get("mesh", options.get("elements", "the default"))
    return f"{mesh} P{options.get('order', 2)} mesh, {options.get('contact', 'fitted')} contact"


def _forces(forces) -> str:
    forces = [float(f) for f in forces]
    return f"Fhat = {forces[0]:.6g}" if len(forces) == 1 else \
        f"{len(forces)} forces Fhat = {min(forces):.6g} to {max(forces):.6g}"


def column_curve(pocket: Pocket, column: Column, forces) -> ColumnCurve:
    """The compression curve of ``pocket`` at ``forces`` by the solver of ``column``."""
    curve = entry(column.solver, "compression_curve", f"the {column.label} column")
    with located(pocket.case.name, f"{column.label} column", _mesh(column), _forces(forces)):
        states = curve(pocket.material, pocket.pressure_initial, [float(f) for f in forces],
                                          **column.kwargs(), **pocket.fluid_options())
    return ColumnCurve(pocket=pocket, column=column, states=tuple(states))
