"""Sizes the membrane model is meant for: lengths a pocket can have, and a sheet thin beside its clamp.

A length is checked after ``pocket.core.units`` has made it SI:

- outside ``SIZES`` it is refused (``InputError`` naming the key): a sheet thinner than a molecule or a
  pocket wider than a building is a typo, not a pocket;
- written as a plain number (no unit, so metres) it draws a warning naming the key, whatever its size
  (``pocket.core.units.plain_warnings``): pocket buttons are millimetres to centimetres across, so
  ``radius = 20`` was most likely meant as ``"20 mm"``, and ``radius = 0.02`` is right only if it was
  meant in metres.

The sheet must be thin: membrane theory drops bending and the clamp's hold through the thickness,
an error of order T/R (a solid model's volume is lower by about 1.0 T/R; where the fluid's surface
lies adds only O((T/R)^2), ``pocket.core.offset``). Above
``THIN_WARNING`` that error passes 10 % and a state draws a warning; at ``THIN_LIMIT`` and above the
sheet is as thick as half its clamp radius, a plate rather than a membrane, and the model is refused.
The four samples of the paper's Table 1 have T/R = 0.0125 to 0.08.
"""

from __future__ import annotations

from .errors import InputError
from .inputs import quote
from .units import plain_warnings

__all__ = ["SIZES", "THIN_LIMIT", "THIN_WARNING", "length_warnings", "thin_sheet"]

#: smallest and largest length (m) pocket accepts: 1 nm (a few molecules) to 1 km
SIZES = (1e-9, 1e3)
#: T/R above which membrane theory's O(T/R) error passes 10 %: a warning
THIN_WARNING = 0.1
#: T/R at and above which the sheet is a plate, not a membrane: refused
THIN_LIMIT = 0.5


def length_warnings(key: str, value, si: float) -> list[str]:
    """The warnings on the length ``key``, written ``value`` and ``si`` metres once parsed (a list, empty
    or of one line); an ``InputError`` if it lies outside ``SIZES``."""
    low, high = SIZES
    if si != 0.0 and not low <= si <= high:
        raise InputError(f"{key} = {quote(value)} is {si:.6g} m, outside the sizes of a pocket "
                         f"({low:g} to {high:g} m)")
    return plain_warnings(key, value, "length")


def thin_sheet(thickness: float, radius: float, why: str) -> list[str]:
    """The warnings on a sheet ``thickness`` T (m) on a clamp of ``radius`` R (m): a list, empty or of one line;
    an ``InputError`` at T/R >= ``THIN_LIMIT``. ``why`` names the inputs they come from
    (``"sheet.thickness = 0.25, clamp.radius = '20 mm'"``)."""
    ratio = thickness / radius
    if ratio >= THIN_LIMIT:
        raise InputError(f"{why}: the sheet's thickness is {ratio:.3g} times the clamp radius, but a membrane "
                         f"needs T/R well below {THIN_LIMIT:g} (it would be a thick plate)")
    if ratio > THIN_WARNING:
        return [f"{why}: the sheet's thickness is {ratio:.3g} times the clamp radius; membrane theory's "
                f"error is of order T/R, past {THIN_WARNING:g} it is no longer small"]
    return []
