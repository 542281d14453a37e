"""A rubber as the compiled shooting code takes it: a law code, a parameter array and its units.

``law_of`` turns what a caller gives (a Mooney-Rivlin alpha, or any ``pocket.core.materials.Material``,
in any stress unit) into a ``Law``: the kernel's code and parameters (``pocket.shooting.tensions``),
stresses in units of mu_0, and the pressure factor p / Phat = 3 mu_0 / tau of the kernel's tension unit
tau (tau = 2 C1 for Mooney-Rivlin, as in the paper's solver; mu_0 for every other law). A rubber given by
alpha keeps the exact arithmetic of the Mooney-Rivlin solver (p = 3 (1 + alpha) Phat).

``stretch_limit`` is the equibiaxial stretch at which the law leaves its domain: Gent's locking,
2 l^2 + l^-4 - 3 = Jm, i.e. the root u = l^2 > 1 of 2 u^3 - (3 + Jm) u^2 + 1 = 0; infinite for the rest.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.materials import Material, as_material

from . import brent
from .tensions import CODES, GENT, MOONEY_RIVLIN

__all__ = ["Law", "law_of", "as_law"]


@dataclasses.dataclass(frozen=True)
class Law:
    """The kernel's view of a rubber. ``key`` identifies it (for caches); ``label`` names it in messages."""

    code: int
    params: np.ndarray = dataclasses.field(compare=False, repr=False)
    pressure_factor: float
    key: tuple
    label: str
    stretch_limit: float = math.inf

    def lock_margin(self, l1: float, l2: float) -> float:
        """1 - (I1 - 3) / Jm at stretches (l1, l2) for a rubber that locks (0 at locking), inf for the rest."""
        if self.code != GENT:
            return math.inf
        return 1.0 - (l1 * l1 + l2 * l2 + 1.0 / (l1 * l2) ** 2 - 3.0) / self.params[1]

    @property
    def tension_scale(self) -> float:
        """Factor from kernel tensions (units tau T) to units of E T: 1 / pressure_factor."""
        return 1.0 / self.pressure_factor


def _gent_limit(jm: float) -> float:
    """The equibiaxial stretch at which I1 - 3 = 2 l^2 + l^-4 - 3 reaches Jm."""
    u = brent.root(lambda u: 2.0 * u + 1.0 / (u * u) - 3.0 - jm, 1.0, 2.0 + 0.5 * jm, rtol=1e-15)
    return math.sqrt(u)


def law_of(value) -> Law:
    """The ``Law`` of a rubber given as a Mooney-Rivlin alpha (a number) or a ``Material`` (checked)."""
    material = as_material(value)
    if not isinstance(value, Material):
        alpha = float(value)  # as_material checked it
        return Law(MOONEY_RIVLIN, np.array([alpha]), 3.0 * (1.0 + alpha), ("alpha", alpha), f"alpha = {alpha!r}")
    label = f"{material.law} rubber (" + ", ".join(f"{k} = {v}" for k, v in material.describe().items()
                                                   if k != "material") + ")"
    if material.law == "mooney-rivlin":
        alpha = material["c2"] / material["c1"]
        return Law(MOONEY_RIVLIN, np.array([alpha]), 3.0 * (1.0 + alpha), ("alpha", alpha), label)
    unit = material.scaled()
    if unit.law == "ogden":
        values = [x for pair in zip(unit["mu"], unit["exponents"], strict=True) for x in pair]
    else:
        values = [v for _, v in unit.params]
    params = np.array(values, dtype=float)
    limit = _gent_limit(unit["jm"]) if unit.law == "gent" else math.inf
    return Law(CODES[unit.law], params, 3.0, (unit.law, tuple(values)), label, limit)


def as_law(value) -> Law:
    """``value`` if it is a ``Law``, else ``law_of(value)``."""
    return value if isinstance(value, Law) else law_of(value)
