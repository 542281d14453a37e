"""The reference solver: shooting on the axisymmetric membrane equations (Yang & Feng).

``inflate`` / ``inflate_volume`` solve step 1 (pressure or volume control), ``inflation_curve`` at
several pressures by one march along the first branch,
``compress`` / ``compression_curve`` step 2 (fixed volume, a flat frictionless
plate, a sphere or a user's profile, force given), ``range_end`` the force at which step 2 leaves the
model (the free sheet reaches the clamp plane; under a sphere also its equator, under a profile its
end, ``pocket.shooting.surfaceend``), ``compress_height`` the state with the indenter at a given height
(travel control, ``pocket.shooting.travel``; a capsule's states past the end of its first branch, and at P_I = 0,
by a descent in the inflation pressure: ``pocket.shooting.descent``).
The rubber is any law of ``pocket.core.materials`` (a number is a Mooney-Rivlin
alpha, ``mooney_rivlin``), its tensions derived from its strain energy in
``pocket.shooting.tensions``; a compression's fluid is a liquid or a gas sealed at the
initial pressure (``pocket.core.fluids``; ``pocket.shooting.contact``). The states are
``pocket.core.states`` containers; the equations and their derivation are in
``pocket.shooting.equations``, the contact problems in ``pocket.shooting.plate`` and
``pocket.shooting.surface``, their range ends in ``pocket.shooting.plateend`` and
``pocket.shooting.surfaceend``. Every entry point also poses a closed capsule squeezed between two parallel plates
(``geometry="capsule"``, ``pocket.shooting.capsule``). ``SOLVER`` is its record (entry points and options,
``pocket.core.solver``).

The entry points, with their types, are in ``pocket.shooting.api``; they are imported on first use, so
that reading ``SOLVER`` (the command line does, to build its flags) costs nothing.
"""

import importlib
from typing import TYPE_CHECKING

from pocket.core.importname import require_import_name
from pocket.core.inputs import check_tolerance
from pocket.core.solver import Option, Solver

require_import_name(__name__, "pocket.shooting")

if TYPE_CHECKING:  # what type checkers and editors see; at run time each is loaded on first use (__getattr__)
    from .api import (
        compress,
        compress_height,
        compression_curve,
        inflate,
        inflate_volume,
        inflation_curve,
        range_end,
    )

__all__ = [
    "SOLVER",
    "compress",
    "compress_height",
    "compression_curve",
    "inflate",
    "inflate_volume",
    "inflation_curve",
    "range_end",
]

#: loosest ODE tolerance accepted: the root finders need residuals far below the quantities they resolve
RTOL_MAX = 1e-4

SOLVER = Solver(
    name="shooting",
    summary="the reference: the membrane equations integrated to the clamp with root finding (fastest, most accurate)",
    module=__name__,
    entry_points=("inflate", "inflation_curve", "inflate_volume", "compress", "compression_curve", "compress_height",
                  "range_end"),
    options=(Option("rtol", "float", 1e-10, f"relative tolerance of the ODE integration (DOP853), "
                    f"at most {RTOL_MAX:g}", lambda name, value: check_tolerance(name, value, RTOL_MAX)),),
)

_LAZY = {"inflate", "inflation_curve", "inflate_volume", "compress", "compression_curve", "compress_height",
         "range_end"}


def __getattr__(name: str) -> object:
    if name in _LAZY:
        return getattr(importlib.import_module(".api", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
