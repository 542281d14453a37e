"""Solvers by name, from their records (``pocket.core.solver``).

``SOLVERS`` maps a name to the solver's record; ``get_solver`` imports the
module of its entry points, ``solver_options`` checks the options a user gave
against the record (an option the solver does not take is an ``InputError``).
Reading the records imports no solver code: each package loads its entry
points on first use, so a shooting run does not pay for scikit-fem's import.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable

from pocket import analytical, fem, shooting
from pocket.core.errors import InputError
from pocket.core.solver import Solver

__all__ = ["SOLVERS", "record", "get_solver", "solver_options", "all_options"]

#: name -> record
SOLVERS: dict[str, Solver] = {s.SOLVER.name: s.SOLVER for s in (shooting, fem, analytical)}


def record(name: str) -> Solver:
    """The record of the solver ``name``."""
    if name not in SOLVERS:
        raise InputError(f"solver = {name!r}, but it must be one of {', '.join(SOLVERS)}")
    return SOLVERS[name]


def get_solver(name: str):
    """The module of the solver ``name``: its entry points (``pocket.core.solver``)."""
    return importlib.import_module(record(name).module)


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
