r"""Indenters: what presses on the inflated pocket, one registered definition per kind.

An indenter is a rigid, frictionless body of revolution pushed down along the axis onto
the dome. Its lower surface is its height profile z(rho) above its lowest point, in units
of the clamp radius R, with z(0) = 0: the surface lies at eta = h + z(rho) when the
indenter's lowest point is at height h.

======  ==========================  ==========  ====================
kind    z(rho)                      parameters  F = P A_c identity
======  ==========================  ==========  ====================
flat    0                           (none)      yes
sphere  R_s - sqrt(R_s^2 - rho^2)   radius R_s  no
profile a user's table or function  shape       no
======  ==========================  ==========  ====================

A sphere's surface exists for rho <= R_s only (its equator); there z is R_s and the slope
infinite, and beyond it ``height``, ``slope`` and ``curvature`` are NaN: a sheet wrapping
past the equator is outside the model, which a solver says in its own words.

A profile is a user's convex z(rho), flat on the axis, given as a table (a CSV file with units in
its header) or as functions with its slope and curvature (``pocket.core.profiles``: the
interpolation and its error, the checks); past its last radius it is NaN like a sphere past its
equator.

On a flat plate the sheet in contact lies flat and carries the fluid pressure P straight
to the plate, and a smooth edge exerts no line force: the force is F = P A_c exactly, an
identity a solver's state can be checked against. On a curved indenter the contact
pressure exceeds P (on a sphere of radius R_s, p_c = P + (T_1 + T_2) / R_s) and the force
is the integral of p_c over the contact area, so F = P A_c is no identity there
(``Indenter.pressure_area`` says which holds).

A ``Kind`` is one entry of the registry ``KINDS``; an ``Indenter`` is a kind with its
parameters (``FLAT`` is the flat plate, every solver's default). Each solver maps a kind
to its own contact formulation through an explicit table and asks ``formulation`` for
it, which refuses a kind the table lacks in one line naming the solver and the indenter:
a new indenter is a new entry here and in the tables of the solvers that pose it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from typing import TypeVar

import numpy as np

from .errors import InputError
from .inputs import check_finite, quote
from .profiles import Shape

#: a kind's parameters by name: numbers (lengths in units of R), or a ``Shape`` for those in its ``shapes``
Params = Mapping[str, "float | Shape"]

__all__ = [
    "FLAT",
    "KINDS",
    "SPHERE_RADII",
    "Indenter",
    "Kind",
    "as_indenter",
    "check_sphere_radius",
    "formulation",
    "posed",
    "profile",
    "register",
    "sphere",
]

T = TypeVar("T")


@dataclasses.dataclass(frozen=True)
class Kind:
    """One kind of indenter: its ``name``, a one-line ``summary``, its ``parameters`` (names, in
    order; lengths in units of R), its ``profile`` z(params, rho) (params: name -> float; rho: float
    array of any shape; returns z of the same shape, units R) and ``pressure_area``, whether
    F = P A_c holds as an identity (module docstring). ``slope`` and ``second`` are dz/drho and
    d2z/drho2 with the signature of ``profile`` (None: the flat plate's zeros); ``check`` refuses
    parameters that make no indenter (params -> None, an ``InputError`` naming the parameter). The
    parameters named in ``shapes`` are a ``pocket.core.profiles.Shape`` rather than a float."""

    name: str
    summary: str
    parameters: tuple[str, ...]
    profile: Callable[[Params, np.ndarray], np.ndarray]
    pressure_area: bool
    slope: Callable[[Params, np.ndarray], np.ndarray] | None = None
    second: Callable[[Params, np.ndarray], np.ndarray] | None = None
    check: Callable[[Params], None] | None = None
    shapes: tuple[str, ...] = ()  # the parameters that are a ``pocket.core.profiles.Shape``, not a float


#: kind name -> its definition
KINDS: dict[str, Kind] = {}


def register(kind: Kind) -> Kind:
    """Add ``kind`` to ``KINDS`` (a name may be registered once); returns it."""
    if kind.name in KINDS:
        raise ValueError(f"indenter kind {kind.name!r} is registered already")
    KINDS[kind.name] = kind
    return kind


@dataclasses.dataclass(frozen=True)
class Indenter:
    """A registered kind by name with its parameters: ``params`` maps each name of the kind's
    ``parameters`` to a float (a ``Shape`` for those in its ``shapes``), given as a mapping or as
    (name, value) pairs in the kind's order (as stored). An unknown kind, a missing or foreign
    parameter or a value that is not a finite number is an ``InputError`` naming it."""

    kind: str
    params: tuple[tuple[str, float | Shape], ...] = ()

    def __post_init__(self):
        if self.kind not in KINDS:
            raise InputError(f"indenter = {quote(self.kind)}, but it must be one of {', '.join(KINDS)}")
        names = KINDS[self.kind].parameters
        given = dict(self.params)
        if set(given) != set(names):
            raise InputError(f"indenter {self.kind} takes the parameters ({', '.join(names)}), "
                             f"not ({', '.join(given)})")
        values = tuple((n, given[n] if n in KINDS[self.kind].shapes else check_finite(f"indenter.{n}", given[n]))
                       for n in names)
        if KINDS[self.kind].check is not None:
            KINDS[self.kind].check(dict(values))
        object.__setattr__(self, "params", values)

    @property
    def definition(self) -> Kind:
        """The registered ``Kind``."""
        return KINDS[self.kind]

    def number(self, name: str) -> float:
        """The numeric parameter ``name`` (a length in units of R); an InputError if it is a shape."""
        return _number(dict(self.params), name)

    def shape(self) -> Shape:
        """A profile's outline (its parameter ``shape``, ``pocket.core.profiles``); an InputError for a kind
        that has none."""
        if "shape" not in self.definition.shapes:
            raise InputError(f"the {self.kind} indenter has no profile (only a profile indenter has)")
        return _shape(dict(self.params))

    @property
    def pressure_area(self) -> bool:
        """F = P A_c holds as an identity (a flat plate), rather than F = the integral of the contact
        pressure."""
        return self.definition.pressure_area

    def height(self, rho) -> np.ndarray:
        """z(rho): the surface's height above its lowest point at the radii ``rho`` (units R, any
        shape; the result has the same shape)."""
        return self.definition.profile(dict(self.params), np.asarray(rho, dtype=float))

    def slope(self, rho) -> np.ndarray:
        """dz/drho at the radii ``rho`` (dimensionless; any shape, the result has the same shape)."""
        rho = np.asarray(rho, dtype=float)
        fn = self.definition.slope
        return np.zeros_like(rho) if fn is None else fn(dict(self.params), rho)

    def curvature(self, rho) -> np.ndarray:
        """The meridional curvature of the surface, z'' / (1 + z'^2)^(3/2), at the radii ``rho`` (units
        1/R, positive where the surface is convex seen from below: 1/R_s everywhere on a sphere)."""
        rho = np.asarray(rho, dtype=float)
        fn = self.definition.second
        if fn is None:
            return np.zeros_like(rho)
        return fn(dict(self.params), rho) / (1.0 + self.slope(rho) ** 2) ** 1.5


def _flat(params: Params, rho: np.ndarray) -> np.ndarray:
    """The flat plate: z = 0 everywhere."""
    return np.zeros_like(rho)


register(Kind("flat", "a flat plate, wider than the pocket", (), _flat, pressure_area=True))


def _number(params: Params, name: str) -> float:
    """The number ``params[name]``; an InputError if a shape stands there instead."""
    value = params[name]
    if isinstance(value, Shape):
        raise InputError(f"indenter.{name} is a profile, but it must be a number")
    return value


def _root(params: Params, rho: np.ndarray) -> np.ndarray:
    """sqrt(R_s^2 - rho^2), NaN past the equator rho > R_s (no warning)."""
    inside = np.square(_number(params, "radius")) - np.square(rho)
    with np.errstate(invalid="ignore"):
        return np.where(inside >= 0.0, np.sqrt(np.maximum(inside, 0.0)), np.nan)


def _sphere(params: Params, rho: np.ndarray) -> np.ndarray:
    """The lower cap of a sphere of radius R_s: z = R_s - sqrt(R_s^2 - rho^2)."""
    return _number(params, "radius") - _root(params, rho)


def _sphere_slope(params: Params, rho: np.ndarray) -> np.ndarray:
    """dz/drho = rho / sqrt(R_s^2 - rho^2) (infinite at the equator)."""
    with np.errstate(divide="ignore"):
        return rho / _root(params, rho)


def _sphere_second(params: Params, rho: np.ndarray) -> np.ndarray:
    """d2z/drho2 = R_s^2 / (R_s^2 - rho^2)^(3/2), so that the curvature is 1/R_s."""
    with np.errstate(divide="ignore"):
        return np.square(_number(params, "radius")) / _root(params, rho) ** 3


#: K = R_s / R of a sphere. From 1e-3: a smaller sphere is finer than the finite-element mesh resolves at the
#: pole (with its default mesh the stretch at the contact is 0.4 % off the shooting solver's at K = 1e-3, 28 % at
#: 1e-4) and nears the start of the shooting solver's pole series (an expansion in r / K from r = 1e-5); and the
#: force it carries before the sheet wraps past its equator, about 4 K in Fhat (Phat_I = 0.3), is no finger's.
#: To 1e3: a larger sphere sags less than R / 2000 over the pocket, which is then the flat plate's (use it), and
#: its height R_s - sqrt(R_s^2 - rho^2) in doubles loses digits as K^2 grows
SPHERE_RADII = (1e-3, 1e3)


def check_sphere_radius(name: str, value, shown: str | None = None) -> float:
    """A sphere's radius K = R_s / R within ``SPHERE_RADII``; otherwise an InputError naming ``name`` and quoting
    the value (``shown`` instead if given: a length as written with its K)."""
    number = check_finite(name, value)
    shown = shown or f"{number:g}"
    if not number > 0.0:
        raise InputError(f"{name} = {shown}, but a sphere's radius must be > 0")
    low, high = SPHERE_RADII
    if not low <= number <= high:
        why = ("a smaller one is finer than the solvers resolve at the pole" if number < low else
               "a larger one sags less than R/2000 over the pocket: use the flat plate")
        raise InputError(f"{name} = {shown}, but a sphere's radius K = R_s/R must lie in "
                         f"[{low:g}, {high:g}] ({why})")
    return number


def _sphere_check(params: Params) -> None:
    check_sphere_radius("indenter.radius", _number(params, "radius"))


register(Kind("sphere", "a sphere of radius R_s (a fingertip), its lowest point on the axis", ("radius",), _sphere,
              pressure_area=False, slope=_sphere_slope, second=_sphere_second, check=_sphere_check))

def _profile(params: Params, rho: np.ndarray) -> np.ndarray:
    """A user's profile: its shape's z(rho)."""
    return _shape(params).height(rho)


def _shape(params: Params) -> Shape:
    """The profile ``params["shape"]``; an InputError if something else stands there."""
    value = params["shape"]
    if not isinstance(value, Shape):
        raise InputError(f"indenter.shape = {quote(value)}, but it must be a profile "
                         "(pocket.core.profiles: table, functions or read_csv)")
    return value


def _profile_check(params: Params) -> None:
    _shape(params)


register(Kind("profile", "a user's convex profile z(rho), flat on the axis (a table or functions)", ("shape",),
              _profile, pressure_area=False, slope=lambda params, rho: _shape(params).slope(rho),
              second=lambda params, rho: _shape(params).second(rho), check=_profile_check, shapes=("shape",)))

#: the flat plate (every solver's default)
FLAT = Indenter("flat")


def sphere(radius: float) -> Indenter:
    """A sphere of radius R_s = ``radius`` (units R)."""
    return Indenter("sphere", (("radius", radius),))


def profile(shape: Shape) -> Indenter:
    """The user's profile ``shape`` (``pocket.core.profiles``) as an indenter."""
    return Indenter("profile", (("shape", shape),))


def as_indenter(value) -> Indenter:
    """The indenter of ``value``: None is the flat plate, an ``Indenter`` is returned as given; anything
    else is an InputError."""
    if value is None:
        return FLAT
    if not isinstance(value, Indenter):
        raise InputError(f"indenter = {quote(value)}, but it must be an Indenter (pocket.core.indenters)")
    return value


def formulation(table: Mapping[str, T], solver: str, indenter: Indenter) -> T:
    """``table[indenter.kind]``: the contact formulation with which ``solver`` poses the indenter; an
    InputError naming the solver and the indenter if its table has no entry for that kind."""
    if indenter.kind not in table:
        raise InputError(f"solver {solver} does not implement the {indenter.kind} indenter "
                         f"(its indenters: {', '.join(table)})")
    return table[indenter.kind]


def posed(table: Mapping[str, T], solver: str, value: Indenter | None) -> tuple[Indenter, T]:
    """The indenter of ``value`` (``as_indenter``) and the formulation with which ``solver`` poses it
    (``formulation``): the check every compression entry point makes of its ``indenter`` argument."""
    indenter = as_indenter(value)
    return indenter, formulation(table, solver, indenter)
