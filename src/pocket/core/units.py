"""Physical quantities in, SI floats out: the one place units are handled (pint).

A value is a number (taken as SI: metres, pascals, newtons, cubic metres) or a
string with a unit, ``"0.25 mm"``, ``"4.8 kPa"``, ``"0.67 N"``, ``"2 mL"``,
which pint parses and converts. A string without a unit is SI too. The
quantity's dimension must match its kind: ``"4 mm"`` for a pressure is an
``InputError`` naming the key. A nonzero magnitude must lie within
``MAGNITUDES`` (in SI): products of a few such values stay far from the
overflow and underflow of doubles, where ``"1e300 m"`` would silently give
inf or 0. Everything past this module is SI floats.

pint is imported on first use, so that commands which need no units do not pay
for its registry (about 0.2 s).
"""

from __future__ import annotations

import functools
import math

from .errors import InputError
from .inputs import quote

__all__ = [
    "KINDS",
    "MAGNITUDES",
    "SUGGESTED",
    "has_unit",
    "is_plain",
    "plain_warnings",
    "positive",
    "quantity",
    "written_like",
]

#: kind -> (pint dimensionality, SI unit)
KINDS = {
    "length": ("[length]", "m"),
    "pressure": ("[pressure]", "Pa"),
    "force": ("[force]", "N"),
    "volume": ("[volume]", "m**3"),
}


#: kind -> the unit a pocket's values of that kind are usually written in (the plain-number warning's hint)
SUGGESTED = {"length": "mm", "pressure": "kPa", "force": "N", "volume": "mL"}

#: smallest and largest nonzero |value| in SI units
MAGNITUDES = (1e-20, 1e20)


@functools.cache
def _registry():
    import pint

    return pint.UnitRegistry()


class _WrongDimension(Exception):
    """A parsed quantity of another dimension (its message is that dimension)."""


def _si(text: str, dimension: str, unit: str) -> float:
    parsed = _registry().Quantity(text)
    if parsed.dimensionless:
        return float(parsed.to("dimensionless").magnitude)
    if not parsed.check(dimension):
        raise _WrongDimension(str(parsed.dimensionality))
    return float(parsed.to(unit).magnitude)


def quantity(key: str, value, kind: str) -> float:
    """The SI magnitude of a physical value, a number (read as SI) or a string with a unit.

    Parameters
    ----------
    key : str
        The value's name in error messages (``sheet.thickness``, ``--radius``).
    value : float or str
        A number in SI units, or a string with a unit pint reads (``"1.5 mm"``, ``"4.8 kPa"``).
    kind : {"length", "pressure", "force", "volume"}
        The quantity expected (``KINDS``).

    Returns
    -------
    float
        In m, Pa, N or m^3.

    Raises
    ------
    InputError
        For a value of another dimension, text that is no quantity, or a magnitude that is not finite or outside
        ``MAGNITUDES``; one line naming ``key``.

    Examples
    --------
    >>> from pocket.core.units import quantity
    >>> print(quantity("sheet.thickness", "1.5 mm", "length"), quantity("initial.pressure", "4.8 kPa", "pressure"))
    0.0015 4800.0
    >>> quantity("initial.pressure", "3 mm", "pressure")
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: initial.pressure = '3 mm' has dimension [length], but a pressure (Pa) is needed
    """
    dimension, unit = KINDS[kind]
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise InputError(f"{key} = {quote(value)} is not a {kind} (give a number in SI or a string like "
                         f"'1 {unit}')")
    try:
        magnitude = _si(value, dimension, unit) if isinstance(value, str) else float(value)
    except OverflowError:
        magnitude = math.inf
    except _WrongDimension as err:
        raise InputError(f"{key} = {quote(value)} has dimension {err}, but a {kind} ({unit}) is needed") from None
    except Exception:  # pint's parser raises many types on malformed text (even AssertionError)
        raise InputError(f"{key} = {quote(value)} is not a quantity with a known unit") from None
    if not math.isfinite(magnitude):
        raise InputError(f"{key} = {quote(value)} is not finite")
    low, high = MAGNITUDES
    if magnitude != 0.0 and not low <= abs(magnitude) <= high:
        raise InputError(f"{key} = {quote(value)} is outside the magnitudes pocket handles "
                         f"({low:g} to {high:g} {unit})")
    return magnitude


def positive(key: str, value, kind: str) -> float:
    """``quantity`` that must be > 0 (a thickness, a radius, a modulus).

    Parameters
    ----------
    key, value, kind
        As for ``quantity``.

    Returns
    -------
    float
        The SI magnitude, > 0.

    Raises
    ------
    InputError
        As ``quantity``, and for a value that is not > 0.

    Examples
    --------
    >>> from pocket.core.units import positive
    >>> print(positive("clamp.radius", "20 mm", "length"))
    0.02
    >>> positive("clamp.radius", "-20 mm", "length")
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: clamp.radius = '-20 mm', but it must be > 0
    """
    magnitude = quantity(key, value, kind)
    if magnitude <= 0.0:
        raise InputError(f"{key} = {quote(value)}, but it must be > 0")
    return magnitude


def _dimensionless(text: str) -> bool | None:
    """Whether pint reads ``text`` as a dimensionless quantity; None for text that is no quantity at all."""
    try:
        return bool(_registry().Quantity(text).dimensionless)
    except Exception:  # pint's parser raises many types on text that is no quantity
        return None


def is_plain(value) -> bool:
    """Whether ``value``, a valid ``quantity``, was written without a unit (a number, or text like ``"20"``).

    Parameters
    ----------
    value : float or str
        As given.

    Returns
    -------
    bool

    Examples
    --------
    >>> from pocket.core.units import is_plain
    >>> print(is_plain(0.02), is_plain("20"), is_plain("20 mm"))
    True True False
    """
    return not isinstance(value, str) or _dimensionless(value) is True


def has_unit(text) -> bool:
    """Whether ``text`` is a quantity written with a unit: a command in the model's units refuses it.

    Parameters
    ----------
    text : object
        As given; a number, or text that is no quantity at all, has no unit.

    Returns
    -------
    bool

    Examples
    --------
    >>> from pocket.core.units import has_unit
    >>> print(has_unit("8 mm"), has_unit("0.4"), has_unit("x"), has_unit(0.4))
    True False False False
    """
    return isinstance(text, str) and _dimensionless(text) is False


def plain_warnings(key: str, value, kind: str) -> list[str]:
    """The warning on ``value``, a valid quantity of ``kind`` given as ``key``, if it was written without a unit.

    This is pocket's one rule for plain numbers where a unit is expected, in case files and on the command
    line alike: the number is read as SI (metres, pascals, newtons, cubic metres), and the reader is told so,
    whatever its size, since ``15`` is as likely millimetres as ``0.015`` is metres.

    Parameters
    ----------
    key : str
        The value's name in the warning.
    value : float or str
        A valid ``quantity`` of ``kind``, as given.
    kind : {"length", "pressure", "force", "volume"}
        The quantity (``KINDS``).

    Returns
    -------
    list of str
        One line, or empty for a value with a unit or a plain zero (zero is zero in every unit).

    Examples
    --------
    >>> from pocket.core.units import plain_warnings
    >>> plain_warnings("--radius", "15", "length")
    ["--radius = '15' has no unit and is read as 15 m; write '15 mm' if millimetres were meant"]
    >>> plain_warnings("--radius", "0.015", "length")
    ["--radius = '0.015' has no unit and is read as 0.015 m; write it with its unit ('15 mm') to say so"]
    >>> plain_warnings("--radius", "15 mm", "length")
    []
    """
    if not is_plain(value):
        return []
    si = quantity(key, value, kind)
    if si == 0.0:
        return []
    unit, hint = KINDS[kind][1], SUGGESTED[kind]
    meant = float(_registry().Quantity(si, unit).to(hint).magnitude)
    text = f"{key} = {quote(value)} has no unit and is read as {si:.6g} {unit.replace('**3', '^3')}"
    if abs(meant) >= _LARGE:  # 15 m is 15000 mm: the number was most likely written in the usual unit
        return [f"{text}; write '{value} {hint}' if {_NAMES[hint]} were meant"]
    return [f"{text}; write it with its unit ('{meant:.6g} {hint}') to say so"]


#: a plain value this many times the usual unit (15 m = 15000 mm) was most likely meant in that unit
_LARGE = 1000.0
#: a suggested unit's name in the warning's sentence
_NAMES = {"mm": "millimetres", "kPa": "kilopascals", "N": "newtons", "mL": "millilitres"}


def written_like(value: float, given, kind: str) -> str:
    """An SI value written in the unit of a value as the user wrote it (SI when that has no unit).

    Parameters
    ----------
    value : float
        The SI magnitude.
    given : float or str
        A value as the user wrote it (``"20 mm"``).
    kind : {"length", "pressure", "force", "volume"}
        The quantity (``KINDS``).

    Returns
    -------
    str
        ``value`` with its unit, six significant digits.

    Examples
    --------
    >>> from pocket.core.units import written_like
    >>> print(written_like(0.0098787, "20 mm", "length"), "|", written_like(0.0098787, 0.02, "length"))
    9.8787 mm | 0.0098787 m
    """
    dimension, unit = KINDS[kind]
    if isinstance(given, str):
        try:
            parsed = _registry().Quantity(given)
            if not parsed.dimensionless and parsed.check(dimension):
                return f"{_registry().Quantity(value, unit).to(parsed.units).magnitude:.6g} {parsed.units:~}"
        except Exception:  # pint's parser raises many types; the SI form below is always right
            pass
    return f"{value:.6g} {unit}"
