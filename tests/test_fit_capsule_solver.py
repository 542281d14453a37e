"""``pocket fit --geometry capsule`` on the shooting solver: a neo-Hookean capsule's wall recovered from its
micromanipulation test, as a user runs it.

Each test makes its data beside the fit: the shooting solver compresses a known capsule (mu = 0.1 MPa, R = 50 um,
T = 1 um, P_I = 1200 Pa: Phat_I = P_I R / (3 mu T) = 0.2) at forces Fhat = F / (P_I pi R^2) from 0 to 2 (to about
half the untouched gap), by one continuation; the fit then solves a new curve at every trial and finds the
parameters back. So each names its exact answer: the truth. Its tolerance, 1e-6 relative: the least squares stop
on steps of 1e-8 (``pocket.apps.fit.leastsquares``) and the solver's gaps are good to ~1e-10, a decade below the
recovery test of the clamped sheet's fit; the achieved error is printed.
"""

import json
import math
import time

import numpy as np
import pytest

from pocket import shooting
from pocket.apps.fit import capsuletest
from pocket.apps.fit.data import Dataset
from pocket.apps.fit.model import Setup
from pocket.cli import main
from pocket.core.materials import Material

pytestmark = pytest.mark.slow  # each fit solves ten to thirty compression curves: seconds

R, T, P_I, MU = 50e-6, 1e-6, 1200.0, 1e5
FHATS = np.linspace(0.0, 2.0, 9)
#: the acceptance command, as a user writes it
COMMAND = ["--geometry", "capsule", "--law", "neo-hookean", "--radius", "50 um", "--thickness", "1 um",
           "--initial-pressure", "1200 Pa", "--json"]


def squeeze(fhats=FHATS, mu=MU):
    """The truth's test: forces (N) and the states the shooting solver gives (one continuation)."""
    phat = P_I * R / (3.0 * mu * T)
    states = shooting.compression_curve(Material("neo-hookean", {"mu": 1.0}), phat, list(fhats), geometry="capsule")
    return np.asarray(fhats) * P_I * math.pi * R**2, states


def csv(path, column="gap", units=("uN", "um"), factors=(1e6, 1e6), fhats=FHATS):
    """The truth's test written as a user has it: forces and gaps (or displacements from first touch)."""
    forces, states = squeeze(fhats)
    values = [2.0 * R * (s.height if column == "gap" else s.inflated.height - s.height) for s in states]
    rows = [f"{float(f * factors[0])!r},{float(v * factors[1])!r}" for f, v in zip(forces, values, strict=True)]
    path.write_text(f"force [{units[0]}],{column} [{units[1]}]\n" + "\n".join(rows) + "\n")
    return str(path)


def _fit(args, capsys):
    clock = time.perf_counter()
    assert main(["fit", *args]) == 0
    out = json.loads(capsys.readouterr().out)
    print(f"{time.perf_counter() - clock:.1f} s, {out['solver_calls']} solver calls:",
          {k: (p["value"], p["standard_error"]) for k, p in out["parameters"].items()}, out["warnings"])
    return out


def test_the_command_recovers_mu(tmp_path, capsys):
    """Exact answer: mu = 0.1 MPa, in Pa, from the gaps in um at forces in uN; P_I held (under ``fixed``), and the
    capsule's block gives the truth's Phat_I and its untouched gap (the data's first row)."""
    out = _fit([csv(tmp_path / "squeeze.csv"), *COMMAND], capsys)
    mu = out["parameters"]["mu"]
    assert mu["unit"] == "Pa"
    assert mu["value"] == pytest.approx(MU, rel=1e-6)
    assert out["fixed"]["initial_pressure"] == {"value": P_I, "unit": "Pa"}
    assert out["capsule"]["pressure_initial"] == pytest.approx(P_I * R / (3.0 * MU * T), rel=1e-6)
    assert out["capsule"]["gap_initial_m"] == pytest.approx(2.0 * R * squeeze([0.0])[1][0].height, rel=1e-6)
    assert out["warnings"] == []


def test_displacement_in_other_units(tmp_path, capsys):
    """Exact answer: the same mu, from the plates' approach since first touch in nm at forces in nN."""
    data = csv(tmp_path / "squeeze.csv", "displacement", ("nN", "nm"), (1e9, 1e9))
    out = _fit([data, *COMMAND], capsys)
    assert out["parameters"]["mu"]["value"] == pytest.approx(MU, rel=1e-6)
    assert out["data"] == FHATS.size - 1  # the zero-force row is the displacement's origin, not a datum


def test_without_thickness_reports_mu_t(tmp_path, capsys):
    """Exact answer: mu T = 0.1 N/m: without a thickness the model sees the wall through mu_0 T only."""
    command = [c for c in COMMAND if c not in ("--thickness", "1 um")]
    out = _fit([csv(tmp_path / "squeeze.csv"), *command], capsys)
    assert out["parameters"]["mu"]["unit"] == "N/m"
    assert out["parameters"]["mu"]["value"] == pytest.approx(MU * T, rel=1e-6)


def test_fits_the_initial_pressure(tmp_path, capsys):
    """Exact answers: mu and P_I = 1200 Pa, from a start of 1000 Pa, with their errors and intervals; compressed to
    half its gap the capsule separates them (no warning)."""
    command = [*COMMAND[:-3], "--initial-pressure", "1000 Pa", "--fit-initial-pressure", "--json"]
    out = _fit([csv(tmp_path / "squeeze.csv"), *command], capsys)
    pressure = out["parameters"]["initial_pressure"]
    assert out["parameters"]["mu"]["value"] == pytest.approx(MU, rel=1e-6)
    assert pressure["value"] == pytest.approx(P_I, rel=1e-6)
    assert pressure["unit"] == "Pa"
    assert pressure["interval_95"][0] <= pressure["value"] <= pressure["interval_95"][1]
    assert out["warnings"] == []


def test_small_deformation_does_not_separate_p_i_from_e_t():
    """At forces of a fiftieth of P_I pi R^2 (each plate displaced by a few hundredths of R) the plates press on the
    inflated wall's tension, and E T enters the curve only through a logarithm: the estimates of P_I and mu are
    correlated beyond ``pocket.apps.fit.stats.CORRELATED`` and the fit says so (noise-free data: the correlation
    is the Jacobian's). Noise-free, the fit still recovers both (exact answer: the truth, to 1e-6)."""
    forces, states = squeeze(np.linspace(0.01, 0.02, 4))
    gaps = np.array([2.0 * R * s.height for s in states])
    setup = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "small"),), R, T)
    result = capsuletest.fit(setup, "neo-hookean", 1000.0, fit_pressure=True)
    s = result.statistics
    print(f"r = {s.correlation[0, 1]:+.6f}", s.values, s.warnings)
    assert any("do not separate the initial pressure" in w for w in s.warnings), s.warnings
    assert result.material["mu"] == pytest.approx(MU, rel=1e-6)
    assert result.initial_pressure == pytest.approx(P_I, rel=1e-6)


@pytest.mark.parametrize(("law", "truth"), [("mooney-rivlin", {"c1": 40e3, "c2": 10e3}),
                                            ("yeoh", {"c10": 50e3, "c20": -1e3, "c30": 200.0}),
                                            ("gent", {"mu": 1e5, "jm": 20.0})])
def test_every_parameter_of_other_laws(law, truth):
    """Exact answer: the truth's every parameter, P_I held, from a capsule of that law (mu_0 = 0.1 MPa: Phat_I =
    0.2) compressed at twelve forces to Fhat = 4 (about 60 % of its gap), where the law's shape shows."""
    from pocket.core.materials import check

    rubber = check(law, truth)
    phat = P_I * R / (3.0 * rubber.mu0 * T)
    fhats = np.linspace(0.0, 4.0, 12)
    states = shooting.compression_curve(rubber.scaled(), phat, list(fhats), geometry="capsule")
    gaps = np.array([2.0 * R * s.height for s in states])
    setup = Setup((Dataset("capsule", fhats * P_I * math.pi * R**2, {"gap": gaps}, None, law),), R, T)
    result = capsuletest.fit(setup, law, P_I)
    print(dict(zip(result.statistics.names, result.statistics.values, strict=True)), result.calls,
          f"{result.seconds:.1f} s")
    for name, value in truth.items():
        assert result.material[name] == pytest.approx(value, rel=1e-6), name


def test_noisy_gaps_give_profile_intervals_around_the_truth():
    """Gaps read to 0.1 um (Gaussian noise of that deviation, a fixed seed, stated as --sigma would): mu and P_I
    are fitted with profile-likelihood intervals (each held in turn, the other re-fitted: P_I is a key like the
    law's), each inside its bound (P_I > 0) and each holding the truth, as a 95 % interval does for all but one
    draw in twenty (this draw is one of the nineteen: a check of the plumbing, not of the coverage)."""
    fhats = np.linspace(0.0, 2.0, 12)
    forces, states = squeeze(fhats)
    gaps = np.array([2.0 * R * s.height for s in states]) + 0.1e-6 * np.random.default_rng(0).standard_normal(12)
    setup = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "noisy"),), R, T, sigma={"gap": 0.1e-6})
    result = capsuletest.fit(setup, "neo-hookean", 1000.0, fit_pressure=True)
    s = result.statistics
    print(dict(zip(s.names, s.values, strict=True)), s.standard_errors, s.intervals.tolist(), s.methods, result.calls)
    assert s.methods == ("profile likelihood", "profile likelihood")
    for (low, high), truth in zip(s.intervals, (MU, P_I), strict=True):
        assert 0.0 < low < truth < high


def test_an_uninflated_capsules_wall_from_its_test(tmp_path, capsys):
    """An uninflated capsule (P_I = 0, ``--initial-pressure "0 Pa"``, held): its test made by the shooting solver
    at four plate heights on its range (its forces F / (E T R) at the truth's E T = 3 mu T), the wall fitted by the
    finite elements (``--solver fem``: the shooting solver finds each force by a root over its heights, sixty times
    slower). mu comes back within 1e-5, the bar of a capsule's fit, which the finite elements' own error at these
    states (the solvers agree to ~1e-9 in every key away from the range's start) leaves far above what they reach;
    the capsule's block reports P_I = 0 and the unstressed sphere's gap 2 R."""
    neo = Material("neo-hookean", {"mu": 1.0})
    et = 3.0 * MU * T
    rows = []
    for height in (0.75, 0.65, 0.55, 0.45):
        state = shooting.compress_height(neo, 0.0, height, geometry="capsule")
        rows.append(f"{float(state.extra['force_ETR'] * et * R * 1e6)!r},{float(2.0 * state.height * R * 1e6)!r}")
    (tmp_path / "squeeze.csv").write_text("force [uN],gap [um]\n" + "\n".join(rows) + "\n")
    command = [*COMMAND[:COMMAND.index("--initial-pressure")], "--initial-pressure", "0 Pa", "--solver", "fem",
               "--json"]
    out = _fit([str(tmp_path / "squeeze.csv"), *command], capsys)
    assert out["parameters"]["mu"]["value"] == pytest.approx(MU, rel=1e-5)
    assert out["fixed"]["initial_pressure"] == {"value": 0.0, "unit": "Pa"}
    assert out["capsule"]["pressure_initial"] == 0.0
    assert out["capsule"]["gap_initial_m"] == pytest.approx(2.0 * R, rel=1e-12)
