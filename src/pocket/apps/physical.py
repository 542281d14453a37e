"""A case resolved to the dimensionless model, and its states back in SI units.

With E = 6 (C1 + C2) the modulus, T the thickness and R the clamp radius
(``pocket.core.states``): P = Phat E T / R, F = Fhat P_I pi R^2, lengths = (x/R) R, areas =
(A/(pi R^2)) pi R^2, volumes = (V/R^3) R^3. An initial height H0 becomes Phat_I
by ``pocket.apps.inverse.pressure_for_height``; an initial volume by the solver's
volume-controlled inflation, checked to lie on the pressure-controlled first
branch (compression starts from there). Plate heights become forces by
``pocket.apps.inverse.force_where``.
"""

from __future__ import annotations

import dataclasses
import math

from pocket.core.errors import OutOfRangeError

from .cases import Case
from .inverse import force_where, pressure_for_height
from .solvers import get_solver, record

__all__ = ["Pocket", "resolve", "forces", "inflated_row", "compressed_row"]


@dataclasses.dataclass(frozen=True)
class Pocket:
    """A case with its dimensionless initial pressure ``pressure_initial`` = Phat_I = P_I R / (E T).

    SI values carry their unit in the name (``pressure_initial_Pa``, ``force_scale_N``).
    """

    case: Case
    pressure_initial: float

    @property
    def alpha(self) -> float:
        return self.case.alpha

    @property
    def pressure_scale_Pa(self) -> float:
        """E T / R: P = Phat * pressure_scale_Pa."""
        return self.case.modulus * self.case.thickness / self.case.radius

    @property
    def pressure_initial_Pa(self) -> float:
        """P_I."""
        return self.pressure_initial * self.pressure_scale_Pa

    @property
    def force_scale_N(self) -> float:
        """P_I pi R^2: F = Fhat * force_scale_N."""
        return self.pressure_initial_Pa * math.pi * self.case.radius**2

    def solver(self):
        """The solver module of the case (its entry points)."""
        return get_solver(self.case.solver)

    def options(self, step: str = "compress") -> dict:
        """The case's solver options that ``step`` ("inflate" or "compress") takes, as keyword arguments."""
        solver = record(self.case.solver)
        return {k: v for k, v in self.case.options if step in solver.option(k).steps}


def resolve(case: Case) -> Pocket:
    """Solve for Phat_I from the case's initial state (pressure, height or volume)."""
    kind, value = case.initial
    unit = Pocket(case, 1.0)  # Phat_I = 1: its pressure_initial_Pa is E T / R
    solver, options = unit.solver(), unit.options("inflate")
    if kind == "pressure":
        return Pocket(case, value / unit.pressure_scale_Pa)
    if kind == "height":
        return Pocket(case, pressure_for_height(solver, case.alpha, value / case.radius, **options))
    volume = value / case.radius**3
    phat = solver.inflate_volume(case.alpha, volume, **options).pressure
    reached = solver.inflate(case.alpha, phat, **options).volume
    if abs(reached - volume) > 1e-6 * volume:  # the two solves agree to ~1e-10 on the first branch
        raise OutOfRangeError(f"initial.volume = {value:.6g} m^3 lies past the pressure maximum of "
                              "the first branch, where the pocket cannot be held at fixed pressure")
    return Pocket(case, phat)


def forces(pocket: Pocket) -> list[float]:
    """The case's loads as forces Fhat (plate heights solved for their force)."""
    case = pocket.case
    if case.load_kind == "forces":
        return [f / pocket.force_scale_N for f in case.loads]
    solver, options = pocket.solver(), pocket.options()
    return [force_where(solver, pocket.alpha, pocket.pressure_initial, "height", h / case.radius,
                        increasing=False, **options) for h in case.loads]


def inflated_row(pocket: Pocket, state) -> dict:
    """The inflated state in SI units, then its dimensionless keys."""
    r = pocket.case.radius
    return {"pressure_Pa": state.pressure * pocket.pressure_scale_Pa, "height_m": state.height * r,
            "volume_m3": state.volume * r**3, **state.scalars()}


def compressed_row(pocket: Pocket, state) -> dict:
    """A compressed state in SI units, then its dimensionless keys (``CompressedState.KEYS``)."""
    r, scale = pocket.case.radius, pocket.pressure_scale_Pa
    return {"force_N": state.force * pocket.force_scale_N, "pressure_Pa": state.pressure * scale,
            "pressure_rise_Pa": (state.pressure - state.pressure_initial) * scale,
            "contact_area_m2": state.contact_area * math.pi * r**2,
            "contact_radius_m": state.contact_radius * r, "height_m": state.height * r,
            "travel_m": (state.inflated.height - state.height) * r, "volume_m3": state.volume * r**3,
            **state.scalars()}
