"""Compression by the finite-element solver, against shooting and conservation laws.

Exact answers: the shooting solver (independent derivation, rtol 1e-10); the
fixed volume V_I; F = P A_c for a frictionless flat plate; the penalty's
penetration ~ p_N / kappa; force control and height control reaching the same
state.
"""

import numpy as np
import pytest

from pocket import fem, meshes, shooting
from pocket.core.errors import OutOfRangeError
from pocket.core.states import CompressedState

KEYS = CompressedState.KEYS[3:]  # the solved-for scalars (alpha, Phat_I and Fhat are inputs)
ALPHA, P_I, FORCES = 47 / 160, 0.31, (0.05, 0.19, 0.5)


@pytest.fixture(scope="module")
def reference():
    return shooting.compression_curve(ALPHA, P_I, list(FORCES))


@pytest.fixture(scope="module")
def default_curve():
    return fem.compression_curve(ALPHA, P_I, list(FORCES))


def _diffs(state, ref):
    return {k: abs(getattr(state, k) / getattr(ref, k) - 1.0) for k in KEYS}


def test_default_mesh_matches_shooting(default_curve, reference):
    """Every scalar within 1e-5 relative of shooting at the default mesh (issue 3)."""
    for state, ref in zip(default_curve, reference, strict=True):
        diffs = _diffs(state, ref)
        assert max(diffs.values()) < 1e-5, f"Fhat = {ref.force}: {diffs}"


@pytest.mark.parametrize("index", range(len(FORCES)))
def test_refined_mesh_matches_shooting(reference, index):
    """Within 1e-6 relative on a mesh refined 8x around the contact edge (issue 3)."""
    ref = reference[index]
    mesh = meshes.refined(200, at=ref.contact_radius)
    diffs = _diffs(fem.compress(ALPHA, P_I, ref.force, mesh=mesh), ref)
    assert max(diffs.values()) < 1e-6, f"Fhat = {ref.force}: {diffs}"


def test_volume_is_conserved(default_curve, reference):
    """V = V_I for every compressed state (the constraint: to Newton tolerance)."""
    for state in default_curve:
        assert state.volume == pytest.approx(state.inflated.volume, rel=1e-10)


def test_force_is_pressure_times_contact_area(default_curve):
    """F = P A_c, with A_c measured independently as the deformed area of the active
    contact set (force_pressure_area). The edge is resolved to a quadrature point, so
    the agreement is O(h): 1 % at the default mesh."""
    for state in default_curve:
        assert state.extra["force_reaction"] == pytest.approx(state.force, rel=1e-9)
        assert state.extra["force_pressure_area"] == pytest.approx(state.force, rel=1e-2)
        assert state.extra["force_difference"] == pytest.approx(
            state.extra["force_reaction"] - state.extra["force_pressure_area"])


def test_contact_profile_is_flat_and_equibiaxial(default_curve):
    """In the contact zone eta = H and lambda_1 = lambda_2 = lambda_c (frictionless
    flat plate); the nodal contact flag marks r <= a_c. Tolerance 1e-6: the Uzawa
    loop stops once P and h settle to 1e-7, leaving ~1e-7 R near the edge."""
    state = default_curve[1]
    prof = state.profile
    inner = prof.r < 0.9 * state.contact_radius
    assert prof.contact[inner].all() and not prof.contact[prof.r > 1.1 * state.contact_radius].any()
    np.testing.assert_allclose(prof.eta[inner], state.height, rtol=1e-6)
    np.testing.assert_allclose(prof.stretch_2[inner], state.stretch_contact, rtol=1e-6)
    np.testing.assert_allclose(prof.stretch_1[inner], state.stretch_contact, rtol=1e-6)


def test_penalty_penetration_scales_as_one_over_penalty():
    """Pure penalty: the pole penetration ~ P lambda_c^2 / kappa, fitted slope -1 (0.05:
    the O(1/kappa^2) term). The height error against the augmented-Lagrangian state on
    the same mesh is bounded by that penetration and falls about as 1/kappa (0.3: the
    penalty also shifts the contact edge, whose discretization error then enters)."""
    mesh = meshes.uniform(40)
    exact = fem.compress(ALPHA, P_I, 0.19, mesh=mesh)
    penalties = np.array([1e2, 1e3, 1e4])
    states = [fem.compress(ALPHA, P_I, 0.19, mesh=mesh, penalty=k, augmented=False) for k in penalties]
    penetration = [s.extra["penetration_pole"] for s in states]
    height_error = [abs(s.height - exact.height) for s in states]
    slope_pen = np.polyfit(np.log(penalties), np.log(penetration), 1)[0]
    slope_h = np.polyfit(np.log(penalties), np.log(height_error), 1)[0]
    assert abs(slope_pen + 1) < 0.05, f"penetration order {slope_pen:.3f}: {penetration}"
    assert abs(slope_h + 1) < 0.3, f"height error order {slope_h:.3f}: {height_error}"
    assert np.all(np.array(height_error) <= np.array(penetration))
    # the leading term: p_N = P lambda_c^2 per reference area (1 %: O(1/kappa^2))
    s = states[-1]
    assert penetration[-1] == pytest.approx(s.pressure * s.stretch_contact**2 / 1e4, rel=1e-2)


def test_augmented_lagrangian_removes_penetration():
    """With Uzawa updates the pole sits on the plate (< 1e-9 R, the loop's target,
    against ~5e-6 R for the pure penalty) and the largest penetration, left in the
    element holding the contact edge, is 10x below the pure penalty's."""
    mesh = meshes.uniform(40)
    plain = fem.compress(ALPHA, P_I, 0.19, mesh=mesh, augmented=False)
    augmented = fem.compress(ALPHA, P_I, 0.19, mesh=mesh)
    assert plain.extra["penetration_pole"] > 1e-6
    assert augmented.extra["penetration_pole"] < 1e-9
    assert augmented.extra["penetration"] < 0.1 * plain.extra["penetration"]


def test_free_part_below_clamp_plane_is_out_of_range():
    """Pressing the plate down to H/R = 0.15 makes the bulging free part dip below
    the clamp plane (eta < 0): outside the model, OutOfRangeError (DESIGN.md)."""
    with pytest.raises(OutOfRangeError, match="clamp plane"):
        fem.compress_height(ALPHA, P_I, 0.15, mesh=meshes.uniform(60))


def test_height_control_reaches_the_force_state():
    """Plate-height control at the height of a force-controlled state gives back that
    force (same mesh: 1e-6, the Uzawa settling tolerance)."""
    mesh = meshes.uniform(60)
    by_force = fem.compress(ALPHA, P_I, 0.19, mesh=mesh)
    by_height = fem.compress_height(ALPHA, P_I, by_force.height, mesh=mesh)
    assert by_height.force == pytest.approx(0.19, rel=1e-6)
    assert by_height.pressure == pytest.approx(by_force.pressure, rel=1e-6)


def test_zero_force_and_plate_above_give_the_inflated_state():
    """Fhat = 0 and a plate above the pole: no contact, the inflated numbers."""
    mesh = meshes.uniform(20)
    zero = fem.compress(ALPHA, P_I, 0.0, mesh=mesh)
    above = fem.compress_height(ALPHA, P_I, 10.0, mesh=mesh)
    for state in (zero, above):
        assert state.contact_radius == 0.0 and state.pressure_ratio == 1.0
        assert state.height == state.inflated.height
