"""The solid's stress, tangent and fluid terms against finite differences of what they differentiate.

Exact answers: each derivative is the limit of the central difference quotient of the function it
differentiates, whose error is O(h^2); with h = 1e-6 relative the quotient carries ~1e-10 of
round-off relative to the function's scale, so the tolerances below are 1e-6 relative (a wrong
term is off by O(1)).
"""

import numpy as np
import pytest
import scipy.sparse as sp
from pocket.solid import DEFAULT_CORNER, laws, mesh, model
from pocket.solid import kinematics as kin
from pocket.solid.equations import Control, system

from pocket.core.materials import LAWS, Material, energy

H = 1e-6
RTOL = 1e-6  # central differences: O(H^2) truncation, ~1e-10 round-off; a wrong term is off by O(1)
INVARIANT_LAWS = sorted(laws.LAWS)


def _material(name):
    return Material(name, dict(LAWS[name].example)).scaled()


def _axisymmetric(rng, shape=(3,)):
    F = np.zeros((3, 3, *shape))
    F[:2, :2] = np.eye(2)[:, :, None] + 0.3 * rng.standard_normal((2, 2, *shape))
    F[2, 2] = 1.0 + 0.3 * rng.random(shape)
    return F


@pytest.mark.parametrize("name", INVARIANT_LAWS)
def test_invariant_derivatives_are_those_of_the_energy(name):
    """dW/dl1 at fixed l2 (l3 = 1/(l1 l2)) from W_1, W_2 equals the difference quotient of ``energy``; so do
    its second derivative and the cross one, from W_11, W_12, W_22."""
    material = _material(name)
    d = laws.derivatives(material)
    for l1, l2 in ((1.3, 1.1), (1.7, 0.8), (2.2, 2.0)):
        def first(a, b):
            c = 1.0 / (a * b)
            i1, i2 = a * a + b * b + c * c, a**-2 + b**-2 + c**-2
            w1, w2 = d(i1, i2)[:2]
            # I1 = a^2 + b^2 + a^-2 b^-2, I2 = a^-2 + b^-2 + a^2 b^2
            return w1 * (2 * a - 2 * c * c / a) + w2 * (-2 / a**3 + 2 * a * b * b)
        exact = first(l1, l2)
        quotient = (energy(material, l1 + H, l2) - energy(material, l1 - H, l2)) / (2 * H)
        assert abs(exact - quotient) <= RTOL * max(1.0, abs(exact)), (name, l1, l2, exact, quotient)
        second = (first(l1 + H, l2) - first(l1 - H, l2)) / (2 * H)
        fd2 = (energy(material, l1 + H, l2) - 2 * energy(material, l1, l2) + energy(material, l1 - H, l2)) / H**2
        assert abs(second - fd2) <= 1e-3 * max(1.0, abs(second)), (name, second, fd2)  # H^2 quotient: 1e-4 noise


def _energy_of_f(material, F):
    """W of the registry's definition at the isochoric invariants of a general (compressible) F."""
    C = np.einsum("ki...,kj...->ij...", F, F)
    i1 = np.einsum("ii...->...", C)
    i2 = 0.5 * (i1**2 - np.einsum("ij...,ij...->...", C, C))
    J = kin.jacobian(F)
    return LAWS[material.law].energy(dict(material.params), None, None, None, J ** (-2 / 3) * i1, J ** (-4 / 3) * i2)


def _unit(i, j, shape):
    E = np.zeros((3, 3, *shape))
    E[i, j] = 1.0
    return E


@pytest.mark.parametrize("name", INVARIANT_LAWS)
def test_energy_and_jacobian_derivatives_are_difference_quotients(name):
    """dW[E_a] is the difference quotient of W(Ib1, Ib2) (the registry's energy at the isochoric invariants)
    along each component E_a; d^2 W[E_a, E_b] that of dW[E_b]; dJ and d^2 J those of det F."""
    material = _material(name)
    law = laws.derivatives(material)
    F = _axisymmetric(np.random.default_rng(1))  # I1 - 3 ~ 0.5: inside Gent's domain (Jm = 10)
    first, second = kin.energy_derivatives(F, law)
    d_j, d2_j = kin.jacobian_derivatives(F)
    for a, (i, j) in enumerate(kin.COMPONENTS):
        E = H * _unit(i, j, F.shape[2:])
        quotient = (_energy_of_f(material, F + E) - _energy_of_f(material, F - E)) / (2 * H)
        np.testing.assert_allclose(first[a], quotient, rtol=RTOL, atol=RTOL)
        np.testing.assert_allclose(d_j[a], (kin.jacobian(F + E) - kin.jacobian(F - E)) / (2 * H), rtol=RTOL,
                                   atol=RTOL)
        plus, minus = kin.energy_derivatives(F + E, law)[0], kin.energy_derivatives(F - E, law)[0]
        np.testing.assert_allclose(second[:, a], (plus - minus) / (2 * H), rtol=RTOL, atol=RTOL)
        plus, minus = kin.jacobian_derivatives(F + E)[0], kin.jacobian_derivatives(F - E)[0]
        np.testing.assert_allclose(d2_j[:, a], (plus - minus) / (2 * H), rtol=RTOL, atol=RTOL)


def test_the_isochoric_energy_ignores_a_change_of_volume():
    """Exact answer: under F = s I the isochoric invariants stay 3, 3, so dW along the volumetric direction
    (E_rr + E_zz + E_thth) vanishes at any s, where the law's W(I1, I2) would not."""
    law = laws.derivatives(_material("mooney-rivlin"))
    F = 1.3 * _unit(0, 0, (1,)) + 1.3 * _unit(1, 1, (1,)) + 1.3 * _unit(2, 2, (1,))
    first = kin.energy_derivatives(F, law)[0]
    assert abs(first[0] + first[3] + first[4]).max() < 1e-14


def test_every_law_of_the_registry_has_a_solid_kernel():
    """Each registered law, the Ogden law included (a law of the principal stretches, ``stretches.Ogden``),
    gives the solid finite stresses at a random F: none is refused."""
    F = _axisymmetric(np.random.default_rng(4))
    for name in LAWS:
        first, second = kin.energy_derivatives(F, laws.derivatives(_material(name)))
        assert np.all(np.isfinite(first)), name
        assert np.all(np.isfinite(second)), name


@pytest.mark.parametrize("contact", [None, "force", "height"])
def test_the_jacobian_is_the_derivative_of_the_residual(contact):
    """The bordered Jacobian (rubber, incompressibility, follower pressure, fluid row of a gas, contact rows,
    force row) applied to a direction equals the difference quotient of the residual along it."""
    t = 0.05
    m = model.discretize(t, mesh.section(t, 8, 2, DEFAULT_CORNER), laws.derivatives(_material("yeoh")))
    rng = np.random.default_rng(2)
    x = m.basis_u.doflocs[0]
    u = np.zeros(m.basis_u.N)
    ur, uz = m.basis_u.split_indices()
    u[uz] = 0.3 * (1 - x[uz] ** 2) + 1e-4 * rng.standard_normal(uz.size)  # noise / node spacing << 1
    u[ur] = x[ur] * (0.05 * (1 - x[ur]) + 1e-4 * rng.standard_normal(ur.size))  # so J > 0 everywhere
    y = np.concatenate([u, 0.1 * rng.standard_normal(m.basis_p.N), [0.02]])
    gas = lambda pf: (0.4 / (1 + pf), -0.4 / (1 + pf) ** 2)  # noqa: E731  (any smooth V(p_f))
    control = Control(volume=gas)
    if contact:
        active = np.array([0, 1, 2, 3])
        y = np.concatenate([y, [0.33], rng.random(active.size)])
        control = Control(volume=gas, active=active, **{contact: 0.5})
    _, jac, keep = system(m, y, control)
    direction = np.zeros_like(y)
    direction[keep] = rng.standard_normal(keep.size)
    plus, _, _ = system(m, y + H * direction, control)
    minus, _, _ = system(m, y - H * direction, control)
    quotient = (plus - minus) / (2 * H)
    exact = jac @ direction[keep]
    assert sp.issparse(jac)
    assert np.all(np.isfinite(exact))
    np.testing.assert_allclose(exact, quotient, rtol=1e-5, atol=1e-6 * np.abs(exact).max())


@pytest.mark.parametrize("name", ["gent", "mooney-rivlin"])
def test_the_vectorised_assembly_is_the_skfem_forms(name):
    """``assembly``'s contractions (R_u, R_p, K_uu, K_pu; V, V', V'') equal scikit-fem's assembly of the weak
    forms they replace (``solidforms``, the forms written for scikit-fem), at a random displacement and
    pressure: the same sums over the same quadrature points in another order, so to round-off (1e-12 of the
    largest entry)."""
    import solidforms as forms
    from pocket.solid import assembly
    from skfem import asm

    t = 0.05
    m = model.discretize(t, mesh.section(t, 8, 2, DEFAULT_CORNER), laws.derivatives(_material(name)))
    rng = np.random.default_rng(3)
    u = 1e-3 * rng.standard_normal(m.basis_u.N)  # gradients ~ 1e-3 / (node spacing 0.0125) << 1: J > 0
    p = 0.1 * rng.standard_normal(m.basis_p.N)
    uq, pq = m.basis_u.interpolate(u), m.basis_p.interpolate(p)
    F = kin.gradient(uq.grad, uq[0], m.basis_u.global_coordinates()[0])
    table = kin.energy_derivatives(F, m.law)[1] + np.asarray(pq) * kin.jacobian_derivatives(F)[1]
    fq = m.bottom.interpolate(u)
    reference = (asm(forms.residual_u(m.law), m.basis_u, u=uq, p=pq), asm(forms.residual_p, m.basis_p, u=uq),
                 asm(forms.tangent_uu, m.basis_u, table=table), asm(forms.coupling, m.basis_u, m.basis_p, u=uq),
                 asm(forms.volume, m.bottom, u=fq), asm(forms.volume_first, m.bottom, u=fq),
                 asm(forms.volume_second, m.bottom, u=fq))
    names = ("R_u", "R_p", "K_uu", "K_pu", "V", "V'", "V''")
    for key, fast, slow in zip(names, assembly.solid(m.tables, m.law, u, p) + assembly.fluid(m.tables, u),
                               reference, strict=True):
        difference = abs(fast - slow).max()
        assert np.isfinite(difference), (key, difference, abs(slow).max())
        assert difference <= 1e-12 * abs(slow).max(), (key, difference, abs(slow).max())
