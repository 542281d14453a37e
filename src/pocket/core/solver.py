"""The record of a solver: its name, its entry points and the options it takes, declared once.

Every solver package declares one ``Solver`` (``pocket.shooting.SOLVER``,
``pocket.fem.SOLVER``, ``pocket.analytical.SOLVER``). The command line's flags
(``--rtol``, ``--elements``, ...), the case-file keys (``[solver] elements = 200``)
and the validation suite's solver columns are all derived from it, so that an
option a solver does not take is an error everywhere, never silently ignored.

An ``Option`` is one keyword argument of the solver's entry points. Its name is
the keyword, the case-file key and (as ``--name``) the command-line flag. Its
``check`` turns a given value into the checked one or raises a one-line
``InputError`` (the checks live in ``pocket.core.inputs``). ``steps`` says
which steps take it: a contact penalty means nothing to an inflation.

Entry points (functions of the module ``Solver.module``), all in the
dimensionless units of ``pocket.core.states``:

- ``inflate(material, pressure, *, geometry=None, **options) -> InflatedState``
- ``inflate_volume(material, volume, *, geometry=None, **options) -> InflatedState``
- ``inflation_curve(material, pressures, *, geometry=None, progress=None, **options) -> list[InflatedState]``: the
  states at several pressures (optional: a solver that can share work between them lists it)
- ``compress(material, pressure_initial, force, *, fluid=None, indenter=None, geometry=None, **options)
  -> CompressedState``
- ``compression_curve(material, pressure_initial, forces, *, fluid=None, indenter=None, geometry=None,
  progress=None, **options) -> list[CompressedState]``
- ``compress_height(material, pressure_initial, height, *, fluid=None, indenter=None, geometry=None, **options)
  -> CompressedState``: travel control, the indenter's lowest point at ``height`` = H/R above the clamp
  plane (optional: listed in ``entry_points`` by a solver that has it)

Each has a ``Protocol`` here (``Inflate``, ``InflateVolume``, ``InflationCurve``, ``Compress``,
``CompressionCurve``, ``CompressHeight``, ``RangeEnd``) that type checkers hold the solvers' ``api`` modules to:
it fixes the positional arguments and the result, and leaves the keywords (``*args: Any, **options: Any``,
which match any) to each solver's own annotated signature.

A record lists the entry points its solver has (``entry_points``, keys of ``ENTRY_POINTS``), and callers
get them from it (``Solver.entry``): a request a solver cannot serve is a one-line ``InputError`` naming
the solver and what it lacks, never an ``AttributeError`` from its module.

``material`` is the rubber, a ``pocket.core.materials.Material``: any law in any stress unit (the
solver scales it to mu_0 itself), a Mooney-Rivlin one given by its alpha = C2/C1 as
``mooney_rivlin(alpha)``; ``pocket.core.materials.as_material`` checks it at each entry point and, as a
convenience for Python callers, takes a number as that alpha. ``fluid`` is the fluid sealed in
the pocket at the initial pressure: None or "liquid" (fixed volume), or a gas
(``pocket.core.fluids.gas``) whose ambient pressure is dimensionless like every pressure,
Phat_atm = P_atm R / (E T) (``pocket.core.fluids.as_fluid`` checks it). Inflation takes no fluid: the
gas is sealed once the pocket is inflated. ``indenter`` is what presses on the pocket: None (the flat
plate, ``pocket.core.indenters.PLATE``) or an ``Indenter``; each solver maps the classes it poses to its
contact formulation in a table and refuses another in one line (``indenters.formulation``).
``geometry`` is the membrane's reference surface (a ``GeometryLike``): None (the flat disc clamped at r = R,
``pocket.core.geometries.DISC``), a ``Geometry`` or its name; each solver maps the surfaces it poses to its
formulation in a table and refuses another in one line (``geometries.formulation``).
States echo ``material`` as given (their ``alpha`` is derived from it: the alpha it was given by, else None),
``fluid`` as given (``LIQUID`` for None) and ``indenter`` (``PLATE`` for None); an inflated state carries its
``geometry`` (``DISC`` for None), and a compressed state that of the inflated state it was pressed from.

``progress``, if given, is called as ``progress(done, total)`` after each force of a
curve (a command line shows a bar with it); it is not an option of the record.
A solver may also have ``range_end(material, pressure_initial, *, fluid=None, indenter=None, geometry=None,
**options) -> float``,
the force Fhat at which its model's range ends (listed in ``entry_points``; inf where the range has
no end, as for a rubber that locks before the sheet reaches the clamp plane).
"""

from __future__ import annotations

import dataclasses
import importlib
from collections.abc import Callable, Iterable, Sequence
from typing import Any, Literal, Protocol, TypeAlias, overload

import numpy as np

from .errors import InputError
from .fluids import Fluid
from .geometries import Geometry
from .inputs import check_file
from .materials import Material
from .states import CompressedState, InflatedState

__all__ = [
    "ENTRY_POINTS",
    "STEPS",
    "Compress",
    "CompressHeight",
    "CompressionCurve",
    "FluidLike",
    "GeometryLike",
    "Inflate",
    "InflateVolume",
    "InflationCurve",
    "MaterialLike",
    "Numbers",
    "Option",
    "Progress",
    "RangeEnd",
    "Solver",
]

#: the two steps of the problem
STEPS = ("inflate", "compress")
#: entry point -> what it computes, in the words of an error naming what a solver lacks
ENTRY_POINTS = {"inflate": "pressure-controlled inflation", "inflate_volume": "volume-controlled inflation",
                "inflation_curve": "inflation curve",
                "compress": "compression", "compression_curve": "compression curve",
                "compress_height": "height-controlled compression",
                "range_end": "end of the compression range"}

#: what a ``material`` argument may be: a ``Material``, or a number taken as the Mooney-Rivlin alpha = C2/C1
#: (``pocket.core.materials.as_material``)
MaterialLike: TypeAlias = Material | float
#: what a ``fluid`` argument may be: None or "liquid" (fixed volume), or a ``Fluid`` (``pocket.core.fluids.as_fluid``)
FluidLike: TypeAlias = Fluid | str | None
#: what a ``geometry`` argument may be: None (the flat clamped disc), a ``Geometry`` or its name
#: (``pocket.core.geometries.as_geometry``)
GeometryLike: TypeAlias = Geometry | str | None
#: several dimensionless values (pressures, forces): a sequence of numbers or a 1-D array
Numbers: TypeAlias = Sequence[float] | np.ndarray
#: a curve's progress callback, called as ``progress(done, total)`` after each point
Progress: TypeAlias = Callable[[int, int], object]


class Inflate(Protocol):
    """``inflate``: the inflated state at a pressure, on the first branch (pressure control).

    Parameters
    ----------
    material : MaterialLike
        The rubber.
    pressure : float
        Phat = P R / (E T), > 0 (dimensionless).
    **options
        ``geometry`` (a ``GeometryLike``: the reference surface, None the flat clamped disc) and the solver's
        options (its record's ``options``; each solver's own signature names them).

    Returns
    -------
    InflatedState
    """

    def __call__(self, material: MaterialLike, pressure: float, *args: Any, **options: Any) -> InflatedState: ...


class InflateVolume(Protocol):
    """``inflate_volume``: the inflated state enclosing a volume (volume control).

    Parameters
    ----------
    material : MaterialLike
        The rubber.
    volume : float
        V / R^3, > 0 (dimensionless).
    **options
        As for ``Compress``.

    Returns
    -------
    InflatedState
    """

    def __call__(self, material: MaterialLike, volume: float, *args: Any, **options: Any) -> InflatedState: ...


class InflationCurve(Protocol):
    """``inflation_curve``: the inflated states at several pressures, in the order given.

    Parameters
    ----------
    material : MaterialLike
        The rubber.
    pressures : Numbers
        Phat of each state, > 0 (dimensionless).
    **options
        ``geometry`` (as for ``Inflate``), ``progress`` (a ``Progress``, called after each pressure) and the
        solver's options.

    Returns
    -------
    list of InflatedState
    """

    def __call__(self, material: MaterialLike, pressures: Numbers, *args: Any,
                 **options: Any) -> list[InflatedState]: ...


class Compress(Protocol):
    """``compress``: the pocket inflated at ``pressure_initial``, sealed, and pressed by ``force``.

    Parameters
    ----------
    material : MaterialLike
        The rubber.
    pressure_initial : float
        Phat_I, the inflation pressure at which the fluid is sealed (dimensionless).
    force : float
        Fhat = F / (P_I pi R^2), >= 0 (dimensionless).
    **options
        ``fluid`` (a ``FluidLike``: the sealed fluid, None a liquid), ``indenter`` (an ``Indenter``, None the flat
        plate), ``geometry`` (as for ``Inflate``) and the solver's options.

    Returns
    -------
    CompressedState
    """

    def __call__(self, material: MaterialLike, pressure_initial: float, force: float, *args: Any,
                 **options: Any) -> CompressedState: ...


class CompressionCurve(Protocol):
    """``compression_curve``: the compressed states at several forces, in the order given.

    Parameters
    ----------
    material, pressure_initial
        As for ``Compress``.
    forces : Numbers
        Fhat of each state, >= 0 (dimensionless); at least one.
    **options
        ``fluid``, ``indenter``, ``geometry`` (as for ``Compress``), ``progress`` (a ``Progress``, called after
        each force), the solver's options and, for the solvers that press an uninflated capsule (shooting, fem),
        ``force_unit`` (``pocket.core.inputs.FORCE_UNITS``: "ETR" for forces F / (E T R)).

    Returns
    -------
    list of CompressedState
    """

    def __call__(self, material: MaterialLike, pressure_initial: float, forces: Numbers, *args: Any,
                 **options: Any) -> list[CompressedState]: ...


class CompressHeight(Protocol):
    """``compress_height``: the compressed state with the indenter's lowest point at ``height`` (travel control).

    Parameters
    ----------
    material, pressure_initial
        As for ``Compress``.
    height : float
        H / R above the clamp plane, > 0 (dimensionless).
    **options
        As for ``Compress``.

    Returns
    -------
    CompressedState
    """

    def __call__(self, material: MaterialLike, pressure_initial: float, height: float, *args: Any,
                 **options: Any) -> CompressedState: ...


class RangeEnd(Protocol):
    """``range_end``: the force at which the model's compression range ends.

    Parameters
    ----------
    material, pressure_initial
        As for ``Compress``.
    **options
        As for ``Compress``.

    Returns
    -------
    float
        Fhat at the end (dimensionless); inf where the range has no end.
    """

    def __call__(self, material: MaterialLike, pressure_initial: float, *args: Any, **options: Any) -> float: ...


@dataclasses.dataclass(frozen=True)
class Option:
    """One keyword option of a solver (see the module docstring).

    ``kind`` is how a user writes it: ``"float"``, ``"int"``, ``"bool"``,
    ``"path"`` (a file name) or ``"choice"`` (one word of ``choices``);
    ``default`` is what the solver uses when it is not given (documentation:
    the solver's signature holds the same value).
    """

    name: str
    kind: str
    default: object
    help: str
    check: Callable[[str, object], object]
    steps: tuple[str, ...] = STEPS
    choices: tuple[str, ...] = ()

    def checked(self, value, spell: Callable[[str], str] = str):
        """``value`` checked, with errors naming the option as ``spell(name)`` would; a ``"path"``
        is first checked to name a readable regular file of bounded size (``check_file``)."""
        if self.kind == "path":
            value = check_file(spell(self.name), value)
        return self.check(spell(self.name), value)


@dataclasses.dataclass(frozen=True)
class Solver:
    """A solver: its name, a one-line summary, the module of its entry points, its options."""

    name: str
    summary: str
    module: str
    entry_points: tuple[str, ...]
    options: tuple[Option, ...] = ()

    def __post_init__(self):
        unknown = sorted(set(self.entry_points) - set(ENTRY_POINTS))
        if unknown:
            raise ValueError(f"solver {self.name}: {', '.join(unknown)} not among the entry points "
                             f"{', '.join(ENTRY_POINTS)}")

    def serves(self, name: str) -> bool:
        """Whether this solver has the entry point ``name`` (a key of ``ENTRY_POINTS``)."""
        if name not in ENTRY_POINTS:
            raise ValueError(f"{name!r} is not an entry point (they are {', '.join(ENTRY_POINTS)})")
        return name in self.entry_points

    @overload
    def entry(self, name: Literal["inflate"], purpose: str,
              alternatives: Iterable[str] = ()) -> Inflate: ...
    @overload
    def entry(self, name: Literal["inflate_volume"], purpose: str,
              alternatives: Iterable[str] = ()) -> InflateVolume: ...
    @overload
    def entry(self, name: Literal["inflation_curve"], purpose: str,
              alternatives: Iterable[str] = ()) -> InflationCurve: ...
    @overload
    def entry(self, name: Literal["compress"], purpose: str,
              alternatives: Iterable[str] = ()) -> Compress: ...
    @overload
    def entry(self, name: Literal["compression_curve"], purpose: str,
              alternatives: Iterable[str] = ()) -> CompressionCurve: ...
    @overload
    def entry(self, name: Literal["compress_height"], purpose: str,
              alternatives: Iterable[str] = ()) -> CompressHeight: ...
    @overload
    def entry(self, name: Literal["range_end"], purpose: str,
              alternatives: Iterable[str] = ()) -> RangeEnd: ...
    @overload
    def entry(self, name: str, purpose: str, alternatives: Iterable[str] = ()) -> Callable[..., Any]: ...

    def entry(self, name: str, purpose: str, alternatives: Iterable[str] = ()) -> Callable[..., Any]:
        """The entry point ``name`` (a function of ``module``), asked for ``purpose``: what needs it, as the
        user gave it (``"initial.volume = '2 mL'"``, ``"--volume"``).

        A solver without it is a one-line ``InputError`` naming ``purpose``, the solver, what it lacks and
        ``alternatives`` (the names of solvers that have it). Typed by name: ``entry("inflate", ...)`` is an
        ``Inflate``, and so on.
        """
        if not self.serves(name):
            alternatives = ", ".join(alternatives)
            offer = f"; solvers that have it: {alternatives}" if alternatives else ""
            raise InputError(f"{purpose}: solver {self.name} has no {ENTRY_POINTS[name]} (entry point {name}{offer})")
        return getattr(importlib.import_module(self.module), name)

    def option(self, name: str) -> Option | None:
        """The option ``name``, or None if this solver does not take it."""
        return next((o for o in self.options if o.name == name), None)

    def check_option(self, name: str, value, spell: Callable[[str], str] = str):
        """``value`` checked by this solver's option ``name`` (``Option.checked``). A ValueError if the record
        does not declare ``name``: a solver checking an option its own record lacks is a defect of the solver."""
        option = self.option(name)
        if option is None:
            raise ValueError(f"solver {self.name} declares no option {name!r}")
        return option.checked(value, spell)

    def checked(self, given: dict, step: str, spell: Callable[[str], str] = str) -> dict:
        """The options ``given`` (name -> value) checked for ``step`` ("inflate" or "compress").

        An option this solver does not take, or one its ``step`` does not use,
        is an ``InputError`` naming it as ``spell(name)``.
        """
        out = {}
        for name, value in given.items():
            option = self.option(name)
            if option is None:
                takes = ", ".join(spell(o.name) for o in self.options) or "none"
                raise InputError(f"{spell(name)} does not apply to solver {self.name} (its options: {takes})")
            if step not in option.steps:
                raise InputError(f"{spell(name)} applies to {' and '.join(option.steps)}, not to {step}")
            out[name] = option.checked(value, spell)
        return out
