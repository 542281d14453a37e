r"""Reference surfaces: the undeformed membrane a solver is given, as it is given a law and an indenter.

A reference surface is what a solver needs to know of the membrane before any load: an axisymmetric
surface whose meridian is described by the arc length S from the pole (S = 0, on the axis) to its end
S = L, every length in units of R. A material point at S sits at the reference radius r0(S) and height
z0(S); the meridian's end is held by a support that fixes where it lies. The undeformed surface
encloses the volume V0 with the plane of its end.

=======  ======================================  =====  ============  ==============  ====
name     surface                                 L      r0(S), z0(S)  end             V0
=======  ======================================  =====  ============  ==============  ====
pocket   a flat disc, clamped at r = R           1      S, 0          clamp r=1, z=0  0
capsule  a closed sphere of radius R (its upper  pi/2   sin S, cos S  the equator's   2 pi/3
         half: the lower is its mirror image)                         symmetry
=======  ======================================  =====  ============  ==============  ====

The flat disc (``DISC``) is every solver's default: its arc length is its radius, so S and r0 are one
coordinate, which is why the solvers write the Lagrangian radius r for both.

The closed capsule (``CAPSULE``, a sphere of radius R pressed between two parallel plates placed symmetrically
about its equatorial plane) is described by its upper half: the meridian runs from the pole S = 0 to the equator
S = pi / 2, with r0 = sin S and z0 = cos S above the equatorial plane, and its end is held by the equator's
mirror symmetry (``Symmetry``: the meridian vertical there and on the plane z = 0, its radius free), not by a
clamp. Its upper half encloses 2 pi / 3 with the equatorial plane (the whole capsule 4 pi / 3).

Each solver maps the surfaces it poses to its own formulation through an explicit table and asks
``formulation`` (or ``posed``, the check every entry point makes of its ``geometry`` argument) for it,
which refuses a surface the table lacks in one line naming the solver and the surface: a new surface
is a new ``Geometry`` here and an entry in the tables of the solvers that pose it. An inflated state
carries the surface it was solved on (``pocket.core.states.InflatedState.geometry``), and a compressed
state the one of the inflated state it was pressed from.

How a solver poses the capsule: it reads r0(S) wherever the disc's equations take the Lagrangian radius for the
reference radius (the hoop stretch lambda_2 = rho / r0 in the shooting equations and their pole series, and in
the finite-element kernels); the disc's closing condition (rho = 1 at the clamp) becomes the equator's symmetry
(eta = 0 and the meridian vertical at S = pi / 2); the volume and the end's stretch report that surface's (the whole
capsule's volume); the inflated capsule has a closed form, a sphere of uniform stretch. The shooting solver poses
it (``pocket.shooting.capsule``); a solver whose table lacks it refuses it in one line.
"""

from __future__ import annotations

import abc
import dataclasses
from collections.abc import Mapping
from typing import ClassVar, TypeVar

import numpy as np

from .errors import InputError
from .inputs import quote

__all__ = [
    "CAPSULE",
    "DISC",
    "GEOMETRIES",
    "Clamp",
    "Disc",
    "Geometry",
    "Support",
    "Symmetry",
    "as_geometry",
    "clamp_of",
    "formulation",
    "posed",
]

T = TypeVar("T")


class Support:
    """What holds the end of the meridian: a subclass per way of holding it (``Clamp``, ``Symmetry``)."""


@dataclasses.dataclass(frozen=True)
class Clamp(Support):
    """The meridian's end held fixed at radius ``radius`` and height ``height`` (units R): the material point
    there neither moves nor is free to turn the sheet about the clamp's line (a membrane carries no moment:
    for it the clamp fixes the point only)."""

    radius: float
    height: float


@dataclasses.dataclass(frozen=True)
class Symmetry(Support):
    """The meridian's end on a plane of mirror symmetry, at height ``height`` (units R): the end point stays on the
    plane, free to move along it, and the meridian crosses it at a right angle (a closed capsule's equator)."""

    height: float


class Geometry(abc.ABC):
    """An axisymmetric reference surface, the undeformed membrane a solver is given, in units of R.

    Its meridian runs by arc length S from the pole (S = 0) to its end S = L, held by a ``Support``; a material
    point at S sits at the reference radius r0(S) and height z0(S). Each solver maps the surfaces it poses to its
    formulation through its table ``GEOMETRIES`` and refuses another in one line.

    Attributes
    ----------
    name : str
        The word a user writes.
    description : str
        One line.

    Examples
    --------
    >>> from pocket.core.geometries import DISC, GEOMETRIES, Geometry
    >>> print(list(GEOMETRIES), isinstance(DISC, Geometry))
    ['pocket', 'capsule'] True
    """

    name: ClassVar[str]
    description: ClassVar[str]

    @property
    @abc.abstractmethod
    def length(self) -> float:
        """L: the meridian's arc length from the pole to its end (units R)."""

    @abc.abstractmethod
    def radius(self, arc) -> np.ndarray:
        """r0(S): the reference radius of the material points at arc lengths ``arc`` (units R, any shape in
        [0, L]; the result has the same shape)."""

    @abc.abstractmethod
    def height(self, arc) -> np.ndarray:
        """z0(S): the reference height of the material points at arc lengths ``arc`` above the plane of the
        meridian's end (units R; any shape, the result has the same shape)."""

    @property
    @abc.abstractmethod
    def end(self) -> Support:
        """What holds the meridian's end S = L."""

    def __reduce_ex__(self, protocol):
        """A surface of ``GEOMETRIES`` is pickled by name, so that one sent to another process (a sweep's workers)
        is the one of ``GEOMETRIES`` there: the solvers tell the surfaces apart by identity (``geometry is
        CAPSULE``). Any other pickles as an object does."""
        if GEOMETRIES.get(self.name) is self:
            return (_named, (self.name,))
        return super().__reduce_ex__(protocol)

    @property
    @abc.abstractmethod
    def volume(self) -> float:
        """V0 / R^3: the volume the undeformed surface encloses with the plane of its end."""


@dataclasses.dataclass(frozen=True)
class Disc(Geometry):
    """The flat disc of radius R clamped at its rim: the pocket's sheet before inflation (``DISC``, every solver's
    default).

    Its arc length is its radius, r0(S) = S, and it lies in the clamp plane, z0 = 0: every solver writes the
    Lagrangian radius r for both.

    Examples
    --------
    >>> from pocket.core.geometries import DISC
    >>> print(DISC.length, DISC.radius([0.0, 0.5]), DISC.height([0.0, 0.5]), DISC.end, DISC.volume)
    1.0 [0.  0.5] [0. 0.] Clamp(radius=1.0, height=0.0) 0.0
    """

    name: ClassVar[str] = "pocket"
    description: ClassVar[str] = "a flat sheet clamped at its rim r = R"

    @property
    def length(self) -> float:
        return 1.0

    def radius(self, arc) -> np.ndarray:
        """r0(S) = S: ``arc`` itself (as a float array: the same array if it is one)."""
        return np.asarray(arc, dtype=float)

    def height(self, arc) -> np.ndarray:
        """z0(S) = 0."""
        return np.zeros_like(np.asarray(arc, dtype=float))

    @property
    def end(self) -> Clamp:
        return _RIM

    @property
    def volume(self) -> float:
        return 0.0


_RIM = Clamp(radius=1.0, height=0.0)  # the disc's clamp


@dataclasses.dataclass(frozen=True)
class Capsule(Geometry):
    """A closed spherical membrane of radius R, described by its upper half (``CAPSULE``): the meridian from the
    pole to the equator, r0(S) = sin S and z0(S) = cos S above the equatorial plane, S in [0, pi / 2], its end on
    the plane of the equator's mirror symmetry.

    Examples
    --------
    >>> import math
    >>> from pocket.core.geometries import CAPSULE
    >>> arc = [0.0, math.pi / 6, math.pi / 2]
    >>> print(CAPSULE.length == math.pi / 2, CAPSULE.radius(arc).round(6), CAPSULE.height(arc).round(6))
    True [0.  0.5 1. ] [1.       0.866025 0.      ]
    >>> print(CAPSULE.end, CAPSULE.volume == 2 * math.pi / 3)
    Symmetry(height=0.0) True
    """

    name: ClassVar[str] = "capsule"
    description: ClassVar[str] = "a closed spherical membrane of radius R, pressed between two parallel plates"

    @property
    def length(self) -> float:
        return 0.5 * np.pi

    def radius(self, arc) -> np.ndarray:
        """r0(S) = sin S."""
        return np.sin(np.asarray(arc, dtype=float))

    def height(self, arc) -> np.ndarray:
        """z0(S) = cos S, above the equatorial plane."""
        return np.cos(np.asarray(arc, dtype=float))

    @property
    def end(self) -> Symmetry:
        return _EQUATOR

    @property
    def volume(self) -> float:
        return 2.0 * np.pi / 3.0


_EQUATOR = Symmetry(height=0.0)  # the capsule's equatorial plane

#: the flat clamped disc (every solver's default)
DISC = Disc()
#: the closed spherical capsule (posed by the solvers whose ``GEOMETRIES`` table names it)
CAPSULE = Capsule()

#: name -> the reference surface of that name (what ``--geometry`` offers)
GEOMETRIES: dict[str, Geometry] = {DISC.name: DISC, CAPSULE.name: CAPSULE}


def _named(name: str) -> Geometry:
    """The surface of ``GEOMETRIES`` named ``name`` (how a pickled surface is read back)."""
    return GEOMETRIES[name]


def as_geometry(value) -> Geometry:
    """The reference surface of ``value``, as every entry point takes its ``geometry`` argument.

    Parameters
    ----------
    value : Geometry or str or None
        None is the flat disc (``DISC``), a name of ``GEOMETRIES`` its surface; a ``Geometry`` is returned as given.

    Returns
    -------
    Geometry

    Raises
    ------
    InputError
        For anything else.

    Examples
    --------
    >>> from pocket.core.geometries import DISC, as_geometry
    >>> print(as_geometry(None) is DISC, as_geometry("pocket") is DISC)
    True True
    >>> as_geometry("torus")
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: geometry = 'torus', but it must be one of pocket, capsule or a Geometry ...
    """
    if value is None:
        return DISC
    if isinstance(value, Geometry):
        return value
    if isinstance(value, str) and value in GEOMETRIES:
        return GEOMETRIES[value]
    raise InputError(f"geometry = {quote(value)}, but it must be one of {', '.join(GEOMETRIES)} "
                     "or a Geometry (pocket.core.geometries)")


def clamp_of(geometry: Geometry) -> Clamp:
    """The clamp that holds the meridian's end of ``geometry``. A ValueError if it is held otherwise: a solver
    that asks poses clamped surfaces only, and its table should have refused this one."""
    end = geometry.end
    if not isinstance(end, Clamp):
        raise ValueError(f"the {geometry.name} geometry's meridian is not clamped at its end")
    return end


def formulation(table: Mapping[str, T], solver: str, geometry: Geometry) -> T:
    """``table[geometry.name]``: the formulation with which ``solver`` poses the reference surface; an
    InputError naming the solver and the surface if its table has no entry for it."""
    if geometry.name not in table:
        raise InputError(f"solver {solver} does not implement the {geometry.name} geometry "
                         f"(its geometries: {', '.join(table)})")
    return table[geometry.name]


def posed(table: Mapping[str, T], solver: str, value: Geometry | str | None) -> tuple[Geometry, T]:
    """The reference surface of ``value`` (``as_geometry``) and the formulation with which ``solver`` poses
    it (``formulation``): the check every entry point makes of its ``geometry`` argument."""
    geometry = as_geometry(value)
    return geometry, formulation(table, solver, geometry)
