"""Each rubber law in the shooting solver: its tensions against its strain energy, its pole series,
and the identities and limits between laws, through the kernel and through the solved states."""

import math

import numpy as np
import pytest
from pocket.shooting.equations import pole_state
from pocket.shooting.integrator import OK, integrate
from pocket.shooting.laws import law_of
from pocket.shooting.tensions import inside, tensions, tensions_compiled
from test_shooting_inflation import hencky_constant

from pocket import shooting
from pocket.core.errors import OutOfRangeError
from pocket.core.materials import Material, check, energy

GRID = [a.ravel() for a in np.meshgrid(np.linspace(0.8, 2.0, 7), np.linspace(0.85, 1.9, 6))]


def _kernel(material, l1, l2, compiled=False):
    """(T_1, T_2, dT_1/dl1, dT_1/dl2) / (E T) from the kernel."""
    law = law_of(material)
    if compiled:
        values = np.array([tensions_compiled(a, b, law.code, law.params) for a, b in zip(l1, l2, strict=True)]).T
    else:
        values = np.array(tensions(l1, l2, law.code, law.params))
    return values * law.tension_scale


def _from_energy(material, l1, l2):
    """The same from central differences of W alone: T_1 / T = (1/l2) dW/dl1, T_2 / T = (1/l1) dW/dl2,
    in units of E T = 3 mu_0 T. Steps: 1e-5 for first derivatives (error ~1e-10 relative), 1e-4 for
    second ones (truncation and rounding both ~1e-8)."""
    def w(a, b):
        return energy(material, a, b)

    h, k = 1e-5, 1e-4
    w1 = (w(l1 + h, l2) - w(l1 - h, l2)) / (2 * h)
    w2 = (w(l1, l2 + h) - w(l1, l2 - h)) / (2 * h)
    w11 = (w(l1 + k, l2) - 2 * w(l1, l2) + w(l1 - k, l2)) / k**2
    w12 = (w(l1 + k, l2 + k) - w(l1 + k, l2 - k) - w(l1 - k, l2 + k) + w(l1 - k, l2 - k)) / (4 * k * k)
    scale = 3 * material.mu0
    return np.array([w1 / l2, w2 / l1, w11 / l2, w12 / l2 - w1 / l2**2]) / scale


def check_tensions(material):
    """T_1 = (T/l2) dW/dl1, T_2 = (T/l1) dW/dl2 and the derivatives of T_1 from the kernel equal central
    differences of ``pocket.core.materials.energy`` (in the material's unit, so the kernel's mu_0 scaling is
    checked too), over stretches 0.8..2 x 0.85..1.9, l1 != l2 included; the compiled kernel is the Python one."""
    ours, ref = _kernel(material, *GRID), _from_energy(material, *GRID)
    for row, what, tol in ((0, "T1", 1e-8), (1, "T2", 1e-8), (2, "dT1/dl1", 1e-6), (3, "dT1/dl2", 1e-6)):
        size = np.max(np.abs(ref[row]))
        err = np.max(np.abs(ours[row] - ref[row])) / size
        assert err < tol, (material.law, what, err)
    # one source, two compilations: they agree to rounding (a few ulps)
    np.testing.assert_allclose(_kernel(material, *GRID, compiled=True), ours, rtol=1e-13, atol=1e-15)


def test_tensions_are_derivatives_of_the_shared_energy(rubber):
    """Exact answer: ``check_tensions`` for every law of the registry (its example rubber, in Pa)."""
    check_tensions(rubber)


def test_small_strain_tension_is_two_e_t_e(rubber):
    """Exact answer: equibiaxial l = 1 + e gives T = 2 E T e + O(e^2) for every law (E = 3 mu_0).
    Richardson extrapolation of T / (2 E T e) from e and e/2 removes the O(e) term."""
    def ratio(e):
        return _kernel(rubber, np.array([1 + e]), np.array([1 + e]))[0, 0] / (2 * e)

    e = 1e-4
    assert 2 * ratio(e / 2) - ratio(e) == pytest.approx(1.0, abs=1e-7)


def test_pole_series_order(rubber):
    """Exact answer: the pole series is regular for every isotropic law, with errors O(r^3) in psi and
    O(r^4) in lambda_1. Measured against the integrated solution from r = 1e-7 (series error ~1e-28),
    at r = 0.01, 0.02, 0.04: the fitted orders."""
    law = law_of(rubber)
    l0, p = 1.2, 0.8 * law.pressure_factor
    radii = [0.01, 0.02, 0.04]
    errors = []
    for r in radii:
        status, r_end, y, _ = integrate(pole_state(l0, law, p, 1e-7), 1e-7, law, p, rtol=1e-13, atol=1e-16, r_end=r)
        assert status == OK
        assert r_end == r
        errors.append(np.abs(pole_state(l0, law, p, r) - y))
    errors = np.array(errors)
    for column, order in ((2, 3), (3, 4)):  # psi, lambda_1
        fitted = np.polyfit(np.log(radii), np.log(errors[:, column]), 1)[0]
        assert fitted == pytest.approx(order, abs=0.1), (rubber.law, column, fitted, errors[:, column])


def _same_states(a, b, rel):
    for x, y in zip(a, b, strict=True):
        for key in x.KEYS:
            if key != "alpha":
                assert getattr(x, key) == pytest.approx(getattr(y, key), rel=rel, abs=1e-13), key


FORCES = [0.05, 0.5, 2.0]


@pytest.mark.parametrize("mu", [1.0, 0.4e6])
def test_neo_hookean_identities_through_the_solver(mu):
    """Exact answer: neo-hookean(mu) = mooney-rivlin(mu/2, 0) = yeoh(mu/2, 0, 0) = ogden([mu], [2]): one
    energy, four kernels (the Mooney-Rivlin alpha path, the I1 path twice, Ogden's stretches), so the
    solved states agree to the solver's precision (rtol 1e-10: 1e-8 allows for the root finders)."""
    nh = shooting.compression_curve(check("neo-hookean", {"mu": mu}), 0.31, FORCES)
    for other in (check("mooney-rivlin", {"c1": mu / 2, "c2": 0.0}), check("yeoh", {"c10": mu / 2, "c20": 0.0,
                                                                                     "c30": 0.0}),
                  check("ogden", {"mu": [mu], "exponents": [2.0]})):
        _same_states(shooting.compression_curve(other, 0.31, FORCES), nh, 1e-8)


def test_ogden_two_terms_is_mooney_rivlin_through_the_solver():
    """Exact answer: ogden([2 C1, -2 C2], [2, -2]) = mooney-rivlin(C1, C2) = alpha C2/C1 in units of mu_0."""
    c1, c2 = 160e3, 47e3
    mr = shooting.compression_curve(47 / 160, 0.31, FORCES)
    _same_states(shooting.compression_curve(check("ogden", {"mu": [2 * c1, -2 * c2], "exponents": [2.0, -2.0]}),
                                            0.31, FORCES), mr, 1e-8)
    _same_states(shooting.compression_curve(check("mooney-rivlin", {"c1": c1, "c2": c2}), 0.31, FORCES), mr, 1e-12)


def test_gent_tends_to_neo_hookean_at_rate_one_over_jm():
    """Exact answer: W_gent = W_nh + (mu/4) (I1 - 3)^2 / Jm + O(Jm^-2), so every solved scalar differs
    from neo-Hookean's by O(1/Jm): the difference shrinks tenfold per tenfold Jm (within 2 %: the next
    term is O(1/Jm) relative, the solver's error ~1e-10 against differences >= 1e-6)."""
    nh = shooting.compression_curve(check("neo-hookean", {"mu": 1.0}), 0.31, FORCES)
    gaps = []
    for jm in (1e2, 1e3, 1e4):
        gent = shooting.compression_curve(check("gent", {"mu": 1.0, "jm": jm}), 0.31, FORCES)
        gaps.append([[getattr(g, k) - getattr(n, k) for k in ("pressure_ratio", "height", "contact_area")]
                     for g, n in zip(gent, nh, strict=True)])
    gaps = np.array(gaps)
    np.testing.assert_allclose(gaps[0] / gaps[1], 10.0, rtol=0.02)
    np.testing.assert_allclose(gaps[1] / gaps[2], 10.0, rtol=0.002)


def test_small_pressure_limit_is_hencky_for_every_law(rubber):
    """Exact answer: H0/R / Phat^(1/3) -> Hencky's constant (nu = 1/2), the same for every law since
    only mu_0 enters at small strain (E = 3 mu_0). Richardson in Phat^(2/3) from 1e-4 and 1e-5 leaves
    O(Phat^(4/3)) ~ 1e-7; the Mooney-Rivlin value by alpha is computed alongside."""
    def limit(rubber):
        k = [shooting.inflate(rubber, p).height / p ** (1 / 3) for p in (1e-4, 1e-5)]
        return k[1] + (k[1] - k[0]) / (10 ** (2 / 3) - 1)

    ours = limit(rubber)
    assert ours == pytest.approx(hencky_constant(), rel=1e-5)
    assert ours == pytest.approx(limit(0.3), rel=1e-6)


def test_gent_locking_stretch_and_domain():
    """Exact answer: the equibiaxial locking stretch solves 2 l^2 + l^-4 - 3 = Jm; ``inside`` is
    I1 - 3 < Jm."""
    law = law_of(check("gent", {"mu": 1.0, "jm": 3.0}))
    lock = law.stretch_limit
    assert 2 * lock**2 + lock**-4 - 3 == pytest.approx(3.0, rel=1e-14)
    assert inside(lock * (1 - 1e-9), lock * (1 - 1e-9), law.code, law.params)
    assert not inside(lock * (1 + 1e-9), lock * (1 + 1e-9), law.code, law.params)
    assert law_of(check("neo-hookean", {"mu": 0.4e6})).stretch_limit == math.inf


def test_gent_past_locking_is_out_of_range():
    """Exact answer: V(lambda_0) stays below its value at the locking stretch, so a larger volume is no
    state (OutOfRangeError naming the locking stretch), never a NaN; any pressure inflates, below it."""
    gent = check("gent", {"mu": 1.0, "jm": 3.0})
    lock = law_of(gent).stretch_limit
    high = shooting.inflate(gent, 1e3)
    assert 1.0 < high.stretch_pole < lock
    assert np.isfinite(high.volume)
    with pytest.raises(OutOfRangeError, match="locks") as err:
        shooting.inflate_volume(gent, 2 * high.volume)
    assert f"{lock:.10g}" in str(err.value)


@pytest.mark.slow
def test_a_pocket_inflated_near_locking_has_no_range_end():
    """Exact answer: near locking the force diverges before the sheet reaches the clamp plane, so
    range_end is inf and large forces solve, with stretches inside the domain and F = P A_c."""
    gent = check("gent", {"mu": 1.0, "jm": 3.0})
    assert shooting.range_end(gent, 2.0) == math.inf
    law = law_of(gent)
    margins = []
    for state in shooting.compression_curve(gent, 2.0, [10.0, 1e3]):
        margins.append(law.lock_margin(state.stretch_contact, state.stretch_contact))
        assert state.pressure_ratio * state.contact_area == pytest.approx(state.force, rel=1e-12)
        assert state.contact_area < 1.0
    assert 0 < margins[1] < 1e-3 < margins[0]  # closer to locking, still inside
    assert shooting.range_end(check("gent", {"mu": 1.0, "jm": 30.0}), 0.5) < 10.0  # a far lock: the usual end


@pytest.mark.parametrize(("bad", "message"), [
    (Material("gent", (("mu", 1.0), ("jm", 0.0))), "jm = 0.0"),
    (Material("ogden", (("mu", (1.0,)), ("exponents", (-2.0,)))), "mu_p alpha_p > 0"),
    (-1.0, "alpha = -1.0"),
])
def test_a_bad_rubber_is_an_input_error_before_any_work(bad, message):
    """Exact answer: the entry points re-check a Material (here built around the check) like an alpha."""
    from pocket.core.errors import InputError

    for call in (lambda: shooting.inflate(bad, 0.1), lambda: shooting.compress(bad, 0.1, 0.1),
                 lambda: shooting.range_end(bad, 0.1), lambda: shooting.inflate_volume(bad, 0.5)):
        with pytest.raises(InputError, match=message):
            call()


@pytest.mark.parametrize("force", [8.298183276809439e-171, 1e-20])
def test_tiny_forces_reach_the_residual_noise_and_solve(force):
    """Exact answer: as Fhat -> 0 the state tends to the inflated one (differences O(Fhat), nothing at
    these forces). Found by the property tests: for ogden([-1000], [-4]) the residual's noise at such
    contact radii (~3e-12) exceeded the Newton tolerance (1e-12), a ConvergenceError; a stall at the
    noise floor is now accepted, and the state equals the inflated one within the solver's precision."""
    rubber = check("ogden", {"mu": [-1000.0], "exponents": [-4.0]})
    state = shooting.compress(rubber, 1.0, force)
    for key, value in (("pressure_ratio", 1.0), ("height_ratio", 1.0), ("volume", state.inflated.volume)):
        assert getattr(state, key) == pytest.approx(value, rel=1e-10), key
