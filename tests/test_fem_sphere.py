"""The finite elements under a sphere (a fingertip): the edge-fitted contact wrapped on the surface.

Each test names its exact answer: mesh convergence at the elements' theoretical orders (the contact
edge a node, the zone exactly on the sphere), the flat plate as R_s -> infinity, the force as the
balance of the contact cap, as the integral of the contact pressure and as the virtual work of the
stored energy, Maxwell-Betti reciprocity at small force, and the ends of the model's range.
"""

import dataclasses

import numpy as np
import pytest
from pocket.fem import api, inflation, obstacle, results, wrapping
from pocket.fem.model import Control
from pocket.fem.newton import Tolerances

from pocket import fem
from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import check

ALPHA, PRESSURE = 47 / 160, 0.31
QUANTITIES = ("height", "pressure", "contact_area", "contact_radius")
YEOH = check("yeoh", {"c10": 0.5, "c20": -0.01, "c30": 0.002})
GAS = gas(5.0, 1.4)


def _order(sizes, errors):
    return np.polyfit(np.log(sizes), np.log(errors), 1)[0]


@pytest.mark.slow
@pytest.mark.parametrize(("order", "meshes", "reference", "least", "rubber", "fluid"), [
    # P2 on edge-fitted meshes: O(h^4) in the functionals (3.5 the bar); P1: O(h^2)
    (2, (8, 16, 32, 64, 128), 1024, 3.5, ALPHA, None),
    (2, (8, 16, 32, 64, 128), 1024, 3.5, YEOH, None),
    (2, (8, 16, 32, 64, 128), 1024, 3.5, ALPHA, GAS),
    (1, (16, 32, 64, 128), 2048, 1.8, ALPHA, None),
])
def test_edge_fitted_sphere_converges_at_full_order(order, meshes, reference, least, rubber, fluid):
    """Self-convergence against a very fine mesh (its own error, by the rate, below 1e-3 of the coarse
    meshes'): the order of the largest relative error over the quantities and three forces."""
    forces = [0.05, 0.19, 1.0]

    def curve(**mesh):
        return fem.compression_curve(rubber, PRESSURE, forces, fluid=fluid, indenter=Sphere(1.0), order=order, **mesh)

    ref = curve(elements=reference)
    errors = np.array([[[abs(getattr(s, q) / getattr(r, q) - 1) for q in QUANTITIES]
                        for s, r in zip(curve(elements=n), ref, strict=True)] for n in meshes])
    h = 1.0 / np.array(meshes)
    each = {(f, q): round(_order(h, errors[:, i, j]), 2)
            for i, f in enumerate(forces) for j, q in enumerate(QUANTITIES)}
    worst = _order(h, errors.max(axis=(1, 2)))
    print(f"P{order}: order of the largest error {worst:.3f}; each {each}")
    assert worst >= least, f"P{order} order {worst!r} < {least}: {each}"


def test_a_large_sphere_is_the_flat_plate_at_first_order():
    """R_s -> infinity: every quantity tends to the plate's, the difference O(R/R_s) (fitted rate printed)."""
    plate = fem.compress(ALPHA, PRESSURE, 0.19)
    radii = np.array([8.0, 16.0, 32.0, 64.0])
    diffs = np.array([[abs(getattr(fem.compress(ALPHA, PRESSURE, 0.19, indenter=Sphere(k)), q) / getattr(plate, q) - 1)
                       for q in QUANTITIES] for k in radii])
    rates = [_order(1.0 / radii, diffs[:, j]) for j in range(len(QUANTITIES))]
    print("rates in R/R_s:", dict(zip(QUANTITIES, np.round(rates, 3), strict=True)))
    assert all(0.9 < r < 1.1 for r in rates), rates


@pytest.mark.parametrize(("rubber", "fluid"), [(ALPHA, None), (YEOH, None), (ALPHA, GAS)])
def test_the_force_is_the_cap_balance_and_the_contact_pressure_integral(rubber, fluid):
    """F = P pi rho_c^2 + 2 pi rho_c T_1 sin(theta_c) (the cap as a free body) = int p_c dA (normal
    equilibrium, p_c = P + (T_1 + T_2)/R_s) = the reaction = the force asked; p_c > P."""
    for state in fem.compression_curve(rubber, PRESSURE, [0.05, 0.19, 1.0], fluid=fluid, indenter=Sphere(0.8)):
        x = state.extra
        # the integral is a quadrature of point tensions: its error O(h^4) ~ 1e-10 on the default mesh
        assert x["force_cap"] == pytest.approx(state.force, rel=1e-9)
        assert x["force_contact_pressure"] == pytest.approx(state.force, rel=1e-8)
        assert x["force_reaction"] == pytest.approx(state.force, rel=1e-9)
        assert x["contact_pressure_min"] > state.pressure
        assert state.contact_pressure_pole > state.contact_pressure_edge > state.pressure


@pytest.mark.slow
@pytest.mark.parametrize("fluid", [None, GAS])
def test_the_force_is_the_virtual_work_of_the_stored_energy(fluid):
    """F = (-dU + P dV)/dh along compress_height (U the stored elastic energy): central differences
    at h +- d, whose error O(d^2) falls 100-fold from d = 1e-3 to 1e-4 (measured 1.8e-5, 1.8e-7)."""
    state = fem.compress(ALPHA, PRESSURE, 0.19, fluid=fluid, indenter=Sphere(1.0))
    errors = []
    for d in (1e-3, 1e-4):
        up, down = (fem.compress_height(ALPHA, PRESSURE, state.height + s, fluid=fluid, indenter=Sphere(1.0))
                    for s in (d, -d))
        work = -(up.extra["energy"] - down.extra["energy"]) + 0.5 * (up.pressure + down.pressure) * (
            up.volume - down.volume)
        errors.append(abs(work / (2 * d) / (np.pi * PRESSURE) / state.force - 1))
    print("virtual work, relative error at d = 1e-3, 1e-4:", errors)
    assert errors[1] < 1e-6
    assert errors[1] < 0.05 * errors[0]


def _reciprocal(rubber, fluid) -> float:
    """pi (dH0/dP) / (dV0/dP + V/(gamma (P + P_atm))) of the inflated pocket: central differences in Phat."""
    d = 1e-5 * PRESSURE
    up, down = fem.inflate(rubber, PRESSURE + d), fem.inflate(rubber, PRESSURE - d)
    dv = (up.volume - down.volume) / (2 * d)
    if fluid is not None:
        dv += fem.inflate(rubber, PRESSURE).volume / (fluid.gamma * (PRESSURE + fluid.ambient))
    return np.pi * (up.height - down.height) / (2 * d) / dv


@pytest.mark.parametrize(("rubber", "fluid"), [(ALPHA, None), (YEOH, None), (ALPHA, GAS)])
def test_small_force_pressure_rise_is_reciprocal_for_sphere_and_plate(rubber, fluid):
    """(P/P_I - 1)/Fhat -> pi (dH0/dP)/(dV0/dP) (Maxwell-Betti; a gas adds its compliance), the same for the
    sphere as for the plate. The remainder falls about as Fhat^0.88 (measured with a liquid: 3.4e-4 and 4.5e-5
    of the limit at Fhat = 1e-4 and 1e-5 for the plate, 4.0e-4 and 5.2e-5 for a sphere of R_s = 0.8 R)."""
    limit = _reciprocal(rubber, fluid)
    for indenter in (None, Sphere(0.8)):
        rise = np.array([(s.pressure_ratio - 1) / s.force for s in
                         fem.compression_curve(rubber, PRESSURE, [1e-5, 1e-4], fluid=fluid, indenter=indenter)])
        gaps = np.abs(rise / limit - 1)
        rate = np.log10(gaps[1] / gaps[0])
        print(f"{indenter}: relative gaps {gaps} at Fhat = 1e-5, 1e-4 (rate {rate:.3f})")
        assert gaps[0] < 2e-4, (gaps, rate)
        assert rate > 0.6, (gaps, rate)


def test_every_returned_state_touches_without_penetration_and_pushes():
    """Along a curve to near the equator: no penetration (round-off), p_c >= 0, positive tensions."""
    for state in fem.compression_curve(ALPHA, 1.5, np.linspace(0.02, 0.24, 6), indenter=Sphere(0.1)):
        assert state.extra["penetration"] <= 1e-12
        assert state.extra["contact_pressure_min"] >= 0.0
        assert state.contact_radius_deformed < 0.1
        assert not state.wrinkled


@pytest.fixture(scope="module")
def solved():
    """(model, y, surface, fill) of a converged state under a sphere of radius R."""
    model = api._model(ALPHA, None, 64, 2, api.DEFAULT_PENALTY)
    tol = Tolerances(1e-10, 1e-10)
    y_i, _ = inflation.inflated_at(model, PRESSURE, tol)
    fill = Control(volume=results.inflated(model, y_i, 0, pressure=PRESSURE).volume, indenter=Sphere(1.0))
    y, _ = wrapping.first_contact(model, y_i, fill, 0.05, tol)
    return model, y, obstacle.surface(fill.indenter), fill


def test_newton_converges_quadratically(solved):
    """From a state at one force to another: the residual at least squares (times a modest constant)."""
    model, y, surf, fill = solved
    control = dataclasses.replace(fill, force=0.1, scale=0.1)
    out = fem.newton.newton(lambda z: obstacle.linearize(model, z, control, surf), y, Tolerances(1e-12, 1e-12),
                            obstacle._increment(model, surf), fem.steps.scales(model, y, "wrapped"))
    r = np.array(out.residuals)
    tail = r[(r < 1e-2) & (r > 1e-11)]
    print("residuals", r)
    assert tail.size >= 2
    assert np.all(tail[1:] <= 10 * tail[:-1] ** 2)


def test_a_state_touching_outside_the_zone_or_pulling_is_refused_by_name(solved):
    """The checks every returned state passes, failed on purpose: the free sheet lifted above the sphere,
    and a pressure so low that p_c < 0."""
    model, y, surf, _ = solved
    n = model.dofs
    lifted = y.copy()
    lifted[1:n:2] += 0.05 * np.exp(-((y[0:n:2] - y[2 * model.order * 16]) / 0.05) ** 2)  # a bump at the edge
    with pytest.raises(OutOfRangeError, match="touches the indenter outside the contact zone"):
        obstacle.check_range(model, obstacle.conform(model, lifted, surf), surf)
    pulled = y.copy()
    pulled[n] = -100.0
    with pytest.raises(OutOfRangeError, match="contact pressure turns negative"):
        obstacle.check_range(model, pulled, surf)


@pytest.mark.parametrize(("radius", "force", "words"), [
    (0.1, 20.0, "wraps past the indenter's equator"),
    (0.3, 5.0, "below the clamp plane"),
    (3.0, 30.0, "reaches the clamp plane"),
])
def test_the_end_of_the_range_is_out_of_range(radius, force, words):
    """Past the equator of a small sphere, the pole pressed to the clamp plane, the free sheet at the clamp
    plane under a wide sphere: each an OutOfRangeError naming it."""
    pressure = 1.5 if radius == 0.1 else PRESSURE
    with pytest.raises(OutOfRangeError, match=words):
        fem.compress(ALPHA, pressure, force, indenter=Sphere(radius))


def test_the_flat_plate_by_name_is_the_default_plate():
    """The plate through the indenter keyword is the default plate, bit for bit, by either method."""
    from pocket.core.indenters import PLATE
    for contact in ("fitted", "penalty"):
        assert fem.compress(ALPHA, PRESSURE, 0.19, indenter=PLATE, contact=contact).scalars() == \
            fem.compress(ALPHA, PRESSURE, 0.19, contact=contact).scalars()


def test_a_failed_solve_is_a_convergence_error_saying_where(monkeypatch):
    """A Newton that never converges (replaced by one that fails) is a ConvergenceError naming the force and
    the first contact, not an out-of-range answer."""
    def fails(*args, **kwargs):
        raise ConvergenceError("Newton failed after 25 iterations, residual 1e-3", iterations=25, residual=1e-3)

    monkeypatch.setattr(wrapping, "solve", fails)
    with pytest.raises(ConvergenceError, match=r"^compression at Fhat = 0.19: first contact with the sphere: "):
        fem.compress(ALPHA, PRESSURE, 0.19, indenter=Sphere(1.0))


@pytest.mark.slow
def test_the_penalty_sphere_tends_to_the_edge_fitted_one():
    """Penalty contact on a fixed mesh, gap measured vertically to the sphere: with the augmented Lagrangian
    within 1e-5 of the edge-fitted state in P and h (measured 3e-6 at most: the edge inside an element), the
    penetration below 1e-6, the force the reaction; the pure penalty's penetration falls as 1/kappa."""
    forces = [0.05, 0.19, 1.0]
    fitted = fem.compression_curve(ALPHA, PRESSURE, forces, indenter=Sphere(1.0))
    pen = fem.compression_curve(ALPHA, PRESSURE, forces, indenter=Sphere(1.0), contact="penalty")
    for f, p in zip(fitted, pen, strict=True):
        assert p.pressure == pytest.approx(f.pressure, rel=1e-5)
        assert p.height == pytest.approx(f.height, rel=1e-5)
        assert p.extra["penetration"] < 1e-6
        assert p.extra["force_reaction"] == pytest.approx(p.force, rel=1e-9)
    depth = [fem.compress(ALPHA, PRESSURE, 0.19, indenter=Sphere(1.0), contact="penalty", penalty=k,
                          augmented=False).extra["penetration"] for k in (1e4, 1e5)]
    print("pure-penalty penetration at kappa = 1e4, 1e5:", depth)
    assert 8.0 < depth[0] / depth[1] < 12.0


def test_the_contact_pressure_is_reported_as_the_shooting_solver_reports_it():
    """The state's own fields, as shooting's: contact_pressure at every profile node (NaN off the contact
    zone), its pole and edge values the scalars, P + (T_1 + T_2)/R_s there from the profile's tensions,
    its integral over the zone the force; the FE-only diagnostics stay in ``extra``."""
    from scipy.integrate import simpson

    from pocket.apps.contactpatch import contact_pressures

    radius = 0.8
    state = fem.compress(ALPHA, PRESSURE, 0.19, indenter=Sphere(radius))
    profile, pc = state.profile, state.contact_pressure
    on = profile.contact
    assert pc.shape == profile.r.shape
    assert np.all(np.isnan(pc[~on]))
    assert np.all(np.isfinite(pc[on]))
    assert pc[0] == state.contact_pressure_pole
    assert pc[on][-1] == state.contact_pressure_edge
    inner = on & (profile.r < state.contact_radius)  # the edge node's value is the one-sided edge value
    expected = state.pressure + (profile.tension_1[inner] + profile.tension_2[inner]) / radius
    assert pc[inner] == pytest.approx(expected, rel=1e-12)
    assert state.contact_radius_deformed == profile.rho[on][-1]
    force = simpson(2.0 * profile.rho[on] * pc[on], x=profile.rho[on]) / state.pressure_initial
    assert force == pytest.approx(state.force, rel=1e-4)  # Simpson on the nodes, O(h^4)
    scalars = state.scalars()
    for key in ("contact_radius_deformed", "contact_pressure_pole", "contact_pressure_edge"):
        assert key not in state.extra
        assert scalars[key] == getattr(state, key)
    assert contact_pressures(state) == {k: getattr(state, k) for k in ("contact_pressure_pole",
                                                                       "contact_pressure_edge")}
