"""The paper's small-strain analytical model (its section 3), corrected: the approximate third column.

``inflate``, ``compress`` and ``compression_curve`` return ``pocket.core.states``
containers, with a warning on every state outside the model's range of validity
(pole or contact stretch above 1.1); ``range_end`` is the force at which its contact
reaches the clamp. The model and its corrections are derived in
``pocket.analytical.model``; the entry points, with their types, are in ``pocket.analytical.api``, imported
on first use (with scipy's solvers). ``SOLVER`` is its record (it takes no options).
"""

import importlib
from typing import TYPE_CHECKING

from pocket.core.importname import require_import_name
from pocket.core.solver import Solver

require_import_name(__name__, "pocket.analytical")

if TYPE_CHECKING:  # what type checkers and editors see; at run time each is loaded on first use (__getattr__)
    from .api import compress, compression_curve, inflate, range_end, shape_function

__all__ = ["SOLVER", "compress", "compression_curve", "inflate", "range_end", "shape_function"]

SOLVER = Solver(
    name="analytical",
    summary="the paper's small-strain model: approximate, good only where the stretches stay small",
    module=__name__,
    entry_points=("inflate", "compress", "compression_curve", "range_end"),
)


_LAZY = {"inflate", "compress", "compression_curve", "range_end", "shape_function"}


def __getattr__(name: str) -> object:
    if name in _LAZY:
        return getattr(importlib.import_module(".api", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
