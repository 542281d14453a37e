"""The solves of a validation run, as functions of plain data (run in worker processes).

``reference(case, plan)``: the shooting solver (the reference) and the analytical
model on a grid of forces from 0 to near the end of the shooting model's range,
which ``range_end`` finds by bisection: the largest Fhat with a compressed state
(past it the free part of the sheet reaches the clamp plane).
``fem_curve(case, order, forces)``: the finite-element curve at the default mesh.
Every function returns frozen dataclasses (picklable) and draws nothing.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from pocket import analytical
from pocket.core.errors import OutOfRangeError
from pocket.core.states import CompressedState

from .plan import RANGE_FRACTION, Plan
from .suite import Case

__all__ = ["Curves", "FemCurve", "reference", "fem_curve", "fem_forces", "range_end", "force_grid",
           "DESIGN_FORCES"]

#: forces always on the grid: fig 2 (0.19) and the section 6 design reading (1/5.7)
DESIGN_FORCES = (0.19, 1.0 / 5.7)
_SMALL_FORCES = (0.005, 0.01, 0.02, 0.05)  # where the analytical model is expected to hold
_PAPER_FORCES = tuple(np.linspace(0.1, 1.0, 10))  # the range of the paper's figs 3 and 5


@dataclasses.dataclass(frozen=True)
class Curves:
    """Shooting and analytical compression curves of one case (index 0: Fhat = 0).

    ``analytical`` holds None where a force is past the analytical model's own range.
    """

    case: Case
    force_end: float
    forces: np.ndarray
    shooting: tuple[CompressedState, ...]
    analytical: tuple[CompressedState | None, ...]
    seconds: float


@dataclasses.dataclass(frozen=True)
class FemCurve:
    """The FEM curve of one case and element order at the default mesh."""

    case: Case
    order: int
    states: tuple[CompressedState, ...]
    seconds: float


def range_end(alpha: float, pressure: float, *, rtol: float = 1e-3) -> float:
    """The end of the shooting model's range in Fhat, to relative ``rtol`` (a lower bound)."""
    from pocket import shooting
    from pocket.apps.inverse import range_end as model_range_end

    return model_range_end(shooting, alpha, pressure, rtol=rtol)


def force_grid(force_end: float, points: int, extra=()) -> np.ndarray:
    """Sorted forces to RANGE_FRACTION * force_end: ``points`` linearly and ``points`` geometrically
    spaced (from 0.005: ranges differ 20-fold between cases), the small, the paper's and the design forces."""
    top = RANGE_FRACTION * force_end
    grid = np.concatenate((np.linspace(0.0, top, points), np.geomspace(0.005, top, points), _SMALL_FORCES,
                           _PAPER_FORCES, DESIGN_FORCES, list(extra)))
    return np.unique(grid[grid <= top])


def fem_forces(plan_forces, force_end: float) -> list[float]:
    """A plan's FEM forces with None replaced by RANGE_FRACTION * force_end."""
    return [RANGE_FRACTION * force_end if f is None else float(f) for f in plan_forces]


def _analytical(alpha, pressure, forces):
    out = []
    for force in forces:
        try:
            out.append(analytical.compress(alpha, pressure, force))
        except OutOfRangeError:
            out.append(None)
    return tuple(out)


def reference(case: Case, plan: Plan) -> Curves:
    """Shooting and analytical curves of ``case`` on the plan's grid (plus its FEM forces)."""
    from pocket import shooting

    start = time.perf_counter()
    alpha, pressure = case.alpha, case.pressure_hat
    end = range_end(alpha, pressure)
    wanted = plan.fem_forces_of(case)
    forces = force_grid(end, plan.curve_points, fem_forces(wanted, end))
    states = tuple(shooting.compression_curve(alpha, pressure, forces))
    return Curves(case=case, force_end=end, forces=forces, shooting=states,
                  analytical=_analytical(alpha, pressure, forces), seconds=time.perf_counter() - start)


def fem_curve(case: Case, order: int, forces) -> FemCurve:
    """The FEM compression curve (default mesh, element ``order``) at ``forces``."""
    from pocket import fem

    start = time.perf_counter()
    states = fem.compression_curve(case.alpha, case.pressure_hat, list(forces), order=order)
    return FemCurve(case=case, order=order, states=tuple(states), seconds=time.perf_counter() - start)
