"""Finite-element solver of the axisymmetric membrane of any incompressible rubber.

Unknowns rho(r), eta(r) on P1 or P2 Lagrange elements (scikit-fem's element
definitions and quadrature) of the Lagrangian radius r in [0, 1], the
pressure as the multiplier of the volume. The frictionless flat plate either
on an edge-fitted mesh (the default: the Lagrangian contact radius is a
Newton unknown, closed by tangent contact, and a mesh vertex follows it, so
that every element is smooth and the contact is exact) or on a fixed mesh by
penalty with augmented-Lagrangian updates; a sphere (``surfaces``) edge-fitted too, the sheet in
contact lying exactly on it (``obstacle``, ``wrapping``, ``wrapstates``), or by penalty on its vertical gap
(``spherepenalty``). The reference surface is the flat clamped disc or the closed capsule, a sphere pressed between
two parallel plates (``capsule``, ``capsulestates``: its upper half on the sphere's arc length, the equator on
its plane of symmetry, the same kernel with the reference radius sin S). The rubber is any law of
``pocket.core.materials`` (a number is a Mooney-Rivlin alpha, ``mooney_rivlin``); the pocket holds
a liquid (fixed volume) or a gas sealed at the initial pressure (the
polytropic law ties the pressure to the volume).

Modules: ``laws`` (each law's membrane energy derivatives, compiled) and
``material`` (a rubber as the kernel's law), ``gas`` (the fluid's volume
row), ``reference`` (element tables), ``geometry`` (the mesh and its map to
the contact edge), ``kernel`` (residual and tangent, derived in its
docstring) and ``loops`` (their compiled element loop), ``model`` (unknowns,
equations and the bordered tangent), ``banded`` and ``condensed`` (its O(N)
solution), ``newton``, ``continuation``, ``steps``, ``inflation``,
``fitted`` and ``penalty`` (the two contact methods), ``curves``, ``post``,
``results`` (the states and their checks) and ``api`` (the entry points
below). ``SOLVER`` is its record (entry points and options,
``pocket.core.solver``).

The entry points, with their types, are in ``pocket.fem.api``; they are imported on first use
(scikit-fem's import is not free), so that reading ``SOLVER`` costs nothing.
"""

import importlib
from typing import TYPE_CHECKING

from pocket.core.importname import require_import_name
from pocket.core.inputs import check_choice, check_count, check_flag, check_positive, check_tolerance
from pocket.core.solver import Option, Solver

require_import_name(__name__, "pocket.fem")

if TYPE_CHECKING:  # what type checkers and editors see; at run time each is loaded on first use (__getattr__)
    from .api import compress, compress_height, compression_curve, default_mesh, inflate, inflate_volume

__all__ = [
    "CONTACT_METHODS",
    "DEFAULT_ELEMENTS",
    "DEFAULT_ELEMENTS_P1",
    "MAX_ELEMENTS",
    "MIN_ELEMENTS",
    "SOLVER",
    "compress",
    "compress_height",
    "compression_curve",
    "default_mesh",
    "inflate",
    "inflate_volume",
]

#: elements of the default mesh with P2 elements (``api.default_mesh`` says how the number was chosen)
DEFAULT_ELEMENTS = 256
#: elements of the default mesh with P1 elements: P1's error falls as h^2, not h^4, and 4 times the
#: elements keep it near 1e-6 (the cost of 1024 P1 elements is that of 512 P2 ones)
DEFAULT_ELEMENTS_P1 = 1024
#: most elements a solve may ask for: bounds the memory and the time a case file or a command can ask for
#: (measured on this 2-core machine with /usr/bin/time: a two-force curve at 1e5 elements in 10 s and
#: 0.38 GB; at 1e6, 90 s and 3.9 GB for one state). The benchmark goes to 1e6 through the internals.
MAX_ELEMENTS = 100_000
#: fewest elements: the pole stretch is fitted to three vertices off the axis
MIN_ELEMENTS = 4
#: the contact methods: the edge-fitted mesh (exact contact) and the fixed-mesh penalty
CONTACT_METHODS = ("fitted", "penalty")


def _mesh(name, value):
    """A mesh file name or an array of nodes: checked when it is read (``pocket.meshes``)."""
    return value


SOLVER = Solver(
    name="fem",
    summary="membrane finite elements on a mesh that follows the contact edge: the independent check of shooting",
    module=__name__,
    entry_points=("inflate", "inflate_volume", "compress", "compression_curve", "compress_height"),
    options=(
        Option("elements", "int", DEFAULT_ELEMENTS,
               f"elements of the default mesh, graded towards the axis ({MIN_ELEMENTS} to {MAX_ELEMENTS}; "
               f"default {DEFAULT_ELEMENTS} with P2, {DEFAULT_ELEMENTS_P1} with P1)",
               lambda name, value: check_count(name, value, MIN_ELEMENTS, MAX_ELEMENTS)),
        Option("mesh", "path", None, "mesh file of [0, 1] (any meshio format), instead of elements", _mesh),
        Option("order", "int", 2, "element order: 1 (P1) or 2 (P2, default)",
               lambda name, value: int(check_choice(name, value, (1, 2)))),
        Option("contact", "choice", "fitted",
               "contact method: fitted (default; a mesh node follows the contact edge, contact exact) or "
               "penalty (fixed mesh, penalty plate)",
               lambda name, value: check_choice(name, value, CONTACT_METHODS), steps=("compress",),
               choices=CONTACT_METHODS),
        Option("penalty", "float", 1e5, "contact penalty stiffness of contact = penalty (units E T / R^2; "
               "default 1e5)", check_positive, steps=("compress",)),
        Option("augmented", "bool", True, "augmented-Lagrangian updates of contact = penalty (default true)",
               check_flag, steps=("compress",)),
        Option("tol", "float", 1e-10, "Newton tolerance on residual and increment (default 1e-10, at most 1e-4)",
               lambda name, value: check_tolerance(name, value, 1e-4)),
    ),
)

_LAZY = {"inflate", "inflate_volume", "compress", "compression_curve", "compress_height", "default_mesh"}


def __getattr__(name: str) -> object:
    if name in _LAZY:
        return getattr(importlib.import_module(".api", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
