"""The evidence behind the report's section on the paper: the buttons of section 6, checked independently."""

import math

import pytest
from pocket.validation.evidence import collect
from pocket.validation.suite import load

from pocket import shooting
from pocket.apps.design import PAPER_FORCE_FACTOR


@pytest.fixture(scope="module")
def evidence():
    button = load()[1]
    return button, collect(button)


def test_full_button_meets_its_targets(evidence):
    """Exact answer: the full model's button, inflated again at its Phat_I, has H0/R = 10 mm / 20 mm, and
    compressed again at its target force has H/H0 = 0.8 (1e-9: the root finders resolve 1e-13, the solver
    1e-10); its coefficient is 1 / that force."""
    button, proof = evidence
    full = proof.buttons["full"]
    assert shooting.inflate(button.alpha, full["pressure_hat"]).height == pytest.approx(0.5, rel=1e-9)
    state = shooting.compress(button.alpha, full["pressure_hat"], full["force_at_target"])
    assert state.height_ratio == pytest.approx(button.height_ratio, rel=1e-9)
    assert full["coefficient"] == 1.0 / full["force_at_target"]


def test_paper_button_is_the_paper_rules_in_the_full_model(evidence):
    """Exact answer: the paper's button has Phat_I = P_I R / (E T) with the rules' P_I and T by hand,
    and its H/H0 is the full model's at Fhat = 1/5.7 (the rule's force, exactly)."""
    button, proof = evidence
    paper = proof.buttons["paper"]
    pressure = 5.7 * 0.67 / (math.pi * 0.02**2)
    thickness = 0.216 * pressure * 0.02**4 / (1e6 * 0.01**3)
    assert paper["pressure_hat"] == pytest.approx(pressure * 0.02 / (1e6 * thickness), rel=1e-13)
    state = shooting.compress(button.alpha, paper["pressure_hat"], 1.0 / PAPER_FORCE_FACTOR)
    assert paper["height_ratio"] == state.height_ratio
    assert paper["height"] == state.inflated.height


def test_thickness_coefficient_gives_back_the_design(evidence):
    """Exact answer: with k of T = k P_I R^4 / (E H0^3) and the full button's P_I = F / (pi R^2 Fhat*),
    T = P_I R / (E Phat_I*) (the definition of Phat): two routes to one number."""
    button, proof = evidence
    full = proof.buttons["full"]
    pressure = button.force / (math.pi * button.radius**2 * full["force_at_target"])
    by_k = proof.thickness_coefficient * pressure * button.radius**4 / (button.modulus * button.height**3)
    assert by_k == pytest.approx(pressure * button.radius / (button.modulus * full["pressure_hat"]), rel=1e-13)
