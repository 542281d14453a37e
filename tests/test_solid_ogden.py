"""The solid's Ogden rubber: its stress and tangent, its special cases, its thin limit, its command line.

Exact answers: the stress and tangent are the limits of difference quotients of the energy (an
independent evaluation: the registry's Ogden energy at the singular values of F's in-plane block);
ogden([mu], [2]) is neo-Hookean and ogden([2 C1, -2 C2], [2, -2]) Mooney-Rivlin at the isochoric
stretches (sum lb_i^2 = Ib1, sum lb_i^-2 = Ib2 when lb1 lb2 lb3 = 1), so their solved states are one;
the membrane (``pocket.shooting``, an independent solver that has the Ogden law) is the solid's limit
as T/R -> 0, at first order (``test_solid_thin``, which has the Ogden rubber among its cases).
"""

import json

import numpy as np
import pytest
from pocket.solid import kinematics as kin
from pocket.solid import laws

from pocket import solid
from pocket.cli import main
from pocket.core.materials import LAWS, Material, mooney_rivlin

H = 1e-6
RTOL = 1e-6  # central differences: O(H^2) truncation, ~1e-10 round-off; a wrong term is off by O(1)
OGDEN = Material("ogden", dict(LAWS["ogden"].example))


def _energy(material, F):
    """W at the isochoric principal stretches of F, from the registry's definition: l1, l2 the singular
    values of the in-plane block (numpy's SVD, not the solid's eigenvalues of C), l3 = F_33."""
    plane = np.linalg.svd(np.moveaxis(F[:2, :2], (0, 1), (-2, -1)), compute_uv=False)
    s = kin.jacobian(F) ** (-1.0 / 3.0)
    l1, l2 = np.moveaxis(plane, -1, 0)
    return LAWS["ogden"].energy(dict(material.params), s * l1, s * l2, s * F[2, 2], None, None)


def _rotated(stretches, hoop, angles):
    """F with in-plane block R(angle) diag(stretches) R(angle + 0.7) (one F per angle) and F_33 = hoop."""
    F = np.zeros((3, 3, len(angles)))
    for k, angle in enumerate(angles):
        rot = [np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]]) for t in (angle, angle + 0.7)]
        F[:2, :2, k] = rot[0] @ np.diag(stretches) @ rot[1]
    F[2, 2] = hoop
    return F


def _random(rng, n=3):
    F = np.zeros((3, 3, n))
    F[:2, :2] = np.eye(2)[:, :, None] + 0.3 * rng.standard_normal((2, 2, n))
    F[2, 2] = 1.0 + 0.3 * rng.random(n)
    return F


CASES = {
    "random": _random(np.random.default_rng(1)),
    "identity": np.eye(3)[:, :, None] * np.ones(2),
    # l1 = l2 to 1e-8 (and to 1e-12), rotated: the divided difference's removable 0/0
    "near-degenerate": np.concatenate([_rotated((1.2, 1.2 + 1e-8), 0.9, (0.3, 1.1)),
                                       _rotated((0.8, 0.8 * (1 + 1e-12)), 1.3, (2.0,))], axis=2),
    # a volume change too: the isochoric factor J^(-a/3)
    "equibiaxial, J != 1": _rotated((1.1, 1.1), 1.05, (0.4,)),
}


@pytest.mark.parametrize("case", CASES)
def test_ogden_stress_and_tangent_are_difference_quotients(case):
    """dW[E_a] is the difference quotient of the independent energy along each component, and d^2 W[E_a, E_b]
    that of dW[E_b]; at random F, at F = I (l1 = l2 = l3) and where l1 = l2 to 1e-8."""
    material = OGDEN.scaled()
    law = laws.derivatives(material)
    F = CASES[case]
    first, second = kin.energy_derivatives(F, law)
    assert np.all(np.isfinite(second))
    for a, (i, j) in enumerate(kin.COMPONENTS):
        E = np.zeros_like(F)
        E[i, j] = H
        quotient = (_energy(material, F + E) - _energy(material, F - E)) / (2 * H)
        np.testing.assert_allclose(first[a], quotient, rtol=RTOL, atol=RTOL)
        plus, minus = kin.energy_derivatives(F + E, law)[0], kin.energy_derivatives(F - E, law)[0]
        np.testing.assert_allclose(second[:, a], (plus - minus) / (2 * H), rtol=RTOL, atol=RTOL)


def test_the_small_strain_shear_modulus_is_mu_0():
    """Exact: at F = I the tangent of a rubber in units of mu_0 is 1 for a simple shear (d^2 W/dF_12^2)."""
    second = kin.energy_derivatives(CASES["identity"], laws.derivatives(OGDEN.scaled()))[1]
    np.testing.assert_allclose(second[1, 1], 1.0, rtol=1e-14)  # round-off of a sum of three terms


@pytest.mark.parametrize(("ogden", "other"), [
    (Material("ogden", {"mu": [1.0], "exponents": [2.0]}), Material("neo-hookean", {"mu": 1.0})),
    (Material("ogden", {"mu": [2.0, -2 * 47 / 160], "exponents": [2.0, -2.0]}), mooney_rivlin(47 / 160)),
])
def test_ogden_special_cases_are_the_invariant_laws(ogden, other):
    """Exact: the same energy, so the same stress and tangent (to round-off at random F) and the same states:
    the inflated pocket and the one pressed to Fhat = 0.5 agree to 1e-10 (the Newton tolerance; both Newton
    runs take the same steps from the same start, so they agree far better)."""
    F = CASES["random"]
    for mine, theirs in zip(kin.energy_derivatives(F, laws.derivatives(ogden.scaled())),
                            kin.energy_derivatives(F, laws.derivatives(other.scaled())), strict=True):
        np.testing.assert_allclose(mine, theirs, rtol=1e-12, atol=1e-13)  # a few ulps of O(1) entries
    options = {"thickness_ratio": 0.04, "elements": 16, "layers": 2}
    a, b = (solid.compress(m, 0.2, 0.5, **options) for m in (ogden, other))
    pairs = {f"inflated {key}": (getattr(a.inflated, key), getattr(b.inflated, key)) for key in ("height", "volume")}
    pairs.update({key: (getattr(a, key), getattr(b, key)) for key in ("pressure_ratio", "height_ratio", "volume")})
    print(f"{ogden.params} vs {other.law}: " + ", ".join(f"{k} {x - y:+.1e}" for k, (x, y) in pairs.items()))
    for key, (x, y) in pairs.items():
        assert abs(x - y) < 1e-10, (key, x, y)


@pytest.mark.slow
def test_the_command_line_solves_an_ogden_rubber_as_a_solid(capsys):
    """Exact: ``pocket compress --solver solid --law ogden`` prints the library's state for the rubber in
    units of mu_0 (the parameters are rescaled: only their ratios matter)."""
    status = main(["compress", "--law", "ogden", "--mu", "630", "1.2", "-10", "--exponents", "1.3", "5", "-2",
                   "--pressure", "0.31", "--force", "0.5", "--solver", "solid", "--thickness-ratio", "0.04",
                   "--elements", "16", "--json"])
    out, err = capsys.readouterr()
    assert status == 0, err
    row = json.loads(out)
    row = row[0] if isinstance(row, list) else row
    state = solid.compress(OGDEN, 0.31, 0.5, thickness_ratio=0.04, elements=16)
    assert row["material"] == "ogden"
    assert row["exponents"] == [1.3, 5.0, -2.0]
    assert row["pressure_ratio"] == pytest.approx(state.pressure_ratio, rel=1e-12)  # the same solve, repr floats
    assert row["height_ratio"] == pytest.approx(state.height_ratio, rel=1e-12)
