"""The fluid's volume under the sheet's lower surface (``pocket.core.offset``): V_lower = V + O((T/R)^2).

Exact answers: (a) a spherical cap whose lower surface is integrated independently (a path integral
along the exact offset curve, by adaptive quadrature, against the module's band formula on splines
through samples); (b) the two membrane solvers, independent of each other; (c) the derivation's
claims measured: no first-order term (fitted rate 2), and the t^2 coefficient
(pi/4) [int lambda_3 (k_1 + k_2) r dr - lambda_3c sin psi_c] from curvatures by finite differences;
(d) the solid, whose cavity and mid-surface volumes are equal for an incompressible sheet: the
lower-surface volume removes only an O(T/R) fraction of the solid's O(T/R) volume gap.
"""

import dataclasses
import math

import numpy as np
import pytest
from scipy.integrate import quad

from pocket import fem, shooting, solid
from pocket.apps.casefile import solve
from pocket.apps.cases import sample
from pocket.apps.physical import Pocket, inflated_row
from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.materials import mooney_rivlin
from pocket.core.offset import volume_correction
from pocket.core.states import Profile

RUBBER = mooney_rivlin(47 / 160)
PHAT = 0.31


def _cap(a: float, n: int) -> Profile:
    """The spherical cap of radius ``a`` through the clamp (1, 0), sampled at n radii r uniform in the polar
    angle theta = theta_c r: lambda_1 = a theta_c, lambda_2 = rho / r, so lambda_3 varies along it."""
    theta_c = np.arcsin(1.0 / a)
    r = np.linspace(0.0, 1.0, n)
    rho, eta = a * np.sin(theta_c * r), a * np.cos(theta_c * r) - np.sqrt(a * a - 1.0)
    hoop = np.divide(rho, r, out=np.full(n, a * theta_c), where=r > 0.0)
    zero = np.zeros(n)
    return Profile(r, rho, eta, np.full(n, a * theta_c), hoop, zero, zero, zero.astype(bool))


def _cap_correction(a: float, t: float) -> float:
    """V_lower - V of ``_cap(a, .)`` at T/R = t, by its own route: the lower surface is the polar curve
    R(theta) = a - d(theta) about the sphere's centre (0, z_c), d = lambda_3 t/2 = t theta / (2 a^2 theta_c^2
    sin theta); V_lower = int (z - z_0) d(pi rho^2) along it (adaptive quadrature) plus the cone frustum
    under the segment to the corner (1, z_0 = -t/2); V the cap's pi h^2 (3a - h) / 3."""
    theta_c, zc, z0 = np.arcsin(1.0 / a), -np.sqrt(a * a - 1.0), -t / 2.0
    k = t / (2.0 * a * a * theta_c**2)

    def radius(th):
        return a - k * (th / np.sin(th) if th > 0.0 else 1.0)

    def slope(th):  # dR/dtheta; (sin - th cos) / sin^2 = th/3 + O(th^3) near the pole
        return -k * ((np.sin(th) - th * np.cos(th)) / np.sin(th) ** 2 if th > 1e-4 else th / 3.0)

    def integrand(th):
        rho, drho = radius(th) * np.sin(th), slope(th) * np.sin(th) + radius(th) * np.cos(th)
        return (zc + radius(th) * np.cos(th) - z0) * 2.0 * np.pi * rho * drho

    v, _ = quad(integrand, 0.0, theta_c, epsabs=1e-14, epsrel=1e-13, limit=200)
    rho_p, z_p = radius(theta_c) * np.sin(theta_c), zc + radius(theta_c) * np.cos(theta_c)
    v += 2.0 * np.pi * (z_p - z0) / (1.0 - rho_p) * (1.0 / 6.0 - rho_p**2 / 2.0 + rho_p**3 / 3.0)
    h = a * (1.0 - np.cos(theta_c))
    return v - np.pi * h * h * (3.0 * a - h) / 3.0


@pytest.mark.parametrize(("a", "t"), [(1.3, 0.02), (1.3, 0.1), (3.0, 0.1)])
def test_a_spherical_cap_converges_to_its_independent_volume(a, t):
    """(a) The band formula on splines through n samples tends to the path integral along the exact offset
    curve; the spline's curvature errs by O(h^2), and the fitted order is printed."""
    exact = _cap_correction(a, t)
    counts = np.array([9, 17, 33, 65, 129])
    errors = np.array([volume_correction(_cap(a, n), t) - exact for n in counts])
    order = -np.polyfit(np.log(counts), np.log(np.abs(errors)), 1)[0]
    message = f"a = {a}, t = {t}: exact {exact:.12g}, errors {errors}, fitted order {order:.3f}"
    assert order > 2.5, message  # the splines' curvature is O(h^2); measured 3.1 (the error integrates smoothly)
    assert abs(errors[-1]) < 1e-6 * abs(exact), message  # measured ~3e-7 of it at 129 samples: the order's reach


def test_a_uniformly_stretched_cap_keeps_its_volume_exactly():
    """A cap sampled with lambda_1 lambda_2 uniform (cos theta = 1 - (1 - cos theta_c) r^2) has a concentric
    lower cap, d = lambda_3 t/2 constant, and the t^2 coefficient is (pi/4) lambda_3 (2/a (1/2) - sin psi_c)
    = 0 (sin psi_c = 1/a); the closed forms (the band, the shell between the spheres; the triangle) cancel at
    every order too. Its correction vanishes to the splines' accuracy, though each of its terms does not."""
    a, t, n = 1.3, 0.1, 129
    c = 1.0 - np.sqrt(1.0 - 1.0 / a**2)
    r = np.linspace(0.0, 1.0, n)
    theta = np.arccos(1.0 - c * r**2)
    rho, eta = a * np.sin(theta), a * np.cos(theta) - np.sqrt(a * a - 1.0)
    hoop = np.divide(rho, r, out=np.full(n, a * np.sqrt(2.0 * c)), where=r > 0.0)
    zero = np.zeros(n)
    profile = Profile(r, rho, eta, 2.0 * a * a * c / hoop, hoop, zero, zero, zero.astype(bool))
    triangle = np.pi * t**2 / 4.0 / (2.0 * a * a * c) / a  # (pi t^2/4) lambda_3 sin psi_c, one of the terms
    assert abs(volume_correction(profile, t)) < 1e-6 * triangle  # the spline error, as in the test above


@pytest.fixture(scope="module")
def states():
    return {"inflated": (shooting.inflate(RUBBER, PHAT), fem.inflate(RUBBER, PHAT)),
            "plate": (shooting.compress(RUBBER, PHAT, 0.5), fem.compress(RUBBER, PHAT, 0.5))}


@pytest.mark.parametrize("which", ["inflated", "plate"])
def test_the_two_membrane_solvers_agree(states, which):
    """(b) Shooting and finite elements give the same lower-surface volume: the corrections differ by the
    finite elements' error in curvature (quadratic elements), a part in 1e4 at their default 256 elements."""
    reference, finite = states[which]
    t = 0.025
    a, b = reference.volume_lower(t) - reference.volume, finite.volume_lower(t) - finite.volume
    message = (f"{which}: shooting {a:.10g}, fem {b:.10g}, relative {b / a - 1:.3g}; "
               f"V: {finite.volume - reference.volume:.3g}")
    # the finite elements' curvature errs by O(h^2) = 1.5e-5 at h = 1/256: measured 1.5e-5 and 1.7e-5
    assert abs(b / a - 1.0) < 1e-4, message
    # that 1.7e-5 of a 2e-5 correction, and V's own 1e-11: measured 3.5e-10
    assert abs(finite.volume_lower(t) - reference.volume_lower(t)) < 2e-9, message


@pytest.mark.parametrize("which", ["inflated", "plate"])
def test_no_first_order_term(states, which):
    """(c) (V_lower - V) / t -> 0: log|V_lower - V| against log t has the slope 2 (printed), not 1."""
    state = states[which][0]
    ratios = np.array([0.005, 0.01, 0.02, 0.04])
    change = np.array([state.volume_lower(t) - state.volume for t in ratios])
    rate = np.polyfit(np.log(ratios), np.log(np.abs(change)), 1)[0]
    assert abs(rate - 2.0) < 0.05, f"{which}: fitted rate {rate:.4f}, (V_lower - V) / t = {change / ratios}"
    # the t^3 term: measured 2 - 0.004 here, its relative size ~0.2 t


def test_the_second_order_coefficient(states):
    """(c) (V_lower - V) / t^2 -> (pi/4) [int_0^1 lambda_3 (k_1 + k_2) r dr - lambda_3c sin psi_c], the
    curvatures by second-order finite differences of the shooting samples (not the module's splines)."""
    p = states["inflated"][0].profile
    r = p.r
    psi = np.arctan2(-np.gradient(p.eta, r, edge_order=2), np.gradient(p.rho, r, edge_order=2))
    # k_1 r = dpsi/ds r = psi' r / lambda_1; k_2 r = sin(psi) r / rho = sin(psi) / lambda_2
    integrand = p.stretch_3 * (np.gradient(psi, r, edge_order=2) * r / p.stretch_1 + np.sin(psi) / p.stretch_2)
    predicted = np.pi / 4.0 * (np.trapezoid(integrand, r) - p.stretch_3[-1] * np.sin(psi[-1]))
    ratios = np.array([0.005, 0.01, 0.02])
    state = states["inflated"][0]
    measured = np.array([state.volume_lower(t) - state.volume for t in ratios]) / ratios**2
    intercept = np.polyval(np.polyfit(ratios, measured, 1), 0.0)  # the t^3 term removed
    # finite differences on samples <= 0.005 apart, trapezoid: ~1e-4 of the coefficient (measured 4e-5)
    assert intercept == pytest.approx(predicted, rel=1e-3), f"measured {intercept:.8g}, predicted {predicted:.8g}"


@pytest.mark.slow
def test_against_the_solid():
    """(d) The solid's cavity (under its lower surface) is lower than the membrane's V by O(T/R); the
    derivation says that is not where the volume is measured: the membrane's V_lower - V and the solid's
    own cavity-minus-mid-surface volume are O(T/R)^2, so the lower-surface volume removes a fraction O(T/R)
    of the gap (printed), while the gap itself is first order (gap / t printed)."""
    membrane = shooting.inflate(RUBBER, PHAT)
    report = []
    for t in (0.0125, 0.025):
        s = solid.inflate(RUBBER, PHAT, thickness_ratio=t)
        gap = s.volume - membrane.volume
        removed = membrane.volume_lower(t) - membrane.volume
        own = s.volume - s.extra["volume_mid"]
        report.append((t, gap / t, removed / gap, own / gap))
    message = "; ".join(f"t = {t}: gap/t = {g:.4f}, fraction removed {f:.2e}, solid's lower-mid {o:.1e} of the "
                        "gap" for t, g, f, o in report)
    for t, _, fraction, own in report:
        # a first-order part would be a fixed fraction of the gap; O(t^2) parts are a fraction O(t) of it
        assert abs(fraction) < t, message
        assert abs(own) < t, message
    (_, g1, _, _), (_, g2, _, _) = report
    assert g1 < 0, message
    assert abs(g2 / g1 - 1.0) < 0.05, message  # first order: gap/t changes by O(t) (2 % measured)


def test_bad_thickness_and_folding():
    """Bad input is an InputError naming the key and quoting the value; a lower surface that would fold
    (a radius of curvature below half the thickness) is an OutOfRangeError."""
    state = shooting.inflate(RUBBER, PHAT)
    for bad in (0.0, -0.1, 0.5, float("nan")):
        with pytest.raises(InputError, match=r"^thickness_ratio = "):
            state.volume_lower(bad)
    tight = _cap(1.3, 33)
    tight = dataclasses.replace(tight, stretch_1=tight.stretch_1 / 20.0)  # lambda_3 20 times: d = 10 t lambda_3
    with pytest.raises(OutOfRangeError, match="folds"):
        volume_correction(tight, 0.2)


def test_pocket_run_reports_it_in_si():
    """``pocket run``: each row's ``volume_lower_m3`` (after ``volume_m3``) is the state's ``volume_lower`` at
    the case's T/R (sample 4: 1.6 mm on 20 mm), times R^3; the solid reports none (its volume is the fluid's)."""
    case = sample(4)
    result = solve(case)
    t, radius = case.thickness / case.radius, case.radius
    row = result["inflated"]
    state = shooting.inflate(RUBBER, row["pressure"])
    # the same shooting solve: equal to its resolution (~1e-10)
    assert row["volume_lower_m3"] == pytest.approx(state.volume_lower(t) * radius**3, rel=1e-9)
    for each in (row, *result["states"]):
        keys = list(each)
        assert keys[keys.index("volume_m3") + 1] == "volume_lower_m3"
        assert math.isfinite(each["volume_lower_m3"])
    as_solid = Pocket(dataclasses.replace(case, solver="solid"), state.pressure)
    assert "volume_lower_m3" not in inflated_row(as_solid, state)
