"""``pocket fit --geometry capsule``: a capsule's micromanipulation test read in any unit, bad data refused in one
line before any solve, and the least squares' plumbing (keys, scales, the held or fitted P_I, statistics, the JSON)
checked on a stand-in model whose answer is known.

The stand-in replaces the solver's compression curve (``pocket.apps.fit.capsulemodel.compressed``) by the
small-force law of docs/theory.md (section 12), a smooth closed form in Phat_I and Fhat: the data are made by it
at a known rubber and P_I, so the fit must return them (to its tolerances, far below 1e-6). The fit against the
solver itself is ``tests/test_fit_capsule_solver.py``.
"""

import json
import math
import types

import numpy as np
import pytest

from pocket.apps.fit import capsuledata, capsulemodel, capsuletest
from pocket.apps.fit.data import Dataset
from pocket.apps.fit.model import PENALTY, Setup
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.materials import check

R, T, P_I = 50e-6, 1e-6, 1200.0  # the capsule's radius and wall (m), its initial pressure (Pa)
TRUTH = check("neo-hookean", {"mu": 1e6})
CAPSULE = ["--geometry", "capsule", "--radius", "50 um", "--thickness", "1 um", "--initial-pressure", "1200 Pa"]
_GAMMA = 0.5772156649015329  # Euler's constant


def stretch(phat: float) -> float:
    """The stand-in's inflated stretch: the small-strain sphere, Phat = 4 (lambda - 1) (docs/theory.md)."""
    return 1.0 + phat / 4.0


def dent(phat: float, force: float) -> float | None:
    """The stand-in's plate height H: lambda minus the small-force law's displacement (docs/theory.md,
    section 12); None past Fhat = Phat_I / 4, where the law's displacement would stop growing (its range end)."""
    lam = stretch(phat)
    if force == 0.0:
        return lam
    if force > phat / 4.0:
        return None
    return lam - force / (2.0 * lam) * (math.log(2.0 * lam**3 * phat / force) + 1.0 - 2.0 * _GAMMA)


def stand_in(setup, material, phat, forces, calls, geometry=None):
    """``pocket.apps.fit.model.compressed`` replaced: the stand-in's states (``height``, ``inflated.height``)."""
    assert geometry == "capsule"
    calls[0] += 1
    inflated = types.SimpleNamespace(height=stretch(phat))
    heights = [dent(phat, f) for f in forces]
    return [None if h is None else types.SimpleNamespace(height=h, inflated=inflated) for h in heights]


@pytest.fixture
def model(monkeypatch):
    """The stand-in as the capsule's model, and its inflation as the summary's."""
    monkeypatch.setattr(capsulemodel, "compressed", stand_in)
    inflate = lambda material, phat, **kw: types.SimpleNamespace(stretch_pole=stretch(phat))  # noqa: E731
    monkeypatch.setattr(capsuletest, "entry", lambda *a: inflate)


@pytest.fixture
def no_solve(monkeypatch):
    """Fail the test if any solver is called (a refusal must come before any solve)."""
    import pocket.apps.fit.model as fitmodel

    monkeypatch.setattr(fitmodel, "entry", lambda *a: pytest.fail("solved"))
    monkeypatch.setattr(capsuletest, "entry", lambda *a: pytest.fail("solved"))


def squeeze(truth=TRUTH, pressure=P_I, share=(0.02, 0.05, 0.1, 0.15, 0.2, 0.25), gap=True):
    """The stand-in's test of ``truth`` at ``pressure`` (Pa): forces Fhat = share * Phat_I, in N, with the gap (or
    the displacement) in m."""
    phat = pressure * R / (3.0 * truth.mu0 * T)
    forces = np.array(share) * phat
    heights = np.array([dent(phat, f) for f in forces])
    values = 2.0 * R * heights if gap else 2.0 * R * (stretch(phat) - heights)
    return forces * pressure * math.pi * R**2, values


def write(path, forces, values, header="force [uN],gap [um]", factors=(1e6, 1e6)):
    rows = [f"{float(f * factors[0])!r},{float(v * factors[1])!r}" for f, v in zip(forces, values, strict=True)]
    path.write_text(header + "\n" + "\n".join(rows) + "\n")
    return str(path)


def test_read_any_unit(tmp_path):
    """Exact answer: the SI values written. The same test in uN and um, in mN and mm with ';' and decimal commas,
    and as displacements from first touch (its zero-force row the origin, not a datum)."""
    forces, gaps = squeeze()
    a = capsuledata.read(write(tmp_path / "a.csv", forces, gaps))
    (tmp_path / "b.csv").write_text("force [mN];gap [mm]\n" + "\n".join(
        f"{float(f * 1e3)!r};{float(g * 1e3)!r}".replace(".", ",") for f, g in zip(forces, gaps, strict=True)) + "\n")
    b = capsuledata.read(tmp_path / "b.csv")
    assert a.kind == b.kind == "capsule"
    np.testing.assert_allclose(a.control, forces, rtol=1e-15)
    np.testing.assert_allclose(b.control, forces, rtol=1e-15)
    np.testing.assert_allclose(a.responses["gap"], gaps, rtol=1e-15)
    np.testing.assert_allclose(b.responses["gap"], gaps, rtol=1e-15)
    moved = capsuledata.read(write(tmp_path / "d.csv", [0.0, *forces], [0.0, *squeeze(gap=False)[1]],
                                   "force [N],displacement [m]", (1.0, 1.0)))
    assert math.isnan(moved.responses["displacement"][0])
    assert moved.count == forces.size


BAD = {
    "a column without a unit": ("force,gap [um]\n0,100\n1,99\n", [], "has no unit"),
    "a cell not a number": ("force [uN],gap [um]\n0,100\n1,abc\n", [], "row 2, gap = 'abc' is not a finite number"),
    "a negative force": ("force [uN],gap [um]\n-1,100\n1,99\n", [], "row 1, force = -1e-06 N, but it must be >= 0"),
    "a force twice": ("force [uN],gap [um]\n1,100\n1,99\n", [], "a force given twice"),
    "no force above zero": ("force [uN],gap [um]\n0,100\n", [], "no row with a force above 0"),
    "a gap of zero": ("force [uN],gap [um]\n0,100\n1,0\n", [], "row 2, gap = 0 m, but it must be > 0"),
    "both gap and displacement": ("force [uN],gap [um],displacement [um]\n0,100,0\n1,99,1\n", [],
                                  "both a gap and a displacement column"),
    "no gap": ("force [uN]\n0\n1\n", [], "no gap or displacement column"),
    "a pressure column": ("force [uN],pressure [kPa]\n0,1\n1,2\n", [], "the fit cannot use a column 'pressure'"),
    "a displacement at zero force": ("force [uN],displacement [um]\n0,3\n1,4\n", [],
                                     "row 1, displacement = 3e-06 m at force = 0 N"),
    "a negative displacement": ("force [uN],displacement [um]\n0,0\n1,-4\n", [], "row 2, displacement = -4e-06 m"),
    "a gap in mm for um": ("force [uN],gap [mm]\n0,101\n1,99\n", [], "the gap column reaches 0.101 m, 2.02e+03 R"),
    "a gap in nm for um": ("force [uN],gap [nm]\n0,101\n1,0.05\n", [], "the gap column falls to 5e-11 m"),
    "no initial pressure": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--initial-pressure"],
                            "--initial-pressure is missing"),
    "a negative initial pressure": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--initial-pressure", "-1 Pa"],
                                    "--initial-pressure = '-1 Pa'"),
    "an initial pressure of 0 fitted": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n",
                                        ["--initial-pressure", "0 Pa", "--fit-initial-pressure", None],
                                        "an uninflated capsule's P_I is held"),
    "no radius": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--radius"], "--radius is missing"),
    "a prestretch fitted": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--fit-prestretch", None],
                            "no prestretch to fit"),
    "a prestretch held": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--fix", "prestretch=1.1"],
                          "--fix prestretch: a capsule's reference sphere"),
    "P_I held by --fix": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--fix", "initial_pressure=1 kPa"],
                          "--fix = 'initial_pressure', but the law's keys are"),
    "an uncertainty of the force": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--sigma", "force=1 uN"],
                                    "force is the controlled variable of capsule tests"),
    "an uncertainty of a height": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--sigma", "height=1 um"],
                                   "--sigma height: not a column of test data (force, gap, displacement)"),
    "an uncertainty above every gap": ("force [uN],gap [um]\n0,100\n1,99\n2,98\n", ["--sigma", "gap=1 mm"],
                                       "--sigma gap: the uncertainty 0.001 m is more than every gap datum"),
    "too few data": ("force [uN],gap [um]\n1,99\n", ["--fit-initial-pressure", None, "--law", "neo-hookean"],
                     "1 data, but fitting 2 parameters"),
}


def _flags(changes):
    """The capsule's flags with ``changes``: pairs (flag, value), value None for a switch (added), a flag alone at
    the end (removed with its value)."""
    flags = list(CAPSULE)
    pairs = list(zip(changes[::2], changes[1::2], strict=False))
    for flag, value in pairs:
        if flag in flags:
            i = flags.index(flag)
            if value is None:
                del flags[i:i + 2]
            else:
                flags[i + 1] = value
        else:
            flags += [flag] if value is None else [flag, value]
    if len(changes) % 2:
        i = flags.index(changes[-1])
        del flags[i:i + 2]
    return flags


@pytest.mark.parametrize("case", list(BAD))
def test_bad_data_one_line_exit_2_before_solving(case, tmp_path, capsys, no_solve, monkeypatch):
    """Each defect of the data or the flags is one line on stderr naming it, exit status 2, and no solve."""
    text, changes, message = BAD[case]
    (tmp_path / "data.csv").write_text(text)
    monkeypatch.chdir(tmp_path)
    status = main(["fit", str(tmp_path / "data.csv"), *_flags(changes)])
    out, err = capsys.readouterr()
    assert status == 2, err
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err


def test_flags_refused_where_they_mean_nothing(tmp_path, capsys, no_solve):
    """--fit-initial-pressure fits a capsule's P_I only; a case file sets up the clamped sheet's fit, not a
    capsule's: each one line, exit 2."""
    (tmp_path / "b.csv").write_text("pressure [kPa],height [mm]\n1,2\n2,3\n3,4\n")
    (tmp_path / "case.toml").write_text('[clamp]\nradius = "20 mm"\n[fit]\ndata = ["b.csv"]\n')
    for args, message in (([str(tmp_path / "b.csv"), "--radius", "20 mm", "--fit-initial-pressure"],
                           "--fit-initial-pressure: only a capsule's fit"),
                          ([str(tmp_path / "case.toml"), "--geometry", "capsule"],
                           "--geometry capsule: a case file sets up")):
        assert main(["fit", *args]) == 2
        out, err = capsys.readouterr()
        assert out == "", err
        assert err.count("\n") == 1, err
        assert message in err, err


def test_keys_move_the_trial():
    """A capsule's keys: the law's (no prestretch) on the trial's rubber, then P_I in Pa; each put returns a new
    trial and leaves the old one as it was."""
    keys = capsulemodel.capsule_keys("mooney-rivlin")
    assert [k.name for k in keys] == ["c1", "c2", "initial_pressure"]
    trial = capsulemodel.Trial(check("mooney-rivlin", {"c1": 1.0, "c2": 2.0}), 5.0)
    moved = keys[1].put(keys[2].put(trial, 7.0), 3.0)
    assert (moved.material["c2"], moved.pressure_initial, trial.material["c2"], trial.pressure_initial) == \
        (3.0, 7.0, 2.0, 5.0)
    assert moved.mu0 == 2.0 * (1.0 + 3.0)
    assert (keys[2].unit, keys[2].lower) == ("pressure", 0.0)


def test_gap_and_displacement_residuals(model):
    """Exact answer: a displacement is the untouched gap less the gap, so at a trial its residual (model - datum)
    / (2 R) is the gap's with its sign turned plus the trial's lambda_I less the truth's; at the truth both are 0
    (to rounding). A datum past the stand-in's range end has the penalty, whatever the column."""
    forces, gaps = squeeze()
    _, moved = squeeze(gap=False)
    by_gap = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "g"),), R, T)
    by_move = Setup((Dataset("capsule", forces, {"displacement": moved}, None, "d"),), R, T)
    truth = capsulemodel.Trial(TRUTH, P_I)
    for trial in (truth, capsulemodel.Trial(check("neo-hookean", {"mu": 0.8e6}), 1150.0)):
        r_gap = capsulemodel.residuals(by_gap, capsulemodel.predict(by_gap, trial)[0])
        r_move = capsulemodel.residuals(by_move, capsulemodel.predict(by_move, trial)[0])
        shift = stretch(trial.pressure_initial * R / (3.0 * trial.mu0 * T)) - stretch(P_I * R / (3.0 * TRUTH.mu0 * T))
        np.testing.assert_allclose(r_move, -r_gap + shift, rtol=1e-9, atol=1e-15)
    assert np.max(np.abs(r_gap)) > 1e-4  # the second trial is off the data
    at_truth = capsulemodel.residuals(by_gap, capsulemodel.predict(by_gap, truth)[0])
    assert np.max(np.abs(at_truth)) < 1e-14
    past = capsulemodel.Trial(check("neo-hookean", {"mu": 2e6}), P_I)  # Phat_I halved: the last three are past
    for setup in (by_gap, by_move):
        r = capsulemodel.residuals(setup, capsulemodel.predict(setup, past)[0])
        assert list(r == PENALTY) == [False, False, False, True, True, True]


@pytest.mark.parametrize("fit_pressure", [False, True])
def test_recovers_the_stand_ins_truth(model, fit_pressure):
    """Exact answer: the truth, mu = 1 MPa (and P_I = 1200 Pa when fitted, from a start 20 % off), from noise-free
    data of the stand-in; 1e-7 relative: the least squares' tolerances (1e-8) on a well-scaled problem."""
    forces, gaps = squeeze()
    setup = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "stand-in"),), R, T)
    result = capsuletest.fit(setup, "neo-hookean", P_I * (1.2 if fit_pressure else 1.0), fit_pressure=fit_pressure)
    print(result.material["mu"], result.initial_pressure, result.statistics.warnings)
    assert result.material["mu"] == pytest.approx(TRUTH["mu"], rel=1e-7)
    assert result.initial_pressure == pytest.approx(P_I, rel=1e-7)
    assert result.statistics.names == (("mu", "initial_pressure") if fit_pressure else ("mu",))
    assert ("initial_pressure" in result.fixed) is not fit_pressure


def test_json_as_the_pockets(model, tmp_path, capsys):
    """The JSON has the pocket fit's keys (the law's parameter under its key, in Pa with a thickness, N/m times T
    without one; P_I under ``fixed``, or under ``parameters`` with its error and interval when fitted), and the
    capsule's block; the text report prints the same table. Exact answers: the stand-in's truth, times T without a
    thickness, and its inflated gap 2 lambda_I R."""
    forces, gaps = squeeze()
    data = write(tmp_path / "squeeze.csv", forces, gaps)
    assert main(["fit", data, *CAPSULE, "--law", "neo-hookean", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["parameters"]["mu"]["value"] == pytest.approx(TRUTH["mu"], rel=1e-7)
    assert out["parameters"]["mu"]["unit"] == "Pa"
    assert out["fixed"] == {"initial_pressure": {"value": P_I, "unit": "Pa"}}
    phat = P_I * R / (3.0 * TRUTH.mu0 * T)
    assert out["capsule"]["gap_initial_m"] == pytest.approx(2.0 * R * stretch(phat), rel=1e-7)
    assert {"law", "mu0", "correlation", "residual_rms", "warnings", "solver_calls"} <= set(out)
    no_thickness = [f for f in CAPSULE if f not in ("--thickness", "1 um")]
    assert main(["fit", data, *no_thickness, "--law", "neo-hookean", "--json", "--fit-initial-pressure"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["parameters"]["mu"]["unit"] == "N/m"
    assert out["parameters"]["mu"]["value"] == pytest.approx(TRUTH["mu"] * T, rel=1e-7)
    pressure = out["parameters"]["initial_pressure"]
    assert pressure["unit"] == "Pa"
    assert pressure["value"] == pytest.approx(P_I, rel=1e-7)
    assert pressure["interval_95"][0] <= pressure["value"] <= pressure["interval_95"][1]
    assert main(["fit", data, *CAPSULE, "--law", "neo-hookean"]) == 0
    text = capsys.readouterr().out
    assert all(word in text for word in ("initial_pressure", "(fixed)", "gap at first touch")), text


@pytest.mark.slow  # matplotlib's import and the figure: a second
def test_out_writes_the_figure(model, tmp_path, capsys):
    """--out DIR writes the figure of the data, the fitted curve and the residuals; not yet a capsule's case file."""
    data = write(tmp_path / "squeeze.csv", *squeeze())
    assert main(["fit", data, *CAPSULE, "--law", "neo-hookean", "--out", str(tmp_path / "res")]) == 0
    capsys.readouterr()
    written = sorted(p.name for p in (tmp_path / "res").iterdir() if not p.name.startswith("."))
    assert written == ["fit.png"]
    assert (tmp_path / "res" / "fit.png").stat().st_size > 0


def test_fit_refuses_what_it_cannot_fit():
    """Before any solve: P_I < 0, P_I = 0 fitted (an uninflated capsule's is held), and P_I held by ``fixed`` (it
    is the fit's own argument)."""
    forces, gaps = squeeze()
    setup = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "s"),), R, T)
    with pytest.raises(InputError, match="needs P_I >= 0"):
        capsuletest.fit(setup, "neo-hookean", -1.0)
    with pytest.raises(InputError, match="an uninflated capsule's P_I is held"):
        capsuletest.fit(setup, "neo-hookean", 0.0, fit_pressure=True)
    with pytest.raises(InputError, match="--fix initial_pressure"):
        capsuletest.fit(setup, "neo-hookean", P_I, fixed={"initial_pressure": 1.0})


@pytest.mark.parametrize(("share", "warned"), [((0.02, 0.05, 0.1, 0.15, 0.2, 0.25), False),
                                                ((0.01, 0.012, 0.015, 0.02), True)])
def test_warns_where_p_i_and_e_t_are_not_separated(model, share, warned):
    """The small-force law's displacement is P_I's load over the wall's tension times a logarithm in which alone E T
    appears: over a narrow range of small forces (a fifth of a decade, Fhat / Phat_I <= 0.02) a change of P_I
    mimics one of E T, over a wide one (more than a decade) it does not. The fit says so exactly where the two
    estimates' correlation passes ``pocket.apps.fit.stats.CORRELATED`` (noise-free data: the correlation is the
    Jacobian's, whatever the noise's size)."""
    from pocket.apps.fit.stats import CORRELATED

    forces, gaps = squeeze(share=share)
    setup = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "s"),), R, T)
    result = capsuletest.fit(setup, "neo-hookean", P_I * 1.1, fit_pressure=True)
    r = result.statistics.correlation[0, 1]
    print(f"r = {r:+.6f}", result.statistics.warnings)
    assert bool(abs(r) > CORRELATED) is warned
    assert any("do not separate the initial pressure" in w for w in result.statistics.warnings) is warned


def test_stated_uncertainty_weighs_the_gaps(model, tmp_path, capsys):
    """Exact answer: with --sigma gap the residuals are (model - datum) / sigma, the plain ones (in units of 2 R)
    times 2 R / sigma at any trial; the fit then recovers the same truth and the report says what its residuals
    are."""
    forces, gaps = squeeze()
    plain = Setup((Dataset("capsule", forces, {"gap": gaps}, None, "g"),), R, T)
    weighed = Setup(plain.tests, R, T, sigma={"gap": 2e-8})
    trial = capsulemodel.Trial(check("neo-hookean", {"mu": 0.8e6}), 1150.0)
    values = capsulemodel.predict(plain, trial)[0]
    np.testing.assert_allclose(capsulemodel.residuals(weighed, values),
                               capsulemodel.residuals(plain, values) * 2.0 * R / 2e-8, rtol=1e-12)
    data = write(tmp_path / "squeeze.csv", forces, gaps)
    assert main(["fit", data, *CAPSULE, "--law", "neo-hookean", "--json", "--sigma", "gap=0.02 um"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["parameters"]["mu"]["value"] == pytest.approx(TRUTH["mu"], rel=1e-7)
    assert out["residuals"] == "in units of the stated uncertainty for gap, in units of the diameter 2R otherwise"
