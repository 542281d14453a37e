"""A rubber as the compiled shooting code takes it: a law code, a parameter array and its units.

``law_of`` turns a ``pocket.core.materials.Material``, in any stress unit (a number: the Mooney-Rivlin
alpha of ``mooney_rivlin``, converted by ``as_material``), into a ``Law``: the kernel's code and
parameters (``pocket.shooting.tensions``), stresses in units of mu_0, and the pressure factor
p / Phat = 3 mu_0 / tau of the kernel's tension unit tau (tau = 2 C1 for Mooney-Rivlin, as in the
paper's solver; mu_0 for every other law). A rubber given by alpha keeps the exact arithmetic of the
Mooney-Rivlin solver (p = 3 (1 + alpha) Phat).

``KERNELS`` is this solver's table from a law's name to its kernel: the code and the parameter
array of ``pocket.shooting.tensions``. A law of the registry (``pocket.core.materials.LAWS``) that is
not in the table is refused in one line naming the law and the solver (InputError), never run as
another law.

``stretch_limit`` is the equibiaxial stretch at which the law leaves its domain, I1 - 3 = x_max
(``Material.domain``: Gent's Jm), 2 l^2 + l^-4 - 3 = x_max, i.e. the root u = l^2 > 1 of
2 u^3 - (3 + x_max) u^2 + 1 = 0; infinite for a law without a bound.

A prestretched sheet (``Material.prestretch`` = lambda_p) has its lambda_p appended to the
parameter array (``pocket.shooting.tensions``); its stretches are relative to the clamped flat sheet,
so its ``stretch_limit`` is the material one divided by lambda_p and ``lock_margin`` takes the material
stretches lambda_p l_i. Its ``key`` gains ("prestretch", lambda_p); a sheet without prestretch keeps
its key.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import InputError
from pocket.core.materials import Material, as_material

from . import brent
from .tensions import GENT, MOONEY_RIVLIN, NEO_HOOKEAN, OGDEN, YEOH, tensions

__all__ = ["KERNELS", "Law", "as_law", "law_of"]


@dataclasses.dataclass(frozen=True)
class Law:
    """The kernel's view of a rubber. ``key`` identifies it (for caches); ``label`` names it in messages;
    ``domain`` is the bound on I1 - 3 (inf: none) and ``stretch_limit`` its equibiaxial stretch."""

    code: int
    params: np.ndarray = dataclasses.field(compare=False, repr=False)
    pressure_factor: float
    key: tuple
    label: str
    stretch_limit: float = math.inf
    domain: float = math.inf
    prestretch: float = 1.0

    def lock_margin(self, l1: float, l2: float) -> float:
        """1 - (I1 - 3) / x_max at stretches (l1, l2) (relative to the clamped flat sheet; I1 of the material
        stretches) for a rubber whose domain ends at I1 - 3 = x_max (Gent's Jm; 0 at locking), inf for the rest."""
        if math.isinf(self.domain):
            return math.inf
        l1, l2 = self.prestretch * l1, self.prestretch * l2
        return 1.0 - (l1 * l1 + l2 * l2 + 1.0 / (l1 * l2) ** 2 - 3.0) / self.domain

    @property
    def flat_tension(self) -> float:
        """N_0 / (E T): the tension of the clamped flat sheet, that of its prestretch (0 without one)."""
        return tensions(1.0, 1.0, self.code, self.params)[0] * self.tension_scale

    @property
    def tension_scale(self) -> float:
        """Factor from kernel tensions (units tau T) to units of E T: 1 / pressure_factor."""
        return 1.0 / self.pressure_factor


def _stretch_limit(bound: float) -> float:
    """The equibiaxial stretch at which I1 - 3 = 2 l^2 + l^-4 - 3 reaches ``bound`` (inf for an inf bound)."""
    if math.isinf(bound):
        return math.inf
    u = brent.root(lambda u: 2.0 * u + 1.0 / (u * u) - 3.0 - bound, 1.0, 2.0 + 0.5 * bound, rtol=1e-15)
    return math.sqrt(u)


def _in_order(code: int):
    """A kernel whose parameters are the law's, in the law's order (stresses in units of mu_0)."""
    return lambda unit: (code, [v for _, v in unit.params])


def _ogden(unit: Material):
    return OGDEN, [x for pair in zip(unit["mu"], unit["exponents"], strict=True) for x in pair]


#: law name -> (material in units of mu_0 -> (kernel code, parameter list)); Mooney-Rivlin is held by its alpha
#: (``Material.alpha``: the alpha it was given by, or C2/C1), in any unit
KERNELS = {
    "mooney-rivlin": lambda material: (MOONEY_RIVLIN, [material.alpha]),
    "neo-hookean": _in_order(NEO_HOOKEAN),
    "yeoh": _in_order(YEOH),
    "gent": _in_order(GENT),
    "ogden": _ogden,
}


def _kernel(law: str):
    if law not in KERNELS:
        raise InputError(f"the shooting solver has no kernel for the {law} law (it has {', '.join(KERNELS)})")
    return KERNELS[law]


def law_of(value) -> Law:
    """The ``Law`` of a rubber, a ``Material`` (or a Mooney-Rivlin alpha: ``as_material``), checked: both
    through ``KERNELS``."""
    material = as_material(value)
    kernel = _kernel(material.law)
    lp = material.prestretch
    stretched = () if lp == 1.0 else (("prestretch", lp),)
    if material.exact_alpha is not None:
        label = f"alpha = {material.alpha!r}" + "".join(f", {k} = {v!r}" for k, v in stretched)
    else:
        label = f"{material.law} rubber (" + ", ".join(f"{k} = {v}" for k, v in material.describe().items()
                                                       if k != "material") + ")"
    if material.law == "mooney-rivlin":  # tau = 2 C1, as in the paper's solver: no rescaling
        code, values = kernel(material)
        alpha = values[0]
        return Law(code, np.array([*values, lp]), 3.0 * (1.0 + alpha), ("alpha", alpha, *stretched), label,
                   prestretch=lp)
    unit = material.scaled()
    code, values = kernel(unit)
    return Law(code, np.array([*values, lp], dtype=float), 3.0, (unit.law, tuple(values), *stretched), label,
               _stretch_limit(unit.domain) / lp, unit.domain, lp)


def as_law(value) -> Law:
    """``value`` if it is a ``Law``, else ``law_of(value)``."""
    return value if isinstance(value, Law) else law_of(value)
