"""The ``--geometry`` flag of ``pocket inflate``, ``compress`` and ``sweep``: the membrane's reference surface.

``--geometry pocket`` (the default) is the flat sheet clamped at its rim r = R; ``--geometry capsule`` is a
closed spherical membrane of radius R squeezed between two parallel plates (``pocket.core.geometries``; the
choices are ``GEOMETRIES``'s names). The surface goes to the solver as ``geometry=``: a solver, or an indenter,
that does not pose it is refused there in one line (exit 2), before any work.
"""

from __future__ import annotations

from pocket.core.geometries import GEOMETRIES, Geometry

__all__ = ["add_geometry_flag", "capsule_units", "geometry_of"]

def capsule_units(step: str) -> str:
    """What the model's units are for a capsule, in the help of a command of ``step`` ("inflate" or
    "compress"; a sweep's is a compression's)."""
    if step == "inflate":
        return ("With --geometry capsule, R is the capsule's radius (lengths in units of R), Phat = P R / (E T), "
                "height the pole's distance from the equatorial plane, volume the whole capsule's; a capsule's "
                "states add radius_equator (R).")
    return ("With --geometry capsule, R is the capsule's radius (lengths in units of R), Phat = P R / (E T), "
            "Fhat = F / (P_I pi R^2) with F the force on each plate, height the plate's distance from the "
            "equatorial plane (the gap between the plates is 2 H R), volume the whole capsule's, contact_radius the "
            "arc length from the pole to the contact edge on the undeformed sphere; a capsule's states add "
            "stretch_pole, radius_equator (R) and force_ETR = F / (E T R).")


def add_geometry_flag(parser) -> None:
    """Add ``--geometry {pocket,capsule}`` (default pocket) to ``parser``."""
    parser.add_argument("--geometry", choices=tuple(GEOMETRIES), default="pocket",
                        help="the membrane: " + "; ".join(f"{name}, {g.description}" for name, g in GEOMETRIES.items())
                        + " (default: pocket)")


def geometry_of(args) -> Geometry:
    """The reference surface ``--geometry`` names (``pocket.core.geometries.GEOMETRIES``)."""
    return GEOMETRIES[args.geometry]
