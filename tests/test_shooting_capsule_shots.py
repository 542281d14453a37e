"""The closed capsule's shots (``pocket.shooting.capsule``) piece by piece: the contact zone's pole series and the
zone started on it, the Jacobian shot column by column, and the profile read off the state's own shot."""

import math

import numpy as np
import pytest
from pocket.shooting import newton
from pocket.shooting.capsule import CapsuleProblem, _zone_series
from pocket.shooting.continuation import first_state
from pocket.shooting.equations import pole_state
from pocket.shooting.inflation import inflate
from pocket.shooting.integrator import OK, integrate
from pocket.shooting.laws import law_of
from pocket.shooting.shots import R_POLE

from pocket.core.materials import check

NEO = check("neo-hookean", {"mu": 1.0})
YEOH = check("yeoh", {"c10": 1.0, "c20": -0.05, "c30": 0.01})


def _problem(material, phat, rtol=1e-10):
    return CapsuleProblem(inflate(material, phat, geometry="capsule", rtol=rtol), rtol, law_of(material))


def _exact_zone(law, stretch, arc):
    """The zone's state at ``arc`` shot from R_POLE (the two-term series' error there O(1e-20)) at rtol 1e-15."""
    return integrate(pole_state(stretch, law, 0.0, R_POLE, sphere=True), R_POLE, law, 0.0, rtol=1e-15, atol=1e-18,
                     r_end=arc, sphere=True, slack=True)[2]


@pytest.mark.parametrize("material", [0.3, -0.3, NEO, YEOH])
@pytest.mark.parametrize("stretch", [0.9, 1.1, 1.5])
def test_the_zones_pole_series_is_of_sixth_order(material, stretch):
    """Exact answer: the zone shot from R_POLE. The series to O(S^4) in the stretches (``_zone_series``) leaves out
    O(S^6): its error, fitted over S = 0.08, 0.04, 0.02 (1e-9 to 1e-14, above the reference's 1e-15), falls with
    an order within 0.5 of 6."""
    law = law_of(material)
    arcs = np.array([0.08, 0.04, 0.02])
    errors = [np.max(np.abs(_zone_series(stretch, law.code, law.params, arc) - _exact_zone(law, stretch, arc)))
              for arc in arcs]
    order = np.polyfit(np.log(arcs), np.log(errors), 1)[0]
    assert abs(order - 6.0) < 0.5, (order, errors)


@pytest.mark.parametrize("material", [0.3, NEO, YEOH])
@pytest.mark.parametrize(("stretch", "arc"), [(1.1, 0.9), (1.3, 0.5), (0.95, 0.2), (1.2, 5e-3)])
def test_the_contact_zone_from_its_pole_series(material, stretch, arc):
    """Exact answer: the zone shot from R_POLE at rtol 1e-15. The zone started at zone_start = (zone rtol)^(1/6)
    leaves out the series' O(S_0^6) = zone rtol, and integrates to its tolerance: within 10 zone rtol (a global
    error a few times the local tolerance); an edge below S_0 is the series' own."""
    problem = _problem(material, 0.3)
    tol = problem.zone_tolerance.rtol
    assert problem.zone_start == pytest.approx(tol ** (1 / 6), rel=1e-15)
    status, edge, _ = problem._zone(stretch, arc, False)
    assert status == OK
    assert np.max(np.abs(edge - _exact_zone(problem.law, stretch, arc))) <= 10 * tol, edge


@pytest.mark.parametrize("material", [0.3, NEO, YEOH])
@pytest.mark.parametrize(("stretch", "arc", "ratio"), [(1.1, 0.9, 1.3), (1.3, 0.5, 1.1), (1.05, 5e-3, 1.0),
                                                       (1.2, 1.2, 2.0), (0.9, 0.7, 3.0)])
def test_the_compiled_shot_is_the_zone_then_the_free_part(material, stretch, arc, ratio):
    """Exact answer: the residual's compiled shot (``_compiled_shot``) makes the same calls of the integrator as
    ``_zone`` then ``_free``: the same status, edge and equator state, bit for bit (a shot that stops too)."""
    problem = _problem(material, 0.3)
    p = problem._pressure * ratio
    status, y, edge = problem._one_shot(stretch, arc, p)
    zone_status, zone_edge, _ = problem._zone(stretch, arc, False)
    assert np.array_equal(edge, zone_edge)
    if zone_status == OK:
        zone_status, zone_y, _, _ = problem._free(zone_edge, arc, p, np.empty((0, 3)), False)
        assert np.array_equal(y, zone_y)
    assert status == zone_status


@pytest.mark.parametrize(("material", "phat", "force"), [(0.2, 0.3, 1.0), (NEO, 0.35, 2.0)])
def test_the_jacobian_is_the_residuals_derivative(material, phat, force):
    """Exact answer: central differences of the residual with steps 1e-4 (truncation O(h^2) ~ 1e-8, the shots' noise
    of about residual_tol over h, 1e-8). The Jacobian shoots forward differences with steps 1e-7 (truncation ~ 1e-7,
    noise ~ 1e-12 / 1e-7 = 1e-5), column by column: within 1e-4 of each column's size."""
    problem = _problem(material, phat)
    _, x = first_state(problem, force)
    f = problem.residual(x, force)
    jac = problem.jacobian(x, force, f)
    for j, h in enumerate(1e-4 * np.maximum(np.abs(x), 1.0)):
        step = np.eye(x.size)[j] * h
        central = (problem.residual(x + step, force) - problem.residual(x - step, force)) / (2 * h)
        assert np.max(np.abs(jac[:, j] - central)) <= 1e-4 * np.max(np.abs(central)), (j, jac[:, j], central)


def test_segments_fall_back_to_the_residuals_differences():
    """Exact answer: with the free part in segments, the nodes' unknowns have no column of their own here: None,
    and Newton differences the residual (``newton.solve``'s ``derivative``)."""
    problem = _problem(0.0, 0.03)
    assert problem.segments > 1
    x = problem.start()
    assert problem.jacobian(x, 1e-3, problem.residual(x, 1e-3)) is None
    assert newton.difference_steps(x).shape == x.shape


def test_the_profile_is_the_states_shot():
    """Exact answer: the profile is read off the state's own shot (its dense output), so it ends where the state
    does, bit for bit at the equator's arc length, to rounding elsewhere; its contact zone has _N_CONTACT points
    equally spaced up to the edge, and its free part points at most PROFILE_STEP apart."""
    problem = _problem(0.2, 0.2)
    force, x = first_state(problem, 0.7)
    state, _ = problem.compressed(force, x, problem.fluid)
    profile = state.profile
    _, y, _, _, edge, _ = problem.shoot(x, force)
    assert profile.r[-1] == 0.5 * math.pi
    assert profile.rho[-1] == pytest.approx(y[0], rel=1e-14, abs=0)
    assert profile.eta[-1] == pytest.approx(0.0, abs=1e-14)
    contact = np.flatnonzero(profile.contact)
    assert contact.size == 65  # the pole and 64 points
    np.testing.assert_allclose(np.diff(profile.r[contact]), state.contact_radius / 64, rtol=1e-12)
    assert profile.rho[contact[-1]] == pytest.approx(edge[0], rel=1e-14)
    assert np.max(np.diff(profile.r[contact[-1]:])) <= 1 / 200 + 1e-15
