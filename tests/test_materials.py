"""The strain-energy laws: identities between laws, the small-strain modulus, and the checks."""

import math

import numpy as np
import pytest

from pocket.core.errors import InputError
from pocket.core.materials import LAWS, Material, check, energy, mooney_rivlin

STRETCHES = np.meshgrid(np.linspace(0.7, 2.5, 13), np.linspace(0.8, 2.2, 11))


def law(name, **params):
    return check(name, params)


@pytest.mark.parametrize("mu", [0.3, 1.0, 250e3])
def test_neo_hookean_is_three_other_laws(mu):
    """Exact identities: neo-hookean(mu) = mooney-rivlin(mu/2, 0) = yeoh(mu/2, 0, 0) = ogden([mu], [2])."""
    w = energy(law("neo-hookean", mu=mu), *STRETCHES)
    for other in (law("mooney-rivlin", c1=mu / 2, c2=0.0), law("yeoh", c10=mu / 2, c20=0.0, c30=0.0),
                  law("ogden", mu=[mu], exponents=[2.0])):
        np.testing.assert_allclose(energy(other, *STRETCHES), w, rtol=1e-13, atol=1e-13 * mu)
        assert other.mu0 == pytest.approx(mu, rel=1e-15)


def test_ogden_with_exponents_two_and_minus_two_is_mooney_rivlin():
    """Exact identity: ogden([2 C1, -2 C2], [2, -2]) = mooney-rivlin(C1, C2) (each term is one invariant)."""
    c1, c2 = 160e3, 47e3
    mr = law("mooney-rivlin", c1=c1, c2=c2)
    og = law("ogden", mu=[2 * c1, -2 * c2], exponents=[2.0, -2.0])
    np.testing.assert_allclose(energy(og, *STRETCHES), energy(mr, *STRETCHES), rtol=1e-13)
    assert og.mu0 == pytest.approx(mr.mu0, rel=1e-15)
    assert mr.modulus == pytest.approx(6 * (c1 + c2), rel=1e-15)


def test_gent_tends_to_neo_hookean_at_rate_one_over_jm():
    """W_gent - W_nh = (mu / 4) (I1 - 3)^2 / Jm + O(Jm^-2): the difference times Jm tends to that limit,
    and halves when Jm doubles."""
    mu = 1.0
    nh = energy(law("neo-hookean", mu=mu), *STRETCHES)
    i1 = STRETCHES[0] ** 2 + STRETCHES[1] ** 2 + (STRETCHES[0] * STRETCHES[1]) ** -2
    limit = mu / 4 * (i1 - 3) ** 2
    gaps = []
    for jm in (1e3, 2e3, 4e3):
        gap = (energy(law("gent", mu=mu, jm=jm), *STRETCHES) - nh) * jm
        gaps.append(np.max(np.abs(gap - limit) / np.maximum(limit, 1e-300)))
    assert gaps[0] < 0.05
    assert gaps[1] / gaps[0] == pytest.approx(0.5, rel=0.05)


def test_small_strain_young_modulus_is_three_mu0(rubber):
    """Uniaxial tension l1 = 1 + e, l2 = l3 = (1 + e)^-1/2: W = (E / 2) e^2 + O(e^3) with E = 3 mu_0.
    The quotient 2 W / e^2 is extrapolated to e = 0 from e and e/2 (Richardson, first order in e)."""
    def quotient(e):
        return 2 * energy(rubber, 1 + e, (1 + e) ** -0.5) / e**2

    e = 1e-3
    extrapolated = 2 * quotient(e / 2) - quotient(e)
    assert extrapolated == pytest.approx(rubber.modulus, rel=1e-5)


def test_scaled_has_unit_mu0_and_the_same_shape_of_energy():
    """scaled(): stresses divided by mu_0, so mu_0 = 1 and W scales by 1/mu_0; mooney_rivlin(alpha) is that."""
    mr = law("mooney-rivlin", c1=160e3, c2=47e3)
    unit = mr.scaled()
    assert unit.mu0 == pytest.approx(1.0, rel=1e-15)
    np.testing.assert_allclose(energy(unit, *STRETCHES), energy(mr, *STRETCHES) / mr.mu0, rtol=1e-14)
    same = mooney_rivlin(47 / 160)
    np.testing.assert_allclose(energy(same, *STRETCHES), energy(unit, *STRETCHES), rtol=1e-14)
    og = law("ogden", mu=[630e3, 1.2e3, -10e3], exponents=[1.3, 5.0, -2.0]).scaled()
    assert og.mu0 == pytest.approx(1.0, rel=1e-14)
    assert og["exponents"] == (1.3, 5.0, -2.0)


@pytest.mark.parametrize(("name", "params", "message"), [
    ("rubber", {}, "material = 'rubber', but it must be one of"),
    ("neo-hookean", {}, "sheet.mu is missing"),
    ("neo-hookean", {"mu": 1.0, "c1": 1.0}, "sheet.c1 is not a parameter of the neo-hookean law"),
    ("neo-hookean", {"mu": -1.0}, "sheet.mu = -1.0, but the shear modulus must be > 0"),
    ("gent", {"mu": 1.0, "jm": 0.0}, "sheet.jm = 0.0, but the locking parameter Jm must be > 0"),
    ("yeoh", {"c10": 1.0, "c20": 0.0, "c30": -0.1}, "a stable Yeoh rubber needs"),
    ("yeoh", {"c10": 1.0, "c20": -1.0, "c30": 0.1}, "a stable Yeoh rubber needs"),
    ("ogden", {"mu": [1.0, 2.0], "exponents": [2.0]}, "sheet.mu has 2 terms but sheet.exponents has 1"),
    ("ogden", {"mu": [1.0], "exponents": [-2.0]}, "mu_p alpha_p > 0"),
    ("ogden", {"mu": "1", "exponents": [2.0]}, "needs a non-empty list"),
    ("mooney-rivlin", {"c1": 1.0, "c2": -1.5}, "C1 + C2 > 0"),
    ("mooney-rivlin", {"c1": "x", "c2": 0.0}, "sheet.c1 = 'x' is not a number"),
])
def test_bad_parameters_are_one_line_errors_naming_the_key(name, params, message):
    with pytest.raises(InputError) as err:
        check(name, params)
    assert message in str(err.value), str(err.value)
    assert "\n" not in str(err.value), str(err.value)


def test_yeoh_stability_boundary():
    """Exact: with C20 < 0 < C30 the slope C10 + 2 C20 x + 3 C30 x^2 has its minimum C10 - C20^2 / (3 C30)
    at x = -C20 / (3 C30); stable iff that is > 0."""
    c20, c30 = -1.0, 0.1
    edge = c20**2 / (3 * c30)
    check("yeoh", {"c10": edge * (1 + 1e-9), "c20": c20, "c30": c30})
    with pytest.raises(InputError):
        check("yeoh", {"c10": edge * (1 - 1e-9), "c20": c20, "c30": c30})


def test_every_law_is_covered():
    assert set(LAWS) == {"mooney-rivlin", "neo-hookean", "yeoh", "gent", "ogden"}
    assert isinstance(mooney_rivlin(0.3), Material)


def test_gas_law_and_its_liquid_limit():
    """(P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma holds for volume_ratio; as P_atm grows V/V_I -> 1 with
    1 - V/V_I ~ (P - P_I) / (gamma P_atm); a liquid keeps V_I."""
    from pocket.core.fluids import LIQUID, gas

    p_i, p = 0.3, 0.45
    for gamma in (1.0, 1.4):
        fluid = gas(1.0, gamma)
        ratio = fluid.volume_ratio(p, p_i)
        assert (p + 1.0) * ratio**gamma == pytest.approx(p_i + 1.0, rel=1e-15)
        gaps = [1 - gas(a, gamma).volume_ratio(p, p_i) for a in (1e3, 1e4)]
        assert gaps[0] * 1e3 * gamma == pytest.approx(p - p_i, rel=2e-3)
        assert gaps[1] / gaps[0] == pytest.approx(
            0.1, rel=2e-3)
    assert LIQUID.volume_ratio(p, p_i) == 1.0


@pytest.mark.parametrize(("ambient", "gamma", "message"), [
    (0.0, 1.0, "fluid.ambient = 0.0, but the ambient (absolute) pressure must be > 0"),
    (1.0, 0.9, "fluid.gamma = 0.9, but it must lie in [1, 5/3]"),
    (1.0, 1.7, "fluid.gamma = 1.7"),
    ("x", 1.0, "fluid.ambient = 'x' is not a number"),
])
def test_bad_gas(ambient, gamma, message):
    from pocket.core.fluids import gas

    with pytest.raises(InputError) as err:
        gas(ambient, gamma)
    assert message in str(err.value)


def test_as_material_takes_an_alpha_or_a_checked_material():
    """Exact answer: a number is the Mooney-Rivlin alpha in units of mu_0, kept exactly; a Material comes back as
    the same object after its check; a Material built around the check, or a bad alpha, is a one-line InputError."""
    from pocket.core.materials import as_material

    assert as_material(0.3) == mooney_rivlin(0.3)
    assert as_material(0.3).exact_alpha == 0.3
    gent = law("gent", mu=0.3e6, jm=10.0)
    assert as_material(gent) is gent
    for bad, message in ((Material("gent", (("mu", 1.0), ("jm", -2.0))), "sheet.jm = -2.0"),
                         (Material("rubber", ()), "must be one of"), (-1.5, "alpha = -1.5"),
                         ("soft", "alpha = 'soft' is not a number")):
        with pytest.raises(InputError, match=message) as err:
            as_material(bad)
        assert "\n" not in str(err.value)


def test_as_fluid_takes_none_liquid_or_a_checked_gas():
    """Exact answer: None and "liquid" are LIQUID; a gas comes back as the same object after its check;
    anything else, or a gas built around the check, is a one-line InputError."""
    from pocket.core.fluids import LIQUID, Fluid, as_fluid, gas

    assert as_fluid(None) is LIQUID
    assert as_fluid("liquid") is LIQUID
    assert as_fluid(LIQUID) is LIQUID
    air = gas(0.5, 1.4)
    assert as_fluid(air) is air
    for bad, message in (("air", "fluid = 'air'"), (Fluid("gas", -1.0, 1.0), "fluid.ambient = -1.0"),
                         (Fluid("gas", 1.0, 2.0), "fluid.gamma = 2.0"), (Fluid("plasma"), "fluid.kind = 'plasma'"),
                         (Fluid("liquid", 1.0), "a liquid has no ambient pressure")):
        with pytest.raises(InputError, match=message):
            as_fluid(bad)


def test_material_takes_a_mapping_of_the_laws_parameter_names():
    """Exact answer: the natural call with a mapping (any order, Ogden's lists) is the material of the
    stored form, pairs in the law's order with floats and tuples; a name that is not the law's is one
    InputError listing the law's names."""
    yeoh = Material("yeoh", {"c30": 0.001, "c10": 1, "c20": -0.02})
    assert yeoh == Material("yeoh", (("c10", 1.0), ("c20", -0.02), ("c30", 0.001)))
    assert yeoh.mu0 == 2.0
    assert energy(yeoh, 1.2, 1.1) == energy(check("yeoh", dict(yeoh.params)), 1.2, 1.1)
    ogden = Material("ogden", {"mu": [1.0, -0.1], "exponents": [2, -2]})
    assert ogden.params == (("mu", (1.0, -0.1)), ("exponents", (2.0, -2.0)))
    with pytest.raises(InputError, match=r"^material\.c40 is not a parameter of the yeoh law \(its parameters: "
                       r"c10, c20, c30\)$"):
        Material("yeoh", {"c10": 1, "c20": 0, "c40": 1})


@pytest.mark.parametrize(("alpha", "message"), [(-1.0, "alpha = -1.0, but the Mooney-Rivlin model needs alpha > -1"),
                                            (math.nan, "alpha = nan"), ("soft", "alpha = 'soft' is not a number")])
def test_mooney_rivlin_refuses_a_bad_alpha_in_one_line(alpha, message):
    """Exact answer: ``mooney_rivlin`` is where every alpha becomes a rubber, so it checks it (alpha = -1 would
    divide by zero, a NaN would make a NaN rubber)."""
    with pytest.raises(InputError, match=message) as err:
        mooney_rivlin(alpha)
    assert "\n" not in str(err.value)


def _alphas_of_one_c1_c2():
    """Two alphas one ulp apart whose mooney_rivlin rubbers have the same C1 and C2 (found, not assumed)."""
    alpha = 1.5  # 1 + alpha in [2, 4) and C2 = alpha C1 in [1/4, 1/2): both coarser than a step of alpha
    for _ in range(10_000):
        other = math.nextafter(alpha, 2.0)
        if mooney_rivlin(alpha).params == mooney_rivlin(other).params:
            return alpha, other
        alpha = other
    raise AssertionError("no two neighbouring alphas share C1 and C2")


def test_rubbers_given_by_two_alphas_are_two_rubbers():
    """Exact answer: the solvers take a Mooney-Rivlin rubber by the alpha it was given by, so two alphas whose C1,
    C2 round to the same numbers are still two rubbers: unequal, and two keys of a dict."""
    a, b = _alphas_of_one_c1_c2()
    assert mooney_rivlin(a) != mooney_rivlin(b)
    assert len({mooney_rivlin(a), mooney_rivlin(b)}) == 2
    assert mooney_rivlin(a) == mooney_rivlin(a)
    assert hash(mooney_rivlin(a)) == hash(mooney_rivlin(a))
