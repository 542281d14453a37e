"""Step 2's contact problems by indenter kind: ``CONTACTS`` maps each kind this solver poses to the problem that
poses it, and ``contact_of`` refuses another.

The flat plate has its own formulation (``pocket.shooting.plate``); every curved indenter shares one
(``pocket.shooting.surface``), whose problem here carries only the words its messages use for the
indenter and the ends of the model under it. A new convex indenter is posed by ``SurfaceProblem`` itself,
in its generic words, through an entry here.
"""

from __future__ import annotations

import dataclasses

from pocket.core.errors import InputError
from pocket.core.geometries import Geometry, Symmetry
from pocket.core.indenters import Indenter, Plate, Profile, Sphere, formulation

from .capsule import CapsuleProblem
from .contact import Contact
from .plate import PlateProblem
from .surface import SurfaceProblem, words

__all__ = ["CONTACTS", "EQUATOR", "PROFILE_END", "ProfileProblem", "SphereProblem", "contact_of", "problem_of"]

#: the end of the model particular to a sphere
EQUATOR = "the sheet would wrap past the sphere's equator"
#: ... and to a profile
PROFILE_END = "the sheet would wrap past the end of the profile (its last radius, or where it turns vertical)"


@dataclasses.dataclass(frozen=True)
class SphereProblem(SurfaceProblem):
    """The compression of ``inflated`` by a sphere (``pocket.shooting.surface``), in its words."""

    NAME, END = "sphere", EQUATOR
    POLE, TOUCH = words("sphere")


@dataclasses.dataclass(frozen=True)
class ProfileProblem(SurfaceProblem):
    """The compression of ``inflated`` by a user's profile (``pocket.shooting.surface``), in its words."""

    NAME, END = "profile", PROFILE_END
    POLE, TOUCH = words("profile")


#: indenter kind -> the problem that poses its contact
CONTACTS: dict[type[Indenter], type[Contact]] = {Plate: PlateProblem, Sphere: SphereProblem,
                                                 Profile: ProfileProblem}


def problem_of(geometry: Geometry, indenter: Indenter) -> type[Contact]:
    """The problem class posing the contact of ``indenter`` on the reference surface ``geometry``: a closed capsule's
    between two plates (``pocket.shooting.capsule``), a pocket's by its indenter (``contact_of``); an InputError for
    an indenter this solver does not pose on that surface."""
    if isinstance(geometry.end, Symmetry):
        if not isinstance(indenter, Plate):
            raise InputError(f"solver shooting presses a {geometry.name} between two flat plates only, not with "
                             f"a {indenter.name}")
        return CapsuleProblem
    return contact_of(indenter)


def contact_of(indenter: Indenter) -> type[Contact]:
    """The problem class posing the contact of ``indenter``; an InputError naming this solver and the
    indenter for a kind it does not pose (``pocket.core.indenters.formulation``)."""
    return formulation(CONTACTS, "shooting", indenter)
