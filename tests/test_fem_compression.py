"""Compression by the finite-element solver, against shooting and the identities of the exact solution.

Exact answers: the shooting solver (independent derivation, rtol 1e-12); the
fixed volume V_I; F = P A_c for a frictionless flat plate (the plate force equals
the fluid pressure times the deformed contact area, since the flat zone carries
exactly P); the flat, equibiaxial contact zone; height control and force control
reaching the same state; the uncompressed state at zero force; the penalty's
penetration ~ p_N / kappa.
"""

import re
import warnings

import numpy as np
import pytest

from pocket import fem, meshes, shooting
from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.states import CompressedState

KEYS = CompressedState.KEYS[3:]  # the solved-for scalars (alpha, Phat_I and Fhat are inputs)
ALPHA, P_I, FORCES = 47 / 160, 0.31, (0.05, 0.19, 0.5, 1.0, 9.4)


@pytest.fixture(scope="module")
def reference():
    return shooting.compression_curve(ALPHA, P_I, list(FORCES), rtol=1e-12)


@pytest.fixture(scope="module")
def default_curve():
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no warning of any kind (a singular matrix, a division by zero)
        return fem.compression_curve(ALPHA, P_I, list(FORCES))


def _diffs(state, ref):
    return {k: abs(getattr(state, k) / getattr(ref, k) - 1.0) for k in KEYS}


def test_default_mesh_matches_shooting(default_curve, reference):
    """Every scalar within 1e-9 relative of shooting at the default mesh, to 0.95 of the range end
    (which is 9.94 here)."""
    for state, ref in zip(default_curve, reference, strict=True):
        diffs = _diffs(state, ref)
        assert max(diffs.values()) < 1e-9, f"Fhat = {ref.force}: {diffs}"


def test_inputs_are_echoed_exactly():
    """alpha, Phat_I and Fhat come back as the very numbers given (0.1 stays 0.1)."""
    state = fem.compress(0.1, 0.3, 0.1, elements=16)
    assert (state.alpha, state.pressure_initial, state.force) == (0.1, 0.3, 0.1)
    assert state.inflated.pressure == 0.3


def test_volume_is_conserved(default_curve):
    """V = V_I for every compressed state (the constraint: to Newton tolerance, 1e-12)."""
    for state in default_curve:
        assert state.volume == pytest.approx(state.inflated.volume, rel=1e-12)


def test_force_is_pressure_times_contact_area(default_curve):
    """The plate reaction (the flux through the first free element) and P A_c (the pressure times
    the deformed area pi rho(a)^2) both equal the force to 1e-9 (the Newton tolerance on the plate's
    rows is 1e-10 of the force)."""
    for state in default_curve:
        assert state.extra["force_reaction"] == pytest.approx(state.force, rel=1e-9)
        assert state.extra["force_pressure_area"] == pytest.approx(state.force, rel=1e-9)
        assert state.contact_area == pytest.approx(state.force / state.pressure_ratio, rel=1e-9)


def test_plate_carries_the_fluid_pressure(default_curve):
    """In the flat zone the plate pressure equals P: the nodal reactions off the edge equal the
    consistent loads of P to 1e-12 of the largest."""
    for state in default_curve:
        assert state.extra["contact_pressure_error"] < 1e-12, state.extra["contact_pressure_error"]


def test_contact_zone_is_flat_and_equibiaxial(default_curve):
    """For r <= a: eta = H exactly and lambda_1 = lambda_2 = lambda_c (frictionless flat plate);
    the free part stays below the plate; the contact flag marks r <= a."""
    for state in default_curve:
        prof = state.profile
        inside = prof.r <= state.contact_radius
        assert prof.contact.tolist() == inside.tolist()
        assert inside.sum() == 3
        assert np.all(prof.eta[inside] == state.height)
        np.testing.assert_allclose(prof.rho[inside], state.stretch_contact * prof.r[inside], rtol=1e-13)
        assert prof.eta[~inside].max() < state.height
        assert state.extra["penetration"] == 0.0


def test_single_force_near_the_range_end():
    """One force at 0.97 of the range end, asked alone (before, a single-force FE compress refused
    it with exit 2 as an overshooting plate step left the model): it solves and agrees with shooting
    to 1e-8 at 128 elements (alpha = Phat_I = 0.3, range end 9.9)."""
    state = fem.compress(0.3, 0.3, 9.6, elements=128)
    ref = shooting.compress(0.3, 0.3, 9.6, rtol=1e-12)
    assert max(_diffs(state, ref).values()) < 1e-8, _diffs(state, ref)


def test_beyond_the_range_end_is_out_of_range():
    """Fhat = 12 is past the end of the range (alpha = Phat_I = 0.3): the free part comes down to the
    clamp plane, OutOfRangeError saying so in the shooting's words and where the range ends: between the
    last load converged and the one tried beyond it, both of which agree with the shooting solver's end
    to 1e-4 even on 16 elements (the end is where the tangent at the clamp turns horizontal, read from
    the clamp reaction)."""
    from pocket.apps.inverse import range_end

    end = range_end(shooting.SOLVER, 0.3, 0.3)
    with pytest.raises(OutOfRangeError, match="clamp plane") as info:
        fem.compress(0.3, 0.3, 12.0, elements=16)
    found = re.match(r"force = 12 is beyond the model's range, which ends at force = ([0-9.e+-]+) to ([0-9.e+-]+) "
                     r"\(.*\): there the free part of the sheet reaches the clamp plane", str(info.value))
    assert found, str(info.value)
    low, high = map(float, found.groups())
    assert low < high, (low, high, end)
    assert low == pytest.approx(end, rel=1e-4), (low, high, end)
    assert high == pytest.approx(end, rel=1e-4), (low, high, end)


def test_height_control_reaches_the_force_state():
    """Plate-height control at the height of a force-controlled state gives back that force and
    that state (same mesh: 1e-9)."""
    by_force = fem.compress(ALPHA, P_I, 0.19, elements=40)
    by_height = fem.compress_height(ALPHA, P_I, by_force.height, elements=40)
    assert by_height.force == pytest.approx(0.19, rel=1e-9)
    for key in ("pressure", "contact_radius", "stretch_contact"):
        assert getattr(by_height, key) == pytest.approx(getattr(by_force, key), rel=1e-9)


def test_zero_force_and_plate_at_the_top_give_the_inflated_state():
    """Fhat = 0 and the plate at the pole's height: no contact, the inflated numbers. A plate above the pole
    touches nothing: no compressed state (out of range, not the inflated state passed off as one)."""
    zero = fem.compress(ALPHA, P_I, 0.0, elements=20)
    top = fem.compress_height(ALPHA, P_I, zero.inflated.height, elements=20)
    for state in (zero, top):
        assert state.contact_radius == 0.0
        assert state.pressure_ratio == 1.0
        assert state.height == state.inflated.height
    with pytest.raises(OutOfRangeError, match="is above the inflated pocket"):
        fem.compress_height(ALPHA, P_I, 10.0, elements=20)


def test_progress_is_called_after_each_force():
    """progress(done, total) after each of the forces, in order."""
    calls = []
    fem.compression_curve(ALPHA, P_I, [0.0, 0.1, 0.2], elements=16, progress=lambda d, t: calls.append((d, t)))
    assert calls == [(1, 3), (2, 3), (3, 3)]


def test_penalty_penetration_scales_as_one_over_penalty():
    """Pure penalty on a fixed mesh: the pole penetration ~ P lambda_c^2 / kappa (slope -1 within
    0.05: the O(1/kappa^2) term), and its leading term to 1 %."""
    mesh = meshes.uniform(40)
    penalties = np.array([1e2, 1e3, 1e4])
    states = [fem.compress(ALPHA, P_I, 0.19, mesh=mesh, contact="penalty", penalty=k, augmented=False)
              for k in penalties]
    penetration = [s.extra["penetration_pole"] for s in states]
    slope = np.polyfit(np.log(penalties), np.log(penetration), 1)[0]
    assert abs(slope + 1) < 0.05, f"penetration order {slope:.3f}: {penetration}"
    s = states[-1]
    assert penetration[-1] == pytest.approx(s.pressure * s.stretch_contact**2 / 1e4, rel=1e-2)


def test_augmented_lagrangian_removes_the_pole_penetration():
    """Penalty with Uzawa updates: the pole sits on the plate (< 1e-9 R, against > 1e-6 R for the
    pure penalty), and the plate reaction equals the force (1e-9)."""
    mesh = meshes.uniform(40)
    plain = fem.compress(ALPHA, P_I, 0.19, mesh=mesh, contact="penalty", augmented=False)
    augmented = fem.compress(ALPHA, P_I, 0.19, mesh=mesh, contact="penalty")
    assert plain.extra["penetration_pole"] > 1e-6
    assert augmented.extra["penetration_pole"] < 1e-9
    assert augmented.extra["force_reaction"] == pytest.approx(0.19, rel=1e-9)


def test_penalty_and_fitted_agree_on_a_fine_mesh():
    """The unfitted penalty method converges to the same state as the fitted one: at 200 uniform P2
    elements they differ by less than 1e-5 in every scalar (the penalty's edge-element error)."""
    fitted = fem.compress(ALPHA, P_I, 0.19, elements=64)
    unfitted = fem.compress(ALPHA, P_I, 0.19, mesh=meshes.uniform(200), contact="penalty")
    assert max(_diffs(unfitted, fitted).values()) < 1e-5, _diffs(unfitted, fitted)


@pytest.mark.parametrize("contact", ["fitted", "penalty"])
def test_first_contact_at_a_small_force_is_quiet(contact):
    """Fhat = 0.0027, where the fixed-mesh Newton used to meet a singular matrix (scipy's
    MatrixRankWarning): no warning of any kind, and the state agrees with shooting (1e-6; the penalty
    method's edge element limits it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        state = fem.compress(0.3, 0.3, 0.0027, elements=64, contact=contact)
    ref = shooting.compress(0.3, 0.3, 0.0027)
    assert max(_diffs(state, ref).values()) < 1e-6, _diffs(state, ref)


def test_a_state_failing_its_own_check_is_not_returned():
    """An inflated unknown vector whose meridian crosses the axis (rho < 0 at vertex 2: a negative hoop
    stretch) given to the state builder is a ConvergenceError naming the check, never a state."""
    from pocket.fem import inflation, model, results
    from pocket.fem.newton import Tolerances

    m = model.discretize(0.3, fem.default_mesh(8), 2, 1e5)
    y, _ = inflation.to_pressure(m, 0.3, Tolerances())
    y = y.copy()
    y[8] = -0.01  # rho at node 4, vertex 2
    with pytest.raises(ConvergenceError, match="fails its own check: a stretch"):
        results.inflated(m, y, 1, pressure=0.3)


def test_a_force_maximum_ends_the_range():
    """alpha = -0.42, Phat_I = 0.173: the plate force has a maximum (a limit point) before the free part
    reaches the clamp plane; a larger force is OutOfRangeError naming the maximum, which agrees with
    the end of the shooting solver's range (bisected to 1e-5) to 1e-4."""
    from pocket.apps.inverse import range_end

    alpha, pressure = -0.42, 0.173
    end = range_end(shooting.SOLVER, alpha, pressure)
    with pytest.raises(OutOfRangeError, match="has a maximum") as info:
        fem.compress(alpha, pressure, 2 * end, elements=64)
    peak = float(re.search(r"force = ([0-9.e+-]+), before", str(info.value)).group(1))
    assert peak == pytest.approx(end, rel=1e-4), (peak, end)
