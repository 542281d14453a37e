"""What every shooting state carries: its inputs exactly as given, and progress reports for curves."""

import numpy as np
import pytest

from pocket import shooting

# Inputs whose recomputation in floating point does not round-trip: 3 (1 + 1.2) 0.1 / (3 (1 + 1.2))
# is 0.10000000000000002, and so on.
ECHOED = [(1.2, 0.1), (0.3, 0.05), (47 / 160, 0.31), (5.0, 0.2), (0.7, 0.32), (-0.3, 0.13)]


@pytest.mark.parametrize("alpha, pressure", ECHOED)
def test_inflated_state_echoes_its_inputs(alpha, pressure):
    """Exact answer: alpha and pressure are the floats given (a sweep keys its rows on them)."""
    state = shooting.inflate(alpha, pressure)
    assert (state.alpha, state.pressure) == (alpha, pressure)


@pytest.mark.parametrize("alpha, pressure", ECHOED)
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
    assert state.profile is not None and state.alpha == 0.3


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
    assert [d for d, _ in calls] == sorted(d for d, _ in calls) and {t for _, t in calls} == {5}
    assert len(calls) == 4  # one call per distinct force
