"""A sheet clamped with an equibiaxial prestretch lambda_p, in both solvers.

Exact answers used here:

- the energy per unit clamped area is w(l) = W~(lambda_p l) / lambda_p^2 (thickness and moduli of the
  unstretched rubber), so the FE kernel's w_a must be the central difference of that energy, taken
  from ``pocket.core.materials.energy`` and not from the kernels;
- the clamped flat sheet carries the uniform tension N_0 = T W~_1(lambda_p, lambda_p) / lambda_p of its
  prestretch (``_flat_tension``, the same central difference), which both kernels must give at l = 1;
- at small pressure the prestretched sheet is a membrane under N_0, the paraboloid of pole height
  H0_lin = P R^2 / (4 N_0). Its corrections are of relative order Phat^2: the tension changes with the
  in-plane strain, which is of order (H0 / R)^2, and a uniform-tension cap differs from the paraboloid
  by (H0 / R)^2 too. So both solvers reach H0_lin at first order exactly, and the relative deviation
  falls at rate 2 (measured: 1.99 to 2.01 for these rubbers);
- the two solvers, independent, agree on every reported scalar within the FE's measured floor
  (``test_solvers_agree``, ``test_sphere_agree``);
- lambda_p = 1 is the unstretched model.
"""

import dataclasses

import numpy as np
import pytest
from pocket.fem.material import law_of as fem_law
from pocket.shooting.laws import law_of as shooting_law
from test_solvers_agree import TOLERANCE, _relative
from test_sphere_agree import FLOOR, FLOOR_MINIMA, _worst

from pocket import analytical, fem, shooting
from pocket.core.errors import InputError
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import Material, check, energy
from pocket.core.states import CHECKS

RUBBERS = {
    "mooney-rivlin": check("mooney-rivlin", {"c1": 160e3, "c2": 47e3}),
    "yeoh": check("yeoh", {"c10": 85e3, "c20": -2e3, "c30": 0.1e3}),
    "ogden": check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]}),
    "gent": check("gent", {"mu": 0.3e6, "jm": 3.0}),  # its domain, and the FE's planar-stretch bracket, shift
}
STEP = 1e-5  # central differences: relative error ~ STEP^2 = 1e-10, below every tolerance they meet


def _stretched(name, lp):
    return dataclasses.replace(RUBBERS[name], prestretch=lp)


def _flat_tension(material: Material) -> float:
    """N_0 / (E T) = W~_1(lambda_p, lambda_p) / (lambda_p E), by a central difference of the energy."""
    lp, unit = material.prestretch, material.scaled()
    slope = (energy(unit, lp * (1 + STEP), lp) - energy(unit, lp * (1 - STEP), lp)) / (2 * lp * STEP)
    return float(slope) / lp / 3.0  # units of mu_0 T -> E T, E = 3 mu_0


@pytest.mark.parametrize("lp", [1.05, 1.3])
@pytest.mark.parametrize("name", list(RUBBERS))
def test_both_kernels_give_the_flat_sheet_its_prestretch_tension(name, lp):
    material = _stretched(name, lp)
    expected = _flat_tension(material)
    law_s, law_f = shooting_law(material), fem_law(material)
    # kernel against a central difference of the energy: the difference's error, 1e-10 relative
    assert law_s.flat_tension == pytest.approx(expected, rel=1e-8)
    assert law_f.flat_tension == pytest.approx(expected, rel=1e-8)
    assert law_f.tensions(1.0, 1.0)[1] == pytest.approx(expected, rel=1e-8)  # equibiaxial: T_2 = T_1


@pytest.mark.parametrize("lp", [1.05, 1.3])
@pytest.mark.parametrize("name", list(RUBBERS))
def test_fem_energy_derivatives_are_those_of_the_scaled_energy(name, lp):
    """w(a, b) = W~(lp a, lp b) / (lp^2 E): w_1, w_2 by central differences, at a stretched point."""
    material = _stretched(name, lp)
    unit = material.scaled()

    def w(a, b):
        return float(energy(unit, lp * a, lp * b)) / lp**2 / 3.0

    a, b = 1.07, 0.98
    d = fem_law(material).derivatives(a, b)
    w1 = (w(a * (1 + STEP), b) - w(a * (1 - STEP), b)) / (2 * a * STEP)
    w2 = (w(a, b * (1 + STEP)) - w(a, b * (1 - STEP))) / (2 * b * STEP)
    assert d[0] == pytest.approx(w1, rel=1e-8)
    assert d[1] == pytest.approx(w2, rel=1e-8)


@pytest.mark.parametrize("lp", [1.05, 1.3])
@pytest.mark.parametrize("name", ["mooney-rivlin", "yeoh", "ogden"])
@pytest.mark.parametrize("solver", [shooting, fem], ids=["shooting", "fem"])
def test_small_pressure_is_the_taut_membranes_paraboloid(solver, name, lp):
    material = _stretched(name, lp)
    n0 = _flat_tension(material)
    pressures = np.array([1e-3, 3e-3, 1e-2])
    deviation = np.array([abs(solver.inflate(material, p).height / (p / (4 * n0)) - 1) for p in pressures])
    rate = np.polyfit(np.log(pressures), np.log(deviation), 1)[0]
    print(f"{solver.__name__} {name} lambda_p = {lp}: |H0/H0_lin - 1| = {deviation}, rate {rate:.4f}")
    # the first-order term is exact: the deviation vanishes faster than Phat, at the rate 2 of the
    # module docstring (0.1: the fit over three points of a curve whose next term is of order Phat^3)
    assert abs(rate - 2.0) < 0.1, rate
    assert deviation[-1] < 0.05  # and H0_lin is already within 5 % at Phat = 1e-2


@pytest.mark.parametrize("fluid", ["liquid", "gas"])
@pytest.mark.parametrize("name", ["mooney-rivlin", "ogden", "gent"])
def test_solvers_agree_under_the_plate(name, fluid):
    medium = None if fluid == "liquid" else gas(1.0, 1.4)
    material = _stretched(name, 1.1)
    refs = shooting.compression_curve(material, 0.3, [0.19, 1.0], fluid=medium, rtol=1e-12)
    states = fem.compression_curve(material, 0.3, [0.19, 1.0], fluid=medium)
    worst = max((_relative(getattr(s, k), getattr(r, k)), k) for s, r in zip(states, refs, strict=True)
                for k in (*s.KEYS[3:], *CHECKS[:2]))
    print(f"{name}, {fluid}: largest difference {worst[0]:.2e} ({worst[1]})")
    assert worst[0] <= TOLERANCE, worst  # the FE's floor at its default mesh (test_solvers_agree)
    assert states[0].scalars()["prestretch"] == refs[0].scalars()["prestretch"] == 1.1


@pytest.mark.parametrize("fluid", [None, gas(5.0, 1.4)], ids=["liquid", "gas"])
def test_solvers_agree_under_a_sphere(fluid):
    material = _stretched("yeoh", 1.1)
    kwargs = dict(fluid=fluid, indenter=Sphere(0.5))
    worst = _worst(shooting.compression_curve(material, 0.3, [0.05, 0.3, 0.8], **kwargs),
                   fem.compression_curve(material, 0.3, [0.05, 0.3, 0.8], **kwargs))
    minima = {key: worst.pop(key) for key in CHECKS[:2]}
    print({key: f"{value:.1e}" for key, value in {**worst, **minima}.items()})
    assert max(worst.values()) < FLOOR, worst  # the FE's floors measured in test_sphere_agree
    assert max(minima.values()) < FLOOR_MINIMA, minima


def test_both_solvers_end_the_sphere_range_where_the_pole_reaches_the_clamp_plane():
    """A taut sheet under a small sphere: its pole reaches the clamp plane first, in both solvers."""
    material, kwargs = _stretched("yeoh", 1.1), dict(fluid=gas(5.0, 1.4), indenter=Sphere(0.5))
    end = shooting.range_end(material, 0.3, **kwargs)
    for solver in (shooting, fem):
        with pytest.raises(Exception, match="beyond the model's range") as err:
            solver.compression_curve(material, 0.3, [0.5, 1.02 * end], **kwargs)
        assert "clamp plane" in str(err.value)


def test_no_prestretch_is_the_unstretched_model():
    """lambda_p = 1 given explicitly is the default: the same Material, the same kernels, the same states."""
    plain = RUBBERS["yeoh"]
    one = dataclasses.replace(plain, prestretch=1)
    assert one == plain
    assert hash(one) == hash(plain)
    assert one.describe() == plain.describe()
    assert "prestretch" not in plain.describe()
    assert shooting_law(one).key == shooting_law(plain).key
    assert shooting.inflate(one, 0.3).scalars() == shooting.inflate(plain, 0.3).scalars()
    assert fem.inflate(one, 0.3).scalars() == fem.inflate(plain, 0.3).scalars()
    # and the kernels at lambda_p = 1 are the unstretched law at the same stretches, bit for bit: their
    # products by 1.0 are exact (a prestretch lp scales the stretches, each a product lp * l)
    law = shooting_law(plain)
    assert law.params[-1] == 1.0
    assert law.prestretch == 1.0


@pytest.mark.parametrize("value", [0.99, float("nan"), float("inf"), "1.1", True])
def test_a_bad_prestretch_is_refused_in_one_line(value):
    with pytest.raises(InputError, match=r"^prestretch = ") as err:
        dataclasses.replace(RUBBERS["yeoh"], prestretch=value)
    assert "\n" not in str(err.value)


def test_a_gent_sheet_clamped_past_its_locking_is_refused():
    """I1 - 3 = 2 lp^2 + lp^-4 - 3 of the clamped flat sheet: 0.362 at lp = 1.2, past Jm = 0.3."""
    gent = check("gent", {"mu": 1.0, "jm": 0.3})
    with pytest.raises(InputError, match="past the gent rubber's locking"):
        dataclasses.replace(gent, prestretch=1.2)
    assert dataclasses.replace(gent, prestretch=1.1).prestretch == 1.1  # I1 - 3 = 0.103 < 0.3


def test_the_analytical_model_refuses_a_prestretch():
    with pytest.raises(InputError, match=r"prestretch = 1\.1"):
        analytical.inflate(_stretched("yeoh", 1.1), 0.3)
