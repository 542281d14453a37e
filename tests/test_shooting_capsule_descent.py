"""The shooting solver's capsule on its second branch and at P_I = 0, reached by the descent in the inflation pressure
(``pocket.shooting.descent``): the balances every state must satisfy, its continuity in P_I, the lower end of the
branch where the contact edge goes slack, and agreement with the first branch's route where both reach a height."""

import math
import re

import numpy as np
import pytest
from pocket.shooting.descent import H_DEEP, _descent, capsule_at_force, capsule_at_height

from pocket import shooting
from pocket.core.errors import CAPSULE_EDGE, ConvergenceError, InputError, OutOfRangeError
from pocket.core.fluids import LIQUID, gas
from pocket.core.indenters import Sphere

NEO = 0.0  # Mooney-Rivlin alpha = 0: the neo-Hookean rubber
SPHERE = 4.0 * math.pi / 3.0  # the unstressed capsule's volume, R = 1
HEIGHTS = (0.7198, 0.4998)  # two of the finite elements' states: the pole wrinkled, and nearly taut (taut below ~0.48)
KEYS = ("pressure", "contact_area", "contact_radius", "height", "volume")


def _values(state):
    return np.array([getattr(state, k) for k in KEYS] + [state.extra["force_ETR"], state.extra["stretch_pole"]])


def _edge_tension(state):
    """T_1 / (E T) at the contact edge: the profile's last point on the plate."""
    return state.profile.tension_1[np.flatnonzero(state.profile.contact)[-1]]


def _lower_end(err):
    """H* quoted by the OutOfRangeError ``err``: the start of the deep branch it names."""
    return float(re.search(r"starts? (?:deeper, )?at height = ([0-9.]+)", str(err)).group(1))


@pytest.fixture(scope="module")
def uninflated():
    states = [capsule_at_height(NEO, 0.0, h) for h in HEIGHTS]
    for h, s in zip(HEIGHTS, states, strict=True):
        print(f"P_I = 0, H = {h}: P = {s.pressure:.9g} E T/R, F = {s.extra['force_ETR']:.9g} E T R, a_c = "
              f"{s.contact_radius:.9g} R, edge T_1 = {_edge_tension(s):.6g} E T, lambda_0 = "
              f"{s.extra['stretch_pole']:.6g}, wrinkled {s.wrinkled}")
    return states


def test_the_uninflated_capsule_holds_the_sphere_and_the_plates_balance(uninflated):
    """Exact answers at P_I = 0 with a liquid: the volume is the unstressed sphere's 4 pi / 3 (to 1e-9, the
    integration's tolerance times V); F = P A_c on each plate; and, independent of the residuals solved, the
    vertical balance at the equator (the first integral 2 pi rho T_1 sin psi = P pi rho^2 - F, psi = pi / 2), from
    the profile's tension there, to 1e-9. The keys with P_I in them have no value; H / R is the height asked."""
    for height, state in zip(HEIGHTS, uninflated, strict=True):
        assert abs(state.volume - SPHERE) < 1e-9
        force = state.extra["force_ETR"]
        assert force == pytest.approx(math.pi * state.pressure * state.contact_area, rel=1e-14)
        rho = state.extra["radius_equator"]
        assert 2.0 * math.pi * rho * state.profile.tension_1[-1] == pytest.approx(
            math.pi * state.pressure * rho**2 - force, rel=1e-9)
        assert state.height == pytest.approx(height, abs=1e-9)
        assert state.height_ratio == state.height
        assert state.pressure_initial == 0.0
        assert math.isnan(state.force)
        assert math.isnan(state.pressure_ratio)
        assert state.inflated.stretch_pole == 1.0
        assert state.inflated.volume == SPHERE
        np.testing.assert_allclose(state.profile.eta[state.profile.contact], state.height, rtol=1e-9)
        assert abs(state.profile.eta[-1]) < 1e-15


def test_the_residuals_vanish_the_equator_vertical():
    """The state solves its equations: the shot from the pole lands on the equatorial plane (eta) vertical
    (psi(pi/2) = pi/2), with the sphere's volume and continuous segments, each residual within the solver's
    tolerance."""
    for height in HEIGHTS:
        problem, x = _descent(NEO, 0.0, height, LIQUID, 1e-10)
        residuals = problem.residual(x, 1.0)
        assert np.max(np.abs(residuals)) <= problem.residual_floor
        shot = problem.shoot(x, 1.0)
        assert abs(shot[1][2] - 0.5 * math.pi) <= problem.residual_floor


def test_the_state_is_continuous_in_the_inflation_pressure(uninflated):
    """The branch at P_I = 0 is the limit of those at P_I > 0: at a fixed height each key X(P_I) is smooth, so the
    line through X(h) and X(2h) (h = 0.005) misses X(0) by h^2 X'' while X moves by h X' from h to 2h: the miss is
    of relative order h X'' / X', about 0.03 here (measured 0.025 for P), and below a quarter of the step (a root
    X ~ sqrt(P_I), a second branch's start at 0, would miss by 1.4 steps; a jump by infinitely many)."""
    zero = _values(uninflated[0])
    h1, h2 = (_values(capsule_at_height(NEO, p, HEIGHTS[0])) for p in (0.005, 0.01))
    miss, step = 2.0 * h1 - h2 - zero, h2 - h1
    print("X(0), X(h) - X(0), X(2h) - X(h), miss:", zero, h1 - zero, step, miss, sep="\n")
    moved = np.abs(step) > 1e-12  # the height is held: it does not move
    assert np.all(np.abs(miss[moved]) < 0.25 * np.abs(step[moved]))
    assert np.all(np.abs(miss[~moved]) < 1e-12)


def test_above_the_second_branch_is_refused_quoting_its_end(uninflated):
    """At P_I = 0 a height between the solved state's and the unstressed sphere's (1) but above H*, the second
    branch's least compression, is refused quoting H* and why (``CAPSULE_EDGE``); above the sphere, the plates
    would not touch it."""
    with pytest.raises(OutOfRangeError, match=re.escape(CAPSULE_EDGE)) as info:
        capsule_at_height(NEO, 0.0, 0.9)
    end = _lower_end(info.value)
    print(f"H* at P_I = 0: {end}")
    assert HEIGHTS[0] < end < 0.9
    with pytest.raises(OutOfRangeError, match="would not touch it"):
        capsule_at_height(NEO, 0.0, 1.01)


def test_inputs_are_refused_before_any_work():
    """One line each: a negative pressure, a non-positive height; a capsule is pressed by two plates only."""
    with pytest.raises(InputError, match="pressure"):
        capsule_at_height(NEO, -0.1, 0.7)
    with pytest.raises(InputError, match="height"):
        capsule_at_height(NEO, 0.0, 0.0)
    with pytest.raises(InputError, match="between two flat plates"):
        shooting.compress_height(NEO, 0.0, 0.7, geometry="capsule", indenter=Sphere(0.5))


def test_height_control_at_zero_pressure_is_the_descent(uninflated):
    """``compress_height`` at P_I = 0 takes the descent's route: the same state, bit for bit; force control at
    P_I = 0 is still refused."""
    state = shooting.compress_height(NEO, 0.0, HEIGHTS[1], geometry="capsule")
    np.testing.assert_array_equal(_values(state), _values(uninflated[1]))
    with pytest.raises(InputError, match="pressure = 0"):
        shooting.compress(NEO, 0.0, 0.1, geometry="capsule")


def test_height_control_below_the_segments_reach_is_refused_at_once():
    """At Phat_I = 0.001 the first branch's shots need more segments than the solver takes: ``compress_height``
    says so before searching that branch's range (the ConvergenceError ``compress`` gives, without its cost)."""
    with pytest.raises(ConvergenceError, match="amplifies its errors"):
        shooting.compress_height(NEO, 0.001, 0.7, geometry="capsule")


def test_a_gas_sealed_at_zero_gauge_pressure():
    """Exact answer: a gas sealed in the unstressed sphere at P_I = 0 (gauge) follows (P + P_atm) V^gamma =
    P_atm (4 pi / 3)^gamma, to 1e-9 (the volume's tolerance), and is squeezed: V < 4 pi / 3, P below the
    liquid's at the same height."""
    air = gas(10.0, 1.4)
    state = capsule_at_height(NEO, 0.0, HEIGHTS[1], fluid=air)
    assert (state.pressure + air.ambient) * state.volume**air.gamma == pytest.approx(
        air.ambient * SPHERE**air.gamma, rel=1e-9)
    assert state.volume < SPHERE
    assert state.pressure < capsule_at_height(NEO, 0.0, HEIGHTS[1]).pressure


@pytest.mark.slow
def test_a_soft_gas_is_pressed_deeper_first():
    """A gas sealed at P_I = 0 under a low ambient pressure (Phat_atm = 0.5, isothermal) yields to the squeeze: its
    second branch starts below H_DEEP, so the descent changes the fluid at a deeper plate height; a height above its
    H* is refused quoting it, one below solves, holding (P + P_atm) V = P_atm 4 pi / 3 to 1e-9."""
    air = gas(0.5, 1.0)
    with pytest.raises(OutOfRangeError, match=re.escape(CAPSULE_EDGE)) as info:
        capsule_at_height(NEO, 0.0, 0.6, fluid=air)
    end = _lower_end(info.value)
    print(f"soft gas at P_I = 0: H* = {end}")
    assert end < H_DEEP
    state = capsule_at_height(NEO, 0.0, end - 0.01, fluid=air)
    assert (state.pressure + air.ambient) * state.volume == pytest.approx(air.ambient * SPHERE, rel=1e-9)


@pytest.mark.slow
def test_the_lower_end_is_where_the_edge_goes_slack():
    """At H*, bisected to 2e-6, the edge's meridional tension vanishes: if T_1(edge) falls at least linearly to 0
    at H*, T_1(H*) / T_1(H* - 1e-3) <= (2e-6 + 1e-7, H*'s quoted digits) / 1e-3 ~ 2e-3; asserted below 1e-2. The
    ends at P_I = 0 and 0.01: the branch reaches further up at 0.01 (the fluid's higher pressure)."""
    ends = []
    for phat in (0.0, 0.01):
        with pytest.raises(OutOfRangeError, match=re.escape(CAPSULE_EDGE)) as info:
            capsule_at_height(NEO, phat, 0.9)
        end = _lower_end(info.value)
        at, below = (capsule_at_height(NEO, phat, h) for h in (end, end - 1e-3))
        print(f"Phat_I = {phat}: H* = {end}, edge T_1 there {_edge_tension(at):.3g}, 1e-3 below "
              f"{_edge_tension(below):.3g} E T")
        assert 0.0 < _edge_tension(at) < 1e-2 * _edge_tension(below)
        ends.append(end)
    assert ends[0] < ends[1]


@pytest.mark.slow
def test_the_descent_agrees_with_the_first_branch_where_both_reach():
    """Two routes: at Phat_I = 0.1 (the anchor, whose first branch has no end) the descent's state at a height and
    the first branch's (force control inverted by Brent's method, ``compress_height``) agree to 1e-9."""
    for height in (0.7198, 0.4):
        first = shooting.compress_height(NEO, 0.1, height, geometry="capsule")
        second = capsule_at_height(NEO, 0.1, height)
        np.testing.assert_allclose(_values(second), _values(first), rtol=1e-9)
        assert second.force == pytest.approx(first.force, rel=1e-9)
        assert second.pressure_ratio == pytest.approx(first.pressure_ratio, rel=1e-9)


@pytest.mark.slow
def test_the_uninflated_capsule_converges_in_the_integration_tolerance(uninflated):
    """Convergence: every key at rtol 1e-10 (the default) within 1e-9 of rtol 1e-12."""
    for height, state in zip(HEIGHTS, uninflated, strict=True):
        np.testing.assert_allclose(_values(capsule_at_height(NEO, 0.0, height, rtol=1e-12)), _values(state),
                                   rtol=1e-9)


@pytest.mark.slow
def test_a_height_between_the_branches_is_refused_quoting_both_ends():
    """At Phat_I = 0.01 the first branch ends (``CAPSULE_EDGE``, at a compression of 5.6 %) above the second's
    least compression: a height between is refused by ``compress_height`` quoting both ends, the asked one between
    them; one below the second's end is on the second branch (the descent's state, bit for bit)."""
    height = 0.9
    with pytest.raises(OutOfRangeError, match="lies between the capsule's two branches") as info:
        shooting.compress_height(NEO, 0.01, height, geometry="capsule")
    second = _lower_end(info.value)
    first = float(re.search(r"the one pressed from the touch ends at height = ([0-9.]+)", str(info.value)).group(1))
    print(f"Phat_I = 0.01: the first branch ends at H = {first}, the second at {second}")
    assert second < height < first
    deep = shooting.compress_height(NEO, 0.01, second - 0.01, geometry="capsule")
    np.testing.assert_array_equal(_values(deep), _values(capsule_at_height(NEO, 0.01, second - 0.01)))


@pytest.mark.slow  # a few descents at Phat_I = 0.01, seconds
def test_a_force_short_of_the_deep_branch_is_refused_quoting_both_ends():
    """At Phat_I = 0.01 the second branch's force falls as the plates rise, to its least at H*: a force past the
    first branch's end (given) but below that least is refused quoting the first's end as given and the second's
    start, whose force is the state's at the height it quotes (both to ten digits)."""
    with pytest.raises(OutOfRangeError, match="lies between the capsule's two branches") as info:
        capsule_at_force(NEO, 0.01, 0.2, "force = 0.1495")
    found = re.search(r"ends at force = 0\.1495, the one reached deeper starts at force = (\S+) \(height = (\S+)\)",
                      str(info.value))
    assert found, str(info.value)
    least, height = (float(v) for v in found.groups())
    assert least > 0.2
    assert capsule_at_height(NEO, 0.01, height).force == pytest.approx(least, rel=1e-8)


@pytest.mark.slow  # the first branch's end at Phat_I = 0.01 (a minute), then the deep state
def test_a_curve_past_the_first_branchs_end_goes_on_deep():
    """A curve at Phat_I = 0.01 through Fhat = 0.1 (its first branch) and 3 (past that branch's end at 0.15): the
    second force is solved on the deep branch, by Brent's method on the plates' height, its force found to 1e-12;
    given back as a height, the descent finds the same state."""
    near, deep = shooting.compression_curve(NEO, 0.01, [0.1, 3.0], geometry="capsule")
    assert near.height > 0.9 > deep.height
    assert deep.force == pytest.approx(3.0, rel=1e-12)
    np.testing.assert_allclose(_values(capsule_at_height(NEO, 0.01, deep.height)), _values(deep), rtol=1e-9)
