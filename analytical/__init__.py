"""The paper's small-strain analytical model (its section 3), corrected: the approximate third column.

``inflate``, ``compress`` and ``compression_curve`` return ``pocket.core.states``
containers, with a warning on every state outside the model's range of validity
(pole or contact stretch above 1.1); ``range_end`` is the force at which its contact
reaches the clamp. The model and its corrections are derived in
``pocket.analytical.model``. ``SOLVER`` is its record (it takes no options).
"""

import importlib

from pocket.core.importname import require_import_name
from pocket.core.solver import Solver

require_import_name(__name__, "pocket.analytical")

__all__ = ["SOLVER", "inflate", "compress", "compression_curve", "range_end", "shape_function"]

SOLVER = Solver(
    name="analytical",
    summary="the paper's small-strain model: approximate, good only where the stretches stay small",
    module=__name__,
    entry_points=("inflate", "compress", "compression_curve", "range_end"),
)


def __getattr__(name):
    if name in __all__[1:]:
        return getattr(importlib.import_module(".model", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
