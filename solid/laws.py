r"""Each rubber's strain energy as a function of the invariants, with its first and second derivatives.

The solid works with the 3-D invariants of C = F^T F,

    I1 = tr C,    I2 = (I1^2 - tr C^2) / 2,

which at J = det F = 1 equal those of ``pocket.core.materials`` (there written through the
principal stretches: I2 = l1^-2 + l2^-2 + l3^-2 = l1^2 l2^2 + l2^2 l3^2 + l3^2 l1^2 when
l1 l2 l3 = 1). Incompressibility is a constraint of the mixed formulation (``kinematics``), so W
itself needs no volumetric part: W(I1, I2) is the law's energy, evaluated as written.

With x = I1 - 3 and y = I2 - 3, the derivatives W_1 = dW/dI1, W_2 = dW/dI2 and the second
derivatives W_11, W_12, W_22 are, per law (units of the law's stresses):

=============  =====================================  ==========================================
law            W_1, W_2                                W_11, W_12, W_22
=============  =====================================  ==========================================
mooney-rivlin  C1, C2                                  0, 0, 0
neo-hookean    mu / 2, 0                               0, 0, 0
yeoh           C10 + 2 C20 x + 3 C30 x^2, 0            2 C20 + 6 C30 x, 0, 0
gent           (mu / 2) / (1 - x / Jm), 0              (mu / 2) / (Jm (1 - x / Jm)^2), 0, 0
=============  =====================================  ==========================================

The Ogden law is a sum over the principal stretches, not a function of I1 and I2:
``derivatives`` gives it as a ``stretches.Ogden``, which differentiates W in F's components
through the isochoric principal stretches.

A test compares the invariant laws' derivatives with finite differences of
``pocket.core.materials.energy`` along uniaxial and equibiaxial paths; another, Ogden's with
finite differences of its energy in F.
"""

from __future__ import annotations

from typing import cast

import numpy as np

from pocket.core.errors import InputError
from pocket.core.materials import Material

from .stretches import Ogden

__all__ = ["LAWS", "derivatives"]


def _mooney_rivlin(p, x, y):
    zero = np.zeros_like(x)
    return p["c1"] + zero, p["c2"] + zero, zero, zero, zero


def _neo_hookean(p, x, y):
    zero = np.zeros_like(x)
    return 0.5 * p["mu"] + zero, zero, zero, zero, zero


def _yeoh(p, x, y):
    zero = np.zeros_like(x)
    return (p["c10"] + 2.0 * p["c20"] * x + 3.0 * p["c30"] * x**2, zero,
            2.0 * p["c20"] + 6.0 * p["c30"] * x, zero, zero)


def _gent(p, x, y):
    zero = np.zeros_like(x)
    s = 1.0 - x / p["jm"]
    return 0.5 * p["mu"] / s, zero, 0.5 * p["mu"] / (p["jm"] * s**2), zero, zero


#: law name -> (params, I1 - 3, I2 - 3) -> (W_1, W_2, W_11, W_12, W_22)
LAWS = {"mooney-rivlin": _mooney_rivlin, "neo-hookean": _neo_hookean, "yeoh": _yeoh, "gent": _gent}


def derivatives(material: Material):
    """The function (I1, I2) -> (W_1, W_2, W_11, W_12, W_22) of ``material`` (arrays broadcast; the
    unit of its stresses), or for the Ogden law its ``stretches.Ogden``; a one-line InputError for a law
    the solid has no kernel for."""
    if material.law == "ogden":
        params = dict(material.params)  # the listed parameters are tuples (``Material``)
        return Ogden(cast(tuple, params["mu"]), cast(tuple, params["exponents"]))
    if material.law not in LAWS:
        raise InputError(f"the solid solver has no kernel for the {material.law} law (it has "
                         f"{', '.join(LAWS)}, ogden)")
    law, params = LAWS[material.law], dict(material.params)
    return lambda i1, i2: law(params, np.asarray(i1) - 3.0, np.asarray(i2) - 3.0)
