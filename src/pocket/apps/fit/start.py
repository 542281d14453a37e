r"""Where a fit starts: the tension scale from the small-strain limit, the law's shape at neutral values.

Tension scale. At small strain every law is its small-strain shear modulus mu_0 (E = 3 mu_0), and
the dome's pole height and volume grow as the cube root of the pressure (Hencky's regime,
``pocket.core.smallstrain``):

    H0 / R = c_H Phat^(1/3),   V / R^3 = c_V Phat^(1/3),   Phat = P R / (E T),

so each datum (P, H0) gives E T = P R (c_H R / H0)^3, and (P, V) gives E T = P R (c_V R^3 / V)^3.
A prestretched sheet is taut: at small pressure it is the paraboloid of the flat sheet's tension
N_0 = n_0 E T (docs/theory.md),

    H0 = P R^2 / (4 N_0),   V = pi R^2 H0 / 2,

so (P, H0) gives E T = P R^2 / (4 n_0 H0), with n_0 = W_1(lambda_p, lambda_p) / (3 lambda_p) of the
start's shape in units of mu_0 (W_1 by a central difference of the law's energy). Either regime's
height is an upper bound on the sheet's (the slack dome is softer than the taut one; the taut
paraboloid stiffens as it stretches), so the smaller of the two estimates is taken at each datum.
The estimate is the median over the first ``SMALL`` rows (the lowest pressures) of each inflation
test, and the zero-force row of a compression test with heights (the dome at P_I). At larger strains
the estimate is biased (a stiffening rubber looks stiffer), which the fit corrects: the scale is the
best-determined direction of every fit. Without such rows (a compression test of forces and
pressures alone) the starts span Phat_I from 0.01 to 1. Each shape is tried at these scales in turn
(``_STIFFER`` times the estimate), and starts from the first that has a state for every datum.

Shape. In units of mu_0, each law's start shapes (``SHAPES``): neutral values (Yeoh's C20 and C30
near 0, Mooney-Rivlin's alpha = C2/C1 small and moderate, Gent's Jm from little to much locking,
Ogden's exponents from Ogden's rubber and neighbours, each term carrying an equal share of mu_0,
mu_p alpha_p = 2 mu_0 / N), each at every prestretch asked (one, or several when the prestretch
is fitted). A law with several starts is fitted from the best few (``pocket.apps.fit.leastsquares``).
"""

from __future__ import annotations

import numpy as np

from pocket.core import smallstrain
from pocket.core.errors import InputError
from pocket.core.materials import Material, energy

from .model import Setup

__all__ = ["MAX_TERMS", "SHAPES", "SMALL", "at_tensions", "flat_tension", "starts", "tension_estimate"]

#: rows of each test used for the small-strain estimate
SMALL = 3
#: Ogden's exponents tried, per number of terms
_OGDEN = {1: ((2.0,), (4.0,), (8.0,), (-2.0,)), 2: ((2.0, -2.0), (4.0, -2.0), (1.3, 5.0), (8.0, -2.0)),
          3: ((1.3, 5.0, -2.0), (2.0, 4.0, -2.0), (1.5, 8.0, -1.0))}
#: law -> its start shapes in units of mu_0 (Ogden: built from ``_OGDEN`` by ``_ogden``)
SHAPES = {
    "neo-hookean": ({"mu": 1.0},),
    "mooney-rivlin": tuple({"c1": 0.5 / (1.0 + a), "c2": 0.5 * a / (1.0 + a)} for a in (0.1, 0.5)),
    "yeoh": ({"c10": 0.5, "c20": 0.0, "c30": 5e-4}, {"c10": 0.5, "c20": -0.01, "c30": 1e-3},
             {"c10": 0.5, "c20": 0.02, "c30": 1e-5}),
    "gent": tuple({"mu": 1.0, "jm": jm} for jm in (100.0, 20.0, 5.0)),
}
#: factors on the small-strain estimate of E T tried: a stiffer start keeps the highest pressures below a
#: pressure maximum that the estimate (biased soft at the larger strains of the first rows) puts them above
_STIFFER = (1.0, 2.0, 4.0)
#: largest number of Ogden terms fitted
MAX_TERMS = max(_OGDEN)


def flat_tension(shape: Material) -> float:
    """n_0 = N_0 / (E T) of the clamped flat sheet of ``shape`` (stresses in any unit), 0 without prestretch."""
    stretch = shape.prestretch
    if stretch == 1.0:
        return 0.0
    unit, h = shape.scaled(), 1e-6 * stretch  # central difference: error O(h^2) ~ 1e-12, rounding ~1e-10
    w_1 = (energy(unit, stretch + h, stretch) - energy(unit, stretch - h, stretch)) / (2.0 * h)
    return float(w_1) / (3.0 * stretch)


def tension_estimate(setup: Setup, shape: Material | None = None) -> float | None:
    """E T (N/m) from the small-strain rows of ``setup``'s tests for a sheet of ``shape``'s law and prestretch
    (module docstring; None: without prestretch), or None if no test has such rows."""
    c_h, c_v = smallstrain.height(1.0), smallstrain.volume(1.0)
    n_0 = 0.0 if shape is None else flat_tension(shape)
    radius = setup.radius
    out = []
    for test in setup.tests:
        if test.kind == "inflation":
            rows = slice(0, SMALL)
            pressures = test.control[rows]
        else:
            rows = test.control == 0.0
            pressures = np.full(np.count_nonzero(rows), test.initial_pressure)
        for name, (c, power) in {"height": (c_h, 1), "volume": (c_v, 3)}.items():
            if name in test.responses:
                values = test.responses[name][rows] / radius**power
                heights = values if name == "height" else 2.0 * values / np.pi  # the paraboloid's V / R^3
                out += [min(p * radius * (c / v) ** 3, p * radius / (4.0 * n_0 * h) if n_0 else np.inf)
                        for p, v, h in zip(pressures, values, heights, strict=True) if np.isfinite(v)]
    return float(np.median(out)) if out else None


def _ogden(terms: int) -> tuple[dict, ...]:
    if terms not in _OGDEN:
        raise InputError(f"--terms = {terms!r}, but an Ogden fit takes 1 to {MAX_TERMS} terms")
    return tuple({"mu": tuple(2.0 / (terms * a) for a in alphas), "exponents": alphas} for alphas in _OGDEN[terms])


def starts(setup: Setup, law: str, terms: int = 1, prestretches=(1.0,)) -> list[list[Material]]:
    """The start materials of ``law`` (stresses in ``setup``'s unit): per shape and prestretch (of
    ``prestretches``), one at each tension scale to try in turn."""
    out = []
    for shape in _ogden(terms) if law == "ogden" else SHAPES[law]:
        for stretch in prestretches:
            unit = Material(law, tuple(shape.items()), prestretch=stretch)
            estimate = tension_estimate(setup, unit)
            if estimate is not None:
                tensions = [estimate * f for f in _STIFFER]
            else:  # no small-strain rows: only compression tests without a row at zero force, each with its P_I
                first = setup.tests[0].initial_pressure
                assert first is not None
                tensions = [first * setup.radius / p for p in (0.01, 0.1, 1.0)]
            out.append([_times_stresses(unit, t / 3.0 / setup.scale / unit.mu0) for t in tensions])
    return out


def at_tensions(setup: Setup, law: str, terms: int, tensions) -> list[Material]:
    """Each start shape of ``law`` (``SHAPES``, Ogden's of ``terms`` terms) at each tension scale E T (N/m) of
    ``tensions``, stresses in ``setup``'s unit, without prestretch: where the data give no estimate of E T, a fit
    ranks these by their cost (a capsule's, ``pocket.apps.fit.capsuletest``)."""
    out = []
    for shape in _ogden(terms) if law == "ogden" else SHAPES[law]:
        unit = Material(law, tuple(shape.items()))
        out += [_times_stresses(unit, t / 3.0 / setup.scale / unit.mu0) for t in tensions]
    return out


def _times_stresses(material: Material, factor: float) -> Material:
    stresses = material.definition.stresses
    return Material(material.law, tuple((n, _times(factor, v) if n in stresses else v) for n, v in material.params),
                    prestretch=material.prestretch)


def _times(factor: float, value):
    return tuple(factor * v for v in value) if isinstance(value, tuple) else factor * value
