"""Property-based tests (hypothesis) of the shooting solver and the analytical model over the parameter space.

alpha in (-0.9, 5), Phat_I in (1e-4, 2) (log-uniform), Fhat in [0, 50]: every call returns a state
that satisfies its invariants, or raises one of the named errors (InputError, OutOfRangeError,
ConvergenceError), never anything else. Many draws are outside the model (above a pressure
maximum for alpha <= 0, past the range end): those must be OutOfRangeErrors, and a compressed
state must lie inside the range (Fhat <= range_end). The deadline only guards against a hang
(speed is measured in benchmarks/).
"""

import datetime
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from pocket import analytical, shooting
from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError

NAMED = (InputError, OutOfRangeError, ConvergenceError)
alphas = st.floats(-0.9, 5.0)
pressures = st.floats(-4.0, math.log10(2.0)).map(lambda e: 10.0**e)
forces = st.one_of(st.just(0.0), st.floats(0.0, 50.0))
def guarded(examples):
    """hypothesis settings: ``examples`` draws, a deadline that only catches a hang."""
    return settings(max_examples=examples, deadline=datetime.timedelta(seconds=120),
                    suppress_health_check=[HealthCheck.too_slow])


def _finite(state):
    scalars = [getattr(state, k) for k in state.KEYS]
    profile = state.profile
    return all(np.isfinite(scalars)) and all(np.all(np.isfinite(getattr(profile, f)))
                                              for f in ("r", "rho", "eta", "stretch_1", "stretch_2"))


def _inflated_invariants(state, alpha, pressure, solver):
    assert (state.alpha, state.pressure) == (alpha, pressure) and state.solver == solver
    assert _finite(state) and state.height > 0 and state.volume > 0
    assert np.all(state.profile.stretch_1 > 0) and np.all(state.profile.stretch_2 > 0)
    assert state.profile.stretch_2[-1] == pytest.approx(1.0, abs=1e-7)  # lambda_2(1) = 1 (the clamp)


def _compressed_invariants(state, alpha, pressure, force, solver, volume_rtol):
    assert (state.alpha, state.pressure_initial, state.force) == (alpha, pressure, force)
    assert _finite(state) and state.stretch_contact > 0 and state.height > 0
    assert np.all(state.profile.stretch_1 > 0) and np.all(state.profile.stretch_2 > 0)
    assert state.volume == pytest.approx(state.inflated.volume, rel=volume_rtol)  # V = V_I
    assert state.pressure_ratio * state.contact_area == pytest.approx(force, rel=1e-12, abs=1e-300)  # F = P A_c
    if solver == "shooting":
        assert state.profile.stretch_2[-1] == pytest.approx(1.0, abs=1e-7)


@guarded(60)
@given(alpha=alphas, pressure=pressures)
def test_shooting_inflation(alpha, pressure):
    """Exact answers: the invariants above, or OutOfRangeError (pressure above the first-branch maximum)."""
    try:
        state = shooting.inflate(alpha, pressure)
    except OutOfRangeError:
        event("no inflated state")
        return
    event("an inflated state")
    _inflated_invariants(state, alpha, pressure, "shooting")


@guarded(100)
@given(alpha=alphas, pressure=pressures, force=forces)
def test_shooting_compression(alpha, pressure, force):
    """Exact answers: V = V_I, F = P A_c, lambda_2(1) = 1, inputs echoed, Fhat <= range_end; or a
    named error, an OutOfRangeError only for a force past the end (or no inflated state)."""
    try:
        state = shooting.compress(alpha, pressure, force)
    except OutOfRangeError as err:
        beyond = "beyond the model's range" in str(err)
        event("past the range end" if beyond else "no inflated state")
        if beyond:
            assert force > shooting.range_end(alpha, pressure)
        return
    except ConvergenceError:
        event("ConvergenceError")
        return  # allowed: a failure that says where (none seen in the runs made)
    event("a compressed state")
    _compressed_invariants(state, alpha, pressure, force, "shooting", 1e-9)
    if force > 0:
        assert force <= shooting.range_end(alpha, pressure)


@guarded(100)
@given(alpha=alphas, pressure=pressures, force=forces)
def test_analytical_model(alpha, pressure, force):
    """Exact answers: V = V_I, F = P A_c, inputs echoed, a warning exactly when a stretch passes 1.1;
    or OutOfRangeError past its range end (the contact reaching the clamp)."""
    try:
        state = analytical.compress(alpha, pressure, force)
    except OutOfRangeError:
        assert force > analytical.range_end(alpha, pressure)
        return
    _compressed_invariants(state, alpha, pressure, force, "analytical", 1e-12)
    stretches = [state.inflated.stretch_pole] + ([state.stretch_contact] if force > 0 else [])
    assert (len(state.warnings) > 0) == (max(stretches) > analytical.model.STRETCH_LIMIT)


bad = st.one_of(st.just(math.nan), st.just(math.inf), st.just(-math.inf), st.just("soft"), st.none())


@settings(max_examples=40, deadline=None)
@given(alpha=st.one_of(bad, st.floats(max_value=-1.0)), pressure=st.one_of(bad, st.floats(max_value=0.0)),
       force=st.one_of(bad, st.floats(max_value=-1e-300)), which=st.integers(0, 2))
def test_bad_input_is_an_input_error(alpha, pressure, force, which):
    """Exact answer: an invalid alpha (<= -1), pressure (<= 0) or force (< 0), or a non-number, is an
    InputError before any work, for both solvers."""
    args = [0.3, 0.2, 0.1]
    args[which] = (alpha, pressure, force)[which]
    for solver in (shooting, analytical):
        with pytest.raises(InputError):
            solver.compress(*args)
