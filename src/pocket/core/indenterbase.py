r"""What every indenter is and says: the abstract ``Indenter`` and the registry ``INDENTERS`` of its kinds by name.

An indenter is a rigid, frictionless body of revolution pushed down along the axis onto the dome. Its lower
surface is its height profile z(rho) above its lowest point, in units of the clamp radius R, with z(0) = 0: the
surface lies at eta = h + z(rho) when the indenter's lowest point is at height h. Each kind is a frozen
dataclass deriving from ``Indenter`` (``pocket.core.indenters``: the plate, the sphere, a profile), registered
under its ``name`` (``register``), the word a user types for it. It owns its geometry (``height``, ``slope``,
``second``, ``curvature``, ``reach``) and what the applications say and read of it (``describe``, ``columns``,
``journal``, ``keys`` with ``from_model`` and ``from_physical``, ``meridian``), so that no code outside the core
and the solvers' contact formulations asks which kind it is.
"""

from __future__ import annotations

import abc
import dataclasses
from collections.abc import Callable, Mapping
from typing import ClassVar, TypeVar

import numpy as np

from .errors import InputError

__all__ = ["INDENTERS", "Indenter", "Spell", "key_name", "register"]

#: how a key of an ``[indenter]`` table is named in messages (``indenter.radius``, or a command line's flag)
Spell = Callable[[str], str]


def key_name(key: str) -> str:
    """The name of the ``[indenter]`` key ``key`` in a case file's messages: ``indenter.<key>``."""
    return f"indenter.{key}"


@dataclasses.dataclass(frozen=True)
class Indenter(abc.ABC):
    """A rigid, frictionless body of revolution pushed down the axis onto the dome: the base of every indenter.

    Its lower surface z(rho) stands above its lowest point (units R, z(0) = 0). A kind defines ``height``,
    ``slope``, ``second`` and ``reach``; the rest follows from them or has a default it may override. The
    kinds are registered in ``INDENTERS`` (``register``); each solver maps a kind to its contact formulation
    through its own table (``CONTACTS``).

    Attributes
    ----------
    name : str
        The kind's name, as case files and flags write it.
    summary : str
        The kind in one line.
    pressure_area : bool
        Whether F = P A_c holds as an identity (the plate: the sheet in contact lies flat and carries the fluid
        pressure P straight to it), rather than F = the integral of the contact pressure.
    keys : tuple of str
        What its ``[indenter]`` table takes besides ``shape`` (its case-file keys and command-line flags).

    Examples
    --------
    >>> from pocket.core.indenters import INDENTERS, Indenter
    >>> print(list(INDENTERS), all(issubclass(kind, Indenter) for kind in INDENTERS.values()))
    ['plate', 'sphere', 'profile'] True
    """

    name: ClassVar[str]
    summary: ClassVar[str]
    pressure_area: ClassVar[bool] = False
    keys: ClassVar[tuple[str, ...]] = ()

    @abc.abstractmethod
    def height(self, rho) -> np.ndarray:
        """z(rho): the surface's height above its lowest point at the radii ``rho`` (units R, any shape; the
        result has the same shape; NaN past ``reach``)."""

    @abc.abstractmethod
    def slope(self, rho) -> np.ndarray:
        """dz/drho at the radii ``rho`` (units R; dimensionless, the shape of ``rho``)."""

    @abc.abstractmethod
    def second(self, rho) -> np.ndarray:
        """d2z/drho2 at the radii ``rho`` (units R; units 1/R, the shape of ``rho``)."""

    @property
    @abc.abstractmethod
    def reach(self) -> float:
        """The largest radius rho the surface stands above (units R; inf for the plate)."""

    @property
    def knots(self) -> tuple[float, ...]:
        """The radii (units R, increasing) where the surface's smooth pieces join, so that a derivative of z (z''
        or a higher one) may jump there: none unless a kind says so."""
        return ()

    def curvature(self, rho) -> np.ndarray:
        """The meridional curvature of the surface, z'' / (1 + z'^2)^(3/2), at the radii ``rho`` (units R; units
        1/R, positive where the surface is convex seen from below: 1/R_s everywhere on a sphere)."""
        rho = np.asarray(rho, dtype=float)
        return self.second(rho) / (1.0 + self.slope(rho) ** 2) ** 1.5

    def describe(self) -> str:
        """The indenter in words, for messages and reports (its kind's summary unless it says more)."""
        return self.summary

    def columns(self, clamp_radius: float) -> dict:
        """The indenter as a case reports it (JSON-ready) on a clamp of radius ``clamp_radius`` (m): ``indenter``
        (its name) and its sizes in physical units."""
        return {"indenter": self.name}

    def journal(self) -> str:
        """The indenter as a sweep's journal records it, one cell of text naming it exactly; an InputError for
        one a sweep cannot record."""
        raise InputError(f"a sweep records its indenter as text (the plate, a sphere or a profile table), not "
                         f"{self.describe()}")

    @classmethod
    def from_model(cls, values: Mapping[str, object], spell: Spell = key_name) -> Indenter:
        """The indenter of its ``keys`` ``values`` in the model's units (lengths in units of R, a profile's file
        in units of R); ``spell(key)`` names a key in messages."""
        raise InputError(f"a {cls.name} indenter cannot be given by {', '.join(map(spell, cls.keys)) or 'keys'}")

    @classmethod
    def from_physical(cls, values: Mapping[str, object], clamp_radius: float, base=None, spell: Spell = key_name,
                      warnings: list | None = None) -> Indenter:
        """The indenter of its ``keys`` ``values`` in physical units (lengths with their unit, files relative to
        the folder ``base``) on a clamp of radius ``clamp_radius`` (m), made dimensionless by it; size warnings
        are appended to ``warnings``."""
        raise InputError(f"a {cls.name} indenter cannot be given in physical units")

    def numbers(self) -> dict[str, float]:
        """Its numeric parameters by name (lengths in units of R: a sphere's ``radius``)."""
        values = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}
        return {name: value for name, value in values.items() if isinstance(value, float)}

    def meridian(self, reach: float, rings: int) -> tuple[np.ndarray, np.ndarray]:
        """(rho, z) at ``rings`` radii rho_k = e sin(pi k / (2 (rings - 1))) out to e = min(``reach``, its own
        reach) (units R), denser towards the rim where a surface steepens: the outline drawn of it (the plate: a
        disc of radius ``reach``)."""
        extent = min(reach, self.reach)
        rho = extent * np.sin(0.5 * np.pi * np.linspace(0.0, 1.0, rings))
        rho[-1] = extent  # sin(pi/2) is 1 only to rounding
        return rho, self.height(rho)


#: name -> the indenter class of that kind
INDENTERS: dict[str, type[Indenter]] = {}

K = TypeVar("K", bound=type[Indenter])


def register(cls: K) -> K:
    """Add the indenter class ``cls`` to ``INDENTERS`` under its ``name`` (a name may be registered once);
    returns it (a class decorator)."""
    if cls.name in INDENTERS:
        raise ValueError(f"indenter {cls.name!r} is registered already")
    INDENTERS[cls.name] = cls
    return cls
