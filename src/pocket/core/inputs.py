"""The one input checker: every value a user gives passes through here before any work.

Each check returns the value in its checked form (a float, an int) or raises an
``InputError`` of one line that names the input and quotes the value, e.g.
``alpha = -1.2, but the Mooney-Rivlin model needs alpha > -1``.
"""

from __future__ import annotations

import math
import numbers
import operator
import os
import pathlib
import reprlib
import stat
from collections.abc import Iterable

import numpy as np

from .errors import STRETCH_LIMIT, InputError

__all__ = [
    "FORCE_UNITS",
    "MAGNITUDES",
    "MAX_FILE_BYTES",
    "VOLUME_LIMIT",
    "check_alpha",
    "check_choice",
    "check_count",
    "check_file",
    "check_finite",
    "check_flag",
    "check_force",
    "check_forces",
    "check_non_negative",
    "check_positive",
    "check_range",
    "check_tolerance",
    "check_volume",
    "forces_in_fhat",
    "quote",
]

#: smallest relative tolerance a solver is asked for: a few ulps of a number of order one
TOLERANCE_FLOOR = 1e-14

#: smallest and largest nonzero |value| of a dimensionless input (alpha, Phat, Fhat, a penalty):
#: far outside what a rubber pocket is, and far from where the solvers' products of such numbers
#: overflow or underflow a double (Phat = 1e300 or 1e-300 would, inside them)
MAGNITUDES = (1e-12, 1e12)

#: the largest volume V/R^3 a sheet within ``STRETCH_LIMIT`` encloses over its clamp circle. The sheet and the
#: clamp's disc bound the fluid; the sheet's area is at most J pi R^2, J = STRETCH_LIMIT^2 its largest thinning
#: (lambda_1 lambda_2), and the isoperimetric inequality (area^3 >= 36 pi V^2) gives V <= (pi / 6) (1 + J)^(3/2) R^3
#: (5.24e5 R^3); a larger volume needs the sheet thinned more than J-fold somewhere
VOLUME_LIMIT = math.pi / 6.0 * (1.0 + STRETCH_LIMIT**2) ** 1.5

#: largest input file a solver option may name (a mesh file): a bound on the work it can ask for
MAX_FILE_BYTES = 100_000_000

_QUOTE = reprlib.Repr()
_QUOTE.maxlevel, _QUOTE.maxlist, _QUOTE.maxdict, _QUOTE.maxstring, _QUOTE.maxother = 2, 4, 4, 60, 60


def quote(value) -> str:
    """A value as a message quotes it: numbers plainly (numpy's ``np.float64(...)`` as ``0.1``), text in
    quotes, long text and nested lists or tables shortened with ``...`` (a message stays one short line)."""
    if isinstance(value, bool) or value is None:
        return repr(value)
    if isinstance(value, numbers.Integral):
        whole = int(value)
        return str(whole) if abs(whole) < 10**30 else _QUOTE.repr(whole)
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return " ".join(_QUOTE.repr(value).split())


def check_finite(name, value) -> float:
    """``value`` as a finite float (a bool is not a number)."""
    if isinstance(value, bool):
        raise InputError(f"{name} = {quote(value)} is not a number")
    try:
        number = float(value)
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"{name} = {quote(value)} is not a number") from None
    if not math.isfinite(number):
        raise InputError(f"{name} = {quote(value)} is not finite")
    return number


def _magnitude(name, value, number: float) -> float:
    """``number`` if it is 0 or its magnitude lies within ``MAGNITUDES``."""
    low, high = MAGNITUDES
    if number != 0.0 and not low <= abs(number) <= high:
        raise InputError(f"{name} = {quote(value)} is outside the magnitudes of the model's dimensionless inputs "
                         f"({low:g} to {high:g})")
    return number


def check_alpha(alpha) -> float:
    """alpha = C2/C1 must be > -1 (E = 6 (1 + alpha) C1 > 0)."""
    value = check_finite("alpha", alpha)
    if value <= -1.0:
        raise InputError(f"alpha = {quote(alpha)}, but the Mooney-Rivlin model needs alpha > -1")
    if value > MAGNITUDES[1]:  # a ratio: any small value (neo-Hookean-like) is fine, a huge one is not a rubber
        raise InputError(f"alpha = {quote(alpha)} is outside the magnitudes of the model's dimensionless inputs "
                         f"(at most {MAGNITUDES[1]:g})")
    return value


def check_positive(name, value) -> float:
    """A dimensionless quantity that must be > 0 (a pressure, a volume, a penalty), within ``MAGNITUDES``."""
    number = check_finite(name, value)
    if number <= 0.0:
        raise InputError(f"{name} = {quote(value)}, but it must be > 0")
    return _magnitude(name, value, number)


def check_range(name, value, low: float, high: float, why: str, shown: str | None = None) -> float:
    """A finite number in [low, high]; otherwise an InputError naming ``name``, quoting the value (``shown``
    instead if given: a case file's text with its dimensionless form) and saying ``why`` the range ends there."""
    number = check_finite(name, value)
    if not low <= number <= high:
        raise InputError(f"{name} = {shown or quote(value)}, but it must lie in [{low:g}, {high:g}] ({why})")
    return number


def check_volume(name, value, shown: str | None = None) -> float:
    """An enclosed volume V/R^3 (volume control): > 0 within ``MAGNITUDES`` and at most ``VOLUME_LIMIT``, the
    most a sheet within ``STRETCH_LIMIT`` encloses (``shown``: the value as a message quotes it, e.g. a case
    file's text with its V/R^3)."""
    number, shown = check_finite(name, value), shown or quote(value)
    if number <= 0.0:
        raise InputError(f"{name} = {shown}, but it must be > 0")
    if number < MAGNITUDES[0]:
        raise InputError(f"{name} = {shown} is outside the magnitudes of the model's dimensionless inputs "
                         f"({MAGNITUDES[0]:g} to {MAGNITUDES[1]:g})")
    if number > VOLUME_LIMIT:
        raise InputError(f"{name} = {shown}, but a state of the model encloses at most V/R^3 = {VOLUME_LIMIT:.3g}: "
                         f"more needs the sheet thinned past {STRETCH_LIMIT**2:g}-fold somewhere (the isoperimetric "
                         f"inequality), past the model's stretch limit of {STRETCH_LIMIT:g}")
    return number


def check_non_negative(name, value) -> float:
    """A quantity that must be finite and >= 0."""
    number = check_finite(name, value)
    if number < 0.0:
        raise InputError(f"{name} = {quote(value)}, but it must be >= 0")
    return number


def check_force(force) -> float:
    """The force Fhat = F / (P_I pi R^2) must be >= 0 (the plate pushes) and at most the largest of
    ``MAGNITUDES``; any small force is the limit of an unloaded pocket, not an error."""
    number = check_finite("force", force)
    if number < 0.0:
        raise InputError(f"force = {quote(force)}, but a plate can only push: it must be >= 0")
    if number > MAGNITUDES[1]:
        raise InputError(f"force = {quote(force)} is outside the magnitudes of the model's dimensionless inputs "
                         f"(at most {MAGNITUDES[1]:g})")
    return number


#: the units a compression's forces are given in: Fhat = F / (P_I pi R^2), or F / (E T R) (a capsule's
#: ``force_ETR``, the only one an uninflated capsule has: its Fhat is undefined)
FORCE_UNITS = ("Fhat", "ETR")


def forces_in_fhat(forces: Iterable[float] | np.ndarray | float, unit: str, pressure_initial: float) -> list[float]:
    """Checked ``forces`` (``check_forces``) given in ``unit`` (one of ``FORCE_UNITS``) as Fhat = F / (P_I pi R^2),
    for P_I = ``pressure_initial`` > 0.

    Examples
    --------
    >>> [round(f, 12) for f in forces_in_fhat([0.0, 0.1 * math.pi], "ETR", 0.1)]
    [0.0, 1.0]
    """
    checked = check_forces(forces)
    if check_choice("force_unit", unit, FORCE_UNITS) == "Fhat":
        return checked
    return [f / (math.pi * pressure_initial) for f in checked]


def check_forces(forces: Iterable[float] | np.ndarray | float) -> list[float]:
    """Each force of ``forces`` (a number or several, in the order given) checked by ``check_force``; none at
    all is an InputError ("no force given")."""
    checked = [check_force(f) for f in np.atleast_1d(np.asarray(forces, dtype=object))]
    if not checked:
        raise InputError("no force given")
    return checked


def check_count(name, value, low: int, high: int) -> int:
    """An integer in [low, high] (an element count, a number of points; ``high`` bounds the work)."""
    try:
        if isinstance(value, bool):
            raise TypeError
        number = operator.index(value)
    except TypeError:
        raise InputError(f"{name} = {quote(value)} is not an integer") from None
    if not low <= number <= high:
        raise InputError(f"{name} = {quote(value)}, but it must lie in [{low}, {high}]")
    return number


def check_tolerance(name, value, high: float) -> float:
    """A relative tolerance in [TOLERANCE_FLOOR, high]: below the floor no double can meet it, above
    ``high`` the solver's answer would not resolve what it reports."""
    number = check_finite(name, value)
    if not TOLERANCE_FLOOR <= number <= high:
        why = ("no double-precision solve can meet it" if number < TOLERANCE_FLOOR else
               "a looser tolerance would not resolve the reported numbers")
        raise InputError(f"{name} = {quote(value)}, but it must lie in [{TOLERANCE_FLOOR:g}, {high:g}] ({why})")
    return number


def check_flag(name, value) -> bool:
    """A true/false switch (a bool, not a number or a string)."""
    if not isinstance(value, bool):
        raise InputError(f"{name} = {quote(value)}, but it must be true or false")
    return value


def check_choice(name, value, choices):
    """One of ``choices`` (compared with ==; a bool is not the integer 1)."""
    if isinstance(value, bool) or value not in choices:
        raise InputError(f"{name} = {quote(value)}, but it must be one of {', '.join(map(repr, choices))}")
    return value


def check_file(name, value, max_bytes: int = MAX_FILE_BYTES) -> str:
    """The name of an existing regular file of at most ``max_bytes`` bytes (an input a solver reads)."""
    if not isinstance(value, (str, os.PathLike)):
        raise InputError(f"{name} = {quote(value)}, but it must be a file name")
    path = pathlib.Path(value)
    try:
        info = path.stat()
    except OSError as err:
        raise InputError(f"{name} = {quote(str(value))}: cannot read it ({err.strerror})") from None
    if not stat.S_ISREG(info.st_mode):
        raise InputError(f"{name} = {quote(str(value))} is not a regular file")
    if info.st_size > max_bytes:
        raise InputError(f"{name} = {quote(str(value))} has {info.st_size} bytes, but an input file has at most "
                         f"{max_bytes}")
    return str(value)
