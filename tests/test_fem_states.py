"""What the finite-element states echo and report about the rubber, the fluid and the tensions.

Exact answers: a state echoes its inputs as given (a float alpha as itself with the Mooney-Rivlin
material it stands for; a Material as the very object, with alpha None; the fluid as given, LIQUID
when none), and its smallest tensions are the least of T_1 = w_1 / lambda_2 and T_2 = w_2 / lambda_1
over the quadrature points (recomputed here from the state's unknowns by the vectorised fields and the
law's tensions, not the compiled loop) and over its profile's nodes.
"""

import numpy as np
import pytest
from pocket.fem import inflation, model, results
from pocket.fem.api import default_mesh
from pocket.fem.newton import Tolerances

from pocket import fem
from pocket.core.fluids import LIQUID, gas
from pocket.core.materials import check, mooney_rivlin

OGDEN = check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]})


def test_a_float_echoes_alpha_and_its_mooney_rivlin_rubber():
    """alpha = 0.3 given: the state's alpha is 0.3, its material mooney_rivlin(0.3), its fluid LIQUID."""
    state = fem.compress(0.3, 0.31, 0.2, elements=32)
    assert state.alpha == 0.3
    assert state.material == mooney_rivlin(0.3)
    assert state.fluid == LIQUID
    assert state.inflated.alpha == 0.3
    assert state.scalars()["material"] == "mooney-rivlin"


def test_a_material_and_a_gas_are_echoed_as_given():
    """An Ogden Material in Pa and a gas given: the same objects come back (identity), alpha None, and the
    scalars carry the law's parameters in Pa and the gas's ambient pressure and gamma."""
    fluid = gas(0.7, 1.4)
    state = fem.compress(OGDEN, 0.31, 0.2, fluid=fluid, elements=32)
    assert state.alpha is None
    assert state.material is OGDEN
    assert state.fluid is fluid
    assert state.inflated.material is OGDEN
    assert state.inflated.alpha is None
    out = state.scalars()
    assert "alpha" not in out
    assert out["material"] == "ogden"
    assert out["mu"] == [630e3, 1.2e3, -10e3]
    assert (out["fluid"], out["ambient"], out["gamma"]) == ("gas", 0.7, 1.4)


@pytest.mark.parametrize("rubber", [0.3, OGDEN, check("gent", {"mu": 1.0, "jm": 2.0})], ids=["alpha", "ogden", "gent"])
def test_smallest_tensions_are_over_quadrature_points_and_nodes(rubber):
    """Inflated at Phat = 0.4 on 24 elements: tension_k_min = min(quadrature points, profile nodes), to
    1e-14; and below or at the profile's own minimum."""
    m = model.discretize(rubber, default_mesh(24), 2, 1e5)
    y, iterations = inflation.to_pressure(m, 0.4, Tolerances())
    state = results.inflated(m, y, iterations, pressure=0.4)
    w = model.fields(m, y, model.FREE)
    d = m.law.derivatives(w.l1, w.l2)
    expected = (min(float((d[0] / w.l2).min()), float(state.profile.tension_1.min())),
                min(float((d[1] / w.l1).min()), float(state.profile.tension_2.min())))
    assert (state.tension_1_min, state.tension_2_min) == pytest.approx(expected, rel=1e-14)
    assert state.tension_1_min <= state.profile.tension_1.min()
    assert state.tension_2_min <= state.profile.tension_2.min()
    assert not state.wrinkled
    assert np.isfinite(expected).all()
