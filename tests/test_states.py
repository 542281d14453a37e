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
    assert state.warnings == ()
    assert "warnings" not in state.scalars()
    noted = dataclasses.replace(state, warnings=("a note",))
    assert report(noted) == {**state.scalars(), "warnings": ["a note"]}


def _inflated(tension_2=None, material=None):
    from pocket.core.materials import mooney_rivlin
    from pocket.core.states import InflatedState

    parts = _fields(5)
    if tension_2 is not None:
        parts[6] = tension_2
    return InflatedState(material=mooney_rivlin(0.3) if material is None else material, pressure=0.3,
                         stretch_pole=1.1, height=0.5, volume=0.8, stretch_clamp=1.05, profile=Profile(*parts),
                         solver="test")


def test_a_rubber_given_by_alpha_reports_that_alpha_first_and_its_c1_c2():
    """Exact answer: alpha = C2/C1 = 0.3 with mu_0 = 2 (C1 + C2) = 1 gives C1 = 1/2.6, C2 = 0.3/2.6; the state's
    alpha is the material's, and it is the first key reported."""
    state = _inflated()
    assert state.alpha == 0.3
    assert state.material.mu0 == pytest.approx(1.0, rel=1e-15)
    out = state.scalars()
    assert next(iter(out)) == "alpha"
    assert out["alpha"] == 0.3
    assert out["material"] == "mooney-rivlin"
    assert out["c1"] == pytest.approx(1 / 2.6, rel=1e-15)
    assert out["c2"] == pytest.approx(0.3 / 2.6, rel=1e-15)


@pytest.mark.parametrize(("law", "params"),
                         [("neo-hookean", {"mu": 1.0}), ("mooney-rivlin", {"c1": 160e3, "c2": 47e3})])
def test_a_rubber_given_by_its_parameters_reports_no_alpha(law, params):
    """Exact answer: the parameters as given, and no alpha (for Mooney-Rivlin none recomputed from C1, C2)."""
    from pocket.core.materials import check

    state = _inflated(material=check(law, params))
    out = state.scalars()
    assert state.alpha is None
    assert "alpha" not in out
    assert out["material"] == law
    assert {k: out[k] for k in params} == params


def test_a_state_has_no_alpha_of_its_own():
    """Exact answer: the material is the one echo of the rubber; alpha cannot be given beside it."""
    import dataclasses

    state = _inflated()
    assert "alpha" not in {f.name for f in dataclasses.fields(state)}
    with pytest.raises(TypeError):
        dataclasses.replace(state, alpha=0.5)


def test_smallest_tensions_and_the_wrinkling_flag():
    """Exact answer: the minima over the profile's tensions; a non-positive one flags the state and
    warns once, naming the tension, its value and where."""
    state = _inflated()
    assert (state.tension_1_min, state.tension_2_min, state.wrinkled, state.warnings) == (1.0, 1.0, False, ())
    slack = _inflated(tension_2=np.array([1.0, 0.5, -0.25, 0.5, 1.0]))
    assert slack.tension_2_min == -0.25
    assert slack.wrinkled
    assert slack.scalars()["wrinkled"] is True
    assert len(slack.warnings) == 1
    assert "T_2 = -0.25 E T at r = 0.5 R" in slack.warnings[0]
