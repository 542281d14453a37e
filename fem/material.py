r"""The rubber as the solver sees it: a law's code and parameters, and what the states echo.

``law_of`` takes a ``pocket.core.materials.Material``, any law in any stress
unit (a number is taken as a Mooney-Rivlin alpha = C2/C1, ``as_material``). It
keeps that Material for the states to echo and turns the law into the kernel's
code and parameters (``laws``) through this solver's table ``KERNELS``, its stresses
divided by E = 3 mu_0 (``Material.scaled`` gives them in units of mu_0; a third
of that is units of E). A law of the registry that the table lacks is refused
in one line naming the law and the solver (InputError), never run as another.
A Mooney-Rivlin Material is held by its alpha = C2/C1 (the alpha it was given
by, if any) and s = 1 / (6 (1 + alpha)).

Planar stretch at the clamp (``planar_stretch``): with lambda_2 = 1 the
meridional tension is T_1 = w_1(l, 1); ``post`` measures T_1 there and needs
the l that carries it (at a capsule's equator lambda_2 = b, its radius, and T_1 = w_1(l, b) / b;
Gent's domain below is then that of l^2 + b^2 + l^-2 b^-2). It is found by bracketing from a guess (the element's
own slope) and Brent's method to 1e-15. A Gent rubber's planar stretch is
confined to I1 - 3 = (l - 1/l)^2 < Jm, that is
(sqrt(Jm + 4) - sqrt(Jm)) / 2 < l < (sqrt(Jm + 4) + sqrt(Jm)) / 2.

A prestretched sheet (``Material.prestretch`` = lambda_p, appended to the kernel's parameters:
``laws``) has its stretches relative to the clamped flat sheet: Gent's domain is that of the material
stretches lambda_p l_i, so the planar stretch is confined to
I1 - 3 = lambda_p^2 (l^2 + 1) + lambda_p^-4 l^-2 - 3 < Jm, i.e. u = l^2 between the roots of
lambda_p^2 u^2 + (lambda_p^2 - 3 - Jm) u + lambda_p^-4 = 0 (with lambda_p = 1 the bounds above, kept in
their closed form), and ``lock_margin`` takes the material stretches.

``lock_margin`` is 1 - (I1 - 3) / Jm, Jm the bound of the law's domain
(``Material.domain``: Gent's Jm; 0 at locking, +inf for the laws that do not
lock): how close a state is to the end of the law's domain.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.optimize import brentq

from pocket.core.errors import ConvergenceError, InputError
from pocket.core.inputs import quote
from pocket.core.materials import Material, as_material

from . import laws

__all__ = ["KERNELS", "Law", "law_of"]


@dataclasses.dataclass(frozen=True, eq=False)
class Law:
    """The kernel's ``code`` and ``params`` (``laws``), the ``material`` states echo, a ``label`` for
    messages and Gent's ``jm`` (inf: no locking)."""

    code: int
    params: np.ndarray
    material: Material
    label: str
    jm: float = math.inf

    @property
    def prestretch(self) -> float:
        """lambda_p, the equibiaxial stretch of the clamped flat sheet (1: none)."""
        return self.material.prestretch

    @property
    def flat_tension(self) -> float:
        """N_0 / (E T): the tension of the clamped flat sheet, that of its prestretch (0 without one)."""
        return float(laws.derivatives(self.code, self.params, 1.0, 1.0)[0])

    def derivatives(self, a, b) -> np.ndarray:
        """(w_1, w_2, w_11, w_12, w_22) at stretches a, b (arrays of one shape): shape (5, *a.shape)."""
        a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
        out = laws.evaluate(self.code, self.params, np.ascontiguousarray(a).ravel(), np.ascontiguousarray(b).ravel())
        return out.reshape((5, *a.shape))

    def tensions(self, a, b) -> tuple[np.ndarray, np.ndarray]:
        """(T_1, T_2) = (w_1 / b, w_2 / a), units E T."""
        d = self.derivatives(a, b)
        return d[0] / b, d[1] / a

    def lock_margin(self, a, b) -> float:
        """min of 1 - (I1 - 3) / Jm over the stretches (+inf for a law that does not lock)."""
        if math.isinf(self.jm):
            return math.inf
        a, b = self.prestretch * np.asarray(a, dtype=float), self.prestretch * np.asarray(b, dtype=float)
        return float(np.min(1.0 - (a * a + b * b + (a * b) ** -2 - 3.0) / self.jm))

    def planar_stretch(self, tension: float, guess: float, hoop: float = 1.0) -> float:
        """The stretch l with T_1(l, ``hoop``) = ``tension`` nearest ``guess`` (module docstring; the hoop stretch
        is 1 at a clamp, and the capsule's equatorial radius at its equator)."""
        low, high = 0.0, math.inf
        lp = self.prestretch
        if not math.isinf(self.jm) and lp == 1.0 and hoop == 1.0:
            root, wide = math.sqrt(self.jm), math.sqrt(self.jm + 4.0)
            low, high = 0.5 * (wide - root), 0.5 * (wide + root)
        elif not math.isinf(self.jm):  # the roots u = l^2 of the quadratic of the module docstring, b = hoop
            lb = lp * hoop
            half = 0.5 * (3.0 + self.jm - lb * lb)
            spread = math.sqrt(half * half - lb**-2)
            low, high = math.sqrt(lp**-4 / hoop**2 / (half + spread)), math.sqrt((half + spread) / (lp * lp))

        def gap(s):
            return laws.derivatives(self.code, self.params, s, hoop)[0] / hoop - tension

        if not low < guess < high:
            guess = 1.0
        for k in range(60):
            factor = 1.01 * 2.0**k  # the bracket widens from 1 % around the guess towards the domain's ends
            left = low + (guess - low) / factor
            right = guess * factor if math.isinf(high) else high - (high - guess) / factor
            if gap(left) * gap(right) <= 0.0:
                return float(brentq(gap, left, right, xtol=1e-15, rtol=1e-15))
        raise ConvergenceError(f"no meridional stretch carries the clamp tension {tension:.6g} E T ({self.label})")


def _mooney_rivlin(unit: Material) -> tuple[int, list]:
    alpha = unit.alpha  # the alpha it was given by, or C2/C1
    assert alpha is not None, "a Mooney-Rivlin rubber has its alpha"
    return laws.MOONEY_RIVLIN, [1.0 / (6.0 * (1.0 + alpha)), alpha]


#: law name -> (the Material in units of mu_0 -> (kernel code, parameters in units of E = 3 mu_0))
KERNELS = {
    "mooney-rivlin": _mooney_rivlin,
    "neo-hookean": lambda p: (laws.YEOH, [p["mu"] / 6.0, 0.0, 0.0]),
    "yeoh": lambda p: (laws.YEOH, [p["c10"] / 3.0, p["c20"] / 3.0, p["c30"] / 3.0]),
    "gent": lambda p: (laws.GENT, [p["mu"] / 3.0, p["jm"]]),
    "ogden": lambda p: (laws.OGDEN, [m / 3.0 for m in p["mu"]] + list(p["exponents"])),
}


def _scaled_params(material: Material) -> tuple[int, np.ndarray, float]:
    """(code, parameters in units of E, the bound of the domain on I1 - 3) of a checked Material."""
    if material.law not in KERNELS:
        raise InputError(f"the finite-element solver has no kernel for the {material.law} law (it has "
                         f"{', '.join(KERNELS)})")
    unit = material.scaled()  # stresses in units of mu_0; a third of that is units of E = 3 mu_0
    code, params = KERNELS[material.law](unit)
    return code, np.array([*params, material.prestretch], dtype=float), unit.domain


def law_of(value) -> Law:
    """The Law of the rubber ``value``, a Material (or a Mooney-Rivlin alpha: ``as_material``), checked,
    through ``KERNELS``; the Law keeps the Material as given for the states to echo."""
    material = as_material(value)
    code, params, jm = _scaled_params(material)
    if material.exact_alpha is not None:
        label = f"alpha = {material.alpha!r}"
    else:
        label = f"{material.law} rubber " + ", ".join(f"{k} = {quote(v)}" for k, v in material.params)
    if material.prestretch != 1.0:
        label += f", prestretch = {quote(material.prestretch)}"
    return Law(code, params, material, label, jm)
