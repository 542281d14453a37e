"""The validation report's capsule section: its closed form, its checks, its figure and its tables."""

import dataclasses
import math

import numpy as np
import pytest
from pocket.validation import capsulechecks, capsulereport, capsules, document
from pocket.validation.plan import DEFAULT, QUICK
from pocket.validation.verdicts import TOLERANCES

from pocket.core.materials import energy, mooney_rivlin

FORCES = (0.0, 0.5, 2.0)


@pytest.fixture(scope="module")
def curve():
    """The gas-filled Mooney-Rivlin capsule at three forces, shooting only (a tenth of a second)."""
    capsule = next(c for c in capsules.CASES if c.material.law == "mooney-rivlin" and c.fluid.is_gas)
    return capsules.solve(capsule, FORCES, ())


@pytest.mark.parametrize("capsule", capsules.CASES[::2], ids=lambda c: c.material.law)
def test_the_closed_form_is_the_energy_derivative(capsule):
    """Independent computation: Phat = w'(lambda) / (E lambda^2), w(lambda) = W(lambda, lambda) of
    ``pocket.core.materials.energy`` differentiated by a 4th-order central difference (h = 1e-3: truncation
    ~h^4 = 1e-12, rounding ~eps w / h), E = 3 mu_0: the hand-written w' of each law agrees to 1e-8."""
    material, h = capsule.material, 1e-3

    def w(x):
        return float(energy(material, x, x))

    for stretch in (1.03, 1.2, 1.6):
        slope = (8.0 * (w(stretch + h) - w(stretch - h)) - (w(stretch + 2 * h) - w(stretch - 2 * h))) / (12 * h)
        expected = slope / (3.0 * material.mu0 * stretch**2)
        assert capsules.sphere_pressure(material, stretch) == pytest.approx(expected, rel=1e-8)


def test_the_mooney_rivlin_closed_form_and_its_small_strain_law():
    """Exact answers: Phat = 2 (1 - l^-6)(1 + alpha l^2) / (3 (1 + alpha) l) (the theory's closed form); at small
    strain Phat = 4 (lambda - 1) (a thin spherical vessel, nu = 1/2) with an O(strain^2) remainder; at lambda = 1
    no pressure."""
    for alpha in (0.0, 0.3, -0.1):
        for stretch in (1.01, 1.3):
            closed = 2 * (1 - stretch**-6) * (1 + alpha * stretch**2) / (3 * (1 + alpha) * stretch)
            assert capsules.sphere_pressure(mooney_rivlin(alpha), stretch) == pytest.approx(closed, rel=1e-14)
        assert capsules.sphere_pressure(mooney_rivlin(alpha), 1.0) == 0.0
        gaps = [abs(capsules.sphere_pressure(mooney_rivlin(alpha), 1 + e) / (4 * e) - 1) for e in (1e-3, 1e-4)]
        assert gaps[0] / gaps[1] == pytest.approx(10.0, rel=0.05)  # the remainder O(e^2): relative O(e)


def test_a_prestretched_rubber_is_refused():
    """The closed form here is the unprestretched sphere's: a prestretch is refused, not answered wrongly."""
    with pytest.raises(ValueError, match="prestretch"):
        capsules.sphere_pressure(dataclasses.replace(mooney_rivlin(0.2), prestretch=1.1), 1.2)


def test_the_suite_covers_every_law_and_fluid():
    """Every law of the rubber registry, each with a liquid and a gas, at one Phat_I, compared with the FE model;
    names unique; the convergence study's capsule is one of them."""
    from pocket.core.materials import LAWS

    pairs = {(c.material.law, c.fluid.kind) for c in capsules.CASES if c.fem and c.pressure == capsules.PRESSURE}
    assert pairs == {(law, kind) for law in LAWS for kind in ("liquid", "gas")}
    assert len({c.name for c in capsules.CASES}) == len(capsules.CASES)
    assert capsules.STUDY in capsules.CASES


def test_the_plans_press_capsules_from_the_inflated_state():
    """Both plans start at Fhat = 0 (the inflated capsule, the closed form's) and reach Fhat = 5, quick with fewer
    forces; their FE forces lie in the range of the shooting curve."""
    for plan in (DEFAULT, QUICK):
        assert plan.capsules[0] == 0.0
        assert plan.capsules[-1] == 5.0
        assert list(plan.capsules) == sorted(plan.capsules)
        assert all(0.0 <= f <= plan.capsules[-1] for f in plan.capsule_fem)
    assert len(QUICK.capsules) < len(DEFAULT.capsules)


def test_every_check_of_a_capsule_passes_and_says_what_it_holds(curve):
    """Exact answers: the closed form's row compares Phat_I with sphere_pressure at the solver's stretch; F = P A_c
    compares force_ETR with pi Phat rho_c^2; the wrinkling verdict is there; without FE states no FE rows."""
    rows = capsulechecks.checks([curve])
    assert {r.verdict for r in rows} == {"pass"}, [r for r in rows if r.verdict != "pass"]
    [sphere] = [r for r in rows if r.comparison == capsulechecks.SPHERE]
    inflated = curve.shooting[0].inflated
    assert sphere.value == inflated.pressure
    assert sphere.reference == capsules.sphere_pressure(curve.capsule.material, inflated.stretch_pole)
    [force] = [r for r in rows if r.quantity.startswith("F = P A_c")]
    state = next(s for s in curve.shooting if s.extra["force_ETR"] == force.value)
    assert force.reference == math.pi * state.pressure * state.contact_radius_deformed**2
    assert force.tolerance == TOLERANCES["capsule_force"][0]
    assert "worst of 2 forces" in force.where
    assert any(r.comparison == "membrane theory (T_1, T_2 > 0)" for r in rows)
    assert not [r for r in rows if r.comparison == capsulechecks.FEM]


def test_a_broken_balance_fails(curve):
    """A state with its contact radius 1e-8 too large fails F = P A_c (twice that, relative, in rho_c^2); one with
    its equator's tension 1e-6 too large fails the equator's balance."""
    last = curve.shooting[-1]
    wide = dataclasses.replace(last, contact_radius_deformed=last.contact_radius_deformed * (1 + 1e-8))
    broken = dataclasses.replace(curve, shooting=(*curve.shooting[:-1], wide))
    [force] = [r for r in capsulechecks.checks([broken]) if r.quantity.startswith("F = P A_c")]
    assert force.verdict == "fail"
    assert force.error == pytest.approx(2e-8, rel=1e-3)
    tension = last.profile.tension_1.copy()
    tension[-1] *= 1 + 1e-6
    taut = dataclasses.replace(last, profile=dataclasses.replace(last.profile, tension_1=tension))
    broken = dataclasses.replace(curve, shooting=(*curve.shooting[:-1], taut))
    [equator] = [r for r in capsulechecks.checks([broken]) if r.quantity.startswith("equator")]
    assert equator.verdict == "fail"


def test_the_equator_balance_of_the_inflated_sphere(curve):
    """Exact answer: on the inflated sphere (F = 0) the tension is Laplace's, T_1 = Phat lambda / 2, so
    2 pi rho T_1 = P pi rho^2 with rho = lambda."""
    state = curve.shooting[0]
    pull, balance = capsulechecks.equator_balance(state)
    stretch = state.inflated.stretch_pole
    assert balance == pytest.approx(math.pi * state.pressure * stretch**2, rel=1e-15)
    assert pull == pytest.approx(balance, rel=1e-12)


def test_the_figure_and_the_tables(curve):
    """Exact answers: the figure plots force_ETR = pi Fhat Phat_I against 1 - H / lambda_I (0 at Fhat = 0); every
    state has a row of capsule_states.csv; the section has its heading, its figure and a row per capsule."""
    fig = capsulereport.figure([curve])
    [series] = [s for p in fig.panels for s in p.series]  # a gas at PRESSURE: panel (b) only
    np.testing.assert_allclose(series.y, [math.pi * f * curve.capsule.pressure for f in FORCES], rtol=1e-15)
    assert series.x[0] == 0.0
    assert np.all(np.diff(series.x) > 0)
    header, rows = capsulereport.state_rows([curve])
    assert len(rows) == len(FORCES)
    assert header[:5] == ["case", "solver", "material", "fluid", "compression"]
    blocks = capsulereport.blocks([curve], None, capsulechecks.checks([curve]), fig.caption)
    text = document.markdown(blocks)
    assert "## A capsule between two plates" in text
    assert f"![{fig.caption} Data: capsules.csv.](capsules.png)" in text
    assert text.count(curve.capsule.label) >= 1


@pytest.mark.slow
def test_the_fe_model_agrees_on_every_capsule_of_the_quick_plan():
    """Independent solvers: every capsule of the suite with an FE column, pressed at the quick plan's FE forces, passes
    every check, and the FE rows cover every key of the capsule's contract at each force (each law and fluid)."""
    assert QUICK.capsule_fem, "the quick plan runs the FE model on capsules"
    curves = [capsules.solve(c, QUICK.capsules, QUICK.capsule_fem) for c in capsules.CASES if c.fem]
    rows = capsulechecks.checks(curves)
    assert [r for r in rows if r.verdict == "fail"] == []
    for curve in curves:
        fem = [r for r in rows if r.case == curve.capsule.name and r.comparison == capsulechecks.FEM]
        for force in QUICK.capsule_fem:
            keys = capsulechecks.INFLATED_KEYS if force == 0.0 else capsulechecks.COMPRESSED_KEYS
            quantities = {r.quantity for r in fem if r.where == f"Fhat = {force:.4g}"}
            assert quantities >= set(keys), (curve.capsule.name, force)


@pytest.mark.slow
def test_the_fe_model_converges_on_a_capsule_at_its_order():
    """Convergence: the quick plan's meshes give the theory's order 4 within the pocket's tolerance for edge-fitted P2,
    the finest error below FITTED_P2_FINEST, and Richardson's extrapolation holds shooting."""
    sequence = capsules.sequence(QUICK.capsule_sizes)
    rows = capsulechecks.order_checks(sequence)
    assert {r.verdict for r in rows} == {"pass"}, [r for r in rows if r.verdict != "pass"]
    assert {r.quantity for r in rows if r.step == "order"} == set(capsules.QUANTITIES)
