"""Step 2 (compression at fixed volume) of the shooting solver."""

import numpy as np
import pytest
from scipy.interpolate import CubicSpline
from test_shooting_inflation import strain_energy

from pocket import shooting
from pocket.core.errors import InputError, OutOfRangeError

SAMPLE = 47 / 160


@pytest.fixture(scope="module")
def curve():
    return shooting.compression_curve(SAMPLE, 0.31, [0.05, 0.19, 0.5, 2.0])


def test_force_is_pressure_times_deformed_contact_area(curve):
    """Exact answer: F = P A_c, with A_c = pi rho(a)^2 read off the profile's contact edge."""
    for s in curve:
        edge = s.profile.rho[s.profile.contact][-1]
        assert s.pressure_ratio * edge**2 == pytest.approx(s.force, rel=1e-12)
        assert s.contact_area == pytest.approx(s.force / s.pressure_ratio, rel=1e-12)


def test_volume_conserved(curve):
    """Exact answer: V = V_I (the constraint), to 1e-10; and the profile encloses that volume."""
    for s in curve:
        assert abs(s.volume / s.inflated.volume - 1) < 1e-10
        p = s.profile
        free = ~p.contact | (np.arange(p.r.size) == np.flatnonzero(p.contact)[-1])
        r, rho, eta = p.r[free], p.rho[free], p.eta[free]
        deta = CubicSpline(r, eta)(r, 1)
        volume = CubicSpline(r, -np.pi * rho**2 * deta).integrate(r[0], 1.0)
        # spline quadrature of a profile stored every <= 1/200 in r
        assert volume == pytest.approx(s.volume, rel=1e-6)


def test_contact_zone_is_flat_and_equibiaxial(curve):
    """Exact answer: lambda_1 = lambda_2 = lambda_c and eta = H on r <= a; T_1 continuous at the edge."""
    for s in curve:
        p = s.profile
        c = p.contact
        np.testing.assert_allclose(p.stretch_1[c], s.stretch_contact, rtol=1e-14)
        np.testing.assert_allclose(p.stretch_2[c][1:], s.stretch_contact, rtol=1e-14)
        np.testing.assert_allclose(p.eta[c], s.height, rtol=1e-9)
        edge = np.flatnonzero(c)[-1]
        assert p.tension_1[edge + 1] == pytest.approx(p.tension_1[edge], rel=1e-3)  # next point ~1/200 away


def test_zero_force_recovers_the_inflated_state():
    """Exact answer: as Fhat -> 0 the state tends to the inflated one (differences O(Fhat))."""
    forces = [1e-4, 1e-5, 1e-6]
    states = shooting.compression_curve(SAMPLE, 0.31, forces)
    gaps = [max(abs(s.pressure_ratio - 1), abs(s.height_ratio - 1),
                abs(s.stretch_contact / s.inflated.stretch_pole - 1)) for s in states]
    order = np.polyfit(np.log(forces), np.log(gaps), 1)[0]
    assert order == pytest.approx(1.0, abs=0.1), (order, gaps)
    assert gaps[-1] < 1e-4
    exact_zero = shooting.compress(SAMPLE, 0.31, 0.0)
    assert exact_zero.height == exact_zero.inflated.height
    assert exact_zero.contact_area == 0


def test_force_is_the_energy_derivative():
    """Exact answer: at fixed volume the plate does work -F dH on the sheet, so
    F / (E T R) = Fhat Phat_I pi = -dU/dH, with U from the profiles alone."""
    forces = np.array([0.19 - 1e-3, 0.19 + 1e-3])
    states = shooting.compression_curve(SAMPLE, 0.31, forces)
    u = []
    for s in states:
        p = s.profile
        edge = np.flatnonzero(p.contact)[-1]
        free = slice(edge, None)
        contact_energy = strain_energy(type(p)(**{k: v[: edge + 1] for k, v in vars(p).items()}), SAMPLE)
        free_energy = strain_energy(type(p)(**{k: v[free] for k, v in vars(p).items()}), SAMPLE)
        u.append(contact_energy + free_energy)
    dudh = (u[1] - u[0]) / (states[1].height - states[0].height)
    # central difference: O(dF^2) ~ 1e-6 relative
    assert -dudh == pytest.approx(0.19 * 0.31 * np.pi, rel=1e-4)


def test_curve_is_independent_of_the_path():
    """Exact answer: a state reached by continuation equals the one solved directly."""
    direct = shooting.compress(SAMPLE, 0.31, 0.5)
    via = shooting.compression_curve(SAMPLE, 0.31, [0.5, 0.1, 0.3])[0]
    for key in direct.KEYS:
        assert getattr(via, key) == pytest.approx(getattr(direct, key), rel=1e-9, abs=1e-12), key


def test_tolerance_refinement():
    """Exact answer: rtol 1e-10 -> 1e-12 changes no scalar by more than 1e-8 relative."""
    a = shooting.compress(SAMPLE, 0.31, 0.19, rtol=1e-10).scalars()
    b = shooting.compress(SAMPLE, 0.31, 0.19, rtol=1e-12).scalars()
    for key in shooting.compress(SAMPLE, 0.31, 0.0).KEYS:
        assert abs(a[key] - b[key]) <= 1e-8 * abs(b[key]), key


def test_force_beyond_the_model_range():
    """Exact answer: at large force the free part folds onto the clamp plane: no state, an error."""
    with pytest.raises(OutOfRangeError, match="beyond the model's range"):
        shooting.compress(SAMPLE, 0.31, 20.0)


@pytest.mark.parametrize("force", [-0.1, np.inf, np.nan])
def test_bad_force(force):
    with pytest.raises(InputError):
        shooting.compress(SAMPLE, 0.31, force)
