"""A gas-filled pocket in the shooting solver: the polytropic law, its liquid limit, and its order in gamma."""

import numpy as np
import pytest

from pocket import shooting
from pocket.core.errors import InputError
from pocket.core.fluids import LIQUID, gas
from pocket.core.materials import check

SAMPLE = 47 / 160
FORCES = [0.05, 0.5, 2.0]


def gas_law_gap(state):
    """(P + P_atm) V^gamma / ((P_I + P_atm) V_I^gamma) - 1 of a compressed state."""
    fluid = state.fluid
    ratio = state.volume / state.inflated.volume
    return (state.pressure + fluid.ambient) * ratio**fluid.gamma / (state.pressure_initial + fluid.ambient) - 1


@pytest.mark.parametrize("rubber", [SAMPLE, check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0,
                                                                                                        -2.0]})])
@pytest.mark.parametrize(("ambient", "gamma"), [(1.0, 1.0), (0.3, 1.4), (10.0, 1.0)])
def test_gas_law_holds_along_a_curve(rubber, ambient, gamma):
    """Exact answer: (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma at every state (the residual solved,
    to 1e-12; 1e-10 asked), with F = P A_c and lambda_2(1) = 1 as for a liquid."""
    fluid = gas(ambient, gamma)
    states = shooting.compression_curve(rubber, 0.31, FORCES, fluid=fluid)
    for s in states:
        assert abs(gas_law_gap(s)) < 1e-10, gas_law_gap(s)
        assert s.pressure_ratio * s.contact_area == pytest.approx(s.force, rel=1e-12)
        assert s.profile.stretch_2[-1] == pytest.approx(1.0, abs=1e-9)
        assert s.fluid is fluid
        assert s.volume < s.inflated.volume
    inflated = shooting.inflate(rubber, 0.31)  # the gas is sealed at P_I: the same inflation
    assert [getattr(states[0].inflated, k) for k in inflated.KEYS] == [getattr(inflated, k) for k in inflated.KEYS]


def test_gas_tends_to_liquid_at_rate_one_over_ambient():
    """Exact answer: V/V_I = 1 - (P - P_I) / (gamma P_atm) + O(P_atm^-2), so every scalar differs from the
    liquid's by O(1/P_atm): tenfold less per tenfold P_atm (within 1 %: the next term is relatively
    (P - P_I)/P_atm <= 1e-2 at P_atm = 1e2; the solver's error ~1e-10 against gaps >= 1e-5)."""
    liquid = shooting.compression_curve(SAMPLE, 0.31, FORCES)
    keys = ("pressure_ratio", "height", "contact_area", "volume")
    gaps = []
    for ambient in (1e3, 1e4, 1e5):
        states = shooting.compression_curve(SAMPLE, 0.31, FORCES, fluid=gas(ambient))
        gaps.append([[getattr(g, k) - getattr(w, k) for k in keys] for g, w in zip(states, liquid, strict=True)])
    gaps = np.array(gaps)
    np.testing.assert_allclose(gaps[0] / gaps[1], 10.0, rtol=2e-3)
    np.testing.assert_allclose(gaps[1] / gaps[2], 10.0, rtol=2e-3)


def test_adiabatic_gas_is_stiffer():
    """Exact answer (ordering): at the same force, the less compressible fluid holds more volume and more
    pressure: isothermal gas (gamma = 1) < adiabatic gas (gamma = 1.4) < liquid, in P/P_I and V/V_I,
    while its contact area (A_c = F/P) is the smallest."""
    curves = [shooting.compression_curve(SAMPLE, 0.31, FORCES, fluid=f) for f in (gas(1.0, 1.0), gas(1.0, 1.4),
                                                                                  None)]
    for isothermal, adiabatic, liquid in zip(*curves, strict=True):
        assert isothermal.pressure_ratio < adiabatic.pressure_ratio < liquid.pressure_ratio
        assert isothermal.volume < adiabatic.volume < liquid.volume
        assert isothermal.contact_area > adiabatic.contact_area > liquid.contact_area


def test_range_end_of_a_gas_pocket():
    """Exact answer: at the end the plate carries the whole P pi R^2 (vertical equilibrium, whatever the
    fluid): Fhat_end = P/P_I and A_c = pi R^2; a softer (gas) pocket ends at another force than the liquid."""
    fluid = gas(1.0, 1.4)
    end = shooting.range_end(SAMPLE, 0.31, fluid=fluid)
    state = shooting.compress(SAMPLE, 0.31, end, fluid=fluid)
    assert state.pressure_ratio == pytest.approx(end, rel=1e-8)
    assert state.contact_area == pytest.approx(1.0, rel=1e-8)
    assert abs(end / shooting.range_end(SAMPLE, 0.31) - 1) > 1e-3


@pytest.mark.parametrize("fluid", ["air", 1.0, "gas"])
def test_a_fluid_that_is_none_is_an_input_error(fluid):
    with pytest.raises(InputError, match="fluid"):
        shooting.compress(SAMPLE, 0.31, 0.1, fluid=fluid)


def test_liquid_by_name_or_default_is_the_liquid():
    """Exact answer: None and "liquid" are LIQUID, and give the states of today's solver bit for bit."""
    default = shooting.compress(SAMPLE, 0.31, 0.5)
    named = shooting.compress(SAMPLE, 0.31, 0.5, fluid="liquid")
    assert default.fluid is LIQUID
    assert named.fluid is LIQUID
    assert [getattr(default, k) for k in default.KEYS] == [getattr(named, k) for k in named.KEYS]
