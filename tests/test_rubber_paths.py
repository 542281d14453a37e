"""A Mooney-Rivlin rubber given by alpha = C2/C1 and the same rubber given by (C1, C2) in Pa are one rubber in every
solver: the states agree bit for bit, every reported scalar and every profile array (only the echo differs: the
alpha for the first, the Material for the second). This guards any change to how a rubber reaches the kernels."""

import dataclasses

import numpy as np
import pytest

from pocket import analytical, fem, shooting
from pocket.core.materials import check
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
