"""The indenter of a case file or of the command line, in physical units, made dimensionless by the clamp radius.

    [indenter]                  # optional, default the flat plate
    shape = "sphere"            # "plate" (default), "sphere" or "profile"
    radius = "8 mm"             # sphere only: its radius R_s
    # file = "tip.csv"          # profile only: a CSV table "radius [mm],height [mm]", relative to the case file

A sphere's radius becomes K = R_s / R; a profile's lengths are divided by R (a column in ``[R]`` is in units
of R already; ``pocket.core.profiles``). The case-file name "plate" is the core's kind "flat". A key the
shape does not take (a radius for a plate), a radius that is not a positive length or gives K outside
1e-3 to 1e3 (``pocket.core.indenters.SPHERE_RADII``), or a profile file that is no profile is a one-line
``InputError`` naming the key, before any solving.
"""

from __future__ import annotations

import pathlib

from pocket.core.errors import InputError
from pocket.core.indenters import FLAT, Indenter, check_sphere_radius, profile, sphere
from pocket.core.inputs import quote
from pocket.core.profiles import read_csv
from pocket.core.sizes import length_warnings
from pocket.core.units import positive

__all__ = ["KEYS", "SHAPES", "describe", "parse"]

#: the shapes a user names -> the keys each takes besides ``shape``
SHAPES = {"plate": (), "sphere": ("radius",), "profile": ("file",)}
#: every key of an ``[indenter]`` table
KEYS = ("shape", "radius", "file")


def parse(table: dict, clamp_radius: float, base=None, given: dict | None = None, *,
          spell=lambda key: f"indenter.{key}", warnings: list | None = None) -> Indenter:
    """The ``Indenter`` of the ``[indenter]`` table ``table`` on a clamp of radius ``clamp_radius`` (m); a
    relative profile file is relative to ``base`` (a folder; the current one by default). Each key is
    recorded in ``given`` as written (``"indenter.radius"``); ``spell(key)`` names a key in messages (a
    command line's flag). A sphere's radius is a length of a pocket's sizes (``pocket.core.sizes``): outside
    them an ``InputError``; a plain number above 1 m (millimetres meant?) a line appended to ``warnings``."""
    if not isinstance(table, dict):
        raise InputError(f"indenter must be a table ([indenter]), got {quote(table)}")
    shape = table.get("shape", "plate")
    if not isinstance(shape, str) or shape not in SHAPES:
        raise InputError(f"{spell('shape')} = {quote(shape)}, but it must be one of {', '.join(SHAPES)}")
    for key in table:
        if key != "shape" and key not in SHAPES[shape]:
            takes = ", ".join(SHAPES[shape]) or "no other key"
            raise InputError(f"{spell(key)} = {quote(table[key])}, but a {shape} indenter takes {takes}")
    for key in SHAPES[shape]:
        if key not in table:
            raise InputError(f"missing key '{spell(key)}' (a {shape} indenter needs it)")
    if given is not None:
        given.update({f"indenter.{k}": v for k, v in table.items()})
    if shape == "sphere":
        radius = positive(spell("radius"), table["radius"], "length")
        found = length_warnings(spell("radius"), table["radius"], radius)
        if warnings is not None:
            warnings.extend(found)
        ratio = radius / clamp_radius
        shown = f"{quote(table['radius'])} (K = R_s/R = {ratio:.3g})"
        return sphere(check_sphere_radius(spell("radius"), ratio, shown))
    if shape == "profile":
        name = table["file"]
        if not isinstance(name, str) or not name:
            raise InputError(f"{spell('file')} = {quote(name)}, but it must be a file name")
        path = pathlib.Path(name) if base is None else pathlib.Path(base) / name
        return profile(read_csv(path, clamp_radius))
    return FLAT


def describe(indenter: Indenter, clamp_radius: float) -> dict:
    """The indenter as a case reports it (JSON-ready): ``indenter`` (plate, sphere or profile), a sphere's
    ``indenter_radius_m`` and a profile's ``indenter_file``, from its dimensionless form on a clamp of
    radius ``clamp_radius`` (m)."""
    if indenter.kind == "flat":
        return {"indenter": "plate"}
    if indenter.kind == "sphere":
        return {"indenter": "sphere", "indenter_radius_m": indenter.number("radius") * clamp_radius}
    return {"indenter": indenter.kind, "indenter_file": indenter.shape().source}
