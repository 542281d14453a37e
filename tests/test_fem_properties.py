"""Property-based tests of the finite-element solver over the parameter space (hypothesis).

Exact answers: whatever alpha in (-0.9, 5), Phat_I in (1e-4, 2) and Fhat in (0, 50), a call either
returns a state that satisfies the identities of the exact solution (the echoed inputs, finite
numbers, positive stretches, rho(1) = 1, V = V_I, F = P A_c with A_c = pi rho(a)^2, 0 < a < 1, a
pressure that has risen and a plate below the inflated pole) or raises one of the named errors
(a state outside the model, a failed solve), never anything else. A coarse mesh (24 P2 elements)
keeps each example to a fraction of a second; the identities hold on any mesh.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from pocket import fem
from pocket.core.errors import ConvergenceError, OutOfRangeError

alphas = st.floats(min_value=-0.9, max_value=5.0, exclude_min=True, exclude_max=True)
pressures = st.floats(min_value=1e-4, max_value=2.0, exclude_min=True, exclude_max=True)
forces = st.floats(min_value=0.0, max_value=50.0, exclude_min=True, exclude_max=True)
ELEMENTS = 24


def _common(state):
    numbers = [v for v in state.scalars().values() if isinstance(v, float)]
    assert np.all(np.isfinite(numbers)), state.scalars()
    prof = state.profile
    assert prof.stretch_1.min() > 0 and prof.stretch_2.min() > 0
    assert prof.rho[-1] == 1.0 and prof.stretch_2[-1] == 1.0 and prof.eta[-1] == 0.0


@settings(max_examples=25, deadline=None)
@given(alphas, pressures)
def test_inflation_returns_a_consistent_state_or_a_named_error(alpha, pressure):
    """An inflated state with the given alpha and Phat, a positive height and volume and a pole
    stretch above 1, or OutOfRangeError (above the first branch's maximum) or ConvergenceError."""
    try:
        state = fem.inflate(alpha, pressure, elements=ELEMENTS)
    except (OutOfRangeError, ConvergenceError):
        return
    assert (state.alpha, state.pressure) == (alpha, pressure)
    _common(state)
    assert state.height > 0 and state.volume > 0 and state.stretch_pole > 1


@settings(max_examples=40, deadline=None)
@given(alphas, pressures, forces)
def test_compression_returns_a_consistent_state_or_a_named_error(alpha, pressure, force):
    """A compressed state with its invariants (module docstring) to 1e-9, or OutOfRangeError (past the
    range end, or no inflated state) or ConvergenceError."""
    try:
        state = fem.compress(alpha, pressure, force, elements=ELEMENTS)
    except (OutOfRangeError, ConvergenceError):
        return
    assert (state.alpha, state.pressure_initial, state.force) == (alpha, pressure, force)
    _common(state)
    assert abs(state.volume / state.inflated.volume - 1) < 1e-9
    assert abs(state.extra["force_pressure_area"] - force) <= 1e-9 * force + 1e-12
    assert abs(state.extra["force_reaction"] - force) <= 1e-9 * force + 1e-12
    assert 0 < state.contact_radius < 1 and state.pressure_ratio >= 1 - 1e-12
    assert 0 < state.height < state.inflated.height
