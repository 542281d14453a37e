"""Physical quantities in, SI floats out: the one place units are handled (pint).

A value is a number (taken as SI: metres, pascals, newtons, cubic metres) or a
string with a unit, ``"0.25 mm"``, ``"4.8 kPa"``, ``"0.67 N"``, ``"2 mL"``,
which pint parses and converts. A string without a unit is SI too. The
quantity's dimension must match its kind: ``"4 mm"`` for a pressure is an
``InputError`` naming the key. Everything past this module is SI floats.

pint is imported on first use, so that commands which need no units do not pay
for its registry (about 0.2 s).
"""

from __future__ import annotations

import functools
import math

from .errors import InputError

__all__ = ["KINDS", "quantity", "positive"]

#: kind -> (pint dimensionality, SI unit)
KINDS = {
    "length": ("[length]", "m"),
    "pressure": ("[pressure]", "Pa"),
    "force": ("[force]", "N"),
    "volume": ("[volume]", "m**3"),
}


@functools.cache
def _registry():
    import pint

    return pint.UnitRegistry()


def quantity(key: str, value, kind: str) -> float:
    """The SI magnitude of ``value`` (number or string with unit), a quantity of ``kind``."""
    dimension, unit = KINDS[kind]
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise InputError(f"{key} = {value!r} is not a {kind} (give a number in SI or a string like "
                         f"'1 {unit}')")
    if isinstance(value, str):
        try:
            parsed = _registry().Quantity(value)
        except Exception:  # pint's parser raises many types on malformed text (even AssertionError)
            raise InputError(f"{key} = {value!r} is not a quantity with a known unit") from None
        if parsed.dimensionless:
            magnitude = float(parsed.to("dimensionless").magnitude)
        elif parsed.check(dimension):
            magnitude = float(parsed.to(unit).magnitude)
        else:
            raise InputError(f"{key} = {value!r} has dimension {parsed.dimensionality}, "
                             f"but a {kind} ({unit}) is needed")
    else:
        magnitude = float(value)
    if not math.isfinite(magnitude):
        raise InputError(f"{key} = {value!r} is not finite")
    return magnitude


def positive(key: str, value, kind: str) -> float:
    """``quantity`` that must be > 0 (a thickness, a radius, a modulus)."""
    magnitude = quantity(key, value, kind)
    if magnitude <= 0.0:
        raise InputError(f"{key} = {value!r}, but it must be > 0")
    return magnitude
