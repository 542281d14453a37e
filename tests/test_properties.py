"""Property-based tests (hypothesis) of the shooting solver and the analytical model over the parameter space.

alpha in (-0.9, 5), Phat_I in (1e-4, 2) (log-uniform), Fhat in [0, 50]; and every rubber law with its
parameters drawn in stable ranges (``rubbers``), filled with a liquid or a gas (ambient Phat_atm in
[0.1, 1e4] log-uniform, gamma in [1, 1.4]): every call returns a state
that satisfies its invariants, or raises one of the named errors (InputError, OutOfRangeError,
ConvergenceError), never anything else. Many draws are outside the model (above a pressure
maximum for alpha <= 0, past the range end): those must be OutOfRangeErrors, and a compressed
state must lie inside the range (Fhat <= range_end). A refusal must be right: past the range end only
for Fhat > range_end; no inflated state, or a failed solve, only where the other solver (the FE, on a
coarse mesh) has no state either. The deadline only guards against a hang (speed is measured in
benchmarks/).
"""

import datetime
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, event, example, given, settings
from hypothesis import strategies as st

from pocket import analytical, fem, shooting
from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError
from pocket.core.fluids import gas
from pocket.core.materials import check

NAMED = (InputError, OutOfRangeError, ConvergenceError)
alphas = st.floats(-0.9, 5.0)
pressures = st.floats(-4.0, math.log10(2.0)).map(lambda e: 10.0**e)
forces = st.one_of(st.just(0.0), st.floats(0.0, 50.0))
moduli = st.floats(3.0, 7.0).map(lambda e: 10.0**e)  # Pa: the checks and the mu_0 scaling see real units


@st.composite
def ogden_sets(draw):
    """1 to 3 Ogden terms, each stable (mu_p alpha_p > 0), exponents in [-4, -0.5] or [0.5, 6]."""
    terms = draw(st.integers(1, 3))
    exponents = [draw(st.one_of(st.floats(-4.0, -0.5), st.floats(0.5, 6.0))) for _ in range(terms)]
    mus = [math.copysign(draw(moduli), a) for a in exponents]
    return check("ogden", {"mu": mus, "exponents": exponents})


@st.composite
def yeohs(draw):
    """C10 > 0, C20 in [-0.1, 0.1] C10, C30 in [0, 0.05] C10, kept only if dW/dI1 > 0 for all I1 >= 3."""
    c10 = draw(moduli)
    c20, c30 = draw(st.floats(-0.1, 0.1)) * c10, draw(st.floats(0.0, 0.05)) * c10
    try:
        return check("yeoh", {"c10": c10, "c20": c20, "c30": c30})
    except InputError:
        assume(False)


rubbers = st.one_of(
    alphas,
    st.builds(lambda c1, alpha: check("mooney-rivlin", {"c1": c1, "c2": alpha * c1}), moduli, alphas),
    st.builds(lambda mu: check("neo-hookean", {"mu": mu}), moduli),
    yeohs(),
    st.builds(lambda mu, jm: check("gent", {"mu": mu, "jm": jm}), moduli, st.floats(-0.3, 2.5).map(lambda e: 10.0**e)),
    ogden_sets(),
)
fluids = st.one_of(st.none(), st.builds(gas, st.floats(-1.0, 4.0).map(lambda e: 10.0**e), st.floats(1.0, 1.4)))


def guarded(examples):
    """hypothesis settings: ``examples`` draws, a deadline that only catches a hang."""
    return settings(max_examples=examples, deadline=datetime.timedelta(seconds=120),
                    suppress_health_check=[HealthCheck.too_slow])


#: the FE mesh that confirms a refusal: 24 P2 elements (a fraction of a second a solve)
ELEMENTS = 24


def _fe_refuses(solve, *args, **kwargs) -> bool:
    """Whether the FE solver ``solve`` (``fem.inflate`` or ``fem.compress``) has no state either."""
    try:
        solve(*args, elements=ELEMENTS, **kwargs)
    except (OutOfRangeError, ConvergenceError):
        return True
    return False


def _finite(state):
    scalars = [getattr(state, k) for k in state.KEYS if getattr(state, k) is not None]  # alpha: None, another law
    profile = state.profile
    return all(np.isfinite(scalars)) and all(np.all(np.isfinite(getattr(profile, f)))
                                              for f in ("r", "rho", "eta", "stretch_1", "stretch_2"))


def _inflated_invariants(state, alpha, pressure, solver):
    assert (state.alpha, state.pressure) == (alpha, pressure)
    assert state.solver == solver
    assert _finite(state)
    assert state.height > 0
    assert state.volume > 0
    assert np.all(state.profile.stretch_1 > 0)
    assert np.all(state.profile.stretch_2 > 0)
    assert state.profile.stretch_2[-1] == pytest.approx(1.0, abs=1e-7)  # lambda_2(1) = 1 (the clamp)


def _compressed_invariants(state, alpha, pressure, force, solver, volume_rtol):
    assert (state.alpha, state.pressure_initial, state.force) == (alpha, pressure, force)
    assert _finite(state)
    assert state.stretch_contact > 0
    assert state.height > 0
    assert np.all(state.profile.stretch_1 > 0)
    assert np.all(state.profile.stretch_2 > 0)
    ratio = 1.0 if force == 0 else state.fluid.volume_ratio(state.pressure, pressure)
    assert state.volume == pytest.approx(state.inflated.volume * ratio, rel=volume_rtol)  # V = V_I (V/V_I)(P)
    assert state.pressure_ratio * state.contact_area == pytest.approx(force, rel=1e-12, abs=1e-300)  # F = P A_c
    if solver == "shooting":
        assert state.profile.stretch_2[-1] == pytest.approx(1.0, abs=1e-7)


@pytest.mark.slow
@guarded(60)
@given(alpha=alphas, pressure=pressures)
@example(0.0573, 1.855)  # no pressure maximum, lambda_0 = 24: once refused as "not reached for lambda_0 up to 21"
@example(0.05543, 1.5)  # a maximum with a dip narrower than a march step: once a second-branch state
def test_shooting_inflation(alpha, pressure):
    """Exact answers: the invariants above, or OutOfRangeError (pressure above the first-branch maximum),
    where the FE has no inflated state either."""
    try:
        state = shooting.inflate(alpha, pressure)
    except OutOfRangeError:
        event("no inflated state")
        assert _fe_refuses(fem.inflate, alpha, pressure), "the FE inflates it"
        return
    event("an inflated state")
    _inflated_invariants(state, alpha, pressure, "shooting")


@pytest.mark.slow
@guarded(100)
@given(alpha=alphas, pressure=pressures, force=forces)
def test_shooting_compression(alpha, pressure, force):
    """Exact answers: V = V_I, F = P A_c, lambda_2(1) = 1, inputs echoed, Fhat <= range_end; or a
    named error, an OutOfRangeError only for a force past the end (or no inflated state, where the FE has
    none either), a ConvergenceError only where the FE has no state either."""
    try:
        state = shooting.compress(alpha, pressure, force)
    except OutOfRangeError as err:
        beyond = "beyond the model's range" in str(err)
        event("past the range end" if beyond else "no inflated state")
        if beyond:
            assert force > shooting.range_end(alpha, pressure)
        else:
            assert _fe_refuses(fem.inflate, alpha, pressure), "the FE inflates it"
        return
    except ConvergenceError:  # a failure below shows this error as its context
        event("ConvergenceError")
        assert _fe_refuses(fem.compress, alpha, pressure, force), "the FE solves it"
        return
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


@pytest.mark.slow
@guarded(120)
@given(rubber=rubbers, pressure=pressures, force=forces, fluid=fluids)
def test_shooting_compression_any_rubber_and_fluid(rubber, pressure, force, fluid):
    """Exact answers: V = V_I (V/V_I)(P) (the fluid's law), F = P A_c, lambda_2(1) = 1, inputs echoed
    (material, fluid), the smallest tensions (tracked over every integration step) no larger than the
    profile's; or a named error, an OutOfRangeError only past the range end, or with no inflated state or past
    a rubber's locking where the FE has no state either, a ConvergenceError only where the FE has none."""
    alpha = rubber if isinstance(rubber, float) else None
    try:
        state = shooting.compress(rubber, pressure, force, fluid=fluid)
    except OutOfRangeError as err:
        beyond = "beyond the model's range" in str(err)
        event("past the range end" if beyond else "no inflated state")
        if beyond:
            assert force > shooting.range_end(rubber, pressure, fluid=fluid)
        else:
            assert _fe_refuses(fem.compress, rubber, pressure, force, fluid=fluid), "the FE solves it"
        return
    except ConvergenceError:  # a failure below shows this error as its context
        event("ConvergenceError")
        assert _fe_refuses(fem.compress, rubber, pressure, force, fluid=fluid), "the FE solves it"
        return
    event(f"a compressed state ({'gas' if fluid else 'liquid'})")
    _compressed_invariants(state, alpha, pressure, force, "shooting", 1e-9)
    assert state.fluid is (fluid or state.fluid)
    assert (alpha is not None or state.material is rubber)
    for k in (1, 2):
        assert getattr(state, f"tension_{k}_min") <= np.min(getattr(state.profile, f"tension_{k}")) + 1e-15
    if force > 0:
        assert force <= shooting.range_end(rubber, pressure, fluid=fluid)


@guarded(100)
@given(rubber=rubbers, pressure=pressures, force=forces, fluid=fluids)
def test_analytical_model_any_rubber_and_fluid(rubber, pressure, force, fluid):
    """Exact answers: V = V_I (V/V_I)(P), F = P A_c, inputs echoed; or OutOfRangeError past its range end."""
    alpha = rubber if isinstance(rubber, float) else None
    try:
        state = analytical.compress(rubber, pressure, force, fluid=fluid)
    except OutOfRangeError:
        assert force > analytical.range_end(rubber, pressure, fluid=fluid)
        return
    _compressed_invariants(state, alpha, pressure, force, "analytical", 1e-12)


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
