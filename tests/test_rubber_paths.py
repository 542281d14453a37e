"""A Mooney-Rivlin rubber given by alpha = C2/C1 and the same rubber given by (C1, C2) in Pa are one rubber in every
solver: the states agree bit for bit, every reported scalar and every profile array (only the echo differs: the
alpha for the first, the Material for the second). This guards any change to how a rubber reaches the kernels."""

import dataclasses

import numpy as np
import pytest

from pocket import analytical, fem, shooting
from pocket.core.materials import check, mooney_rivlin
from pocket.core.states import CHECKS

C1, C2 = 160e3, 47e3
RUBBERS = {"positive": (C2 / C1, check("mooney-rivlin", {"c1": C1, "c2": C2})),
           "negative": (-0.4, check("mooney-rivlin", {"c1": 1.0, "c2": -0.4}))}
SOLVERS = {"shooting": (shooting, {}), "fem": (fem, {"elements": 64}), "analytical": (analytical, None)}


def _same(a, b):
    for key in (*a.KEYS, *CHECKS):
        if key != "alpha":
            assert getattr(a, key) == getattr(b, key), key
    for field in dataclasses.fields(a.profile):
        assert np.array_equal(getattr(a.profile, field.name), getattr(b.profile, field.name)), field.name


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("name", RUBBERS)
def test_alpha_and_c1_c2_give_the_same_states_bit_for_bit(name, solver):
    """Exact answer: one rubber, so identical numbers (an inflation at Phat 0.2 and a compression at Fhat 0.3)."""
    alpha, material = RUBBERS[name]
    module, options = SOLVERS[solver]
    options = options or {}
    states = {}
    for given in (alpha, material):
        states[given is material] = (module.inflate(given, 0.2, **options),
                                     module.compress(given, 0.2, 0.3, **options))
    for by_alpha, by_material in zip(states[False], states[True], strict=True):
        _same(by_alpha, by_material)
        assert (by_alpha.alpha, by_material.alpha) == (alpha, None)
        assert by_material.material == material


def _alpha_that_does_not_round_trip():
    """The first alpha = k/100 (k = 1, 2, ...) whose C2/C1, recomputed from mooney_rivlin(alpha), is not alpha."""
    for k in range(1, 1000):
        alpha = k / 100
        material = mooney_rivlin(alpha)
        if material["c2"] / material["c1"] != alpha:
            return alpha
    raise AssertionError("every alpha round-trips")


def test_a_material_given_by_alpha_keeps_that_alpha():
    """Exact answer: mooney_rivlin(alpha).alpha is alpha, also where C2/C1 of its C1, C2 is not (one ulp off),
    and through ``scaled``; a rubber given by C1, C2 has alpha = C2/C1."""
    alpha = _alpha_that_does_not_round_trip()
    assert mooney_rivlin(alpha).alpha == alpha
    assert mooney_rivlin(alpha).scaled().alpha == alpha
    assert check("mooney-rivlin", {"c1": C1, "c2": C2}).alpha == C2 / C1


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_a_material_given_by_alpha_is_solved_as_that_alpha(solver):
    """Exact answer: the rubber mooney_rivlin(alpha) reaches the kernel with alpha itself, so its states are the
    float alpha's bit for bit, for an alpha whose C2/C1 is one ulp off (``_alpha_that_does_not_round_trip``)."""
    alpha = _alpha_that_does_not_round_trip()
    module, options = SOLVERS[solver]
    by_alpha, by_material = (module.compress(given, 0.2, 0.3, **options) for given in (alpha, mooney_rivlin(alpha)))
    _same(by_alpha, by_material)


@pytest.mark.parametrize("solver", SOLVERS)
def test_a_float_alpha_and_mooney_rivlin_of_it_are_one_input(solver):
    """Exact answer: an entry point converts a float alpha with mooney_rivlin, so passing either is passing the
    same rubber: the same scalars (keys, their order and every bit, alpha first), the state's alpha that alpha."""
    alpha = _alpha_that_does_not_round_trip()
    module, options = SOLVERS[solver]
    by_float, by_material = (module.compress(given, 0.2, 0.3, **(options or {})) for given in
                             (alpha, mooney_rivlin(alpha)))
    assert list(by_material.scalars().items()) == list(by_float.scalars().items())
    assert next(iter(by_material.scalars().items())) == ("alpha", alpha)
    assert by_material.inflated.alpha == alpha
