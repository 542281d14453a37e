"""The ``[indenter]`` table of a case file (or of ``pocket design``'s flags), in physical units, made dimensionless
by the clamp radius.

    [indenter]                  # optional, default the flat plate
    shape = "sphere"            # "plate" (default), "sphere" or "profile": an indenter's name
    radius = "8 mm"             # sphere only: its radius R_s
    # file = "tip.csv"          # profile only: a CSV table "radius [mm],height [mm]", relative to the case file

``shape`` names a registered indenter (``pocket.core.indenters.INDENTERS``) and the other keys are its ``keys``,
which it reads itself (``Indenter.from_physical``): a sphere's radius becomes K = R_s / R; a profile's lengths are
divided by R (a column in ``[R]`` is in units of R already; ``pocket.core.profiles``). A key the shape does not
take (a radius for a plate), a missing one, a radius that is not a positive length or gives K outside 1e-3 to 1e3
(``pocket.core.indenters.SPHERE_RADII``), or a profile file that is no profile is a one-line ``InputError`` naming
the key, before any solving.
"""

from __future__ import annotations

from pocket.core.errors import InputError
from pocket.core.indenters import INDENTERS, Indenter
from pocket.core.inputs import quote

__all__ = ["KEYS", "parse"]

#: every key of an ``[indenter]`` table
KEYS = ("shape", *dict.fromkeys(key for kind in INDENTERS.values() for key in kind.keys))


def _kind(shape, values: dict, spell) -> type[Indenter]:
    """The indenter class named ``shape``, its ``keys`` all in ``values`` and no other (the keys given besides
    ``shape``); otherwise an InputError naming the first key amiss by ``spell(key)``."""
    if not isinstance(shape, str) or shape not in INDENTERS:
        raise InputError(f"{spell('shape')} = {quote(shape)}, but it must be one of {', '.join(INDENTERS)}")
    kind = INDENTERS[shape]
    for key in values:
        if key not in kind.keys:
            raise InputError(f"{spell(key)} = {quote(values[key])}, but a {shape} indenter takes "
                             f"{', '.join(kind.keys) or 'no other key'}")
    for key in kind.keys:
        if key not in values:
            raise InputError(f"missing key '{spell(key)}' (a {shape} indenter needs it)")
    return kind


def parse(table: dict, clamp_radius: float, base=None, given: dict | None = None, *,
          spell=lambda key: f"indenter.{key}", warnings: list | None = None) -> Indenter:
    """The ``Indenter`` of the ``[indenter]`` table ``table`` on a clamp of radius ``clamp_radius`` (m); a
    relative profile file is relative to ``base`` (a folder; the current one by default). Each key is
    recorded in ``given`` as written (``"indenter.radius"``); ``spell(key)`` names a key in messages (a
    command line's flag). A sphere's radius is a length of a pocket's sizes (``pocket.core.sizes``): outside
    them an ``InputError``; a plain number above 1 m (millimetres meant?) a line appended to ``warnings``."""
    if not isinstance(table, dict):
        raise InputError(f"indenter must be a table ([indenter]), got {quote(table)}")
    values = {k: v for k, v in table.items() if k != "shape"}
    kind = _kind(table.get("shape", "plate"), values, spell)
    if given is not None:
        given.update({f"indenter.{k}": v for k, v in table.items()})
    return kind.from_physical(values, clamp_radius, base, spell, warnings)
