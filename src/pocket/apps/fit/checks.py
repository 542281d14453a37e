r"""What a fit's data make absurd: a unit gone wrong, found before any solve, and a fitted modulus no rubber has.

A value in the wrong unit (a height column in metres for millimetre data, a clamp radius ``15`` read as
15 m, an uncertainty ``0.02`` read as 20 mm) gives a fit of the wrong rubber, or no fit. The data, the
clamp radius R and the thickness T bound each other, so such a mistake shows before the fit:

Heights and volumes. The pole's height H is at most the length of the deformed meridian from the clamp
to the pole, and that is at most the largest stretch lambda_max the rubber takes times R (each element
of the meridian, of reference length at most R, is stretched at most lambda_max times):
H <= lambda_max R. The enclosed volume is bounded by the isoperimetric inequality: the dome's area is
at most lambda_max^2 pi R^2, the closed surface (dome and clamp disc) at most A = (lambda_max^2 + 1) pi R^2,
and no surface of area A encloses more than the sphere's A^(3/2) / (6 sqrt(pi)). No rubber stretches
ten times before it breaks (natural rubber about 8, the most extensible silicones about 10 at 900 %
elongation), so ``MAX_STRETCH`` = 20 is twice any rubber's, and a column past these bounds is refused as
being in the wrong unit. The plate's height in a compression test is the sheet's top: the same bound.

Modulus. The dimensionless group of the problem is Phat = P R / (E T). At small strain the dome's
height and volume give Phat alone (``pocket.apps.fit.start``: H / R = c_H Phat^(1/3)), so the first rows
of a test give E T = P R / Phat whatever the material. A modulus E = E T / T above ``MAX_MODULUS``,
stiffer than any solid, or below ``MIN_MODULUS``, softer than any gel that holds a shape, means a unit
is wrong (the pressures', the heights' or R's); without T, a membrane is thinner than its clamp radius,
so E >= E T / R, refused above ``MAX_MODULUS`` too. The estimate is biased at the larger strains of a
test's first rows by a factor of a few (``pocket.apps.fit.start``), far inside these bounds (a rubber's E
is about 1e6 Pa). It holds for a slack sheet only: a prestretched one is taut, its height at small
pressure P R^2 / (4 N_0) set by the flat sheet's tension N_0, so a tiny dome on a large clamp is no
contradiction; where the prestretch is held above 1 or fitted, the modulus is not checked.

Uncertainties. A stated uncertainty larger than every value of its column (``--sigma height=0.02``,
20 mm, beside heights of a few mm) is no measurement's: refused.

After the fit, E = 3 mu_0 outside ``RUBBER_MODULI`` (or, without T, E T / R above its top) is a warning:
possible for some solid, not for a rubber.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from pocket.core.errors import InputError
from pocket.core.units import KINDS

from .data import QUANTITIES
from .model import Setup
from .start import tension_estimate

__all__ = ["MAX_MODULUS", "MAX_STRETCH", "MIN_MODULUS", "RUBBER_MODULI", "check", "modulus_warnings"]

#: twice the largest stretch any rubber takes before it breaks (module docstring)
MAX_STRETCH = 20.0
#: Young's modulus above which no solid is (diamond's, the stiffest, is 1.05e12 Pa)
MAX_MODULUS = 1e12
#: Young's modulus below which no solid sheet is (the softest hydrogels that hold their shape are ~10 Pa)
MIN_MODULUS = 1.0
#: Young's moduli of rubbers, Pa: the softest silicone gels (~10 kPa) to hard rubbers (~100 MPa), a decade wider
RUBBER_MODULI = (1e3, 1e9)
#: the largest value of each column allowed by MAX_STRETCH, in units of R^power
_LIMITS = {"height": (1, MAX_STRETCH),
           "volume": (3, (MAX_STRETCH**2 + 1.0) ** 1.5 * math.pi / 6.0)}


def _plain(value: float, unit: str) -> str:
    return f"{value:.4g} {unit}"


def _columns(test, radius: float) -> None:
    for name, (power, limit) in _LIMITS.items():
        if name in test.responses:
            values = test.responses[name]
            top = float(np.nanmax(values))
            if top > limit * radius**power:
                unit = "m" if power == 1 else "m^3"
                raise InputError(
                    f"{test.source}: the {name} column reaches {_plain(top, unit)}, {top / radius**power:.3g} R"
                    f"{'' if power == 1 else '^3'} on a clamp of radius R = {_plain(radius, 'm')}, but no rubber "
                    f"stretches far enough for a {name} above {limit:.4g} R{'' if power == 1 else '^3'}: its unit "
                    f"(or the clamp radius's) is wrong")


def _modulus(setup: Setup, test) -> None:
    tension = tension_estimate(dataclasses.replace(setup, tests=(test,)))
    if tension is None:
        return
    thickness = setup.thickness
    modulus = tension / (thickness if thickness else setup.radius)
    what = f"E = {modulus:.3g} Pa" if thickness else f"E >= {modulus:.3g} Pa even for a sheet as thick as R"
    where = (f"{test.source}: the pressures and {'heights' if 'height' in test.responses else 'volumes'} of its "
             f"first rows on a clamp of radius R = {_plain(setup.radius, 'm')} give E T = {tension:.3g} N/m, so {what}")
    if modulus > MAX_MODULUS:
        raise InputError(f"{where}: stiffer than any solid (diamond: 1.05e12 Pa), so a unit is wrong (the "
                         "pressures', the heights', R's or T's)")
    if thickness and modulus < MIN_MODULUS:
        raise InputError(f"{where}: softer than any solid sheet (the softest gels: ~10 Pa), so a unit is wrong "
                         "(the pressures', the heights', R's or T's)")


def _uncertainties(setup: Setup, spell: Callable[[str], str], quantities: dict) -> None:
    for name, sigma in setup.sigma.items():
        data = [t.responses[name] for t in setup.tests if name in t.responses]
        top = max((float(np.nanmax(np.abs(d))) for d in data), default=math.inf)
        if sigma > top:
            unit = KINDS[quantities[name]][1].replace("**3", "^3")
            raise InputError(f"{spell(name)}: the uncertainty {_plain(sigma, unit)} is more than every {name} "
                             f"datum (the largest: {_plain(top, unit)}): no measurement is that uncertain, so its "
                             "unit is wrong")


def check(setup: Setup, spell: Callable[[str], str] = lambda name: f"--sigma {name}", slack: bool = True,
          quantities: dict = QUANTITIES) -> None:
    """Refuse ``setup`` where its data beside the clamp radius, the thickness and the stated uncertainties
    can only be in a wrong unit (module docstring): an InputError naming the file and column, or the
    uncertainty (a column's, named by ``spell(column)``). ``slack``: the sheet is fitted without prestretch
    (else the modulus is not checked); ``quantities``: the kind of each column (a capsule's tests have their
    own, ``pocket.apps.fit.capsuledata``)."""
    for test in setup.tests:
        _columns(test, setup.radius)
    for test in setup.tests if slack else ():
        _modulus(setup, test)
    _uncertainties(setup, spell, quantities)


def modulus_warnings(setup: Setup, mu0: float) -> list[str]:
    """A warning if the fitted ``mu0`` (Pa, or N/m times T without a thickness) is no rubber's (module
    docstring); empty otherwise."""
    low, high = RUBBER_MODULI
    radius = "capsule's radius" if any(t.kind == "capsule" for t in setup.tests) else "clamp radius"
    if setup.thickness:
        modulus = 3.0 * mu0
        if low <= modulus <= high:
            return []
        return [f"the fitted E = 3 mu_0 = {modulus:.3g} Pa is no rubber's ({low:.0e} to {high:.0e} Pa): check the "
                f"units of the data, the {radius} and the thickness"]
    bound = 3.0 * mu0 / setup.radius
    if bound <= high:
        return []
    return [f"the fitted E T = 3 mu_0 T = {3.0 * mu0:.3g} N/m gives E >= {bound:.3g} Pa even for a sheet as thick "
            f"as the {radius}, no rubber's ({low:.0e} to {high:.0e} Pa): check the units of the data and the "
            f"{radius}"]
