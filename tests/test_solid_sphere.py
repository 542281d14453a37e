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
from pocket.solid import DEFAULT_CLAMP_RADIUS, DEFAULT_CORNER, compression, contact, inflation, laws, mesh, model
from pocket.solid.equations import Control
from pocket.solid.model import split
from solidstates import bent, check_jacobian

from pocket import shooting, solid
from pocket.cli import main
from pocket.core.fluids import LIQUID
from pocket.core.indenters import Sphere
from pocket.core.materials import mooney_rivlin

T, ELEMENTS, PHAT, FORCE, K = 0.02, 32, 0.31, 0.5, 0.4
TOL = 1e-10
MATERIAL = mooney_rivlin(47 / 160)


@pytest.fixture(scope="module")
def pressed():
    """The headline rubber (alpha = 47/160, Phat_I = 0.31, T/R = 0.02) pressed by a sphere of K = 0.4 at
    Fhat = 0.5: (model, y, control)."""
    m = model.discretize(T, mesh.section(T, ELEMENTS, 2, DEFAULT_CORNER), laws.derivatives(MATERIAL.scaled()))
    p_i = 3.0 * T * PHAT
    y, _ = inflation.to_pressure(m, p_i, TOL)
    v_i = model.fluid(m, split(m, y)[0])[0]
    fill = compression.fluid_control(m, LIQUID, PHAT, v_i)
    y, control = compression.first_contact(m, y, fill, contact.Surface(Sphere(K)))
    y, control, _ = compression.to_force(m, y, control, FORCE * np.pi * p_i, np.pi * p_i, TOL)
    return m, y, control


@pytest.mark.parametrize("held", ["force", "height"])
def test_the_sphere_jacobian_is_the_derivative_of_the_residual(held):
    """Exact answer: the bordered Jacobian with a sphere's contact rows (the two-dof normal columns, the
    curvature lambda_k d2g_k/du2, the normal's turn with h, the force row's derivatives) applied to a random
    direction is the central difference quotient of the residual along it."""
    t, h, radius = 0.05, 0.33, 0.5
    m = model.discretize(t, mesh.section(t, 8, 2, DEFAULT_CORNER), laws.derivatives(MATERIAL.scaled()))
    rng = np.random.default_rng(5)
    u = bent(m, rng)
    active = np.array([0, 1, 2, 3])
    lam = 0.5 + rng.random(active.size)
    y = np.concatenate([u, 0.1 * rng.standard_normal(m.basis_p.N), [0.02, h], lam])
    gas = lambda pf: (0.4 / (1 + pf), -0.4 / (1 + pf) ** 2)  # noqa: E731  (any smooth V(p_f))
    control = Control(volume=gas, active=active, surface=contact.Surface(Sphere(radius)), **{held: 0.5})
    direction, atol = check_jacobian(m, y, control, rng)
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
    assert inner.size >= 4
    assert np.array_equal(inner, np.arange(1, inner.max() + 1))


def _state(indenter, thickness_ratio=T, elements=ELEMENTS, layers=2, force=FORCE):
    return solid.compress(MATERIAL, PHAT, force, indenter=indenter, thickness_ratio=thickness_ratio,
                          elements=elements, layers=layers)


@pytest.mark.slow
def test_a_large_sphere_is_the_flat_plate_to_first_order_in_1_over_k():
    """Limit: the sphere's surface deviates from the plate's by rho^2 / (2 K) over the contact zone, so a
    sphere of radius K gives the plate's state to O(1/K): the differences in P/P_I, the contact radius and the
    height at K = 25 and 50 fall by the factor 2 (order 1 fitted)."""
    plate = _state(None)
    diffs = {}
    for radius in (25.0, 50.0):
        s = _state(Sphere(radius))
        diffs[radius] = np.array([s.pressure_ratio - plate.pressure_ratio, s.contact_radius - plate.contact_radius,
                                  s.height - plate.height])
    order = np.log2(np.abs(diffs[25.0] / diffs[50.0]))
    print(f"K = 50 minus the plate: P/P_I {diffs[50.0][0]:.3e}, r_c {diffs[50.0][1]:.3e}, h {diffs[50.0][2]:.3e}; "
          f"orders in 1/K {order.round(2)}")
    assert np.all(np.sign(diffs[25.0]) == np.sign(diffs[50.0]))
    # the contact radius comes from the edge's extrapolation, which moves by a fraction of a node's spacing
    # from state to state (``results``), a few 1e-4 R: its order only within 0.5 of 1
    assert np.all(np.abs(order[[0, 2]] - 1.0) <= 0.15), order
    assert abs(order[1] - 1.0) <= 0.5, order


def _against_membrane(radius, clamp_radius):
    """(T/R, dq, dA, bound on |dA|) for T/R = 0.01 and 0.02: the solid's P/P_I and contact area minus the
    membrane's (``pocket.shooting``) under the sphere of radius K = ``radius`` at Fhat = 0.3."""
    membrane = shooting.compress(MATERIAL, PHAT, 0.3, indenter=Sphere(radius))
    rows = []
    for t in (0.01, 0.02):
        s = solid.compress(MATERIAL, PHAT, 0.3, indenter=Sphere(radius), thickness_ratio=t,
                           clamp_radius=clamp_radius)
        r, rho_c = s.profile.r, s.contact_radius_deformed
        spacing = np.diff(r)[min(np.searchsorted(r, s.contact_radius), r.size - 2)]
        slope = 2.0 * radius * rho_c / np.sqrt(radius**2 - rho_c**2)  # d(cap area)/d rho_c
        edge = slope * (rho_c / s.contact_radius) * 0.5 * spacing  # half a node's spacing, deformed, as area
        rows.append((t, s.pressure_ratio - membrane.pressure_ratio, s.contact_area - membrane.contact_area, edge))
    return rows


@pytest.mark.slow
@pytest.mark.parametrize("radius", [0.4, 2.0])
@pytest.mark.parametrize("clamp_radius", [0.0, DEFAULT_CLAMP_RADIUS])
def test_the_solid_tends_to_the_membrane_under_a_sphere(radius, clamp_radius):
    """Limit: as T/R -> 0 the solid's P/P_I and contact area tend to the membrane's under the same sphere, the
    difference O(T/R) or smaller (fitted order between T = 0.01 and 0.02 printed). The bounds on the differences
    themselves were measured without the clamp's upper jaw; the jaw's edge (T/2) moves the sheet's hinge inwards
    by a fraction of T, a further O(T/R) difference of its own, so with it only the order is held."""
    (t1, dq1, da1, e1), (t2, dq2, da2, e2) = _against_membrane(radius, clamp_radius)
    q_order, a_order = np.log2(dq2 / dq1), np.log2(abs(da2 / da1))
    print(f"K = {radius}: P/P_I - membrane {dq1:.3e} (T/R {t1}), {dq2:.3e} (T/R {t2}), order {q_order:.2f}; "
          f"A_c - membrane {da1:.3e}, {da2:.3e} (edge resolution {e1:.1e}, {e2:.1e}), order {a_order:.2f}")
    # Measured (64 and 128 elements, T/R 0.01 to 0.04): |dq| / T from 0.023 to 0.061 at K = 0.4 (order ~1.5:
    # the first-order term is small there) and 0.078 to 0.096 at K = 2 (order ~1); the orders move by ~0.2
    # with the mesh (the contact edge). Bounds: the order between 0.7 and 2.2, |dq| <= 0.15 T.
    assert np.sign(dq1) == np.sign(dq2)
    assert 0.7 <= q_order <= 2.2
    if clamp_radius:
        return
    assert abs(dq1) <= 0.15 * t1
    assert abs(dq2) <= 0.15 * t2
    # The contact area's difference (|dA| / T measured up to 0.16) is of the size of the contact edge's own
    # resolution (the edge placed within about half a node, ``results``); so it is bounded by that plus the
    # first-order term, 0.1 T: its rate is not resolved at this mesh.
    assert abs(da1) <= 0.1 * t1 + e1
    assert abs(da2) <= 0.1 * t2 + e2


def test_the_command_line_presses_with_a_sphere(capsys):
    """``pocket compress --solver solid --indenter sphere --indenter-radius K`` solves and reports the sphere's
    states: the curved contact area is the cap's 2 K z(rho_c) of the reported rho_c, and the reaction the
    force asked."""
    from pocket.solid.contact import cap_area

    status = main(["compress", "--alpha", "47/160", "--pressure", "0.31", "--force", "0.3", "--solver", "solid",
                   "--thickness-ratio", "0.02", "--elements", "32", "--layers", "2", "--indenter", "sphere",
                   "--indenter-radius", "0.4"])
    out = dict(line.split()[:2] for line in capsys.readouterr().out.splitlines() if not line.startswith("#"))
    assert status == 0
    # the output's 10 significant digits
    assert float(out["contact_area"]) == pytest.approx(cap_area(0.4, float(out["contact_radius_deformed"])),
                                                       rel=1e-8)
    assert float(out["reaction"]) == pytest.approx(0.3, rel=1e-9)
    assert float(out["contact_area"]) != pytest.approx(float(out["contact_radius_deformed"]) ** 2, rel=1e-3)


@pytest.mark.parametrize("radius", [0.4, 2.0])
def test_the_cap_area_is_the_spheres_surface_integral(radius):
    """Exact answer: the curved contact area, int_0^rho_c 2 pi rho sqrt(1 + z'^2) d rho / (pi R^2) with the
    sphere's own slope (``Indenter.slope``), integrated by Gauss-Legendre (the integrand is smooth below the
    equator: 40 points reach round-off), is ``cap_area``; not the disc's rho_c^2."""
    from pocket.solid.contact import cap_area

    rho_c = 0.3 * radius
    x, w = np.polynomial.legendre.leggauss(40)
    rho = 0.5 * rho_c * (x + 1.0)
    integral = np.sum(0.5 * rho_c * w * 2.0 * rho * np.sqrt(1.0 + Sphere(radius).slope(rho) ** 2))
    assert cap_area(radius, rho_c) == pytest.approx(integral, rel=1e-13)  # 40-point Gauss: round-off
    assert abs(cap_area(radius, rho_c) - rho_c**2) > 1e-3 * rho_c**2


def test_a_contact_past_the_equator_is_out_of_range(pressed):
    """A contact edge at or beyond the sphere's radius has no cap: the state says so (OutOfRangeError), not a NaN
    area. Shown by reading the pressed state against a sphere smaller than its own contact edge."""
    from pocket.solid import results

    from pocket.core.errors import OutOfRangeError

    m, y, control = pressed
    material = MATERIAL.scaled()
    start = results.inflated(m, material, inflation.to_pressure(m, 3.0 * T * PHAT, TOL)[0], 0, pressure=PHAT)
    state = results.compressed(m, material, y, control.active, 0, start, LIQUID, surface=contact.Surface(Sphere(K)))
    assert state.contact_radius_deformed < K
    with pytest.raises(OutOfRangeError, match="equator"):
        results.compressed(m, material, y, control.active, 0, start, LIQUID,
                           surface=contact.Surface(Sphere(0.5 * state.contact_radius_deformed)))
