"""The verdicts on states of any law and fluid: the fluid's own law, the wrinkling verdict, FE tolerances."""

import dataclasses

import pytest
from pocket.validation.plan import FEM_COLUMNS
from pocket.validation.verdicts import MEMBRANE, TOLERANCES, _fem_tolerance, fluid_row, membrane_checks

from pocket import shooting
from pocket.core.fluids import gas


@pytest.fixture(scope="module")
def gas_curve():
    return shooting.compression_curve(0.3, 0.31, [0.2, 1.0, 3.0], fluid=gas(6.5, 1.4))


def test_fluid_row_holds_the_gas_law(gas_curve):
    """Exact answer: a gas state's volume is V_I ((P_I + P_atm)/(P + P_atm))^(1/gamma) (the row passes, its
    reference that formula by hand); 1e-6 more volume fails; a liquid's reference is V_I."""
    state = gas_curve[1]
    expected = state.inflated.volume * ((0.31 + 6.5) / (state.pressure + 6.5)) ** (1 / 1.4)
    row = fluid_row("c", "shooting", "", state)
    assert row.verdict == "pass"
    assert row.reference == pytest.approx(expected, rel=1e-15)
    assert "gas law" in row.quantity
    bad = dataclasses.replace(state, volume=state.volume * (1 + 1e-6))
    assert fluid_row("c", "shooting", "", bad).verdict == "fail"
    liquid = shooting.compress(0.3, 0.31, 1.0)
    row = fluid_row("c", "shooting", "", liquid)
    assert row.quantity == "volume = V_I"
    assert row.reference == liquid.inflated.volume
    assert row.verdict == "pass"
    assert TOLERANCES["fluid"][0] == 1e-9


def test_membrane_verdict_fails_on_any_wrinkled_state(gas_curve):
    """Exact answer: the verdict's value is the smallest tension of the curve's states and their inflated state
    (here the inflated state's T_2, as min over the states by hand); one state with T_2 = -1e-3 (patched in)
    fails it, saying how many states wrinkled."""
    [row] = membrane_checks("c", "shooting", gas_curve)
    states = [gas_curve[0].inflated, *gas_curve]
    assert row.value == min(min(s.tension_1_min, s.tension_2_min) for s in states) > 0
    assert (row.comparison, row.verdict) == (MEMBRANE, "pass")
    assert "4 states" in row.where
    slack = [gas_curve[0], dataclasses.replace(gas_curve[1], tension_2_min=-1e-3), gas_curve[2]]
    [row] = membrane_checks("c", "FEM P2", slack)
    assert (row.verdict, row.value) == ("fail", -1e-3)
    assert "1 of 4 states wrinkled" in row.where
    assert "FEM P2" in row.where
    assert row.error == 1e-3


def test_fe_tolerance_follows_the_element_order():
    """The P1 column is held to 1e-6, the P2 column to the 1e-9 quality bar."""
    assert [_fem_tolerance(c) for c in FEM_COLUMNS] == [1e-6, 1e-9]
    assert [c.label for c in FEM_COLUMNS] == ["FEM P1", "FEM P2"]
