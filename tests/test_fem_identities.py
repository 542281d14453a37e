"""Identities between rubber laws, and the small-pressure limit, through the finite-element solver.

Exact answers: laws whose strain energies are the same function give the same states, to the
solver's precision (Newton's tolerance 1e-10 on relative rows: 1e-9 on every reported scalar):
neo-hookean(mu) = mooney-rivlin(mu/2, 0) = yeoh(mu/2, 0, 0) = ogden([mu], [2]), and
ogden([2 C1, -2 C2], [2, -2]) = mooney-rivlin(C1, C2) = the float alpha = C2/C1 (the last two run on
the same kernel parameters: bit for bit). Gent(mu, Jm) -> neo-Hookean(mu) as Jm grows, the gap
falling as 1/Jm (W_gent - W_nh = (mu/4)(I1 - 3)^2 / Jm + O(Jm^-2)). As Phat -> 0 every law is the
linear membrane with E = 3 mu_0 and nu = 1/2: H0/R = K Phat^(1/3) with Hencky's K, computed here
from the small-strain membrane equations by a boundary-value solver (independent of both the
finite elements and the rubber laws).
"""

import numpy as np
import pytest
from scipy.integrate import solve_bvp

from pocket import fem
from pocket.core.materials import check

PHAT, FORCES, ELEMENTS = 0.31, [0.19, 0.8], 48
KEYS = ("pressure", "pressure_ratio", "contact_area", "contact_radius", "stretch_contact", "height", "height_ratio",
        "volume", "tension_1_min", "tension_2_min")


def _curve(material):
    return fem.compression_curve(material, PHAT, FORCES, elements=ELEMENTS)


def _worst(states, reference) -> tuple[float, str]:
    """Largest relative difference over KEYS of the compressed states and the inflated ones' scalars."""
    worst = (0.0, "")
    for a, b in zip(states, reference, strict=True):
        pairs = [(a, b, KEYS), (a.inflated, b.inflated, ("stretch_pole", "height", "volume", "stretch_clamp"))]
        for x, y, keys in pairs:
            for key in keys:
                error = abs(getattr(x, key) / getattr(y, key) - 1.0)
                worst = max(worst, (error, f"Fhat = {a.force}, {key}"))
    return worst


@pytest.mark.parametrize("mu", [1.0, 250e3])
def test_neo_hookean_is_three_other_laws(mu):
    """neo-hookean(mu) = mooney-rivlin(mu/2, 0) = yeoh(mu/2, 0, 0) = ogden([mu], [2]): the same states to
    1e-9 (three kernels: the Mooney-Rivlin closed form, the I1 chain rule, Ogden's principal stretches)."""
    reference = _curve(check("neo-hookean", {"mu": mu}))
    for other in (check("mooney-rivlin", {"c1": mu / 2, "c2": 0.0}),
                  check("yeoh", {"c10": mu / 2, "c20": 0.0, "c30": 0.0}),
                  check("ogden", {"mu": [mu], "exponents": [2.0]})):
        error, where = _worst(_curve(other), reference)
        assert error < 1e-9, (other.law, error, where)


def test_ogden_with_exponents_two_and_minus_two_is_mooney_rivlin():
    """ogden([2 C1, -2 C2], [2, -2]) = mooney-rivlin(C1, C2): the same states to 1e-9; and the
    Mooney-Rivlin Material is the float alpha = C2/C1 exactly (same kernel parameters), echoing itself."""
    c1, c2 = 160e3, 47e3
    mooney = check("mooney-rivlin", {"c1": c1, "c2": c2})
    reference = _curve(mooney)
    error, where = _worst(_curve(check("ogden", {"mu": [2 * c1, -2 * c2], "exponents": [2.0, -2.0]})), reference)
    assert error < 1e-9, (error, where)
    by_alpha = _curve(c2 / c1)
    for a, b in zip(by_alpha, reference, strict=True):
        assert all(getattr(a, key) == getattr(b, key) for key in KEYS)
        assert (a.alpha, a.material, b.alpha, b.material) == (c2 / c1, by_alpha[0].material, None, mooney)


def test_gent_tends_to_neo_hookean_at_rate_one_over_jm():
    """|Gent(mu, Jm) - neo-Hookean(mu)| in every scalar falls as 1/Jm: doubling Jm from 100 to 800 halves
    the largest difference (observed order 1 within 0.05), and Jm times it settles (the last two within 5 %)."""
    reference = _curve(check("neo-hookean", {"mu": 1.0}))
    jms = [100.0, 200.0, 400.0, 800.0]
    gaps = [_worst(_curve(check("gent", {"mu": 1.0, "jm": jm})), reference)[0] for jm in jms]
    orders = np.log2(np.array(gaps[:-1]) / np.array(gaps[1:]))
    assert np.all(np.abs(orders - 1.0) < 0.05), (orders, gaps)
    scaled = np.array(gaps) * jms
    assert abs(scaled[-1] / scaled[-2] - 1.0) < 0.05, scaled


def hencky_constant(nu: float = 0.5, start: float = 1e-6) -> float:
    """K of H0/R = K (q R / (E T))^(1/3), the clamped small-strain (Foppl) membrane.

    Resultants N_r, N_t and the radial displacement u, in units where E T = R = q = 1 (the problem is
    self-similar in q, so K is the deflection at the centre): equilibrium (r N_r)' = N_t and
    N_r w' = -r / 2; strains eps_r = u' + w'^2 / 2 = N_r - nu N_t, eps_t = u / r = N_t - nu N_r.
    Unknowns (u, N_r, w) of r in [start, 1]: u' = eps_r - w'^2 / 2, N_r' = (N_t - N_r) / r, w' = -r / (2 N_r),
    with u = r (1 - nu) N_r at the start (equibiaxial centre), u(1) = 0 and w(1) = 0 (the clamp).
    scipy's collocation solver (tolerance 1e-8; the start at 1e-6 costs ~1e-9 of K).
    """
    def rates(r, y):
        u, n_r, _ = y
        eps_t = u / r
        eps_r = (1 - nu**2) * n_r - nu * eps_t
        slope = -r / (2 * n_r)
        n_t = (eps_t + nu * eps_r) / (1 - nu**2)
        return np.vstack([eps_r - slope**2 / 2, (n_t - n_r) / r, slope])

    def ends(a, b):
        return np.array([a[0] - start * (1 - nu) * a[1], b[0], b[2]])

    r = np.geomspace(start, 1.0, 300)
    solution = solve_bvp(rates, ends, r, np.vstack([0 * r, 0.3 + 0 * r, 0.6 * (1 - r**2)]), tol=1e-8, max_nodes=10**5)
    assert solution.status == 0, solution.message
    return float(solution.sol(start)[2])


def test_hencky_constant_of_the_classical_plate():
    """The helper reproduces the corrected Hencky constant for nu = 0.3, K = 0.6535 (four digits, as
    tabulated for the clamped circular membrane)."""
    assert hencky_constant(0.3) == pytest.approx(0.6535, abs=1e-4)


@pytest.mark.parametrize("material", [
    47 / 160, check("neo-hookean", {"mu": 2.0}), check("yeoh", {"c10": 85e3, "c20": -2e3, "c30": 0.3e3}),
    check("gent", {"mu": 1.0, "jm": 3.0}),
    check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]})],
    ids=["alpha", "neo-hookean", "yeoh", "gent", "ogden"])
def test_small_pressure_limit_is_hencky_for_every_law(material):
    """H0/R / Phat^(1/3) at Phat = 1e-5 and 1e-6 (default mesh), extrapolated in Phat^(2/3) (the first
    correction: strains ~ Phat^(2/3)), equals Hencky's K for nu = 1/2 to 1e-6 (the next term, O(Phat^(4/3)),
    is ~1e-8 here; the mesh's error ~1e-10)."""
    k = [fem.inflate(material, p).height / p ** (1 / 3) for p in (1e-5, 1e-6)]
    limit = k[1] + (k[1] - k[0]) / (10 ** (2 / 3) - 1)
    assert limit == pytest.approx(hencky_constant(), rel=1e-6), (limit, k)
