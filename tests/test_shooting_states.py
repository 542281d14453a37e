"""What every shooting state carries: its inputs exactly as given, and progress reports for curves."""

import numpy as np
import pytest

from pocket import shooting

# Inputs whose recomputation in floating point does not round-trip: 3 (1 + 1.2) 0.1 / (3 (1 + 1.2))
# is 0.10000000000000002, and so on.
ECHOED = [(1.2, 0.1), (0.3, 0.05), (47 / 160, 0.31), (5.0, 0.2), (0.7, 0.32), (-0.3, 0.13)]


@pytest.mark.parametrize(("alpha", "pressure"), ECHOED)
def test_inflated_state_echoes_its_inputs(alpha, pressure):
    """Exact answer: alpha and pressure are the floats given (a sweep keys its rows on them)."""
    state = shooting.inflate(alpha, pressure)
    assert (state.alpha, state.pressure) == (alpha, pressure)


@pytest.mark.parametrize(("alpha", "pressure"), ECHOED)
def test_compressed_states_echo_their_inputs(alpha, pressure):
    """Exact answer: alpha, pressure_initial and force are the floats given, in every state of a curve,
    and the inflated state inside echoes alpha and pressure too."""
    forces = [0.05, 0.1, 0.0, 0.2, 0.05]
    for force, state in zip(forces, shooting.compression_curve(alpha, pressure, forces), strict=True):
        assert (state.alpha, state.pressure_initial, state.force) == (alpha, pressure, force)
        assert (state.inflated.alpha, state.inflated.pressure) == (alpha, pressure)


def test_volume_control_echoes_the_volume():
    """Exact answer: the volume asked; the volume of the solved state agrees to the root tolerance."""
    target = shooting.inflate(0.3, 0.1).volume * 1.1
    state = shooting.inflate_volume(0.3, target)
    assert state.volume == target
    assert state.profile is not None
    assert state.alpha == 0.3


def test_numpy_and_integer_inputs_are_echoed_as_floats():
    """Exact answer: float(x) of what was given (the input check turns numbers into floats)."""
    state = shooting.compress(np.float32(0.5), 1, np.int64(1))
    assert (state.alpha, state.pressure_initial, state.force) == (float(np.float32(0.5)), 1.0, 1.0)
    assert all(type(v) is float for v in (state.alpha, state.pressure_initial, state.force))


def test_progress_is_called_after_each_force():
    """Exact answer: progress(done, total) with done = 1..len(forces) (repeats counted), total = len(forces)."""
    calls = []
    forces = [0.3, 0.1, 0.0, 0.1, 0.2]
    shooting.compression_curve(0.3, 0.2, forces, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (5, 5)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)
    assert {t for _, t in calls} == {5}
    assert len(calls) == 4  # one call per distinct force


@pytest.mark.parametrize("rubber", [0.3, 5.0])
def test_smallest_tensions_are_refined_between_steps(rubber):
    """Exact answer: at a large force T_1 has an interior minimum (near r = 0.93); the state's tension_1_min
    equals the minimum over the same free part integrated with steps of at most 1e-5 (independent
    sampling: 1e-9 relative), and lies at or below the profile's sampled minimum."""
    from pocket.shooting.laws import law_of
    from pocket.shooting.plate import PlateProblem
    from pocket.shooting.tensions import tensions

    state = shooting.compress(rubber, 0.31, 3.0)
    law = law_of(rubber)
    problem = PlateProblem(state.inflated, 1e-10, law)
    x = [state.pressure_ratio, (state.stretch_contact - 1) / problem.strain]
    _, lc, a, p = problem.geometry(x, state.force)
    from pocket.shooting.integrator import OK, integrate
    from pocket.shooting.shots import edge_state

    status, _, _, steps = integrate(edge_state(lc, a), a, law, p, rtol=1e-10, store=200000, max_step=1e-5,
                                    psi_max=4.0)
    assert status == OK
    fine = tensions(steps[:, 4], steps[:, 1] / steps[:, 0], law.code, law.params)[0] * law.tension_scale
    assert state.tension_1_min == pytest.approx(np.min(fine), rel=1e-9)
    assert state.tension_1_min <= np.min(state.profile.tension_1)
    assert 0.05 < state.profile.r[np.argmin(state.profile.tension_1)] < 0.999  # interior, as stated


def test_a_slack_shot_is_a_status_not_a_state():
    """Exact answer: for alpha = -0.5 the equibiaxial tension (1 - l^-6)(1 + alpha l^2) vanishes at
    l^2 = 2; a shot from a contact edge at lambda_c = 1.5 stops with SLACK (finite numbers, no NaN) and
    the compression residual there is undefined (None: outside the model's domain)."""
    from pocket.shooting.integrator import SLACK, integrate
    from pocket.shooting.laws import law_of
    from pocket.shooting.plate import PlateProblem
    from pocket.shooting.shots import edge_state

    status, r, y, _ = integrate(edge_state(1.5, 0.3), 0.3, law_of(-0.5), 0.3, rtol=1e-10)
    assert status == SLACK
    assert r < 1.0
    assert np.all(np.isfinite(y))
    problem = PlateProblem(shooting.inflate(-0.5, 0.1), 1e-10, law_of(-0.5))
    assert problem.residual(np.array([1.0, (1.5 - 1) / problem.strain]), 0.01) is None
    assert "tension vanished" in problem.failure()
