"""Step 1 (inflation) of the shooting solver: limits, self-consistency, energy."""

import re

import numpy as np
import pytest
from pocket.analytical import model as analytical
from scipy.integrate import quad, solve_ivp
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from pocket import shooting
from pocket.core import smallstrain
from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.materials import Material
from pocket.core.states import InflatedState

SAMPLE = 47 / 160


def hencky_constant(nu=0.5):
    """K in H0/R = K Phat^(1/3) for a clamped Foppl-Hencky membrane (E T = 1, q = 1).

    Independent of the membrane equations: small-strain plate-membrane theory,
    d(r N_r)/dr = N_t, N_r w' = -q r / 2, compatibility with eps = N - nu N_other,
    clamp u(1) = 0 (N_t = nu N_r), shooting on the centre tension with solve_ivp.
    """
    def f(r, y):
        nr, nt, _ = y
        dnr = (nt - nr) / r
        return [dnr, nu * dnr + ((1 + nu) * (nr - nt) - r * r / (8 * nr * nr)) / r, r / (2 * nr)]

    def shot(n0):
        return solve_ivp(f, (1e-8, 1.0), [n0, n0, 0.0], rtol=1e-12, atol=1e-14).y[:, -1]

    n0 = brentq(lambda n: shot(n)[1] - nu * shot(n)[0], 0.05, 5.0, xtol=1e-14)
    return shot(n0)[2]


def test_small_pressure_limit_is_hencky():
    """Exact answer: H0/R / Phat^(1/3) -> Hencky's constant (nu = 1/2, incompressible) as Phat -> 0.

    The first correction is O(Phat^(2/3)) (stretch ~ Phat^(2/3)); Richardson extrapolation
    with that order removes it.
    """
    k = [shooting.inflate(SAMPLE, p).height / p ** (1 / 3) for p in (1e-4, 1e-5)]
    ratio = 10 ** (2 / 3)
    k0 = k[1] + (k[1] - k[0]) / (ratio - 1)
    hencky = hencky_constant()
    # Next term O(Phat^(4/3)) ~ 1e-7 at Phat = 1e-5; the ODE error is ~1e-10.
    assert k0 == pytest.approx(hencky, rel=1e-5), (k0, hencky)
    # The analytical model (eqs (16a) + corrected (18)) gives a nearby constant: within 5 %.
    assert smallstrain.height_constant() == pytest.approx(hencky, rel=0.05)
    assert analytical.inflate(SAMPLE, 1e-5).height / 1e-5 ** (1 / 3) == pytest.approx(
        smallstrain.height_constant(), rel=1e-12)


@pytest.mark.parametrize(("alpha", "phat"), [(SAMPLE, 0.05), (SAMPLE, 0.31), (0.0, 0.31), (1.0, 1.0)])
def test_pressure_and_volume_control_agree(alpha, phat):
    """Exact answer: the state reached by volume control at V(Phat) is the same state."""
    a = shooting.inflate(alpha, phat)
    b = shooting.inflate_volume(alpha, a.volume)
    for key in a.KEYS:
        # Both are root-found to ~1e-14 in lambda_0; the ODE error is common to both.
        assert getattr(b, key) == pytest.approx(getattr(a, key), rel=1e-9), key


@pytest.mark.parametrize(("alpha", "phat"), [(SAMPLE, 0.31), (0.0, 0.05)])
def test_tolerance_refinement(alpha, phat):
    """Exact answer: rtol 1e-10 -> 1e-12 changes no reported scalar by more than 1e-8 relative."""
    a = shooting.inflate(alpha, phat, rtol=1e-10).scalars()
    b = shooting.inflate(alpha, phat, rtol=1e-12).scalars()
    for key in InflatedState.KEYS:
        assert abs(a[key] - b[key]) <= 1e-8 * abs(b[key]), (key, a[key], b[key])


def test_clamp_and_profile():
    """Exact answer: lambda_2(1) = 1, eta(1) = 0, the pole equibiaxial, tensions from eq (6)."""
    s = shooting.inflate(SAMPLE, 0.31)
    prof = s.profile
    assert prof.r[0] == 0
    assert prof.r[-1] == 1.0
    assert prof.stretch_2[-1] == pytest.approx(1.0, abs=1e-9)
    assert prof.eta[-1] == 0
    assert prof.eta[0] == pytest.approx(s.height, rel=1e-9)
    assert prof.stretch_1[0] == prof.stretch_2[0] == s.stretch_pole
    assert prof.r.size >= 200  # plotted and written to VTK
    # Equibiaxial Mooney-Rivlin at the pole, eq (6): T / (E T) = (1 - l^-6)(1 + alpha l^2) / (3 (1 + alpha)).
    l0 = s.stretch_pole
    t0 = (1 - l0**-6) * (1 + SAMPLE * l0**2) / (3 * (1 + SAMPLE))
    assert prof.tension_1[0] == pytest.approx(t0, rel=1e-12)


def strain_energy(profile, alpha):
    """U / (E T R^2) = 2 pi int W r dr, W / (E T) = [(I1 - 3) + alpha (I2 - 3)] / (6 (1 + alpha))."""
    l1, l2 = profile.stretch_1, profile.stretch_2
    l3 = 1 / (l1 * l2)
    i1 = l1**2 + l2**2 + l3**2
    i2 = (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l1 * l3) ** 2
    w = ((i1 - 3) + alpha * (i2 - 3)) / (6 * (1 + alpha))
    spline = CubicSpline(profile.r, 2 * np.pi * w * profile.r)
    return spline.integrate(profile.r[0], profile.r[-1])


@pytest.mark.parametrize("alpha", [SAMPLE, 0.0])
def test_pressure_is_the_energy_derivative(alpha):
    """Exact answer: at equilibrium Phat = dU/dV (virtual work of the fluid), from energies
    computed from the profiles alone, independent of the equilibrium equations."""
    v0 = shooting.inflate(alpha, 0.31).volume
    dv = 1e-3 * v0
    u = [strain_energy(shooting.inflate_volume(alpha, v0 + k * dv).profile, alpha) for k in (-1, 1)]
    # Central difference O(dv^2) ~ 1e-6; spline quadrature on >= 200 points ~ 1e-9 / dv.
    assert (u[1] - u[0]) / (2 * dv) == pytest.approx(0.31, rel=1e-5)


def test_pressure_maximum_reported_and_passed_by_volume_control():
    """Exact answer: for alpha = 0 Phat(V) has a maximum; above it there is no first-branch state,
    while volume control continues past it to states with smaller pressure."""
    with pytest.raises(OutOfRangeError, match="no inflated state on the first branch"):
        shooting.inflate(0.0, 1.0)
    below = shooting.inflate(0.0, 0.6)
    beyond = shooting.inflate_volume(0.0, 4 * below.volume)
    assert beyond.pressure < 0.6
    assert beyond.stretch_pole > 2.5


@pytest.mark.parametrize(("alpha", "phat"), [(-1.0, 0.3), (-2.0, 0.3), (0.3, 0.0), (0.3, -1.0), (np.nan, 0.3)])
def test_bad_input(alpha, phat):
    with pytest.raises(InputError):
        shooting.inflate(alpha, phat)


def test_volume_formula_matches_disc_integration():
    """Exact answer: V = int pi rho^2 d eta (eq (13)) by quadrature of the profile."""
    s = shooting.inflate(SAMPLE, 0.31)
    p = s.profile
    spline = CubicSpline(p.r, -np.pi * p.rho**2 * CubicSpline(p.r, p.eta)(p.r, 1))
    assert quad(spline, 0, 1, limit=400)[0] == pytest.approx(s.volume, rel=1e-7)


@pytest.mark.parametrize(("alpha", "pressure"), [(-0.9, 0.1), (-0.9, 2.0), (-0.5, 2.0), (-0.2, 0.5)])
def test_negative_alpha_above_its_maximum_names_it(alpha, pressure):
    """Exact answer: for alpha < 0 Phat(V) has a first-branch maximum; above it an OutOfRangeError
    quotes it (and the pole stretch there). Checked independently: a pressure 1e-5 below it inflates,
    1e-5 above it does not, and volume control, which passes the maximum, reaches no higher
    pressure around that stretch (a smooth maximum: within O(dV^2))."""
    with pytest.raises(OutOfRangeError, match="above its pressure maximum") as err:
        shooting.inflate(alpha, pressure)
    found = re.search(r"maximum Phat = (\S+), reached at V/R\^3 = \S+ \(lambda_0 = (\S+)\)", str(err.value))
    peak, stretch = float(found.group(1)), float(found.group(2))
    shooting.inflate(alpha, peak * (1 - 1e-5))
    with pytest.raises(OutOfRangeError):
        shooting.inflate(alpha, peak * (1 + 1e-5))
    at_peak = shooting.inflate(alpha, peak * (1 - 1e-5))
    assert at_peak.stretch_pole == pytest.approx(stretch, rel=1e-2)  # ~sqrt(1e-5) from the top
    swept = [shooting.inflate_volume(alpha, at_peak.volume * k).pressure for k in np.linspace(0.999, 1.0005, 7)]
    # quoted to 6 digits: 1e-6 relative
    assert max(swept) <= peak * (1 + 1e-6), (max(swept), peak)
    assert max(swept) >= peak * (1 - 1e-4), (max(swept), peak)


@pytest.mark.parametrize("material", [0.3, Material("yeoh", {"c10": 0.5, "c20": 0.02, "c30": 0.001}),
                                      Material("gent", {"mu": 1.0, "jm": 20.0}, prestretch=1.05)],
                         ids=["mooney-rivlin", "yeoh", "gent-prestretched"])
def test_a_curve_is_each_pressure_inflated(material):
    """``inflation_curve`` marches once along the first branch through the pressures (given out of order and
    repeated) and returns each state in the given order; each is ``inflate``'s state at that pressure to the
    root finders' tolerance (measured <= 4e-11: the march's guesses differ, not the roots), and reported
    with the pressure echoed exactly. ``progress`` sees every distinct pressure."""
    pressures = [0.3, 0.02, 0.6, 0.3, 0.1]
    calls = []
    curve = shooting.inflation_curve(material, pressures, progress=lambda d, t: calls.append((d, t)))
    assert [s.pressure for s in curve] == pressures
    assert calls == [(1, 4), (2, 4), (3, 4), (4, 4)]
    for got, pressure in zip(curve, pressures, strict=True):
        ref = shooting.inflate(material, pressure)
        for key in ("height", "volume", "stretch_pole", "stretch_clamp", "tension_1_min", "tension_2_min"):
            assert getattr(got, key) == pytest.approx(getattr(ref, key), rel=1e-9), key


def test_a_curve_past_the_pressure_maximum_is_out_of_range():
    """A neo-Hookean sheet's pressure has a maximum (about Phat = 0.63): the curve stops with inflate's own
    OutOfRangeError at the first pressure above it; no pressure is an InputError."""
    with pytest.raises(OutOfRangeError, match="Phat = 5 is above its pressure maximum"):
        shooting.inflation_curve(Material("neo-hookean", {"mu": 1.0}), [0.1, 0.5, 5.0])
    with pytest.raises(InputError, match="no pressure given"):
        shooting.inflation_curve(0.3, [])
    assert shooting.SOLVER.serves("inflation_curve")
