"""The compiled assembly (fem/kernel.py, fem/loops.py) against scikit-fem's assembly of the same weak forms.

Exact answer: the residual and tangent of the membrane (with the penalty plate)
written below as scikit-fem forms, assembled by scikit-fem's own machinery on
the same mesh with the same quadrature, equal the kernel's to round-off, for
each rubber law. The forms here are an independent transcription of the
energy's first and second variations (fem/kernel.py docstring); the two share
only the law's derivatives (tested against the shared energy in
test_fem_laws.py), evaluated here through the Python entry, there inside the
compiled loop.
Also: the bordered banded solver equals a dense solve of the same matrix.
"""

import numpy as np
import pytest
from pocket.fem import banded, condensed, kernel
from pocket.fem.geometry import place
from pocket.fem.material import law_of
from pocket.fem.reference import reference
from skfem import Basis, BilinearForm, ElementLineP1, ElementLineP2, ElementVector, LinearForm, MeshLine

from pocket.core.materials import check

ALPHA, P, H, KAPPA = 0.31, 0.27, 0.55, 40.0
#: one rubber of each law (and a Mooney-Rivlin alpha): parameters in a stress unit of their own
RUBBERS = {
    "alpha": ALPHA,
    "neo-hookean": check("neo-hookean", {"mu": 2.0}),
    "yeoh": check("yeoh", {"c10": 0.5, "c20": -0.02, "c30": 0.003}),
    "gent": check("gent", {"mu": 1.0, "jm": 4.0}),
    "ogden": check("ogden", {"mu": [1.1, 0.02, -0.05], "exponents": [1.4, 4.5, -2.2]}),
}


def _state(r):
    """A smooth, strongly deformed meridian at the points r (not an equilibrium)."""
    return np.stack([r * (1.2 - 0.15 * r**2) + 0.02 * np.sin(4 * r) * r * (1 - r),
                     0.6 * (1 - r**2) + 0.03 * np.cos(3 * r) * (1 - r)])


def _skfem(order, nodes, law):
    element = {1: ElementLineP1, 2: ElementLineP2}[order]()
    basis = Basis(MeshLine(nodes), ElementVector(element, 2), intorder=2 * order + 1)  # the kernel's rule
    u = basis.project(lambda x: _state(x[0]))

    def kin(w):
        r = w.x[0]
        rho, eta, drho, deta = w.u[0], w.u[1], w.u.grad[0, 0], w.u.grad[1, 0]
        l1 = np.sqrt(drho**2 + deta**2)
        return r, rho, eta, drho, deta, l1, rho / r

    @LinearForm
    def residual(v, w):
        r, rho, eta, drho, deta, l1, l2 = kin(w)
        w1, w2 = law.derivatives(l1, l2)[:2]
        p_n = np.maximum(KAPPA * (eta - H), 0.0)
        return (2 * np.pi * w1 * (drho * v.grad[0, 0] + deta * v.grad[1, 0]) / l1 * r
                + 2 * np.pi * w2 * v[0] + np.pi * P * (2 * rho * deta * v[0] + rho**2 * v.grad[1, 0])
                + 2 * np.pi * p_n * v[1] * r)

    @BilinearForm
    def tangent(du, v, w):
        r, rho, eta, drho, deta, l1, l2 = kin(w)
        w1, _, w11, w12, w22 = law.derivatives(l1, l2)
        t = (drho / l1, deta / l1)
        tdu = t[0] * du.grad[0, 0] + t[1] * du.grad[1, 0]
        tv = t[0] * v.grad[0, 0] + t[1] * v.grad[1, 0]
        dudv = du.grad[0, 0] * v.grad[0, 0] + du.grad[1, 0] * v.grad[1, 0]
        chi = KAPPA * (eta - H) > 0
        return (2 * np.pi * (w11 * tdu * tv + w1 / l1 * (dudv - tdu * tv)) * r
                + 2 * np.pi * w12 * (du[0] * tv + tdu * v[0]) + 2 * np.pi * w22 * du[0] * v[0] / r
                + np.pi * P * (2 * deta * du[0] * v[0] + 2 * rho * du.grad[1, 0] * v[0]
                               + 2 * rho * du[0] * v.grad[1, 0])
                + 2 * np.pi * KAPPA * chi * du[1] * v[1] * r)

    return basis, u, residual.assemble(basis, u=basis.interpolate(u)), tangent.assemble(basis, u=basis.interpolate(u))


def _reorder(order, basis):
    """Map from scikit-fem's global dofs to the kernel's (node along r, then component)."""
    mesh = basis.mesh
    n = mesh.p.shape[1] - 1
    out = np.empty(basis.N, dtype=int)
    nodal, facets = basis.nodal_dofs, basis.interior_dofs if order == 2 else None
    for c in range(2):
        out[nodal[c]] = 2 * (order * np.arange(n + 1)) + c
        if order == 2:
            out[facets[c]] = 2 * (2 * np.arange(n) + 1) + c
    return out


@pytest.mark.parametrize("rubber", RUBBERS)
@pytest.mark.parametrize("order", [1, 2])
def test_kernel_equals_scikit_fem(order, rubber):
    """Residual and tangent (membrane, pressure, active penalty) equal to 1e-12 relative, for each law."""
    nodes = np.linspace(0.0, 1.0, 13) ** 1.3
    law = law_of(RUBBERS[rubber])
    basis, u, r_sk, k_sk = _skfem(order, nodes, law)
    perm = _reorder(order, basis)
    u_k = np.empty_like(u)
    u_k[perm] = u
    ref = reference(order)
    w = kernel.fields(ref, place(nodes, ref), u_k, P)
    assert (w.eta > H).any(), "the plate must touch part of the sheet"
    assert (w.eta < H).any(), "the plate must touch part of the sheet"
    linear = kernel.evaluate(law, ref, place(nodes, ref), u_k, P, kernel.Contact(H, KAPPA))
    r = linear.residual
    kl = 2 * order + 1
    band = banded.band(linear.matrices, 2 * order, kl)
    dense = np.zeros((u.size, u.size))
    for i in range(u.size):
        e = np.zeros(u.size)
        e[i] = 1.0
        dense[:, i] = banded.matvec(band, kl, kl, e)
    k_perm = k_sk.toarray()[np.argsort(perm)][:, np.argsort(perm)]
    np.testing.assert_allclose(r, r_sk[np.argsort(perm)], rtol=1e-12, atol=1e-13 * np.abs(r).max())
    np.testing.assert_allclose(dense, k_perm, rtol=1e-12, atol=1e-12 * np.abs(dense).max())


def test_bordered_solve_equals_dense_solve():
    """A random banded matrix with three dense borders: block elimination = numpy's dense solve (1e-12)."""
    rng = np.random.default_rng(3)
    n, kl, m = 40, 3, 3
    a = np.zeros((n, n))
    for d in range(-kl, kl + 1):
        a += np.diag(rng.standard_normal(n - abs(d)), d)
    a += 8 * np.eye(n)
    band = np.zeros((3 * kl + 1, n))
    for i in range(n):
        for j in range(max(0, i - kl), min(n, i + kl + 1)):
            band[2 * kl + i - j, j] = a[i, j]
    b, c, corner = rng.standard_normal((n, m)), rng.standard_normal((m, n)), rng.standard_normal((m, m))
    r, s = rng.standard_normal(n), rng.standard_normal(m)
    x, y = banded.Bordered(band, kl, b, c, corner).solve(r, s)
    full = np.block([[a, b], [c, corner]])
    np.testing.assert_allclose(np.concatenate([x, y]), np.linalg.solve(full, np.concatenate([r, s])), rtol=1e-12)


def test_bordered_solve_with_a_singular_band():
    """A singular banded block with a regular bordered matrix (a limit point under pressure control):
    the solve falls back and still equals the dense solve (1e-10)."""
    rng = np.random.default_rng(4)
    n, kl = 12, 1
    a = np.diag(2.0 * np.ones(n)) - np.diag(np.ones(n - 1), 1) - np.diag(np.ones(n - 1), -1)
    a[0, 0] = a[-1, -1] = 1.0  # the singular Neumann Laplacian: constants in its kernel
    band = np.zeros((3 * kl + 1, n))
    for i in range(n):
        for j in range(max(0, i - kl), min(n, i + kl + 1)):
            band[2 * kl + i - j, j] = a[i, j]
    b, c = np.ones((n, 1)), np.ones((1, n))
    r, s = rng.standard_normal(n), rng.standard_normal(1)
    r -= r.mean()
    x, y = banded.Bordered(band, kl, b, c, np.zeros((1, 1))).solve(r, s)
    full = np.block([[a, b], [c, np.zeros((1, 1))]])
    np.testing.assert_allclose(np.concatenate([x, y]), np.linalg.solve(full, np.concatenate([r, s])), rtol=1e-10,
                               atol=1e-10)


def test_condensed_solve_equals_the_full_band():
    """P2: eliminating the midpoint dofs element by element (static condensation) and solving the
    vertex band gives the solution of the whole banded system (1e-10 relative): at a pressed state
    on the edge-fitted mesh, with its three border unknowns."""
    from pocket.fem import fitted, inflation, model
    from pocket.fem.api import default_mesh
    from pocket.fem.newton import Tolerances

    m = model.discretize(0.3, default_mesh(16), 2, 1e5)
    y_i, _ = inflation.to_pressure(m, 0.3, Tolerances())
    volume = inflation.volume(m, y_i)
    y, _ = fitted.first_contact(m, y_i, model.Control(volume=volume), 0.1, Tolerances())
    r, system = model.linearize(m, y, model.FITTED, model.Control(volume=volume, force=0.5, scale=0.5))
    assert isinstance(system, condensed.Condensed)
    full = banded.Bordered(banded.band(system.matrices, 4, 5), 5, system.B, system.C, system.D)
    rhs = np.random.default_rng(5).standard_normal(r.size)
    n = m.dofs
    x_c, y_c = system.solve(rhs[:n], rhs[n:])
    x_f, y_f = full.solve(rhs[:n], rhs[n:])
    np.testing.assert_allclose(np.concatenate([x_c, y_c]), np.concatenate([x_f, y_f]), rtol=1e-10,
                               atol=1e-10 * np.abs(x_f).max())


def test_a_slack_element_sends_the_solve_to_the_full_band():
    """An element whose midpoint block is singular (a slack element: no stiffness of its midpoint
    against itself, only its couplings to the vertices) cannot be condensed: the system falls back
    to the whole band, whose solve equals numpy's dense solve of the assembled bordered matrix
    (1e-10; that matrix is regular, its condition printed on failure)."""
    rng = np.random.default_rng(6)
    n, size = 5, 6
    matrices = rng.standard_normal((n, size, size))
    matrices = matrices + matrices.transpose(0, 2, 1) + 12 * np.eye(size)
    matrices[2, 2:4, 2:4] = 0.0
    b, c, corner = rng.standard_normal((4 * n + 2, 1)), rng.standard_normal((1, 4 * n + 2)), np.eye(1)
    system = condensed.system(matrices, 2, b, c, corner)
    assert isinstance(system, banded.Bordered)
    dense = np.zeros((4 * n + 2, 4 * n + 2))
    for e in range(n):
        dense[4 * e: 4 * e + size, 4 * e: 4 * e + size] += matrices[e]
    full = np.block([[dense, b], [c, corner]])
    r = rng.standard_normal(4 * n + 3)
    x, y = system.solve(r[:-1], r[-1:])
    np.testing.assert_allclose(np.concatenate([x, y]), np.linalg.solve(full, r), rtol=1e-10, atol=1e-10,
                               err_msg=f"condition {np.linalg.cond(full):.3g}")
