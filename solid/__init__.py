"""Axisymmetric solid model of the sheet: the continuum the membrane solvers approximate.

The sheet's cross-section, r in [0, R] by the thickness T, as an incompressible hyperelastic
solid: Taylor-Hood quadrilaterals (biquadratic displacement, bilinear pressure) on scikit-fem,
the rubber's own strain energy at the isochoric invariants (the Ogden law's at the isochoric
principal stretches: ``laws``), the clamp r = R fixed through the thickness.
The fluid presses on the lower surface as a follower load, its pressure the multiplier of the
cavity's volume (a liquid keeps it; a gas follows the polytropic law); the frictionless indenter
(the flat plate or a sphere) touches the upper surface's nodes through Lagrange multipliers on an
active set, without a penalty error. States in the membrane solvers' units (lengths / R, Phat =
P R / (E T), E = 3 mu_0), key by key comparable: their difference is the membrane's modelling
error, O(T/R).

Modules: ``laws`` (W's derivatives), ``kinematics`` (F, stress, tangent), ``stretches`` (the Ogden
law's stress and tangent), ``mesh`` (the cross-section), ``assembly`` (the weak forms and their
vectorised assembly), ``model`` (bases and constraints), ``contact`` (the indenter's gap and its
derivatives), ``jaw`` (the clamp's upper jaw: a rigid obstacle with a rounded edge), ``equations`` (the
bordered system), ``newton`` (Newton, active set), ``inflation`` and ``compression`` (the load paths),
``edgemesh`` (the mesh's cluster of short elements that follows the contact edge, the state carried over to
it), ``results`` (the states) and ``api`` (the entry points, with their types, imported on first use:
scikit-fem's import is not free). ``SOLVER`` is its record.
"""

import importlib
from typing import TYPE_CHECKING

from pocket.core.importname import require_import_name
from pocket.core.inputs import check_count, check_non_negative, check_range, check_tolerance
from pocket.core.offset import check_thickness
from pocket.core.solver import Option, Solver

require_import_name(__name__, "pocket.solid")

if TYPE_CHECKING:  # what type checkers and editors see; at run time each is loaded on first use (__getattr__)
    from .api import compress, compress_height, compression_curve, inflate, inflate_volume

__all__ = [
    "DEFAULT_CLAMP_RADIUS",
    "DEFAULT_CORNER",
    "DEFAULT_ELEMENTS",
    "DEFAULT_LAYERS",
    "DEFAULT_THICKNESS",
    "MAX_CORNER",
    "MAX_ELEMENTS",
    "MAX_LAYERS",
    "MIN_CORNER",
    "MIN_ELEMENTS",
    "MIN_LAYERS",
    "SOLVER",
    "compress",
    "compress_height",
    "compression_curve",
    "inflate",
    "inflate_volume",
]

#: T/R of the paper's thinnest sample (the headline pocket)
DEFAULT_THICKNESS = 0.0125
#: fewest layers of elements through the thickness: one biquadratic layer bends, two resolve the
#: stress's linear variation with one to spare
MIN_LAYERS = 2
#: most layers: bounds the unknowns a command can ask for
MAX_LAYERS = 16
#: fewest and most elements along the radius
MIN_ELEMENTS = 8
MAX_ELEMENTS = 2000
#: default elements along the radius and through the thickness: P/P_I converged to 1e-4, through the thickness.
#: Measured on the headline pocket's 10-force curve under the plate (Fhat 0.1 .. 1, T/R = 0.0125,
#: benchmarks/bench_solid.py): with the mesh that follows the contact edge (``edgemesh``) and the clamp's upper jaw
#: (the default), its wrap zone meshed at the corner's length (``mesh.WRAP``), P/P_I moves by 1e-6 from 24 to 256
#: elements, four layers (6.4e-5 before the wrap zone was: the sheet's lift-off from the jaw fell inside a long
#: element; without the jaw by at most 2.5e-6 from 16 to 256, and without the edge followed it moved 3.6e-5 from
#: 64 to 128: that error was the edge's), and the curve takes 1.5 s on 16
#: elements, 1.8 s on 24, 2.2 s on 32 and 3.1 s on 64 (idle; 2.4 s on 64 before the edge was followed). 24, not 16:
#: pressed towards Fhat = 9 (alpha = 0.3, Phat_I = 0.3) the march on 16 stops at Fhat = 5.01 where an iterate
#: inverts an element though the path goes on; on 24, 32 and 64 without the clamp's upper jaw it stops where the
#: corner folds, 5.43 (``newton``; with the jaw, the default, it reaches 9). Through the thickness P/P_I moved by
#: 2.8e-4 from two layers to four and by 5.5e-5 from four to eight without the jaw, order ~2.3 (with it, by 9.2e-6
#: from four to eight); four layers cost twice two. Sample 4's contact area (T/R = 0.08, Fhat 0.08 to 0.32) is
#: within 0.5 % of 256 x 8's on 24 x 4 (-0.49 %, +0.24 %, +0.10 %: tests/test_solid_edgemesh.py, a study).
#: Inflated (tests/test_solid_thin.py): along the radius V converges to ~1e-6 by 32 elements (the validation's
#: study: sample 4's V moves by 1e-7 from 16 to 32); through the thickness V moves by ~3e-4 (relative) from two
#: layers to four, by ~4e-5 from four to eight (the clamp's corners are meshed at T/2 whatever the layers,
#: ``mesh``; the corner size itself moves V by ~4e-4 when doubled: the model's own choice at the singular corner,
#: a few percent of the membrane's O(T/R) difference the solid is there to measure).
DEFAULT_ELEMENTS = 24
DEFAULT_LAYERS = 4
#: the length of the clamp's corner elements, in thicknesses (``mesh``): half the radius of the clamp's upper jaw's
#: edge (below), so that two elements span it. Measured on sample 4's pocket (T/R = 0.08, 5 kPa, Fhat 0.08 to
#: 0.32): from corner elements T/4 to T/16 its V moves by 7e-4 and its contact area by up to 0.14 %, where from
#: T/2 they moved by 2.4e-3 and 0.4 % (at T/2 the sheet's inflated upper surface does not reach the edge at all, at
#: T/4 and finer it wraps it). Without the jaw the corner is singular, the answer depends on this length at every
#: scale, and elements much shorter than T/2 fold (``mesh``): there T/2 was the default.
DEFAULT_CORNER = 0.25
MIN_CORNER = 0.05
MAX_CORNER = 4.0
#: the radius of the clamp's upper jaw's rounded edge, in thicknesses (``jaw``): a real clamp's upper plate
#: holds the sheet inside r = R; without it the solid's upper corner moves past r = R above the sheet and its
#: element folds (alpha = 0.3, Phat_I = 0.3, T/R = 0.0125: at Fhat = 5.43, where the membrane's range goes on to
#: 10.4). With an edge of T/2, as long as the corner's elements, the same pocket reaches Fhat = 9 at every corner
#: mesh from T to T/16; a sharper edge (T/10) reaches it too, but its round is then shorter than the corner's
#: elements. 0: no jaw.
DEFAULT_CLAMP_RADIUS = 0.5

SOLVER = Solver(
    name="solid",
    summary="the sheet's cross-section as an incompressible solid: the membrane's own O(T/R) error for a thick "
            "sheet (seconds a curve)",
    module=__name__,
    entry_points=("inflate", "inflate_volume", "compress", "compression_curve", "compress_height"),
    options=(
        Option("thickness_ratio", "float", DEFAULT_THICKNESS,
               f"sheet thickness over clamp radius T/R, in (0, 0.5) (default {DEFAULT_THICKNESS})", check_thickness),
        Option("layers", "int", DEFAULT_LAYERS,
               f"elements through the thickness ({MIN_LAYERS} to {MAX_LAYERS}; default {DEFAULT_LAYERS})",
               lambda name, value: check_count(name, value, MIN_LAYERS, MAX_LAYERS)),
        Option("elements", "int", DEFAULT_ELEMENTS,
               f"elements along the radius, graded towards the clamp ({MIN_ELEMENTS} to {MAX_ELEMENTS}; "
               f"default {DEFAULT_ELEMENTS}); the clamp's corner elements, T/2 long, replace the nodes near it, "
               "and in contact a cluster of short elements follows the contact edge, so a state's "
               "'mesh_elements' (the mesh's count) differs from it",
               lambda name, value: check_count(name, value, MIN_ELEMENTS, MAX_ELEMENTS)),
        Option("corner", "float", DEFAULT_CORNER,
               f"length of the clamp's corner elements, in thicknesses ({MIN_CORNER:g} to {MAX_CORNER:g}; default "
               f"{DEFAULT_CORNER:g}, half the default jaw's edge radius, which they must resolve; without a jaw "
               "the corner is singular and the answer depends on this length)",
               lambda name, value: check_range(name, value, MIN_CORNER, MAX_CORNER,
                                               "in thicknesses T: the corner elements must fit beside the sheet")),
        Option("tol", "float", 1e-10, "Newton tolerance on the displacement increment, units R (default 1e-10, "
               "at most 1e-4)", lambda name, value: check_tolerance(name, value, 1e-4)),
        Option("clamp_radius", "float", DEFAULT_CLAMP_RADIUS,
               "the clamp's upper jaw as a rigid frictionless obstacle the sheet's upper surface may not enter, its "
               f"edge rounded to this radius, in thicknesses T (default {DEFAULT_CLAMP_RADIUS:g}; less than half the "
               "clamp's radius); 0: no jaw, the sheet only fixed at r >= R (its upper corner then folds at high "
               "force)", check_non_negative),
    ),
)

_LAZY = {"inflate", "inflate_volume", "compress", "compression_curve", "compress_height"}


def __getattr__(name: str) -> object:
    if name in _LAZY:
        return getattr(importlib.import_module(".api", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
