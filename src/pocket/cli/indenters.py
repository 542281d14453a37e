"""The indenter flags of ``pocket compress``, in the model's units (lengths in the clamp radius R).

``--indenter {plate,sphere,profile}`` (default plate, the flat plate), ``--indenter-radius K`` for a
sphere (K = R_s / R, > 0) and ``--indenter-file FILE.csv`` for a profile, its header in units of R:
``radius [R],height [R]`` (``pocket.core.profiles``; a case file takes physical units, since it knows R).
A flag the shape does not take, a missing one, a radius that is not positive or a bad profile file is a
one-line error before any solving.
"""

from __future__ import annotations

from pocket.apps.indenters import SHAPES
from pocket.core.errors import InputError
from pocket.core.indenters import FLAT, Indenter, profile, sphere
from pocket.core.profiles import read_csv

from .common import number

__all__ = ["add_indenter_flags", "indenter_of"]

_FLAGS = {"radius": "--indenter-radius", "file": "--indenter-file"}


def add_indenter_flags(parser) -> None:
    """Add ``--indenter``, ``--indenter-radius`` and ``--indenter-file`` to ``parser``."""
    parser.add_argument("--indenter", choices=tuple(SHAPES), default="plate",
                        help="what presses: the flat plate (default), a sphere (a fingertip) or a profile")
    parser.add_argument(_FLAGS["radius"], type=number, metavar="K", help="a sphere's radius K = R_s / R")
    parser.add_argument(_FLAGS["file"], metavar="FILE.csv", help="a profile's table: a header 'radius [R],height "
                        "[R]' (units of the clamp radius R) and rows of two numbers, from the axis outwards")


def indenter_of(args) -> Indenter:
    """The indenter the flags ``args`` give; an InputError for a flag the shape does not take or lacks."""
    shape = args.indenter
    values = {"radius": args.indenter_radius, "file": args.indenter_file}
    for key, value in values.items():
        if value is not None and key not in SHAPES[shape]:
            raise InputError(f"{_FLAGS[key]} is given, but a {shape} indenter takes "
                             f"{' '.join(_FLAGS[k] for k in SHAPES[shape]) or 'no size'}")
        if value is None and key in SHAPES[shape]:
            raise InputError(f"--indenter {shape} needs {_FLAGS[key]}")
    if shape == "sphere":
        if not values["radius"] > 0.0:
            raise InputError(f"--indenter-radius = {values['radius']:g}, but a sphere's radius must be > 0")
        return sphere(values["radius"])
    if shape == "profile":
        return profile(read_csv(values["file"]))
    return FLAT
