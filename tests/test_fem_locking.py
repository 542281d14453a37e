"""A rubber with a locking stretch (Gent, I1 - 3 < Jm) in the finite-element solver: no NaN states.

Exact answers: Gent's energy diverges as I1 - 3 -> Jm, so the inflation pressure and the plate force
grow without bound as the sheet approaches locking, while the volume and the plate height of a
sealed pocket stay bounded: every pressure and force has a state (finite, short of locking: the
margin 1 - (I1 - 3)/Jm > 0 at every node, shrinking as the load grows), and a volume or plate height
beyond what the sheet reaches before locking is OutOfRangeError (one line, naming the locking), never
a NaN state or a traceback. The vertical balance F = P A_c still holds at the stiffest state.
"""

import numpy as np
import pytest
from pocket.fem.material import law_of

from pocket import fem
from pocket.core.errors import OutOfRangeError
from pocket.core.materials import check

GENT = check("gent", {"mu": 1.0, "jm": 1.0})
PHAT = 0.5


def _margin(state) -> float:
    return law_of(GENT).lock_margin(state.profile.stretch_1, state.profile.stretch_2)


def test_inflation_pressure_diverges_before_locking():
    """Phat = 1, 10, 100, 1000: finite states, volumes rising to a bound (each step adds less than the one
    before) and lock margins falling towards 0 but positive."""
    states = [fem.inflate(GENT, p) for p in (1.0, 10.0, 100.0, 1000.0)]
    volumes, margins = np.array([s.volume for s in states]), np.array([_margin(s) for s in states])
    assert np.all(np.diff(volumes) > 0), volumes
    assert np.all(np.diff(np.diff(volumes)) < 0), volumes
    assert np.all(margins > 0), margins
    assert np.all(np.diff(margins) < 0), margins
    assert margins[-1] < 1e-2, margins


def test_a_volume_below_locking_is_reached_by_cutting_steps():
    """V = 1.745, just under the volume at Phat = 1000 (1.7489: the locking volume is above it): the log V
    path's long steps land past locking, where the energy is NaN, and are cut; the state is finite and
    near locking, its pressure high."""
    state = fem.inflate_volume(GENT, 1.745)
    assert state.volume == 1.745
    assert 0 < _margin(state) < 0.05
    assert state.pressure > 50


@pytest.mark.parametrize(("call", "what"), [
    (lambda: fem.inflate_volume(GENT, 3.0), "volume = 3.0 is not reached before the rubber locks"),
    (lambda: fem.compress_height(GENT, PHAT, 0.1), "plate height h/R = 0.1 is not reached before the rubber locks"),
])
def test_a_target_past_locking_is_out_of_range(call, what):
    """A volume, or a plate height, that the sheet cannot reach before locking: OutOfRangeError, one
    line, naming the target and the locking."""
    with pytest.raises(OutOfRangeError) as info:
        call()
    message = str(info.value)
    assert what in message, message
    assert "locking" in message, message
    assert "\n" not in message, message


def test_plate_force_diverges_before_locking():
    """Fhat = 1e2, 1e3, 1e4 on one curve: finite states, the plate height falling by less each decade,
    the margins positive and falling, and F = P A_c to 1e-9 at the stiffest."""
    states = fem.compression_curve(GENT, PHAT, [1e2, 1e3, 1e4])
    heights, margins = np.array([s.height for s in states]), np.array([_margin(s) for s in states])
    assert np.all(np.diff(heights) < 0), heights
    assert abs(heights[2] - heights[1]) < abs(heights[1] - heights[0]), heights
    assert np.all(margins > 0), margins
    assert np.all(np.diff(margins) < 0), margins
    assert states[-1].extra["force_pressure_area"] == pytest.approx(1e4, rel=1e-9)
    assert all(np.isfinite(v) for s in states for v in s.scalars().values() if isinstance(v, float))
