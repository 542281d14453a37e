"""Finite-element solver of the axisymmetric Mooney-Rivlin membrane (scikit-fem).

Unknowns rho(r), eta(r) on P1 or P2 Lagrange elements of the Lagrangian radius
r in [0, 1], the pressure as the multiplier of the volume, a frictionless flat
plate by penalty (optionally augmented Lagrangian). Modules: ``material`` (the
energy), ``forms`` (residual and tangent, derived in its docstring), ``model``
(the bordered system), ``newton``, ``continuation``, ``inflation``,
``compression``, ``post`` and ``api`` (the entry points below). ``SOLVER`` is
its record (entry points and options, ``pocket.core.solver``).

The entry points are imported on first use (scikit-fem's import is not free),
so that reading ``SOLVER`` costs nothing.
"""

import importlib

from pocket.core.inputs import check_choice, check_count, check_flag, check_positive, check_tolerance
from pocket.core.solver import Option, Solver

__all__ = ["SOLVER", "inflate", "inflate_volume", "compress", "compression_curve", "compress_height",
           "default_mesh", "DEFAULT_ELEMENTS", "MAX_ELEMENTS"]

#: elements of the default uniform mesh
DEFAULT_ELEMENTS = 1000
#: most elements a solve may ask for: bounds the memory and time a case file can ask for (measured on
#: 2 cores: a P2 inflation takes 0.55 GB and 45 s at 1e5 elements, 0.9 GB at 2e5; 1e6 would need ~5 GB)
MAX_ELEMENTS = 100_000
#: fewest elements: the pole stretch uses the first two vertices off the axis
MIN_ELEMENTS = 4


def _mesh(name, value):
    """A mesh file name or an array of nodes: checked when it is read (``pocket.meshes``)."""
    return value


SOLVER = Solver(
    name="fem",
    summary="finite elements (scikit-fem): P1/P2 membrane, volume multiplier, penalty plate",
    module=__name__,
    entry_points=("inflate", "inflate_volume", "compress", "compression_curve"),
    options=(
        Option("elements", "int", DEFAULT_ELEMENTS,
               f"elements of a uniform mesh ({MIN_ELEMENTS} to {MAX_ELEMENTS}; default {DEFAULT_ELEMENTS})",
               lambda name, value: check_count(name, value, MIN_ELEMENTS, MAX_ELEMENTS)),
        Option("mesh", "path", None, "mesh file of [0, 1] (any meshio format), instead of elements", _mesh),
        Option("order", "int", 2, "element order: 1 (P1) or 2 (P2, default)",
               lambda name, value: int(check_choice(name, value, (1, 2)))),
        Option("penalty", "float", 1e5, "contact penalty stiffness (units E T / R^2; default 1e5)",
               check_positive, steps=("compress",)),
        Option("augmented", "bool", True, "augmented-Lagrangian contact updates (default true)",
               check_flag, steps=("compress",)),
        Option("tol", "float", 1e-10, "Newton tolerance on residual and increment (default 1e-10, at most 1e-4)",
               lambda name, value: check_tolerance(name, value, 1e-4)),
    ),
)

_LAZY = {"inflate", "inflate_volume", "compress", "compression_curve", "compress_height", "default_mesh"}


def __getattr__(name):
    if name in _LAZY:
        return getattr(importlib.import_module(".api", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
