"""Where the solid's load march stops when Newton fails however short the step (``pocket.solid.compression``).

Exact answers: the ConvergenceError names the last force solved, which is the force of the last state the march
returned before the failure (the same number, read back as ``err.load``), the shortest step it tried beyond,
and Newton's reason; under height control it names the height and the force there; on the command line it is
one line and exit status 1. The failure is made where it is known: Newton is told to fail above a chosen force
(``FAIL_ABOVE``), so the march stops within twice its smallest step (``MIN_FRACTION`` of the first) below it.

The slow lane measures the stop that made this necessary: the headline-like pocket of the range command
(alpha = 0.3, Phat_I = 0.3, T/R = 0.0125, the default mesh) without the clamp's upper jaw (``--clamp-radius 0``,
its corner elements T/2 long, the default without a jaw)
stops where its discrete path turns, at the clamp's upper corner (``pocket.solid.newton``); the force it names
solves, and a force a step beyond it does not. (With the default jaw it reaches Fhat = 9: ``test_solid_jaw``.)
"""

import re

import numpy as np
import pytest
from pocket.solid import compression

from pocket import solid
from pocket.cli import main
from pocket.core.errors import ConvergenceError

COARSE = {"elements": 8, "layers": 2}
ALPHA, PHAT, FAIL_ABOVE = 47 / 160, 0.31, 0.1


def _named(err: ConvergenceError) -> float:
    """The force the stop names (``compression._stopped``'s wording)."""
    return float(re.search(r"stopped at (?:height = [-+0-9.e]+ R, )?Fhat = ([-+0-9.e]+)", str(err)).group(1))


#: the force of Fhat = 1 (mu_0 R^2): P_I pi R^2, P_I = 3 (T/R) Phat_I in units of mu_0
UNIT = np.pi * 3.0 * solid.DEFAULT_THICKNESS * PHAT


@pytest.fixture
def failing_above(monkeypatch):
    """Newton (the contact solve the march calls) failing wherever its state's force is above ``FAIL_ABOVE``."""
    real = compression.contact

    def contact(model, y, control, tol):
        out = real(model, y, control, tol)
        if compression.force_of(model, control.surface, out[0], np.asarray(out[1].active)) > FAIL_ABOVE * UNIT:
            raise ConvergenceError("Newton did not converge (told to fail)", iterations=25, residual=1.0)
        return out

    monkeypatch.setattr(compression, "contact", contact)


def test_a_force_past_the_stop_names_the_last_force_solved(failing_above):
    """The error names the last force solved: within the march's smallest step below the failure, and the
    number ``err.load`` carries."""
    with pytest.raises(ConvergenceError) as caught:
        solid.compression_curve(ALPHA, PHAT, [0.05, 0.3], **COARSE)
    err = caught.value
    print(err)
    # the march halves a failed step until it is below MIN_FRACTION of the first: the last step tried (from the
    # force named, to past FAIL_ABOVE) was shorter than twice that
    smallest = 2.0 * compression.MIN_FRACTION * compression.MAX_FORCE_STEP
    tried = float(re.search(r"the shortest to Fhat = ([-+0-9.e]+)", str(err)).group(1))
    assert FAIL_ABOVE - smallest < _named(err) <= FAIL_ABOVE < tried < _named(err) + smallest
    assert abs(err.load - _named(err)) <= 1e-6 * FAIL_ABOVE  # the message's six digits
    assert "told to fail" in str(err)


def test_height_control_names_the_height_and_the_force(failing_above):
    """Under height control the stop names the height reached and the force there, below the failure."""
    top = solid.inflate(ALPHA, PHAT, **COARSE).height
    with pytest.raises(ConvergenceError) as caught:
        solid.compress_height(ALPHA, PHAT, 0.8 * top, **COARSE)
    print(caught.value)
    assert "stopped at height = " in str(caught.value)
    assert 0.0 < _named(caught.value) <= FAIL_ABOVE


def test_the_command_line_says_it_in_one_line(failing_above, capsys):
    """Exit status 1, one line on stderr naming the force."""
    code = main(["compress", "--solver", "solid", "--alpha", str(ALPHA), "--pressure", str(PHAT), "--force", "0.3",
                 "--elements", str(COARSE["elements"]), "--layers", str(COARSE["layers"])])
    err = capsys.readouterr().err
    print(err)
    assert code == 1
    assert err.count("\n") == 1
    assert "stopped at Fhat = " in err


@pytest.mark.slow
def test_the_range_command_stops_where_its_path_turns_and_names_a_force_that_solves(capsys):
    """The range command (five forces to Fhat = 9 at the default mesh) without the jaw exits 1 naming a force
    between its third (5) and fourth (7) forces, and the shortest step it tried beyond; a force 1e-3 below the one
    named solves from the inflated pocket by another path of steps, one 1e-2 above it does not. (Not the forces
    named and tried themselves: the mesh that follows the contact edge depends on the path's steps, which moves the
    turning point by a few 1e-4.)"""
    args = ["compress", "--solver", "solid", "--thickness-ratio", "0.0125", "--alpha", "0.3", "--pressure", "0.3",
            "--force", "1", "3", "5", "7", "9", "--clamp-radius", "0", "--corner", "0.5", "--json"]
    assert main(args) == 1
    err = capsys.readouterr().err
    print(err)
    named = float(re.search(r"stopped at Fhat = ([-+0-9.e]+)", err).group(1))
    tried = float(re.search(r"the shortest to Fhat = ([-+0-9.e]+)", err).group(1))
    assert 5.0 < named < tried < 7.0
    state = solid.compress(0.3, 0.3, named - 1e-3, thickness_ratio=0.0125, clamp_radius=0, corner=0.5)
    assert state.force == named - 1e-3
    with pytest.raises(ConvergenceError):
        solid.compress(0.3, 0.3, named + 1e-2, thickness_ratio=0.0125, clamp_radius=0, corner=0.5)
