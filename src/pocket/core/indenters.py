r"""Indenters: what presses on the inflated pocket, one registered class per kind.

An indenter (``Indenter``, ``pocket.core.indenterbase``) is a rigid, frictionless body of revolution pushed
down along the axis onto the dome, its lower surface z(rho) above its lowest point (units R, z(0) = 0):

=======  ==========================  ==============  ====================
name     z(rho)                      class           F = P A_c identity
=======  ==========================  ==============  ====================
plate    0                           ``Plate()``     yes
sphere   R_s - sqrt(R_s^2 - rho^2)   ``Sphere(K)``   no
profile  a user's table or function  ``Profile(s)``  no
=======  ==========================  ==============  ====================

A sphere's surface exists for rho <= R_s only (its equator; ``pocket.core.sphereindenter``). A profile is a
user's convex z(rho), flat on the axis, given as a table (a CSV file with units in its header) or as functions
with its slope and curvature (``pocket.core.profiles``: the interpolation and its error, the checks); past its
last radius it is NaN like a sphere past its equator.

On a flat plate the sheet in contact lies flat and carries the fluid pressure P straight to the plate, and a
smooth edge exerts no line force: the force is F = P A_c exactly, an identity a solver's state can be checked
against. On a curved indenter the contact pressure exceeds P (on a sphere of radius R_s, p_c = P + (T_1 + T_2) /
R_s) and the force is the integral of p_c over the contact area (``Indenter.pressure_area`` says which holds).

``INDENTERS`` maps each name to its class (``register``); ``PLATE`` is the flat plate, every solver's default.
Each solver maps an indenter's class to its own contact formulation through an explicit table (its
``CONTACTS``) and asks ``formulation`` for it, which refuses a class the table lacks in one line naming the
solver and the indenter: a new indenter is a new class here and an entry in the tables of the solvers that pose
it.
"""

from __future__ import annotations

import dataclasses
import pathlib
from collections.abc import Mapping
from typing import TypeVar

import numpy as np

from .errors import InputError
from .indenterbase import INDENTERS, Indenter, Spell, key_name, register
from .inputs import quote
from .profiles import Shape, read_csv
from .sphereindenter import SPHERE_RADII, Sphere, check_sphere_radius

__all__ = [
    "INDENTERS",
    "PLATE",
    "SPHERE_RADII",
    "Indenter",
    "Plate",
    "Profile",
    "Sphere",
    "as_indenter",
    "check_sphere_radius",
    "formulation",
    "posed",
    "register",
]

T = TypeVar("T")


@register
@dataclasses.dataclass(frozen=True)
class Plate(Indenter):
    """The flat plate, wider than the pocket: z = 0 everywhere; every solver's default (``PLATE``).

    On the plate the sheet in contact lies flat and carries the fluid pressure straight to it: the force is
    F = P A_c exactly (``pressure_area``).

    Examples
    --------
    >>> from pocket.core.indenters import PLATE, Plate
    >>> print(Plate() == PLATE, PLATE.height([0.0, 0.5]), PLATE.reach, PLATE.pressure_area)
    True [0. 0.] inf True
    """

    name = "plate"
    summary = "the flat plate, wider than the pocket"
    pressure_area = True

    def height(self, rho) -> np.ndarray:
        """0 at the radii ``rho`` (any shape): the plate, and so its slope, second derivative and curvature."""
        return np.zeros_like(np.asarray(rho, dtype=float))

    slope = second = curvature = height

    @property
    def reach(self) -> float:
        """inf: the plate covers the pocket."""
        return np.inf

    def journal(self) -> str:
        return self.name

    @classmethod
    def from_model(cls, values: Mapping[str, object], spell: Spell = key_name) -> Plate:
        return PLATE

    @classmethod
    def from_physical(cls, values: Mapping[str, object], clamp_radius: float, base=None, spell: Spell = key_name,
                      warnings: list | None = None) -> Plate:
        return PLATE


register(Sphere)  # after the plate: the registry's order is the order the choices are offered in


@register
@dataclasses.dataclass(frozen=True)
class Profile(Indenter):
    """A user's convex indenter z(rho), flat on the axis: its ``shape`` in units of R.

    Parameters
    ----------
    shape : Shape
        A ``pocket.core.profiles.Shape``: ``pocket.core.profiles.table`` (rows of radii and heights),
        ``pocket.core.profiles.functions`` (z, its slope and curvature) or ``pocket.core.profiles.read_csv``
        (a CSV file with units in its header).

    Raises
    ------
    InputError
        For anything but a ``Shape``.

    Examples
    --------
    A profile tabulated from a sphere of radius 0.5 R, pressing the headline pocket:

    >>> import numpy as np
    >>> from pocket import shooting
    >>> from pocket.core.indenters import Profile, Sphere
    >>> from pocket.core.profiles import table
    >>> rho = np.linspace(0.0, 0.45, 40)
    >>> cap = Profile(table(rho, Sphere(0.5).height(rho)))
    >>> print(cap.reach, abs(float(cap.height(0.3)) - float(Sphere(0.5).height(0.3))) < 1e-5)
    0.45 True
    >>> state = shooting.compress(47 / 160, 0.31, 0.19, indenter=cap)
    >>> ball = shooting.compress(47 / 160, 0.31, 0.19, indenter=Sphere(0.5))
    >>> print(abs(state.pressure_ratio / ball.pressure_ratio - 1) < 1e-4)
    True
    """

    shape: Shape
    name = "profile"
    summary = "a user's convex profile z(rho), flat on the axis (a table or functions)"
    keys = ("file",)

    def __post_init__(self):
        if not isinstance(self.shape, Shape):
            raise InputError(f"indenter.shape = {quote(self.shape)}, but it must be a profile "
                             "(pocket.core.profiles: table, functions or read_csv)")

    def height(self, rho) -> np.ndarray:
        return self.shape.height(np.asarray(rho, dtype=float))

    def slope(self, rho) -> np.ndarray:
        return self.shape.slope(np.asarray(rho, dtype=float))

    def second(self, rho) -> np.ndarray:
        return self.shape.second(np.asarray(rho, dtype=float))

    @property
    def reach(self) -> float:
        """Its last radius, the shape's ``extent`` (units R)."""
        return self.shape.extent

    @property
    def knots(self) -> tuple[float, ...]:
        """A table's rows (``Shape.knots``)."""
        return self.shape.knots

    def describe(self) -> str:
        return f"the profile {self.shape.source}"

    def columns(self, clamp_radius: float) -> dict:
        return {"indenter": self.name, "indenter_file": self.shape.source}

    def journal(self) -> str:
        """``profile sha256=...``: a table's content in units of R (``Shape.digest``: the same table read from
        another file or folder is the same indenter); an InputError for a profile given as functions."""
        if not self.shape.digest:
            raise InputError("a sweep records its indenter as text (the plate, a sphere or a profile table), not a "
                             f"{self.name} given as functions")
        return f"{self.name} sha256={self.shape.digest}"

    @classmethod
    def from_model(cls, values: Mapping[str, object], spell: Spell = key_name) -> Profile:
        """The profile of the CSV table ``values["file"]``, its header in units of R (``radius [R],height
        [R]``)."""
        return cls(read_csv(_file(values["file"], spell)))

    @classmethod
    def from_physical(cls, values: Mapping[str, object], clamp_radius: float, base=None, spell: Spell = key_name,
                      warnings: list | None = None) -> Profile:
        """The profile of the CSV table ``values["file"]`` (relative to ``base``), its header in any length unit,
        divided by ``clamp_radius``."""
        name = _file(values["file"], spell)
        return cls(read_csv(pathlib.Path(name) if base is None else pathlib.Path(base) / name, clamp_radius))


def _file(name, spell: Spell) -> str:
    """The file name ``name``; an InputError naming its key if it is none."""
    if not isinstance(name, str) or not name:
        raise InputError(f"{spell('file')} = {quote(name)}, but it must be a file name")
    return name


#: the flat plate (every solver's default)
PLATE = Plate()


def as_indenter(value) -> Indenter:
    """The indenter of ``value``, as every compression entry point takes its ``indenter`` argument.

    Parameters
    ----------
    value : Indenter or None
        None is the flat plate (``PLATE``); an ``Indenter`` is returned as given.

    Returns
    -------
    Indenter

    Raises
    ------
    InputError
        For anything else.

    Examples
    --------
    >>> from pocket.core.indenters import as_indenter
    >>> print(as_indenter(None).name)
    plate
    >>> as_indenter("sphere")
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: indenter = 'sphere', but it must be an Indenter (pocket.core.indenters)
    """
    if value is None:
        return PLATE
    if not isinstance(value, Indenter):
        raise InputError(f"indenter = {quote(value)}, but it must be an Indenter (pocket.core.indenters)")
    return value


def formulation(table: Mapping[type[Indenter], T], solver: str, indenter: Indenter) -> T:
    """``table[type(indenter)]``: the contact formulation with which ``solver`` poses the indenter; an
    InputError naming the solver and the indenter if its table has no entry for its class."""
    if type(indenter) not in table:
        raise InputError(f"solver {solver} does not implement the {indenter.name} indenter "
                         f"(its indenters: {', '.join(kind.name for kind in table)})")
    return table[type(indenter)]


def posed(table: Mapping[type[Indenter], T], solver: str, value: Indenter | None) -> tuple[Indenter, T]:
    """The indenter of ``value`` (``as_indenter``) and the formulation with which ``solver`` poses it
    (``formulation``): the check every compression entry point makes of its ``indenter`` argument."""
    indenter = as_indenter(value)
    return indenter, formulation(table, solver, indenter)
