"""Solvers by name: each entry has ``inflate(alpha, pressure, **options)`` and
``compression_curve(alpha, pressure_initial, forces, **options)``.

Imported lazily, so that a shooting run does not pay for scikit-fem's import.
"""

from __future__ import annotations

import importlib

__all__ = ["SOLVERS", "get_solver"]

#: name -> module implementing it
SOLVERS = {"shooting": "shooting", "fem": "fem", "analytical": "pocket.analytical"}


def get_solver(name: str):
    """The module of the solver ``name`` (a key of ``SOLVERS``)."""
    return importlib.import_module(SOLVERS[name])
