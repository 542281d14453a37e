"""The end of the compression range as an entry point: the largest force a pocket's first branch carries.

Each indenter's formulation finds it (``pocket.shooting.problem.CONTACTS``; the plate's in
``pocket.shooting.plateend``, a curved indenter's in ``pocket.shooting.surfaceend``), once per pocket
(``pocket.shooting.end``).
"""

from __future__ import annotations

from pocket.core.fluids import as_fluid
from pocket.core.geometries import posed
from pocket.core.indenters import as_indenter
from pocket.core.inputs import check_positive

from .end import cached, end_of
from .inflation import GEOMETRIES, inflate
from .laws import law_of
from .problem import contact_of

__all__ = ["range_end"]


def range_end(material, pressure_initial, *, fluid=None, indenter=None, geometry=None, rtol=1e-10) -> float:
    """The largest force Fhat for which the pocket (its rubber ``material``, a ``Material`` or a Mooney-Rivlin
    alpha; Phat_I; its ``fluid``, the ``indenter`` and its ``geometry``, as for ``compression_curve``) has a
    compressed state (``pocket.shooting.plateend``): forces up to and including it solve; above it, none do."""
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    law = law_of(material)
    pressure_initial = check_positive("pressure", pressure_initial)
    fluid = as_fluid(fluid)
    indenter = as_indenter(indenter)
    contact = contact_of(indenter)
    end = cached((law.key, pressure_initial, rtol, fluid, indenter))
    if end is None:
        end = end_of(contact(inflate(material, pressure_initial, geometry=geometry, rtol=rtol), rtol, law, fluid,
                             indenter))
    return end.force
