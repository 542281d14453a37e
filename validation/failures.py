"""Solver failures inside the suite, re-raised saying where: the case, the study, the mesh and the force.

A run holds many solves on worker processes; a bare "Newton failed after 2
iterations" would not say which. ``located`` wraps a solve: a
``ConvergenceError`` leaving it is raised again with its message prefixed by
the four, keeping the load, iterations and residual (the command line prints
it as one line, exit status 1).
"""

from __future__ import annotations

import contextlib

from pocket.core.errors import ConvergenceError

__all__ = ["located"]


@contextlib.contextmanager
def located(case: str, study: str, mesh: str, force: str):
    """Re-raise a ConvergenceError of the enclosed solve as "case <case>, <study>, <mesh>, <force>: <message>".

    case: the case's name; study: what was being solved (a reference curve, a solver column, a
    convergence sequence); mesh: the mesh it was solved on (or that there was none); force: the force(s)
    Fhat = F / (P_I pi R^2) asked for.
    """
    try:
        yield
    except ConvergenceError as err:
        raise ConvergenceError(f"case {case!r}, {study}, {mesh}, {force}: {err}", load=err.load,
                               iterations=err.iterations, residual=err.residual) from err
