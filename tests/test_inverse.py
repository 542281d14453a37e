"""The inverse problems hand the solver options through (pocket.apps.inverse)."""

from pocket import shooting
from pocket.apps.inverse import range_end


def test_range_end_passes_the_solver_options_through():
    """Exact answer: the shooting solver's own range end at the same ODE tolerance, for two tolerances (a
    case file's [solver] rtol once stood in for the bisection width and never reached the solver)."""
    for rtol in (1e-8, 1e-12):
        assert range_end(shooting.SOLVER, 0.3, 0.3, rtol=rtol) == shooting.range_end(0.3, 0.3, rtol=rtol)
    assert range_end(shooting.SOLVER, 0.3, 0.3, rtol=1e-8) != range_end(shooting.SOLVER, 0.3, 0.3, rtol=1e-12)
