"""Property-based tests of the finite-element solver over the parameter space (hypothesis).

Exact answers: whatever alpha in (-0.9, 5), Phat_I in (1e-4, 2) and Fhat in (0, 50), a call either
returns a state that satisfies the identities of the exact solution (the echoed inputs, finite
numbers, positive stretches, V = V_I, F = P A_c with A_c = pi rho(a)^2, 0 < a < 1, a pressure that
has risen and a plate below the inflated pole) or raises one of the named errors (a state outside the
model, a failed solve), never anything else, and only where the shooting solver has no state either
(an OutOfRangeError where it too says out of range); and the same over every rubber
law (stresses in any unit) and fluid (a liquid, or a gas with Phat_atm in (1e-2, 1e3) and gamma in
[1, 5/3]: then the polytropic law replaces V = V_I). A coarse mesh (24 P2 elements) keeps each example
to a fraction of a second; the identities hold on any mesh.
"""

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from pocket.fem import fitted

from pocket import fem, shooting
from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.fluids import LIQUID, gas
from pocket.core.materials import check, mooney_rivlin

alphas = st.floats(min_value=-0.9, max_value=5.0, exclude_min=True, exclude_max=True)
pressures = st.floats(min_value=1e-4, max_value=2.0, exclude_min=True, exclude_max=True)
forces = st.floats(min_value=0.0, max_value=50.0, exclude_min=True, exclude_max=True)
ELEMENTS = 24


def _common(state):
    numbers = [v for v in state.scalars().values() if isinstance(v, float)]
    assert np.all(np.isfinite(numbers)), state.scalars()
    prof = state.profile
    assert prof.stretch_1.min() > 0
    assert prof.stretch_2.min() > 0


def _confirmed(refusal, solve, *args, **kwargs) -> None:
    """Assert that the shooting solver ``solve`` has no state either: an OutOfRangeError for an FE
    OutOfRangeError (the model has none), any named refusal for an FE ConvergenceError."""
    expected = OutOfRangeError if isinstance(refusal, OutOfRangeError) else (OutOfRangeError, ConvergenceError)
    try:
        solve(*args, **kwargs)
    except expected:
        return
    raise AssertionError(f"the FE refused what the shooting solver solves: {refusal!r}")


def _confirmed_compression(refusal, material, pressure, force, fluid=None) -> None:
    """``_confirmed`` for ``fem.compress``, where a force below the edge-fitted FE's documented floor
    (``fitted.SMALLEST_FORCE``: the plate's balance would be lost in round-off) is a ConvergenceError."""
    if isinstance(refusal, ConvergenceError) and force < fitted.SMALLEST_FORCE:
        return
    _confirmed(refusal, shooting.compress, material, pressure, force, fluid=fluid)


@settings(max_examples=25, deadline=None)
@given(alphas, pressures)
@example(0.125, 1.5)  # no pressure maximum, V/R^3 = 254: once refused as "not reached on the first branch"
def test_inflation_returns_a_consistent_state_or_a_named_error(alpha, pressure):
    """An inflated state with the given alpha and Phat, a positive height and volume and a pole
    stretch above 1, or OutOfRangeError (above the first branch's maximum) or ConvergenceError, where
    the shooting solver has no state either."""
    try:
        state = fem.inflate(alpha, pressure, elements=ELEMENTS)
    except (OutOfRangeError, ConvergenceError) as err:
        _confirmed(err, shooting.inflate, alpha, pressure)
        return
    assert (state.alpha, state.pressure) == (alpha, pressure)
    _common(state)
    assert state.height > 0
    assert state.volume > 0
    assert state.stretch_pole > 1


@pytest.mark.slow
@settings(max_examples=40, deadline=None)
@given(alphas, pressures, forces)
def test_compression_returns_a_consistent_state_or_a_named_error(alpha, pressure, force):
    """A compressed state with its invariants (module docstring) to 1e-9, or OutOfRangeError (past the
    range end, or no inflated state) or ConvergenceError, where the shooting solver has no state either
    (or below the FE's smallest force)."""
    try:
        state = fem.compress(alpha, pressure, force, elements=ELEMENTS)
    except (OutOfRangeError, ConvergenceError) as err:
        _confirmed_compression(err, alpha, pressure, force)
        return
    assert (state.alpha, state.pressure_initial, state.force) == (alpha, pressure, force)
    _common(state)
    assert abs(state.volume / state.inflated.volume - 1) < 1e-9
    assert abs(state.extra["force_pressure_area"] - force) <= 1e-9 * force + 1e-12
    assert abs(state.extra["force_reaction"] - force) <= 1e-9 * force + 1e-12
    assert 0 < state.contact_radius < 1
    assert state.pressure_ratio >= 1 - 1e-12
    assert 0 < state.height < state.inflated.height


def _ogden(terms):
    """An Ogden rubber from (mu_p magnitude, alpha_p) pairs; each mu_p takes its exponent's sign (stable)."""
    return check("ogden", {"mu": [math.copysign(m, a) for m, a in terms], "exponents": [a for _, a in terms]})


exponents = st.one_of(st.floats(-6.0, -0.5), st.floats(0.5, 6.0))
materials = st.one_of(
    alphas,
    st.builds(lambda mu: check("neo-hookean", {"mu": mu}), st.floats(1e-3, 1e7)),
    st.builds(lambda c10, c20, c30: check("yeoh", {"c10": c10, "c20": c20 * c10, "c30": c30 * c10}),
              st.floats(1e-3, 1e6), st.floats(0.0, 0.5), st.floats(0.0, 0.1)),
    st.builds(lambda mu, jm: check("gent", {"mu": mu, "jm": jm}), st.floats(1e-3, 1e6), st.floats(0.3, 100.0)),
    st.builds(_ogden, st.lists(st.tuples(st.floats(1e-2, 10.0), exponents), min_size=1, max_size=3)),
)
fluids = st.one_of(st.none(), st.builds(gas, st.floats(1e-2, 1e3), st.floats(1.0, 5.0 / 3.0)))
#: loads where most pockets have a state (below neo-Hookean's pressure maximum 0.626, forces short of most
#: range ends), so that the examples test states rather than errors
moderate_pressures = st.floats(min_value=1e-3, max_value=0.6)
moderate_forces = st.floats(min_value=1e-3, max_value=3.0)


@settings(max_examples=30, deadline=None)
@given(materials, moderate_pressures, moderate_forces, fluids)
# a soft gas whose Newton iterate once passed below vacuum (P + P_atm < 0): a math domain error, not a named one
@example(material=0.0, pressure=0.03431140593820599, force=2.7578125, fluid=gas(0.01, 1.0))
def test_any_rubber_and_fluid_give_a_consistent_state_or_a_named_error(material, pressure, force, fluid):
    """Any law (stresses in any unit), any fluid: a compressed state echoing the rubber and fluid as given,
    with F = P A_c, the fluid's volume law (V = V_I for a liquid, the polytropic law for a gas) to 1e-9,
    finite smallest tensions; or OutOfRangeError or ConvergenceError, where the shooting solver has no
    state either."""
    try:
        state = fem.compress(material, pressure, force, fluid=fluid, elements=ELEMENTS)
    except (OutOfRangeError, ConvergenceError) as err:
        _confirmed_compression(err, material, pressure, force, fluid)
        return
    assert (state.pressure_initial, state.force, state.fluid) == (pressure, force, fluid or LIQUID)
    assert (state.alpha, state.material) == ((material, mooney_rivlin(material)) if isinstance(material, float)
                                             else (None, material))
    _common(state)
    ratio = state.volume / state.inflated.volume
    if fluid is None:
        assert abs(ratio - 1) < 1e-9
    else:
        law = (state.pressure + fluid.ambient) / (pressure + fluid.ambient) * ratio**fluid.gamma
        assert abs(law - 1) < 1e-9
        assert ratio < 1
    assert abs(state.extra["force_pressure_area"] - force) <= 1e-9 * force + 1e-12
    assert 0 < state.contact_radius < 1
    assert state.pressure_ratio >= 1 - 1e-12
    assert math.isfinite(state.tension_1_min)
    assert math.isfinite(state.tension_2_min)
