"""The shooting solver's scalar root finder and maximiser (``pocket.shooting.brent``) against scipy's."""

import math

import numpy as np
import pytest
from pocket.shooting import brent
from scipy.optimize import brentq, minimize_scalar

HARD = {
    "cubic": (lambda x: x**3 - 2 * x - 5, 2.0, 3.0),
    "ninefold root (flat)": (lambda x: (x - 1) ** 9, 0.0, 3.0),
    "jump, no root": (lambda x: -1.0 if x < 0.3 else 1.0, 0.0, 1.0),
    "steep exponential": (lambda x: math.exp(100 * x) - 2, -1.0, 1.0),
    "far from zero": (lambda x: x - (1e10 + 1e-3), 1e10, 1e10 + 1),
    "Wilkinson": (lambda x: math.prod(x - k for k in range(1, 21)), 0.5, 1.5),
    "root at an end": (lambda x: x - 2.0, 1.0, 2.0),
}


@pytest.mark.parametrize("name", HARD)
@pytest.mark.parametrize(("xtol", "rtol"), [(2e-12, 8.9e-16), (1e-300, 1e-13)])
def test_same_root_and_evaluations_as_scipy_brentq(name, xtol, rtol):
    """Exact answer: scipy's brentq, the same algorithm: the same root, bit for bit, with the same
    number of evaluations (the port keeps its arithmetic)."""
    f, a, b = HARD[name]
    count = [0]

    def counted(x):
        count[0] += 1
        return f(x)

    ours = brent.root(counted, a, b, xtol=xtol, rtol=rtol, maxiter=1000)
    theirs, info = brentq(f, a, b, xtol=xtol, rtol=rtol, maxiter=1000, full_output=True)
    assert ours == theirs, (name, ours, theirs, count[0], info.function_calls)
    assert count[0] == info.function_calls, (name, ours, theirs, count[0], info.function_calls)


def test_known_values_spare_evaluations():
    """Exact answer: passing f(a), f(b) changes nothing but the two evaluations."""
    f = HARD["cubic"][0]
    count = [0]

    def counted(x):
        count[0] += 1
        return f(x)

    root = brent.root(counted, 2.0, 3.0, fa=f(2.0), fb=f(3.0), xtol=2e-12, rtol=8.9e-16)
    assert root == brentq(f, 2.0, 3.0)
    assert count[0] == brentq(f, 2.0, 3.0, full_output=True)[1].function_calls - 2


def test_no_sign_change_is_an_error():
    with pytest.raises(brent.BracketError, match="same sign"):
        brent.root(lambda x: x * x + 1, -1.0, 1.0)


@pytest.mark.parametrize(("f", "a", "b"), [
    (lambda x: -(x - 0.3) ** 2, 0.0, 1.0),          # smooth
    (lambda x: -abs(x - 0.7123), 0.0, 1.0),          # a kink at the top
    (lambda x: math.sin(x), 0.0, 3.0),               # the top at pi/2
    (lambda x: x, 0.0, 1.0),                         # monotone: the top at the end
    (lambda x: -math.inf if x > 0.6 else x, 0.0, 1.0),  # undefined past 0.6 (-inf), as inflation uses it
])
def test_maximum_agrees_with_scipy_bounded_minimisation(f, a, b):
    """Exact answer: scipy's minimize_scalar(bounded) on -f, to the tolerance asked (1e-9 in x)."""
    x, value = brent.maximum(f, a, b, xtol=1e-9)
    ref = minimize_scalar(lambda t: -f(t) if np.isfinite(f(t)) else 1e300, bounds=(a, b), method="bounded",
                          options=dict(xatol=1e-10))
    assert x == pytest.approx(ref.x, abs=2e-8)
    assert value == pytest.approx(f(x))
    assert value >= -ref.fun - 1e-12
