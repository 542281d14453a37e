"""Bad input to the finite-element solver: a one-line InputError quoting the value,
raised before any work (STYLE.md, DESIGN.md quality bars)."""

import numpy as np
import pytest

from pocket import fem
from pocket.core.errors import ConvergenceError, InputError

CASES = [
    (lambda: fem.inflate(-1.0, 0.1), "alpha = -1.0"),
    (lambda: fem.inflate(-1.5, 0.1), "alpha = -1.5"),
    (lambda: fem.inflate(0.3, 0.0), "pressure = 0.0"),
    (lambda: fem.inflate(0.3, -0.2), "pressure = -0.2"),
    (lambda: fem.inflate_volume(0.3, -1.0), "volume = -1.0"),
    (lambda: fem.compress(0.3, 0.31, -0.1), "force = -0.1"),
    (lambda: fem.compress(0.3, -0.31, 0.1), "pressure_initial = -0.31"),
    (lambda: fem.compress(0.3, 0.31, 0.1, penalty=0.0), "penalty = 0.0"),
    (lambda: fem.compress(0.3, 0.31, 0.1, penalty=-5.0), "penalty = -5.0"),
    (lambda: fem.compress_height(0.3, 0.31, -0.1), "height = -0.1"),
    (lambda: fem.inflate(0.3, 0.1, order=3), "order = 3"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.linspace(0, 1, 3)),
     f"mesh elements = 2, but it must lie in [4, {fem.MAX_ELEMENTS}]"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.linspace(0, 2, 11)), "spans"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.linspace(0, 1, 11)[::-1]), "increasing"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.zeros((3, 4))), "1-D"),
]


@pytest.mark.parametrize("call, quoted", CASES)
def test_bad_input_is_a_one_line_input_error(call, quoted):
    """InputError, one line, quoting the offending value."""
    with pytest.raises(InputError) as info:
        call()
    message = str(info.value)
    assert quoted in message and "\n" not in message, message


def test_load_stepping_cuts_steps_then_says_where():
    """A solve that fails beyond load 0.3: the stepping halves its step until it is
    below min_step, then raises ConvergenceError with the load reached (just under
    0.3), the iterations and the residual of the last failure."""
    from pocket.fem.continuation import follow

    tried = []

    def solve(load, guess):
        tried.append(load)
        if load > 0.3:
            raise ConvergenceError("no", iterations=7, residual=1.5)
        return guess, 2

    with pytest.raises(ConvergenceError) as info:
        list(follow(solve, np.zeros(3), 0.0, 1.0, first_step=0.25, min_step=1e-3))
    err = info.value
    assert 0.29 < err.load <= 0.3 and err.iterations == 7 and err.residual == 1.5
    assert "gave up at load =" in str(err) and "\n" not in str(err)
    assert min(t for t in tried if t > 0.3) - err.load < 2e-3  # the step was cut down
