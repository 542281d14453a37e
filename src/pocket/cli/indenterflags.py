"""The indenter flags of ``pocket compress`` (the model's units) and ``pocket design`` (physical units).

``--indenter {plate,sphere,profile}`` (default plate, the flat plate), ``--indenter-radius`` for a sphere
and ``--indenter-file FILE.csv`` for a profile. In the commands of the model's units (``compress``, ``sweep``)
the radius is K = R_s / R (1e-3 to 1e3; a value with a unit is refused) and the profile's header is in units of R,
``radius [R],height [R]`` (``pocket.core.profiles``); in ``design``, which knows R, the radius is a length
('8 mm'; a plain number is metres, with a warning) and the profile's header in any length unit
(``radius [mm],...``).
A flag the shape does not take, a missing one, a radius outside K = 1e-3 to 1e3
(``pocket.core.indenters.SPHERE_RADII``) or a bad profile file is a one-line error before any solving.
"""

from __future__ import annotations

from pocket.core.errors import InputError
from pocket.core.indenters import INDENTERS, Indenter

from .common import model_value, path_name, physical_help

__all__ = ["add_indenter_flags", "flag", "indenter_of", "indenter_table"]

_FLAGS = {"shape": "--indenter", "radius": "--indenter-radius", "file": "--indenter-file"}


def add_indenter_flags(parser, *, command: str | None = None) -> None:
    """Add ``--indenter``, ``--indenter-radius`` and ``--indenter-file`` to ``parser``: in units of R for
    ``command``, the name of a command in the model's units; a length and a file in any length unit if None
    (``design``)."""
    parser.add_argument("--indenter", choices=tuple(INDENTERS), default="plate",
                        help="what presses: the flat plate (default), a sphere (a fingertip) or a profile")
    if command is None:
        parser.add_argument(_FLAGS["radius"], metavar="LENGTH",
                            help=f"a sphere's radius R_s: {physical_help('length', '8 mm')}")
        parser.add_argument(_FLAGS["file"], type=path_name, metavar="FILE.csv",
                            help="a profile's table: a header 'radius [mm],height [mm]' (any length unit) and rows of "
                            "two numbers, from the axis outwards")
        return
    parser.add_argument(_FLAGS["radius"], type=model_value(command, "R_s/R"), metavar="K",
                        help="a sphere's radius as K = R_s/R (a number), from 1e-3 to 1e3")
    parser.add_argument(_FLAGS["file"], type=path_name, metavar="FILE.csv",
                        help="a profile's table: a header 'radius [R],height [R]' (units of the clamp radius R) and "
                        "rows of two numbers, from the axis outwards")


def _given(args) -> tuple[type[Indenter], dict]:
    """The indenter class ``--indenter`` names and {key: value} of the size flags given, checked against its
    ``keys``: an InputError for one it does not take or lacks."""
    kind = INDENTERS[args.indenter]
    values = {"radius": args.indenter_radius, "file": args.indenter_file}
    for key, value in values.items():
        if value is not None and key not in kind.keys:
            raise InputError(f"{_FLAGS[key]} is given, but a {kind.name} indenter takes "
                             f"{' '.join(_FLAGS[k] for k in kind.keys) or 'no size'}")
        if value is None and key in kind.keys:
            raise InputError(f"--indenter {kind.name} needs {_FLAGS[key]}")
    return kind, {k: v for k, v in values.items() if v is not None}


def indenter_of(args) -> Indenter:
    """The indenter the dimensionless flags ``args`` give (``compress``, ``sweep``)."""
    kind, values = _given(args)
    return kind.from_model(values, flag)


def flag(key: str) -> str:
    """The flag of the ``[indenter]`` key ``key`` (``--indenter-radius`` for ``radius``), for messages."""
    return _FLAGS[key]


def indenter_table(args) -> dict:
    """The physical flags ``args`` as an ``[indenter]`` table (``pocket.apps.indentertable.parse``, ``design``)."""
    kind, values = _given(args)
    return {"shape": kind.name, **values}
