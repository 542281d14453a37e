"""The closed capsule's equations (docs/theory.md, section 12), checked symbolically before any solver poses them.

Each test takes one equation of that section and checks it independently: against the rubber's strain energy
(differentiated here by sympy), against the pocket's integrated equations (``pocket.shooting.equations``) on the
flat reference, or against a limit it must meet. Numbers are substituted early where a general simplification
would be slow.
"""

import math

import numpy as np
import pytest
import sympy as sp
from pocket.shooting.equations import pole_state, rhs
from pocket.shooting.laws import law_of

S, LAM, L1, L2, AL = sp.symbols("S lambda lambda_1 lambda_2 alpha", positive=True)
L3 = 1 / (L1 * L2)
I1 = L1**2 + L2**2 + L3**2
I2 = L1**-2 + L2**-2 + L3**-2
# Mooney-Rivlin, eq-mooney-rivlin-tension in units of 2 C1 T (as the pocket's solver), typed from the page.
T1_MR = (L1 / L2 - 1 / (L1**3 * L2**3)) * (1 + AL * L2**2)
T2_MR = T1_MR.subs({L1: L2, L2: L1}, simultaneous=True)


def capsule_rhs(s, y, p, t1, t2, a11, a12, r0, dr0):
    """eq-capsule-ode and eq-capsule-volume: d/dS of y = [rho, eta, psi, lambda_1, V] (V the whole capsule's), the
    tensions and their derivatives at (lambda_1, lambda_2) given by the callables, the reference radius r0(S) and
    its slope dr0(S)."""
    rho, psi, l1 = y[0], y[2], y[3]
    l2 = rho / r0(s)
    drho = l1 * math.cos(psi)
    dl2 = (drho - l2 * dr0(s)) / r0(s)
    T1, T2 = t1(l1, l2), t2(l1, l2)
    return np.array([
        drho,
        -l1 * math.sin(psi),
        l1 * (p - T2 * math.sin(psi) / rho) / T1,
        ((T2 - T1) * drho / rho - a12(l1, l2) * dl2) / a11(l1, l2),
        2.0 * math.pi * rho**2 * l1 * math.sin(psi),
    ])


def test_uniform_sphere_solves_free_equations_for_any_law():
    """Exact answer: rho = lambda sin S, psi = S, lambda_1 = lambda solve eq-capsule-ode with psi' = 1 and
    lambda_1' = 0 when P = 2 T1 / lambda, and 2 T1 / lambda = w'(lambda) / lambda^2 (eq-capsule-inflation), for a
    strain energy W(I1, I2) left unspecified (every isotropic incompressible law is one): at equal stretches
    T2 = T1 and lambda_2' = 0, so tangential equilibrium holds whatever T_{1,1}, T_{1,2} are."""
    W = sp.Function("W")(I1, I2)
    T1 = sp.diff(W, L1) / L2  # eq-tensions, in units of T
    T2 = sp.diff(W, L2) / L1
    equal = {L1: LAM, L2: LAM}
    assert sp.simplify((T2 - T1).subs(equal).doit()) == 0
    t = T1.subs(equal).doit()
    w = W.subs(equal).doit()
    assert sp.simplify(2 * t / LAM - sp.diff(w, LAM) / LAM**2) == 0
    rho, psi, l1 = LAM * sp.sin(S), S, LAM
    drho = l1 * sp.cos(psi)
    assert sp.simplify(drho - sp.diff(rho, S)) == 0  # the sphere's meridian is consistent with its angle
    assert sp.simplify((drho - (rho / sp.sin(S)) * sp.cos(S)) / sp.sin(S)) == 0  # lambda_2' = 0
    P = 2 * t / LAM
    dpsi = l1 * (P - t * sp.sin(psi) / rho) / t
    assert sp.simplify(dpsi - 1) == 0


def test_sphere_volume_and_equator_force_balance_at_zero_force():
    """Exact answer: eq-capsule-volume on the sphere of stretch lambda is 4 pi lambda^3 / 3, and the equator's
    balance 2 pi rho_eq T1 = P pi rho_eq^2 - F holds there with F = 0, rho_eq = lambda, P = 2 T1 / lambda."""
    V = 2 * sp.pi * sp.integrate((LAM * sp.sin(S)) ** 2 * LAM * sp.sin(S), (S, 0, sp.pi / 2))
    assert sp.simplify(V - sp.Rational(4, 3) * sp.pi * LAM**3) == 0
    t = sp.Symbol("t", positive=True)
    P = 2 * t / LAM
    assert sp.simplify(2 * sp.pi * LAM * t - (P * sp.pi * LAM**2 - 0)) == 0


def test_vertical_force_is_a_first_integral_of_the_free_equations():
    """Exact answer: d/dS (rho T1 sin psi - P rho^2 / 2) = 0 along eq-capsule-ode for any tensions, using
    rho' = lambda_1 cos psi, normal equilibrium for psi' and tangential equilibrium (rho T1)' = T2 rho': so
    eq-capsule-first-integral holds everywhere on the free part, at the equator with sin psi = 1 included."""
    rho, psi, l1, T1, T2 = (sp.Function(n)(S) for n in ("rho", "psi", "l1", "T1", "T2"))
    P = sp.Symbol("P", positive=True)
    drho = l1 * sp.cos(psi)
    rules = {
        sp.Derivative(rho, S): drho,
        sp.Derivative(psi, S): l1 * (P - T2 * sp.sin(psi) / rho) / T1,
        sp.Derivative(T1, S): (T2 * drho - drho * T1) / rho,
    }
    derivative = sp.diff(rho * T1 * sp.sin(psi) - P * rho**2 / 2, S).subs(rules)
    assert sp.simplify(derivative) == 0


@pytest.mark.parametrize("alpha", [0.0, 0.1, 1.3])
def test_capsule_equations_on_flat_reference_are_the_pockets(alpha):
    """Exact answer: with r0 = S (r0' = 1) eq-capsule-ode is the pocket's shooting right-hand side
    (``pocket.shooting.equations.rhs``, run as plain Python) at any state, the volume twice the pocket's one-sided
    one (the capsule's two halves). Relative 1e-12: the same arithmetic in another order."""
    t1 = sp.lambdify((L1, L2), T1_MR.subs(AL, alpha))
    t2 = sp.lambdify((L1, L2), T2_MR.subs(AL, alpha))
    a11 = sp.lambdify((L1, L2), sp.diff(T1_MR, L1).subs(AL, alpha))
    a12 = sp.lambdify((L1, L2), sp.diff(T1_MR, L2).subs(AL, alpha))
    law = law_of(alpha)
    rng = np.random.default_rng(7)
    for _ in range(5):
        r, l1, l2, psi, p = rng.uniform([0.05, 1.01, 1.01, 0.05, 0.01], [0.95, 2.5, 2.5, 1.4, 5.0])
        y = np.array([l2 * r, 0.3, psi, l1, 0.2])
        pocket = np.empty(5)
        rhs.py_func(r, y, law.code, law.params, p, pocket)
        ours = capsule_rhs(r, y, p, t1, t2, a11, a12, lambda s: s, lambda s: 1.0)
        ours[4] *= 0.5
        np.testing.assert_allclose(ours, pocket, rtol=1e-12, atol=1e-14)


def _series_residuals(r0, l0, p, k, c1, c2, alpha):
    """rho' - lambda_1 cos psi and rho T1' - (T2 - T1) rho' (tangential equilibrium), both even in S, over S^2,
    and rho (T1 psi' - lambda_1 (p - T2 sin psi / rho)) (normal equilibrium times rho T1, regular at the pole), odd,
    over S, at S = 1e-12 in 60 digits, for lambda_1 = l0 + c1 S^2, lambda_2 = l0 + c2 S^2, psi = k S + S^3
    (the S^3 term enters none of them to these orders), rho = lambda_2 r0: about 1e-24 if the series is right, of
    order one if a coefficient is wrong."""
    l1 = l0 + c1 * S**2
    l2 = l0 + c2 * S**2
    psi = k * S + S**3
    rho = l2 * r0
    T1 = T1_MR.subs(AL, alpha).subs({L1: l1, L2: l2}, simultaneous=True)
    T2 = T2_MR.subs(AL, alpha).subs({L1: l1, L2: l2}, simultaneous=True)
    kinematic = sp.diff(rho, S) - l1 * sp.cos(psi)
    tangential = rho * sp.diff(T1, S) - (T2 - T1) * sp.diff(rho, S)
    normal = rho * T1 * sp.diff(psi, S) - l1 * (p * rho - T2 * sp.sin(psi))
    small = sp.Integer(10) ** -12
    return [abs(f.subs(S, small).evalf(60)) for f in (kinematic / S**2, tangential / S**2, normal / S)]


def _pole_coefficients(l0, p, alpha, shift):
    """eq-capsule-pole-series: k, c1, c2 with k^2 - shift in place of k^2 - 1 (shift = 1: the sphere; 0: the
    pocket's series)."""
    t0 = T1_MR.subs(AL, alpha).subs({L1: l0, L2: l0})
    A = sp.diff(T1_MR, L1).subs(AL, alpha).subs({L1: l0, L2: l0})
    B = sp.diff(T1_MR, L2).subs(AL, alpha).subs({L1: l0, L2: l0})
    k = l0 * p / (2 * t0)
    c2 = -l0 * (k**2 - shift) * (3 * A - B) / (16 * A)
    c1 = 3 * c2 + l0 * (k**2 - shift) / 2
    return k, c1, c2


@pytest.mark.parametrize("p", [sp.Rational(2, 5), 0])
def test_pole_series_makes_the_capsule_regular(p):
    """Exact answer: with eq-capsule-pole-series (k^2 - 1) the kinematics, tangential and normal equilibrium
    vanish to O(S^2) on r0 = sin S, for a free pole (p > 0) and for the contact zone's pole
    (p = 0 there: the plate takes the pressure, k = 0, eq-capsule-contact-series); the pocket's series (k^2 in place
    of k^2 - 1) leaves the kinematics off by l0 / 2 at O(S^2)."""
    l0, alpha = sp.Rational(6, 5), sp.Rational(1, 10)
    k, c1, c2 = _pole_coefficients(l0, p, alpha, shift=1)
    assert all(residual < 1e-20 for residual in _series_residuals(sp.sin(S), l0, p, k, c1, c2, alpha))
    k, c1, c2 = _pole_coefficients(l0, p, alpha, shift=0)  # the pocket's series does not fit the sphere
    assert _series_residuals(sp.sin(S), l0, p, k, c1, c2, alpha)[0] > 0.1


def test_capsule_pole_series_on_flat_reference_is_the_pockets():
    """Exact answer: the same series with k^2 in place of k^2 - 1 (r0 = S has no S^3 term) is regular on the
    flat reference and is the pocket's pole start ``pole_state``: its rho and lambda_1 at a small r0 give c2 and c1
    exactly (rho = r0 (l0 + c2 r0^2), lambda_1 = l0 + c1 r0^2)."""
    l0, p, alpha = sp.Rational(6, 5), sp.Rational(2, 5), sp.Rational(1, 10)
    k, c1, c2 = _pole_coefficients(l0, p, alpha, shift=0)
    assert all(residual < 1e-20 for residual in _series_residuals(S, l0, p, k, c1, c2, alpha))
    r = 1e-2
    y = pole_state(float(l0), law_of(float(alpha)), float(p), r)
    assert (y[0] / r - float(l0)) / r**2 == pytest.approx(float(c2), rel=1e-9)
    assert (y[3] - float(l0)) / r**2 == pytest.approx(float(c1), rel=1e-9)


def test_contact_zone_is_uniformly_stretched_only_on_a_flat_reference():
    """Exact answer: in the contact zone (eq-capsule-contact-ode, psi = 0, rho' = lambda_1) a uniform
    equibiaxial stretch lambda_c, rho = lambda_c r0, solves it when r0 = S (lambda_2' = 0, T2 = T1) and breaks
    rho' = lambda_1 when r0 = sin S (lambda_c cos S != lambda_c); and the only equal-stretch flattening of the
    sphere, rho = C tan(S / 2), has the varying stretch C / (1 + cos S), which tangential equilibrium with
    T1 = T2 (rho T1' = 0) forbids since dT1/dlambda = A + B > 0 along equal stretches (Mooney-Rivlin here)."""
    lc = sp.Rational(13, 10)
    rho_flat = lc * S
    assert sp.diff(rho_flat, S) - lc == 0
    dl2 = (lc - (rho_flat / S) * 1) / S
    assert sp.simplify(dl2) == 0
    rho_sphere = lc * sp.sin(S)
    assert sp.simplify(sp.diff(rho_sphere, S) - lc) != 0
    C = sp.Symbol("C", positive=True)
    rho = C * sp.tan(S / 2)
    stretch_1, stretch_2 = sp.diff(rho, S), rho / sp.sin(S)
    assert sp.simplify(stretch_1 - stretch_2) == 0
    for angle in (sp.Rational(1, 3), sp.Rational(6, 5)):
        assert abs(float((stretch_2 - C / (1 + sp.cos(S))).subs({C: 1, S: angle}))) < 1e-15
    slope = (sp.diff(T1_MR, L1) + sp.diff(T1_MR, L2)).subs({L1: LAM, L2: LAM})
    tangential = rho * slope * sp.diff(stretch_2, S)  # rho T1' with T1 = T2: must vanish, does not
    value = tangential.subs({C: 2, S: sp.Rational(1, 2), AL: sp.Rational(1, 10), LAM: 2 / (1 + sp.cos(sp.S.Half))})
    assert float(value) > 0.1


def test_mooney_rivlin_sphere_pressure_from_its_energy():
    """Exact answer: eq-capsule-mooney-rivlin, Phat = 2 (1 - l^-6)(1 + alpha l^2) / (3 (1 + alpha) l), is
    w'(l) / (E l^2) of W = C1 (I1 - 3) + C2 (I2 - 3) with E = 6 (C1 + C2), equals 2 t / l with the page's
    Mooney-Rivlin tension, tends to 4 (l - 1) (a thin sphere's 2 eps E / (1 - nu), nu = 1/2), and has the slope
    2 (alpha l^8 - l^6 + 5 alpha l^2 + 7) / (3 (1 + alpha) l^8)."""
    C1 = sp.Symbol("C1", positive=True)
    W = C1 * (I1 - 3) + AL * C1 * (I2 - 3)
    E = 6 * C1 * (1 + AL)
    w = W.subs({L1: LAM, L2: LAM})
    phat = 2 * (1 - LAM**-6) * (1 + AL * LAM**2) / (3 * (1 + AL) * LAM)
    assert sp.simplify(sp.diff(w, LAM) / (E * LAM**2) - phat) == 0
    t = 2 * C1 * T1_MR.subs({L1: LAM, L2: LAM}) / E  # units E T
    assert sp.simplify(2 * t / LAM - phat) == 0
    e = sp.Symbol("e")
    assert sp.simplify(phat.subs(LAM, 1 + e).series(e, 0, 2).removeO() - 4 * e) == 0
    slope = 2 * (AL * LAM**8 - LAM**6 + 5 * AL * LAM**2 + 7) / (3 * (1 + AL) * LAM**8)
    assert sp.simplify(sp.diff(phat, LAM) - slope) == 0


def test_neo_hookean_balloon_pressure_peaks_at_seventh_root():
    """Exact answer: at alpha = 0 the slope's numerator 7 - l^6 vanishes at l = 7^(1/6), where
    Phat = (4/7) 7^(-1/6) = 0.4131 is the largest on l > 1 (the page's limit point)."""
    phat = (2 * (1 - LAM**-6) / (3 * LAM))
    peak = sp.Integer(7) ** sp.Rational(1, 6)
    assert sp.simplify(sp.diff(phat, LAM).subs(LAM, peak)) == 0
    assert sp.simplify(phat.subs(LAM, peak) - sp.Rational(4, 7) * 7 ** sp.Rational(-1, 6)) == 0
    grid = np.linspace(1.0, 20.0, 20001)
    values = sp.lambdify(LAM, phat)(grid)
    assert values.max() <= float(phat.subs(LAM, peak)) + 1e-15
    assert round(float(phat.subs(LAM, peak)), 4) == 0.4132  # the value the page prints


def test_mooney_rivlin_balloon_loses_its_pressure_maximum_at_alpha_c():
    """Exact answer: the slope's numerator g = alpha x^4 - x^3 + 5 alpha x + 7 (x = l^2) has a double root where
    its discriminant in x, a multiple of alpha (625 alpha^6 - 4974 alpha^3 + 49), vanishes: alpha_c^3 =
    (2487 - sqrt(6154544)) / 625 (eq-capsule-alpha-c), the smaller root. Just below alpha_c, Phat rises, falls and
    rises (g has two roots x > 1); just above it rises throughout (none)."""
    x = sp.Symbol("x", positive=True)
    g = AL * x**4 - x**3 + 5 * AL * x + 7
    resultant = sp.factor(sp.resultant(g, sp.diff(g, x), x))
    assert sp.simplify(resultant / (AL * (625 * AL**6 - 4974 * AL**3 + 49))).is_number
    alpha_c = ((2487 - sp.sqrt(6154544)) / 625) ** sp.Rational(1, 3)
    assert sp.simplify((625 * AL**6 - 4974 * AL**3 + 49).subs(AL, alpha_c)) == 0
    ac = float(alpha_c)
    for alpha, turns in ((ac - 1e-3, 2), (ac + 1e-3, 0)):
        roots = np.roots([alpha, -1.0, 0.0, 5.0 * alpha, 7.0])
        assert sum(1 for z in roots if abs(z.imag) < 1e-9 and z.real > 1.0) == turns
    double = [z.real for z in np.roots([ac, -1.0, 0.0, 5.0 * ac, 7.0]) if z.real > 1.0]
    assert (round(ac, 4), round(math.sqrt(np.mean(double)), 3)) == (0.2145, 1.841)  # the page's numbers


def test_small_force_dent_solves_the_linearised_membrane():
    """Exact answer: in-plane compatibility of a shallow sphere (eps_r = u' - w/a, eps_th = u/r - w/a) is
    (r eps_th)' - eps_r = -r w'/a, and with Hooke's plane stress in an Airy function phi it is
    (r/(E T)) (lap phi)' for any nu; w = A K0(r/l) solves N0 lap w - (E T/a^2) w = 0 with l^2 = N0 a^2/(E T)
    (eq-capsule-dent), and carries the plate's load: 2 pi N0 r w' -> -2 pi N0 A = -F as r -> 0."""
    r, a, nu, ET, N0, A = sp.symbols("r a nu ET N0 A", positive=True)
    u, w, phi = (sp.Function(n)(r) for n in ("u", "w", "phi"))
    eps_r, eps_t = sp.diff(u, r) - w / a, u / r - w / a
    assert sp.simplify(sp.diff(r * eps_t, r) - eps_r + r * sp.diff(w, r) / a) == 0
    n_r, n_t = sp.diff(phi, r) / r, sp.diff(phi, r, 2)
    hooke_r, hooke_t = (n_r - nu * n_t) / ET, (n_t - nu * n_r) / ET
    lap_phi = sp.diff(phi, r, 2) + sp.diff(phi, r) / r
    assert sp.simplify(sp.diff(r * hooke_t, r) - hooke_r - r * sp.diff(lap_phi, r) / ET) == 0
    ell = sp.sqrt(N0 * a**2 / ET)
    dent = A * sp.besselk(0, r / ell)
    residual = N0 * (sp.diff(dent, r, 2) + sp.diff(dent, r) / r) - ET / a**2 * dent
    z = sp.Wild("z")  # K2(z) = K0(z) + 2 K1(z) / z, the recurrence of the modified Bessel functions
    residual = residual.replace(sp.besselk(2, z), lambda z: sp.besselk(0, z) + 2 * sp.besselk(1, z) / z)
    assert sp.simplify(residual) == 0
    flux = sp.limit(2 * sp.pi * N0 * r * sp.diff(A * sp.besselk(0, r), r), r, 0)  # r/l -> r: the flux scales out
    assert sp.simplify(flux + 2 * sp.pi * N0 * A) == 0


def test_small_force_matching_recovers_contact_area_and_plate_displacement():
    """Exact answer: with K0(x) = ln(2/x) - gamma + O(x^2 ln x), matching the flat patch w = delta - r^2/(2a) to
    the dent A K0(r/l) at r = c gives, from the slopes, c^2 = A a, which with A = F/(2 pi N0) and the inflated
    sphere's N0 = P_I a/2 is c^2 = F/(pi P_I): the contact area F = P A_c (eq-capsule-contact-force) must give at
    P = P_I; and from the values delta = A [ln(2 l/c) - gamma + 1/2], which in units of R (A = Fhat/lambda,
    l^2 = lambda^3 Phat_I/2, c^2 = Fhat) is eq-capsule-small-force, vanishing like Fhat ln(1/Fhat) as Fhat -> 0."""
    x, c, a, A, ell, F, PI = sp.symbols("x c a A ell F P_I", positive=True)
    k0 = sp.besselk(0, x).series(x, 0, 2).removeO()
    assert sp.simplify(k0 - (sp.log(2 / x) - sp.EulerGamma)) == 0
    assert sp.limit(c * sp.diff(sp.besselk(0, c / ell), c), c, 0) == -1  # K0(c/l)' = -1/c + o(1/c)
    c2 = sp.solve(sp.Eq(A * (-1 / c), -c / a), c)[0] ** 2  # the slopes: dent -A/c, patch -c/a
    assert sp.simplify(c2 - A * a) == 0
    N0 = PI * a / 2
    assert sp.simplify((F / (2 * sp.pi * N0)) * a - F / (sp.pi * PI)) == 0
    delta = A * k0.subs(x, c / ell) + c**2 / (2 * a)
    delta = sp.expand_log(delta.subs(c**2, A * a).subs(c, sp.sqrt(A * a)), force=True)
    expected = A * (sp.log(2 * ell / sp.sqrt(A * a)) - sp.EulerGamma + sp.Rational(1, 2))
    assert sp.simplify(delta - sp.expand_log(expected, force=True)) == 0
    fhat, phat = sp.symbols("Fhat Phat", positive=True)
    in_units = expected.subs({A: fhat / LAM, a: LAM, ell: sp.sqrt(LAM**3 * phat / 2)})
    in_units = in_units.subs(sp.sqrt(A * a), sp.sqrt(fhat))
    page = fhat / (2 * LAM) * (sp.log(2 * LAM**3 * phat / fhat) + 1 - 2 * sp.EulerGamma)
    assert sp.simplify(sp.expand_log(in_units - page, force=True)) == 0
    small = [float(page.subs({LAM: 1, phat: sp.Rational(1, 10), fhat: sp.Integer(10) ** -n})) for n in (4, 8, 16)]
    assert small[0] > small[1] > small[2] > 0  # delta -> 0 with Fhat
    assert small[0] * 1e4 < small[1] * 1e8 < small[2] * 1e16  # delta / Fhat -> infinity
