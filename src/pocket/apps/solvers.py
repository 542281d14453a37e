"""Solvers by name, from their records (``pocket.core.solver``).

``SOLVERS`` maps a name to the solver's record; ``entry`` gives one of its entry
points (a solver without it is a one-line ``InputError`` naming the solvers that
have it), ``solver_options`` checks the options a user gave against the record
(an option the solver does not take is an ``InputError``). Reading the records
imports no solver code: each package loads its entry points on first use, so a
shooting run does not pay for scikit-fem's import.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Literal, overload

from pocket import analytical, fem, shooting, solid
from pocket.core.errors import InputError
from pocket.core.solver import (
    Compress,
    CompressHeight,
    CompressionCurve,
    Inflate,
    InflateVolume,
    InflationCurve,
    RangeEnd,
    Solver,
)

__all__ = ["SOLVERS", "all_options", "entry", "record", "solver_options"]

#: name -> record (in the order of their codes in VTK files, ``pocket.apps.vtk.files.CODES``: a new solver goes last)
SOLVERS: dict[str, Solver] = {s.SOLVER.name: s.SOLVER for s in (shooting, fem, analytical, solid)}


def record(name: str) -> Solver:
    """The record of the solver ``name``."""
    if name not in SOLVERS:
        raise InputError(f"solver = {name!r}, but it must be one of {', '.join(SOLVERS)}")
    return SOLVERS[name]


@overload
def entry(solver: Solver | str, name: Literal["inflate"], purpose: str) -> Inflate: ...
@overload
def entry(solver: Solver | str, name: Literal["inflate_volume"], purpose: str) -> InflateVolume: ...
@overload
def entry(solver: Solver | str, name: Literal["inflation_curve"], purpose: str) -> InflationCurve: ...
@overload
def entry(solver: Solver | str, name: Literal["compress"], purpose: str) -> Compress: ...
@overload
def entry(solver: Solver | str, name: Literal["compression_curve"], purpose: str) -> CompressionCurve: ...
@overload
def entry(solver: Solver | str, name: Literal["compress_height"], purpose: str) -> CompressHeight: ...
@overload
def entry(solver: Solver | str, name: Literal["range_end"], purpose: str) -> RangeEnd: ...
@overload
def entry(solver: Solver | str, name: str, purpose: str) -> Callable[..., Any]: ...


def entry(solver: Solver | str, name: str, purpose: str) -> Callable[..., Any]:
    """The entry point ``name`` of ``solver`` (its record or its name), asked for ``purpose``
    (``Solver.entry``; the error offers the solvers of ``SOLVERS`` that have it)."""
    solver = record(solver) if isinstance(solver, str) else solver
    return solver.entry(name, purpose, [n for n, s in SOLVERS.items() if s.serves(name)])


def solver_options(name: str, given: dict, step: str, spell: Callable[[str], str] = str) -> dict:
    """``given`` options checked against the solver ``name`` for ``step`` (``Solver.checked``)."""
    return record(name).checked(given, step, spell)


def all_options() -> dict:
    """Option name -> [(solver name, option)] over every solver, in declaration order."""
    out: dict = {}
    for solver in SOLVERS.values():
        for option in solver.options:
            out.setdefault(option.name, []).append((solver.name, option))
    return out
