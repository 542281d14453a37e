"""Travel control: the compressed state with the indenter's lowest point at a given height.

The force Fhat is the load this solver's equations take (``pocket.shooting.compression``). Along
the first branch the indenter's height H/R falls strictly as the force grows from 0 (where it is
the inflated height H0/R) to the end of the range Fhat_end (``pocket.shooting.plateend``: the
free sheet at the clamp plane, a force maximum, or under a sphere or a profile the end of what
it can wrap). So a height h in [H(Fhat_end), H0] belongs to exactly one force of [0, Fhat_end],
the root of H(Fhat) - h, found by Brent's method (``pocket.shooting.brent``) on that bracket,
each H(Fhat) a force-controlled solve. The state returned is the one solved at the root, its
``height`` the solved height (within the shots' tolerance of h, ``rtol``), never overwritten by h.

A height above H0 is not a compressed state (the indenter would not touch the pocket), and one
below H(Fhat_end) is outside the model: each an OutOfRangeError naming the bound. A rubber whose
range has no end (Fhat_end = inf, a Gent sheet locking first) is bracketed by doubling the force
from 1; a solve that fails there is the ConvergenceError it raised.

A closed capsule (``pocket.shooting.capsule``) at a low Phat_I ends its first branch where the meridional tension
at the contact edge vanishes (``CAPSULE_EDGE``), and has none at P_I = 0; its states at larger compressions, its
second branch, are reached by a descent in the inflation pressure (``pocket.shooting.descent``): that route is taken
at P_I = 0 and for a height below the end of the first branch. A height between the two branches is an
OutOfRangeError quoting both ends.

The finite-element solver controls the height directly (its load is the indenter's position):
the two routes are independent, and the tests compare them.
"""

from __future__ import annotations

import math

from pocket.core.errors import OutOfRangeError, above_the_pocket, capsule_gap
from pocket.core.fluids import as_fluid
from pocket.core.geometries import CAPSULE, Symmetry, posed
from pocket.core.indenters import Indenter, as_indenter
from pocket.core.inputs import check_non_negative, check_positive
from pocket.core.solver import FluidLike, GeometryLike, MaterialLike
from pocket.core.states import CompressedState

from . import brent
from .capsule import CapsuleProblem
from .compression import compress
from .descent import capsule_at_height
from .inflation import GEOMETRIES, inflate
from .laws import law_of
from .problem import problem_of
from .rangeend import range_end

__all__ = ["compress_height"]

_FORCE_RTOL = 1e-14  # relative width of the force bracket at the root: far below the shots' height error


def compress_height(material: MaterialLike, pressure_initial: float, height: float, *, fluid: FluidLike = None,
                    indenter: Indenter | None = None, geometry: GeometryLike = None,
                    rtol: float = 1e-10) -> CompressedState:
    """The compressed state with the indenter's lowest point at H/R = ``height`` above the clamp plane.

    Travel control: the force is found.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0; a capsule's >= 0 (at P_I = 0 the state's ``force`` and ``pressure_ratio`` are
        NaN, its force ``extra["force_ETR"]`` = F / (E T R): ``pocket.shooting.descent``).
    height : float
        H / R > 0, at most the inflated pocket's height H0 / R (there the force is 0).
    fluid, indenter, geometry, rtol
        As for ``compression_curve``.

    Returns
    -------
    CompressedState
        Its ``force`` is the Fhat = F / (P_I pi R^2) found.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a height above the inflated pocket, or below the lowest the model reaches, or (a capsule) between its
        two branches.
    ConvergenceError
        If a solve fails.

    Examples
    --------
    Travel control inverts force control:

    >>> from pocket import shooting
    >>> pressed = shooting.compress(47 / 160, 0.31, 0.19)
    >>> print(round(shooting.compress_height(47 / 160, 0.31, pressed.height).force, 8))
    0.19

    The uninflated capsule (P_I = 0) of liquid, pressed to H = 0.6 R: F / (E T R), and its volume, the unstressed
    sphere's:

    >>> import math
    >>> state = shooting.compress_height(0.0, 0.0, 0.6, geometry="capsule")
    >>> print(f"{state.extra['force_ETR']:.4f}", abs(state.volume - 4.0 * math.pi / 3.0) < 1e-9)
    0.3646 True
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    height = check_positive("height", height)
    capsule = isinstance(geometry.end, Symmetry)
    if capsule:
        problem_of(geometry, as_indenter(indenter))  # an InputError for an indenter other than the plates
        if check_non_negative("pressure", pressure_initial) == 0.0:
            return _uninflated(material, height, fluid, rtol)
    inflated = inflate(material, pressure_initial, geometry=geometry, rtol=rtol)
    top = inflated.height
    if capsule and height < top:  # a Phat_I too low for the shots' segments: refused before the search of the range
        CapsuleProblem(inflated, rtol, law_of(material), as_fluid(fluid)).conditioned()

    def solved(force):
        return compress(material, pressure_initial, force, fluid=fluid, indenter=indenter, geometry=geometry,
                        rtol=rtol)

    if height > top:
        raise above_the_pocket(height, top)
    if height == top:
        return solved(0.0)
    end = range_end(material, pressure_initial, fluid=fluid, indenter=indenter, geometry=geometry, rtol=rtol)
    hi = end if math.isfinite(end) else 1.0
    low = solved(hi).height
    while not math.isfinite(end) and low > height:
        hi *= 2.0
        low = solved(hi).height
    if low > height and capsule and math.isfinite(end):  # its first branch ends where the edge goes slack: deeper
        return _second_branch(material, pressure_initial, height, fluid, rtol, low)  # lies the second
    if low > height:
        raise OutOfRangeError(f"height = {height!r} is below the lowest the model reaches (H/R = {low:.10g}, at "
                              f"the end of its range, force = {end:.10g})")
    force = brent.root(lambda f: solved(f).height - height if f > 0.0 else top - height, 0.0, hi,
                       fa=top - height, fb=low - height, rtol=_FORCE_RTOL)
    return solved(force)


def _uninflated(material, height, fluid, rtol) -> CompressedState:
    """The uninflated capsule's state at ``height``: the unstressed sphere the plates touch at its own height,
    else a state of the branch reached deep (``capsule_at_height``)."""
    top = inflate(material, 0.0, geometry=CAPSULE, rtol=rtol).height
    if height > top:
        raise above_the_pocket(height, top)
    if height == top:
        return compress(material, 0.0, 0.0, fluid=fluid, geometry=CAPSULE, rtol=rtol, force_unit="ETR")
    return capsule_at_height(material, 0.0, height, fluid=fluid, rtol=rtol)


def _second_branch(material, pressure_initial, height, fluid, rtol, first) -> CompressedState:
    """The capsule's state at ``height`` on its second branch (``capsule_at_height``); an OutOfRangeError quoting
    both ends for a height between the branches, the first's end at H/R = ``first``."""
    try:
        return capsule_at_height(material, pressure_initial, height, fluid=fluid, rtol=rtol)
    except OutOfRangeError as err:
        if err.end is None:
            raise
        raise capsule_gap(f"height = {height!r}", err.end, f"height = {first:.10g}") from None
