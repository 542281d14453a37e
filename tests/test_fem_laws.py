"""Each rubber law's membrane energy derivatives in the finite-element kernel (fem/laws.py, fem/material.py).

Exact answers: w = W / E per unit reference area with E = 3 mu_0, W the one shared definition
(``pocket.core.materials.energy``); the kernel's w_1, w_2 equal its central differences and
w_11, w_12, w_22 its second central differences (both O(h^2), h chosen so that truncation and
round-off stay below the tolerances); the small-strain equibiaxial tension is 2 E T e for every law
(linearised membrane, nu = 1/2); a law given in Pa and the same law in units of mu_0 are one law; a
Gent rubber has no energy at or past I1 - 3 = Jm; the planar stretch at the clamp carries the
tension it is asked for.
"""

import math

import numpy as np
import pytest
from pocket.fem import laws
from pocket.fem.material import law_of

from pocket.core.errors import InputError
from pocket.core.materials import check, energy, mooney_rivlin

#: rubbers beyond the registry's examples (``conftest.rubber``, one per law, in Pa): Mooney-Rivlin by its alpha,
#: a one-term Ogden rubber in units of mu_0, the Yeoh example with a stiffer C30
OTHERS = {
    "alpha": 47 / 160,
    "alpha-negative": -0.4,
    "ogden-one": check("ogden", {"mu": [2.0], "exponents": [0.6]}),
    "yeoh-stiffer": check("yeoh", {"c10": 85e3, "c20": -2e3, "c30": 0.3e3}),
}
#: stretches from compressive to large, meridional a and hoop b (Gent's I1 - 3 stays below Jm = 10)
A, B = (g.ravel() for g in np.meshgrid(np.linspace(0.75, 2.2, 9), np.linspace(0.8, 2.0, 7)))


def _energy(rubber):
    """w(a, b) = W / E from the shared definition, E = 3 mu_0 (W and mu_0 in the rubber's own unit)."""
    material = mooney_rivlin(rubber) if isinstance(rubber, float) else rubber
    return lambda a, b: energy(material, a, b) / material.modulus


def _gradient(rubber):
    """w_1, w_2 = (w(a +- h) difference) / 2h to 1e-8 relative to the gradient's size (h = 1e-5:
    truncation h^2 w''' ~ 1e-10, round-off 1e-16 / h ~ 1e-11)."""
    w, law, h = _energy(rubber), law_of(rubber), 1e-5
    d = law.derivatives(A, B)
    w1 = (w(A + h, B) - w(A - h, B)) / (2 * h)
    w2 = (w(A, B + h) - w(A, B - h)) / (2 * h)
    scale = np.abs(np.concatenate([w1, w2])).max()
    np.testing.assert_allclose(d[0], w1, rtol=0, atol=1e-8 * scale)
    np.testing.assert_allclose(d[1], w2, rtol=0, atol=1e-8 * scale)


def _hessian(rubber):
    """w_11, w_22 = (w(a + h) - 2 w(a) + w(a - h)) / h^2 and w_12 from the four corners / 4 h^2, to 1e-6
    relative to the Hessian's size (h = 1e-4: truncation h^2 w'''' ~ 1e-8, round-off 1e-16 / h^2 ~ 1e-8)."""
    w, law, h = _energy(rubber), law_of(rubber), 1e-4
    d = law.derivatives(A, B)
    w11 = (w(A + h, B) - 2 * w(A, B) + w(A - h, B)) / h**2
    w22 = (w(A, B + h) - 2 * w(A, B) + w(A, B - h)) / h**2
    w12 = (w(A + h, B + h) - w(A + h, B - h) - w(A - h, B + h) + w(A - h, B - h)) / (4 * h**2)
    scale = np.abs(np.concatenate([w11, w12, w22])).max()
    for ours, differences in ((d[2], w11), (d[3], w12), (d[4], w22)):
        np.testing.assert_allclose(ours, differences, rtol=0, atol=1e-6 * scale)


def _small_strain(rubber):
    """Linear membrane, nu = 1/2: T = E T e / (1 - nu) = 2 E T e at lambda_1 = lambda_2 = 1 + e. The
    quotient T / (2 e) - 1 = O(e): at e = 1e-6 within 1e-4 (a loose bound on the O(e) term's coefficient),
    and the same for T_2."""
    law, e = law_of(rubber), 1e-6
    t1, t2 = law.tensions(1 + e, 1 + e)
    assert abs(t1 / (2 * e) - 1) < 1e-4, (t1 / (2 * e), t2 / (2 * e))
    assert abs(t2 / (2 * e) - 1) < 1e-4, (t1 / (2 * e), t2 / (2 * e))


def _planar_stretch(rubber):
    """The clamp's stretch from its tension: T_1(l, 1) = T at the l returned, which is the stretch the
    tension was made from (to 1e-12, from a guess 5 % off), for l = 0.9, 1 + 1e-7, 1.3, 2."""
    law = law_of(rubber)
    for stretch in (0.9, 1.0 + 1e-7, 1.3, 2.0):
        tension = float(law.tensions(stretch, 1.0)[0])
        found = law.planar_stretch(tension, stretch * 1.05)
        assert found == pytest.approx(stretch, rel=1e-12), (found, stretch, tension)


def check_derivatives(rubber):
    """The kernel's gradient and Hessian are the central differences of the shared energy, its
    small-strain tension is 2 E T e and its clamp stretch carries its tension (``_gradient``, ``_hessian``,
    ``_small_strain``, ``_planar_stretch``)."""
    for check_one in (_gradient, _hessian, _small_strain, _planar_stretch):
        check_one(rubber)


def test_derivatives_of_every_registered_law(rubber):
    """Exact answers: ``check_derivatives`` for every law of the registry (its example rubber, in Pa)."""
    check_derivatives(rubber)


@pytest.mark.parametrize("name", OTHERS)
def test_derivatives_of_other_rubbers(name):
    """Exact answers: ``check_derivatives`` for a rubber given by alpha and other parameters."""
    check_derivatives(OTHERS[name])


def test_a_law_in_pascal_is_the_law_in_units_of_mu0(rubber):
    """law_of divides the stresses by E: the Material in Pa and its ``scaled()`` copy (units of mu_0) give
    the same derivatives to 1e-14."""
    material = rubber
    np.testing.assert_allclose(law_of(material).derivatives(A, B), law_of(material.scaled()).derivatives(A, B),
                               rtol=1e-14, atol=1e-15)


def test_a_mooney_rivlin_material_is_its_alpha_bit_for_bit():
    """MR(C1, C2) in Pa runs on the parameters of the float alpha = C2/C1: identical arrays; each law keeps the
    rubber as given to echo (the float as ``mooney_rivlin(alpha)``, which keeps that alpha)."""
    material = check("mooney-rivlin", {"c1": 160e3, "c2": 47e3})
    by_alpha, by_material = law_of(47 / 160), law_of(material)
    assert by_alpha.code == by_material.code
    assert np.array_equal(by_alpha.params, by_material.params)
    assert by_alpha.material == mooney_rivlin(47 / 160)
    assert by_alpha.material.exact_alpha == 47 / 160
    assert by_material.material is material
    assert by_material.material.exact_alpha is None


def test_gent_has_no_energy_past_locking():
    """Gent's W = -(mu Jm/2) ln(1 - (I1 - 3)/Jm) exists only for I1 - 3 < Jm: at equibiaxial stretches with
    I1 - 3 = Jm (1 - 1e-9) the derivatives are finite, at Jm (1 + 1e-9) and 1.5 Jm NaN (the formulas alone
    would be finite and of the wrong sign there). The lock margin 1 - (I1 - 3)/Jm says how close."""
    jm = 10.0
    law = law_of(check("gent", {"mu": 1.0, "jm": jm}))
    for factor, finite in ((1 - 1e-9, True), (1 + 1e-9, False), (1.5, False)):
        s = _equibiaxial_stretch(jm * factor)
        assert bool(np.all(np.isfinite(law.derivatives(s, s)))) is finite, (factor, law.derivatives(s, s))
    s = _equibiaxial_stretch(jm * (1 - 1e-3))
    assert law.lock_margin(s, s) == pytest.approx(1e-3, rel=1e-6)
    assert math.isinf(law_of(0.3).lock_margin(s, s))


def _equibiaxial_stretch(x):
    """The stretch l > 1 with 2 l^2 + l^-4 - 3 = x > 0 (bisection: the left side rises for l > 1)."""
    low, high = 1.0, 10.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if 2 * mid**2 + mid**-4 - 3 < x else (low, mid)
    return low


def test_gent_planar_stretch_stays_inside_the_domain():
    """Close to Gent's planar locking, (l - 1/l)^2 = Jm, a guess past it still finds the stretch below it."""
    jm = 2.0
    law = law_of(check("gent", {"mu": 1.0, "jm": jm}))
    locking = 0.5 * (math.sqrt(jm + 4) + math.sqrt(jm))
    stretch = locking * (1 - 1e-6)
    tension = float(law.tensions(stretch, 1.0)[0])
    assert law.planar_stretch(tension, locking * 1.2) == pytest.approx(stretch, rel=1e-12)


def test_neo_hookean_runs_as_yeoh():
    """neo-Hookean runs on Yeoh's kernel with C10 = mu / 2 (in units of E = 3 mu: C10 / E = 1/6), then its
    prestretch (1: none)."""
    law = law_of(check("neo-hookean", {"mu": 0.4e6}))
    assert law.code == laws.YEOH
    assert list(law.params) == [0.4e6 / 0.4e6 / 6.0, 0.0, 0.0, 1.0]


def test_an_unstable_material_is_refused_by_the_shared_check():
    """A Material built around the shared check (a Yeoh rubber whose slope dW/dI1 turns negative) is
    re-checked: InputError, one line."""
    from pocket.core.materials import Material

    bad = Material("yeoh", (("c10", 1.0), ("c20", -1.0), ("c30", 0.1)))
    with pytest.raises(InputError, match="stable Yeoh") as info:
        law_of(bad)
    assert "\n" not in str(info.value)
