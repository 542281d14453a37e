"""The solid pressed by a sphere (a fingertip): its contact rows, its states, and their limits.

Exact answers: the bordered Jacobian with the sphere's curvature terms is the difference quotient of
the residual; global vertical equilibrium (the fluid's upward resultant p_f pi R^2 equals the clamp's
reaction plus the vertical part of the contact forces); the active nodes lie on the sphere (their rows)
and the free ones outside it. Limits: a sphere of large radius K is the flat plate, to O(1/K); as
T/R -> 0 the solid tends to the membrane under the same sphere (``pocket.shooting``), at first order.
"""

import numpy as np
import pytest
import scipy.sparse as sp
from pocket.solid import compression, contact, inflation, laws, mesh, model
from pocket.solid.equations import Control, system
from pocket.solid.model import split

from pocket import shooting, solid
from pocket.cli import main
from pocket.core.fluids import LIQUID
from pocket.core.indenters import sphere
from pocket.core.materials import mooney_rivlin

T, ELEMENTS, PHAT, FORCE, K = 0.02, 32, 0.31, 0.5, 0.4
TOL = 1e-10
MATERIAL = mooney_rivlin(47 / 160)


@pytest.fixture(scope="module")
def pressed():
    """The headline rubber (alpha = 47/160, Phat_I = 0.31, T/R = 0.02) pressed by a sphere of K = 0.4 at
    Fhat = 0.5: (model, y, control)."""
    m = model.discretize(T, mesh.section(T, ELEMENTS, 2), laws.derivatives(MATERIAL.scaled()))
    p_i = 3.0 * T * PHAT
    y, _ = inflation.to_pressure(m, p_i, TOL)
    v_i = model.fluid(m, split(m, y)[0])[0]
    fill = compression.fluid_control(m, LIQUID, PHAT, v_i)
    y, control = compression.first_contact(m, y, fill, contact.Surface(K))
    y, control, _ = compression.to_force(m, y, control, FORCE * np.pi * p_i, np.pi * p_i, TOL)
    return m, y, control


@pytest.mark.parametrize("held", ["force", "height"])
def test_the_sphere_jacobian_is_the_derivative_of_the_residual(held):
    """Exact answer: the bordered Jacobian with a sphere's contact rows (the two-dof normal columns, the
    curvature lambda_k d2g_k/du2, the normal's turn with h, the force row's derivatives) applied to a random
    direction is the central difference quotient of the residual along it."""
    t, h, radius = 0.05, 0.33, 0.5
    m = model.discretize(t, mesh.section(t, 8, 2), laws.derivatives(MATERIAL.scaled()))
    rng = np.random.default_rng(5)
    x = m.basis_u.doflocs[0]
    u = np.zeros(m.basis_u.N)
    ur, uz = m.basis_u.split_indices()
    u[uz] = 0.3 * (1 - x[uz] ** 2) + 1e-4 * rng.standard_normal(uz.size)  # noise / node spacing << 1: J > 0
    u[ur] = x[ur] * (0.05 * (1 - x[ur]) + 1e-4 * rng.standard_normal(ur.size))
    active = np.array([0, 1, 2, 3])
    lam = 0.5 + rng.random(active.size)
    y = np.concatenate([u, 0.1 * rng.standard_normal(m.basis_p.N), [0.02, h], lam])
    gas = lambda pf: (0.4 / (1 + pf), -0.4 / (1 + pf) ** 2)  # noqa: E731  (any smooth V(p_f))
    control = Control(volume=gas, active=active, surface=contact.Surface(radius), **{held: 0.5})
    _, jac, keep = system(m, y, control)
    direction = np.zeros_like(y)
    direction[keep] = rng.standard_normal(keep.size)
    step = 1e-6
    plus, _, _ = system(m, y + step * direction, control)
    minus, _, _ = system(m, y - step * direction, control)
    quotient = (plus - minus) / (2 * step)
    exact = jac @ direction[keep]
    # central differences: O(step^2) truncation, ~1e-10 relative round-off; a wrong term is off by O(1)
    atol = 1e-6 * np.abs(exact).max()
    np.testing.assert_allclose(exact, quotient, rtol=1e-5, atol=atol)
    # the curvature terms are large enough here that leaving one out would fail the comparison above
    rows = contact.rows(m, control.surface, y, active)
    assert np.abs(rows.k_uu @ direction[:m.basis_u.N]).max() > 1e3 * atol
    assert np.abs(rows.k_uh.toarray()).max() * np.abs(direction[m.size + 1]) > 1e3 * atol
    assert sp.issparse(rows.E)


def test_global_vertical_equilibrium(pressed):
    """p_f pi R^2 = clamp reaction + sum_k lambda_k (-n_z,k), the clamp's reaction read from its dofs' residual."""
    m, y, control = pressed
    u, p = split(m, y)
    pf = y[m.size]
    residual = model.solid(m, u, p)[0] - pf * model.fluid(m, u)[1]
    clamp = -residual[m.basis_u.get_dofs("right").all("u^2")].sum()  # as for the plate (test_solid_states)
    rho, z = m.top_r[control.active] + y[m.top_radial[control.active]], 0.5 * T + y[m.top_z[control.active]]
    n_z = (z - (y[m.size + 1] + K)) / np.hypot(rho, z - (y[m.size + 1] + K))
    pushed = np.sum(y[m.size + 2:] * -n_z)
    print(f"p_f pi = {pf * np.pi:.15g}, contact + clamp = {pushed + clamp:.15g}")
    # Newton's last increment is below 1e-10 R, the residual quadratically smaller; forces here are ~0.1
    assert abs(pf * np.pi - (pushed + clamp)) <= 1e-9 * pf * np.pi
    assert pushed == pytest.approx(FORCE * np.pi * 3.0 * T * PHAT, rel=1e-12)  # the force row of Newton's system


def test_active_nodes_on_the_sphere_free_nodes_outside(pressed):
    """Active nodes: gap zero to the Newton tolerance, force >= 0; free nodes: gap >= -SWEEP_TOL (the active
    set's test, ``newton``). The contact zone is a disc: the nodes from the pole (whose consistent force, at
r = 0, is zero to the discretisation: it may leave) to the edge."""
    from pocket.solid.newton import SWEEP_TOL

    m, y, control = pressed
    gap = contact.gaps(m, control.surface, y)
    free = np.setdiff1d(np.arange(gap.size), control.active)
    print(f"{control.active.size} active nodes, max |g| on them {np.abs(gap[control.active]).max():.2e} R, "
          f"min g off them {gap[free].min():.2e} R")
    assert np.abs(gap[control.active]).max() <= TOL  # the contact rows, solved to the tolerance
    assert np.all(y[m.size + 2:] >= 0.0)
    assert gap[free].min() >= -SWEEP_TOL
    inner = control.active[control.active > 0]
    assert inner.size >= 4 and np.array_equal(inner, np.arange(1, inner.max() + 1))


def _state(indenter, thickness_ratio=T, elements=ELEMENTS, layers=2, force=FORCE):
    return solid.compress(MATERIAL, PHAT, force, indenter=indenter, thickness_ratio=thickness_ratio,
                          elements=elements, layers=layers)
