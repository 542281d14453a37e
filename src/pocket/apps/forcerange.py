"""The end of a pocket's compression range, said in the units the user gave a force in.

A force past the end is refused before any solve, in the one wording of
``pocket.core.errors.beyond_range``, whatever the solver: ``loads.forces[0] = '61 N'
(Fhat = 10.09) is beyond the model's range, which ends at 60.14 N (Fhat = 9.941): there
the free part of the sheet reaches the clamp plane``. The end is the solver's own
``range_end`` where it has one (shooting, analytical); the FE, which approximates
the same membrane model as the shooting (to ~1e-9 at its default mesh), is given the
shooting's, so that both quote the same end. At the clamp-plane end the plate carries
all of P pi R^2, so the deformed contact area is pi R^2 (``shooting.plateend``); an end
with less is a force maximum of the branch. A capsule has no clamp plane: its range ends where the meridional
tension at the contact edge vanishes (``pocket.core.errors.CAPSULE_EDGE``), if it does, and its states resume
deeper, on a second branch: a force past that end is asked of the solver, whose refusal (a force between the two
branches) is quoted after the load as the case gives it.
"""

from __future__ import annotations

from pocket.core.errors import CLAMP_PLANE, OutOfRangeError, beyond_range
from pocket.core.geometries import DISC
from pocket.core.inputs import quote
from pocket.core.units import written_like

from .solvers import SOLVERS, entry

__all__ = ["check_force", "range_end_of"]

_PURPOSE = "the end of the compression range"
_FULL_CONTACT = 1e-6  # contact area / (pi R^2) within this of 1: the end is the clamp plane, not a force maximum


def _model(pocket):
    """The record of the solver that locates the end, with its options: the pocket's if it has ``range_end``,
    else the shooting."""
    solver = pocket.solver()
    if solver.serves("range_end"):
        return solver, pocket.options()
    return SOLVERS["shooting"], pocket.fluid_options()


def range_end_of(pocket) -> float:
    """Fhat_end of ``pocket`` (a ``pocket.apps.physical.Pocket``): the largest force with a compressed state."""
    solver, options = _model(pocket)
    return entry(solver, "range_end", _PURPOSE)(pocket.material, pocket.pressure_initial, **options)


def check_force(pocket, key: str, given, force: float) -> float:
    """``force`` (Fhat) if the pocket has a state there; else the ``OutOfRangeError`` of the module docstring,
    quoting ``key`` = ``given`` (the force as the user wrote it) and the end in ``given``'s unit."""
    solver, options = _model(pocket)
    end = entry(solver, "range_end", _PURPOSE)(pocket.material, pocket.pressure_initial, **options)
    if force <= end:
        return force
    if pocket.case.geometry != DISC:  # no clamp plane; past the first branch's end a capsule's states resume deeper
        try:
            entry(solver, "compress", _PURPOSE)(pocket.material, pocket.pressure_initial, force, **options)
        except OutOfRangeError as err:
            raise OutOfRangeError(f"{key} = {quote(given)} (Fhat = {force:.10g}): {err}") from None
        return force
    at_end = entry(solver, "compress", _PURPOSE)(pocket.material, pocket.pressure_initial, end, **options)
    reason = CLAMP_PLANE if abs(at_end.contact_area - 1.0) < _FULL_CONTACT else "the force has a maximum"
    raise beyond_range(f"{key} = {quote(given)} (Fhat = {force:.10g})",
                       f"{written_like(end * pocket.force_scale_N, given, 'force')} (Fhat = {end:.10g})", reason)
