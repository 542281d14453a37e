"""A gas-filled pocket in the finite-element solver (fem/gas.py): the polytropic law and its liquid limit.

Exact answers: every compressed state of a gas sealed at (P_I, V_I) satisfies
(P + Pa) V^gamma = (P_I + Pa) V_I^gamma (checked here from the reported scalars, to 1e-10);
as the ambient pressure Pa grows, V / V_I = 1 - (P - P_I) / (gamma Pa) + O(Pa^-2), so the states
tend to the liquid's at rate 1/Pa and, to first order, depend on gamma and Pa only through
gamma Pa (the gaps times gamma Pa share one limit for gamma = 1 and 1.4); at one Pa a larger gamma
loses less volume, so the pressure at a given force rises with gamma and the liquid's is highest.
"""

import numpy as np
import pytest

from pocket import fem
from pocket.core.fluids import LIQUID, gas

ALPHA, PHAT = 47 / 160, 0.31
KEYS = ("pressure", "contact_area", "contact_radius", "stretch_contact", "height", "volume")


def _gas_law(state) -> float:
    """(P + Pa) V^gamma / ((P_I + Pa) V_I^gamma) - 1 from the state's own numbers."""
    fluid, gamma = state.fluid, state.fluid.gamma
    return ((state.pressure + fluid.ambient) * state.volume**gamma
            / ((state.pressure_initial + fluid.ambient) * state.inflated.volume**gamma) - 1.0)


@pytest.mark.parametrize(("ambient", "gamma"), [(0.1, 1.0), (0.1, 1.4), (2.0, 5 / 3)])
def test_gas_law_holds_along_a_compression_curve(ambient, gamma):
    """Ten forces from 0.02 to 1.5 (default mesh): the polytropic law to 1e-10 at every state, the volume
    below V_I, the fluid echoed; F = P A_c as for a liquid."""
    fluid = gas(ambient, gamma)
    states = fem.compression_curve(ALPHA, PHAT, np.linspace(0.02, 1.5, 10), fluid=fluid)
    for state in states:
        assert abs(_gas_law(state)) < 1e-10, (state.force, _gas_law(state))
        assert state.volume < state.inflated.volume
        assert state.fluid is fluid
        assert state.extra["force_pressure_area"] == pytest.approx(state.force, rel=1e-9)


def test_gas_law_with_penalty_contact_and_plate_height():
    """The other controls carry the gas too: the penalty plate under force control and the edge-fitted
    plate under height control satisfy the polytropic law to 1e-10; the penalty state's pressure is the
    fitted one's within the penalty method's own accuracy (1e-4)."""
    fluid = gas(0.3, 1.4)
    fitted = fem.compress(ALPHA, PHAT, 0.4, fluid=fluid, elements=64)
    penalty = fem.compress(ALPHA, PHAT, 0.4, fluid=fluid, elements=64, contact="penalty")
    lowered = fem.compress_height(ALPHA, PHAT, 0.3, fluid=fluid, elements=64)
    for state in (fitted, penalty, lowered):
        assert abs(_gas_law(state)) < 1e-10, _gas_law(state)
    assert penalty.pressure == pytest.approx(fitted.pressure, rel=1e-4)
    assert lowered.height == pytest.approx(0.3, rel=1e-12)


def _gaps(states, liquid) -> np.ndarray:
    """(state - liquid) of each KEY at each force, shape (forces, keys)."""
    return np.array([[getattr(s, k) - getattr(w, k) for k in KEYS] for s, w in zip(states, liquid, strict=True)])


def test_gas_tends_to_liquid_at_rate_one_over_ambient():
    """Pa = 100, 200, 400, 800: the largest gap to the liquid halves with each doubling (order 1 within
    0.02), and gamma Pa times the gaps, extrapolated to Pa -> inf (Richardson, first order), is the same
    for gamma = 1 and 1.4 (to 1e-4 of its size): the first-order effect of the gas is (P - P_I) / (gamma Pa)."""
    forces, ambients = [0.19, 0.8], [100.0, 200.0, 400.0, 800.0]
    liquid = fem.compression_curve(ALPHA, PHAT, forces, elements=64)
    limits = []
    for gamma in (1.0, 1.4):
        gaps = [_gaps(fem.compression_curve(ALPHA, PHAT, forces, fluid=gas(pa, gamma), elements=64), liquid)
                for pa in ambients]
        sizes = [np.abs(g).max() for g in gaps]
        orders = np.log2(np.array(sizes[:-1]) / np.array(sizes[1:]))
        assert np.all(np.abs(orders - 1.0) < 0.02), (gamma, orders)
        scaled = [g * gamma * pa for g, pa in zip(gaps, ambients, strict=True)]
        limits.append(2 * scaled[-1] - scaled[-2])
    np.testing.assert_allclose(limits[1], limits[0], rtol=0, atol=1e-4 * np.abs(limits[0]).max())


def test_adiabatic_is_stiffer_than_isothermal():
    """At Pa = 0.5 and each force: P(liquid) > P(gamma = 1.4) > P(gamma = 1), and V_I > V(1.4) > V(1)."""
    forces = [0.1, 0.5, 1.0]
    liquid = fem.compression_curve(ALPHA, PHAT, forces, elements=64)
    adiabatic = fem.compression_curve(ALPHA, PHAT, forces, fluid=gas(0.5, 1.4), elements=64)
    isothermal = fem.compression_curve(ALPHA, PHAT, forces, fluid=gas(0.5, 1.0), elements=64)
    for w, a, i in zip(liquid, adiabatic, isothermal, strict=True):
        assert w.pressure > a.pressure > i.pressure, (w.force, w.pressure, a.pressure, i.pressure)
        assert w.volume > a.volume > i.volume


@pytest.mark.parametrize("given", [None, "liquid", LIQUID])
def test_a_liquid_by_any_name_is_the_liquid(given):
    """fluid None, "liquid" or LIQUID: the same states as without the keyword, echoing LIQUID."""
    plain = fem.compress(ALPHA, PHAT, 0.3, elements=32)
    state = fem.compress(ALPHA, PHAT, 0.3, fluid=given, elements=32)
    assert state.fluid == LIQUID
    assert state.scalars() == plain.scalars()
