"""pocket: mechanics of pressurised elastic pockets (clamped, fluid-inflated sheets).

Solvers (by name in ``pocket.solvers.SOLVERS``): ``shooting`` (the reference),
``fem`` (scikit-fem membrane model) and ``analytical`` (the paper's small-strain
model). All return the containers of ``pocket.states``.
"""

from .errors import ConvergenceError, InputError, OutOfRangeError, PocketError
from .states import CompressedState, InflatedState, Profile

__all__ = [
    "CompressedState",
    "ConvergenceError",
    "InflatedState",
    "InputError",
    "OutOfRangeError",
    "PocketError",
    "Profile",
]
