"""pocket: mechanics of pressurised elastic pockets (clamped, fluid-inflated rubber sheets).

A flat circular rubber sheet clamped at its edge is inflated by a fluid, then
pressed by a rigid flat plate at fixed fluid volume (Bouremel et al.,
"Compression of pressurised elastic pockets"). pocket predicts its shape,
contact area, height and pressure rise against the applied force.

Layers, each importing only from those below it:

- ``pocket.core``: the vocabulary (states, errors, input checks, units, solver records);
- ``pocket.meshes``: 1-D meshes of the Lagrangian radius;
- the solvers ``pocket.shooting`` (the reference), ``pocket.fem`` (finite
  elements) and ``pocket.analytical`` (the paper's small-strain model),
  independent of each other;
- ``pocket.apps``: case files in physical units, inverse problems, button
  design, force sensing, sweeps, VTK output;
- ``pocket.validation`` (the validation suite and its report) and, on top,
  ``pocket.cli`` (the ``pocket`` command).

Quick use::

    from pocket import shooting
    state = shooting.compress(47 / 160, 0.31, 0.19)   # alpha, Phat_I, Fhat
    state.scalars()
"""

from .core.errors import ConvergenceError, InputError, OutOfRangeError, PocketError
from .core.states import CompressedState, InflatedState, Profile

__all__ = [
    "CompressedState",
    "ConvergenceError",
    "InflatedState",
    "InputError",
    "OutOfRangeError",
    "PocketError",
    "Profile",
]
