"""The shared state vocabulary: a profile's fields sample one set of radii."""

import numpy as np
import pytest

from pocket.core.states import Profile


def _fields(n):
    r = np.linspace(0.0, 1.0, n)
    return [r, r, 1 - r**2, np.ones(n), np.ones(n), np.ones(n), np.ones(n), np.zeros(n, bool)]


def test_profile_of_equal_lengths_is_accepted():
    """Exact answer: lambda_3 = 1 / (lambda_1 lambda_2) = 1 for unit stretches."""
    assert np.array_equal(Profile(*_fields(5)).stretch_3, np.ones(5))


@pytest.mark.parametrize("field", range(8))
def test_profile_with_a_field_of_another_length_is_refused(field):
    """Exact answer: every field but one has n = 5 points, that one 4: a ValueError naming the shapes."""
    fields = _fields(5)
    fields[field] = fields[field][:4]
    with pytest.raises(ValueError, match="one common shape"):
        Profile(*fields)


def test_warnings_stay_out_of_the_scalars():
    """Exact answer: a state's warnings default to none and are no reported scalar; the command line
    adds them to JSON as a list (pocket.cli.common.report)."""
    import dataclasses

    from pocket import shooting
    from pocket.cli.common import report

    state = shooting.inflate(0.3, 0.3)
    assert state.warnings == () and "warnings" not in state.scalars()
    noted = dataclasses.replace(state, warnings=("a note",))
    assert report(noted) == {**state.scalars(), "warnings": ["a note"]}
