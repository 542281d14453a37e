"""The end of the compression range as an entry point: the largest force a pocket's first branch carries.

Each indenter's formulation finds it (``pocket.shooting.problem.CONTACTS``; the plate's in
``pocket.shooting.plateend``, a curved indenter's in ``pocket.shooting.surfaceend``), once per pocket
(``pocket.shooting.end``).
"""

from __future__ import annotations

from pocket.core.fluids import as_fluid
from pocket.core.geometries import DISC, posed
from pocket.core.indenters import as_indenter
from pocket.core.inputs import check_positive

from .end import cached, end_of
from .inflation import GEOMETRIES, inflate
from .laws import law_of
from .problem import problem_of

__all__ = ["range_end"]


def range_end(material, pressure_initial, *, fluid=None, indenter=None, geometry=None, rtol=1e-10) -> float:
    """The largest force Fhat = F / (P_I pi R^2) for which the pocket has a compressed state.

    Forces up to and including it solve; above it, none do (the free sheet reaches the clamp plane, under
    a sphere its equator, under a profile its end: ``pocket.shooting.plateend``, ``pocket.shooting.surfaceend``).
    It is computed once per pocket, whatever force was asked.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    fluid, indenter, geometry, rtol
        As for ``compression_curve``.

    Returns
    -------
    float
        Fhat_end.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a Phat_I above the first branch's pressure maximum.
    ConvergenceError
        If the end's solve fails.

    Examples
    --------
    >>> from pocket import shooting
    >>> end = shooting.range_end(47 / 160, 0.31)
    >>> print(round(end, 4))
    9.9411

    A force past it is refused, naming the end:

    >>> shooting.compress(47 / 160, 0.31, 1.01 * end)
    Traceback (most recent call last):
        ...
    pocket.core.errors.OutOfRangeError: force = 10.04... is beyond the model's range, which ends at ...
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    law = law_of(material)
    pressure_initial = check_positive("pressure", pressure_initial)
    fluid = as_fluid(fluid)
    indenter = as_indenter(indenter)
    contact = problem_of(geometry, indenter)
    end = cached((law.key, pressure_initial, rtol, fluid, indenter, geometry.name) if geometry.end != DISC.end
                 else (law.key, pressure_initial, rtol, fluid, indenter))
    if end is None:
        end = end_of(contact(inflate(material, pressure_initial, geometry=geometry, rtol=rtol), rtol, law, fluid,
                             indenter))
    return end.force
