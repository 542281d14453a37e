"""Fitting a law to test data: recovery from another solver's data, honest intervals, identifiability warnings.

The data are generated here by a solver from a known rubber (the truth), so each test names its exact
answer: the truth's parameters.
"""

import dataclasses

import numpy as np
import pytest

from pocket import fem, shooting
from pocket.apps.fit.data import Dataset
from pocket.apps.fit.leastsquares import fit
from pocket.apps.fit.model import Setup
from pocket.core.materials import Material, check

pytestmark = pytest.mark.slow  # the slow lane (pytest -m slow)

R, T = 0.02, 1e-3  # clamp radius and thickness (m)

#: law -> (truth in Pa, largest Phat of its inflation data): each reaches strains where its shape shows
TRUTHS = {
    "neo-hookean": ({"mu": 0.4e6}, 0.5),
    "mooney-rivlin": ({"c1": 160e3, "c2": 47e3}, 0.6),
    "yeoh": ({"c10": 85e3, "c20": -2e3, "c30": 0.2e3}, 0.6),
    "gent": ({"mu": 0.3e6, "jm": 10.0}, 0.6),
    "ogden": ({"mu": [0.2e6], "exponents": [3.0]}, 0.6),
}


def bulge(truth: Material, phats, inflate=shooting.inflate, noise=0.0, rng=None, column="height") -> Dataset:
    """An inflation test of ``truth`` at the dimensionless pressures ``phats``, in SI, heights (or volumes)
    times (1 + noise N(0, 1))."""
    tension = 3.0 * truth.mu0 * T
    states = [inflate(truth.scaled(), p) for p in phats]
    values = np.array([s.height * R if column == "height" else s.volume * R**3 for s in states])
    if noise:
        values = values * (1.0 + noise * rng.standard_normal(values.size))
    return Dataset("inflation", np.asarray(phats) * tension / R, {column: values}, None, "synthetic")


def relative_errors(result, truth: Material) -> dict:
    return {name: abs(v / truth_value - 1.0) for name, v in zip(result.statistics.names, result.statistics.values,
                                                                 strict=True)
            for truth_value in [_value(truth, name)]}


def _value(material, name):
    if name == "prestretch":
        return material.prestretch
    if "[" in name:
        base, k = name[:-1].split("[")
        return material[base][int(k)]
    return material[name]


@pytest.mark.parametrize("law", list(TRUTHS))
def test_recovers_every_parameter_from_fem_data(law):
    """Exact answer: the truth. Ten noise-free inflation heights by the finite-element solver (P2, its
    default graded mesh, which agrees with the shooting solver to ~1e-10) are fitted with the shooting
    solver; every parameter comes back to 1e-6 relative (the data's 1e-10 amplified by the fit's
    conditioning, at most ~1e3 here: Yeoh's C30 is the least determined). One-term Ogden: both mu and
    alpha are determined by inflation to a pole stretch of ~1.6 (more terms are not: see the warnings)."""
    params, top = TRUTHS[law]
    truth = check(law, params)
    data = bulge(truth, np.linspace(top / 10.0, top, 10), inflate=fem.inflate)
    result = fit(Setup((data,), R, T), law)
    errors = relative_errors(result, truth)
    print(law, {k: f"{v:.2e}" for k, v in errors.items()}, "calls", result.calls, f"{result.seconds:.2f} s")
    assert max(errors.values()) < 1e-6, errors
    assert result.statistics.rms < 1e-8  # noise-free data: the residuals are the solvers' differences


def test_recovers_a_prestretch_and_ignoring_it_biases_the_fit():
    """Exact answer: the truth. A neo-Hookean sheet clamped with a prestretch of 1.1, ten noise-free heights by
    the finite-element solver: the fit asked for the prestretch recovers mu and lambda_p to 1e-6 (as above). The
    fit that holds the prestretch at 1 (the default) cannot follow the taut sheet's curve: its mu is off the
    truth by more than 1e-3 relative (a thousand times what the recovery meets: the model's bias, not the
    solvers' noise), and its residuals are far above the noise-free data's (1e-8 above)."""
    truth = dataclasses.replace(check("neo-hookean", TRUTHS["neo-hookean"][0]), prestretch=1.1)
    data = bulge(truth, np.linspace(0.06, 0.6, 10), inflate=fem.inflate)
    result = fit(Setup((data,), R, T), "neo-hookean", prestretch=True)
    errors = relative_errors(result, truth)
    print("fitted prestretch:", {k: f"{v:.2e}" for k, v in errors.items()})
    assert result.statistics.names == ("mu", "prestretch"), errors
    assert max(errors.values()) < 1e-6, errors
    ignored = fit(Setup((data,), R, T), "neo-hookean")
    bias = relative_errors(ignored, truth)
    print(f"prestretch ignored: mu {ignored.material['mu']:.6g} Pa against {truth['mu']:.6g} Pa, relative error "
          f"{bias['mu']:.3g}, residual RMS {ignored.statistics.rms:.3g}")
    assert ignored.statistics.names == ("mu",)
    assert bias["mu"] > 1e-3
    assert ignored.statistics.rms > 1e-3


@pytest.mark.study  # 100 fits: minutes; the 25-fit counts of test_fit_intervals run in the slow lane
def test_intervals_cover_the_truth():
    """Exact answer: a 95 % interval covers the truth in 95 % of repetitions. 100 seeded repetitions of a
    Mooney-Rivlin fit to 8 heights with 0.5 % Gaussian noise (6 degrees of freedom: Student's t, not the normal
quantile, makes the intervals honest here); the binomial spread of the count of covering
    intervals over 100 is sqrt(100 0.95 0.05) = 2.2, so an honest 95 % lands in 90-99 with margin (the
    linearisation's error at this noise level is far below that spread). Each fit starts at the truth (as a
user's good guess would): the result depends on the data, not on where the fit starts."""
    truth = check("mooney-rivlin", TRUTHS["mooney-rivlin"][0])
    phats = np.linspace(0.05, 0.6, 8)
    clean = bulge(truth, phats)
    rng = np.random.default_rng(20240518)
    start = TRUTHS["mooney-rivlin"][0]  # a good start keeps 100 fits affordable; the question is the interval
    covered = np.zeros(2, dtype=int)
    for _ in range(100):
        data = Dataset("inflation", clean.control, {"height": clean.responses["height"] *
                                                  (1.0 + 0.005 * rng.standard_normal(phats.size))}, None, "noisy")
        s = fit(Setup((data,), R, T), "mooney-rivlin", start=start).statistics
        covered += [(lo <= _value(truth, name) <= hi) for name, (lo, hi) in zip(s.names, s.intervals, strict=True)]
    print("coverage of c1, c2 over 100 repetitions:", covered.tolist())
    assert np.all((covered >= 90) & (covered <= 99)), covered


def test_warns_on_c30_from_small_strains():
    """Yeoh's C30 weighs (I1 - 3)^3: from heights that stay at small strain (Phat <= 0.05, pole strain
    < 6 %) with 0.2 % noise it is not determined, and the report says so and names mu_0 as what is."""
    truth = check("yeoh", TRUTHS["yeoh"][0])
    data = bulge(truth, np.linspace(0.005, 0.05, 12), noise=0.002, rng=np.random.default_rng(3))
    warnings = fit(Setup((data,), R, T), "yeoh").statistics.warnings
    print(warnings)
    assert any(w.startswith("c30") or "c30 are correlated" in w or "and c30" in w for w in warnings)
    assert any("mu_0" in w for w in warnings)


def test_warns_on_alpha_from_compression_alone():
    """A compression test alone (pressure against force at one P_I, 0.2 % noise) does not separate C1 from C2
    (alpha): the report warns on them and gives mu_0 as what is determined."""
    truth = check("mooney-rivlin", TRUTHS["mooney-rivlin"][0])
    tension, phat_i = 3.0 * truth.mu0 * T, 0.3
    forces = np.linspace(0.2, 2.0, 10)
    states = shooting.compression_curve(truth.scaled(), phat_i, forces)
    p_i = phat_i * tension / R
    rng = np.random.default_rng(5)
    pressure = np.array([s.pressure_ratio for s in states]) * p_i * (1.0 + 0.002 * rng.standard_normal(forces.size))
    data = Dataset("compression", forces * p_i * np.pi * R**2, {"pressure": pressure}, p_i, "pressing")
    warnings = fit(Setup((data,), R, T), "mooney-rivlin").statistics.warnings
    print(warnings)
    assert any("c2" in w for w in warnings)
    assert any("mu_0" in w for w in warnings)


def test_silent_on_a_well_posed_fit():
    """A Gent rubber inflated towards its locking (I1 - 3 up to ~60 % of Jm), 0.2 % noise: both mu and Jm are
    determined, so no warning."""
    truth = check("gent", TRUTHS["gent"][0])
    data = bulge(truth, np.linspace(0.06, 0.6, 12), noise=0.002, rng=np.random.default_rng(7))
    s = fit(Setup((data,), R, T), "gent").statistics
    print(s.standard_errors / np.abs(s.values), s.correlation)
    assert s.warnings == ()


def test_a_datum_beyond_a_trial_set_does_not_end_the_fit():
    """A Mooney-Rivlin rubber of alpha = 0.05 has a pressure maximum; its data reach close to it (states by
    volume control up to V = 5 R^3, the maximum being near 6 R^3), and the fit starts at a stiffer C2. Trial
    steps that soften it put the highest pressures above their maximum (no state there): they are penalised,
    the trust region backs off, and the fit still recovers the truth."""
    truth = check("mooney-rivlin", {"c1": 200e3, "c2": 10e3})
    states = [shooting.inflate_volume(truth.scaled(), v) for v in np.linspace(0.3, 5.0, 10)]
    tension = 3.0 * truth.mu0 * T
    data = Dataset("inflation", np.array([s.pressure for s in states]) * tension / R,
                   {"height": np.array([s.height for s in states]) * R}, None, "near the maximum")
    result = fit(Setup((data,), R, T), "mooney-rivlin", start={"c2": 40e3})
    errors = relative_errors(result, truth)
    print("penalised trial sets:", result.penalised, errors)
    assert result.penalised > 0
    assert max(errors.values()) < 1e-6  # as for noise-free data above


def test_too_few_data_is_refused_before_solving(monkeypatch):
    """Three heights cannot determine Yeoh's three parameters and a residual variance: an InputError, and
    no solve (the model is not called)."""
    import pocket.apps.fit.leastsquares as module
    from pocket.core.errors import InputError

    monkeypatch.setattr(module, "predict", lambda *a: pytest.fail("solved"))
    data = Dataset("inflation", np.array([1e3, 2e3, 3e3]), {"height": np.array([1e-3, 2e-3, 3e-3])}, None, "few")
    with pytest.raises(InputError, match="3 data, but fitting 3 parameters"):
        fit(Setup((data,), R, T), "yeoh")


def test_fem_solver_fits_as_shooting_does(monkeypatch):
    """The finite-element solver as the fit's model (``Setup.solver = "fem"``): every solve of the fit goes to
    its record (counted through ``pocket.apps.fit.model.entry``), and it recovers the parameter the shooting fit
    recovers from the same noise-free data, to 1e-8 relative: the FE heights' floor (~1e-10 relative to the
    shooting solver's, its default P2 mesh) times the fit's conditioning (mu ~ H^-3 at small strain: 3)."""
    import pocket.apps.fit.model as model

    used = []
    original = model.entry
    monkeypatch.setattr(model, "entry", lambda solver, name, purpose: used.append((solver.name, name)) or
                        original(solver, name, purpose))
    truth = check("neo-hookean", TRUTHS["neo-hookean"][0])
    data = bulge(truth, np.linspace(0.1, 0.5, 5))
    by_fem = fit(Setup((data,), R, T, "fem"), "neo-hookean")
    assert by_fem.calls > 0, set(used)
    assert set(used) == {("fem", "inflate")}, set(used)
    used.clear()
    by_shooting = fit(Setup((data,), R, T), "neo-hookean")
    assert ("shooting", "inflation_curve") in used
    assert {s for s, _ in used} == {"shooting"}
    difference = abs(by_fem.material["mu"] / by_shooting.material["mu"] - 1.0)
    print(f"mu by fem {by_fem.material['mu']:.12g}, by shooting {by_shooting.material['mu']:.12g}: {difference:.2e}; "
          f"fem calls {by_fem.calls}")
    assert difference < 1e-8


def test_two_term_ogden_gives_mu0_and_the_curve():
    """Exact answer: the truth's mu_0 and its curve (the data). A two-term Ogden rubber (exponents 2 and 5), ten
    noise-free heights by the finite-element solver, fitted with two terms by the shooting solver: the fit ends
    (its evaluations are capped), mu_0 comes back to 1e-6 relative and the model meets every datum to 1e-6 (as
    the one-term recovery above), and the report says which parameters the data determine only together (the
    stiff term's modulus and exponent: near the small strains of a bulge test, a stiffer exponent and a smaller
    modulus give nearly the same curve)."""
    truth = check("ogden", {"mu": [150e3, 10e3], "exponents": [2.0, 5.0]})
    data = bulge(truth, np.linspace(0.06, 0.6, 10), inflate=fem.inflate)
    result = fit(Setup((data,), R, T), "ogden", terms=2)
    s = result.statistics
    print({k: f"{v:.2e}" for k, v in relative_errors(result, truth).items()}, "calls", result.calls,
          f"{result.seconds:.1f} s", s.warnings)
    assert abs(s.mu0 / truth.mu0 - 1.0) < 1e-6
    assert np.max(np.abs(result.residuals)) < 1e-6
    stiff = int(np.argmax(result.material["exponents"]))  # the terms come back in either order
    assert any(f"mu[{stiff}] and exponents[{stiff}] are correlated" in w for w in s.warnings), s.warnings
