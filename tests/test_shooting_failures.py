"""A solver that fails says so (ConvergenceError, exit 1), with where; only a state outside the model
is an OutOfRangeError. Failures are provoked by an integrator that reports a failing status."""

import pytest
from pocket.shooting import shots
from pocket.shooting.integrator import FOLD, STEPS

from pocket import shooting
from pocket.core.errors import ConvergenceError, OutOfRangeError

SAMPLE = 47 / 160


def _failing(monkeypatch, when, status):
    """Make every shot for which when(r0, store) holds stop at once with ``status``."""
    real = shots.integrate

    def integrate(y0, r0, alpha, p, **kw):
        if when(r0, kw.get("store", 0)):
            result = real(y0, r0, alpha, p, **kw)
            return status, r0, y0, result[3][:1]
        return real(y0, r0, alpha, p, **kw)

    monkeypatch.setattr(shots, "integrate", integrate)


def test_compression_that_cannot_integrate_is_a_failure_not_a_range_end(monkeypatch):
    """Exact answer: Fhat = 2 is inside the range (test_shooting_rangeend); shots from contact radii
    above 0.6 (Fhat > ~1.6) that take too many steps are a ConvergenceError naming a force."""
    _failing(monkeypatch, lambda r0, store: r0 > 0.6, STEPS)
    with pytest.raises(ConvergenceError, match="force") as err:
        shooting.compress(SAMPLE, 0.31, 2.0)
    assert not isinstance(err.value, OutOfRangeError)


def test_inflation_that_cannot_integrate_is_a_failure(monkeypatch):
    """Exact answer: a pole shot that takes too many steps is a ConvergenceError saying so."""
    _failing(monkeypatch, lambda r0, store: r0 < 1e-3, STEPS)
    with pytest.raises(ConvergenceError, match="too many steps"):
        shooting.inflate(SAMPLE, 0.31)


@pytest.mark.parametrize("solve", [lambda: shooting.inflate(SAMPLE, 0.31),
                                   lambda: shooting.inflate_volume(SAMPLE, 0.5),
                                   lambda: shooting.compress(SAMPLE, 0.31, 0.5)])
def test_a_profile_shot_that_stops_is_a_failure(monkeypatch, solve):
    """Exact answer: the stored profile comes from its own, finer-stepped shot; if that one stops
    early the state is not returned with a truncated profile: ConvergenceError naming the profile."""
    _failing(monkeypatch, lambda r0, store: store > 0, FOLD)
    with pytest.raises(ConvergenceError, match="profile shot"):
        solve()
