"""``pocket fit`` never fits in the wrong unit silently: a plain number is said, data that make a unit absurd are
refused before any solve, spreadsheet habits (a byte-order mark, ``;`` with decimal commas) are read as meant,
and the report says what its numbers are (a parameter at a bound, mu_0's interval, the correlations).

The data are a bulge test as a user has it: pressures in kPa and heights in mm of a known Mooney-Rivlin sheet,
solved by pocket's shooting solver (``test_cli_fit.bulge_csv``), then written with the user's mistakes."""

import json
import math
import pathlib
import types

import numpy as np
import pytest
from test_cli_fit import TRUTH, R, T, bulge_csv

from pocket.apps.fit import checks, stats
from pocket.apps.fit.data import Dataset, read
from pocket.apps.fit.keys import keys
from pocket.apps.fit.model import Setup
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.materials import check
from pocket.core.units import plain_warnings, quantity

SHEET = ["--radius", "20 mm", "--thickness", "1 mm"]


@pytest.fixture
def no_solve(monkeypatch):
    """Fail the test if the model is solved (a refusal must come before any solve)."""
    import pocket.apps.fit.model as model

    monkeypatch.setattr(model, "entry", lambda *a: pytest.fail("solved"))


@pytest.fixture
def stop_fit(monkeypatch):
    """Stop ``pocket fit`` where the fit would start: the warnings and checks before it are what is tested."""
    import pocket.apps.fit.leastsquares as fit

    def stop(*args, **kwargs):
        raise InputError("stopped before the fit")

    monkeypatch.setattr(fit, "fit", stop)


def _run(args, capsys):
    status = main(["fit", *args])
    out, err = capsys.readouterr()
    return status, out, err


def _refused(status, out, err, *words):
    """Exit 2, nothing on stdout, the error the last line of stderr (after any warnings), naming ``words``."""
    lines = err.splitlines()
    assert status == 2, err
    assert out == "", err
    assert lines[-1].startswith("pocket: error: "), err
    assert all(w in lines[-1] for w in words), err
    return lines


def test_fit_plain_radius_warns(tmp_path, capsys, no_solve):
    """``--radius 15`` is 15 m (the units rule): the plain_warnings line naming --radius, then a refusal before any
    solve, since a dome of millimetres on a 15 m clamp is a strain of 1e-4, which the kPa pressures reach only on
    a sheet stiffer than any solid (E >= E T / R, as a membrane is thinner than R)."""
    data = bulge_csv(tmp_path / "b.csv")
    lines = _refused(*_run([data, "--radius", "15"], capsys), str(tmp_path / "b.csv"), "stiffer than any solid")
    assert lines[:-1] == [f"pocket: warning: {w}" for w in plain_warnings("--radius", "15", "length")]
    assert "read as 15 m" in lines[0]


@pytest.mark.parametrize(("flag", "value", "kind"), [("--thickness", "0.001", "length"),
                                               ("--initial-pressure", "5000", "pressure"),
                                               ("--fix", "c2=47000", "pressure")])
def test_fit_plain_sheet_values_warn(flag, value, kind, tmp_path, capsys, stop_fit):
    """Every plain dimensional value on fit's command line is said, naming its option (a held stress as
    ``--fix c2``), by the one rule's line: the same text as ``plain_warnings`` gives (the values are the right SI
    ones, so nothing is refused)."""
    args = {"--thickness": ["--radius", "20 mm", flag, value],
            "--initial-pressure": [*SHEET, flag, value], "--fix": [*SHEET, flag, value]}[flag]
    status, _out, err = _run([bulge_csv(tmp_path / "b.csv"), *args], capsys)
    key, written = ("--fix c2", "47000") if flag == "--fix" else (flag, value)
    assert status == 2, err
    assert (err.splitlines()[:-1] == [f"pocket: warning: {w}"
                                                     for w in plain_warnings(key, written, kind)]), err
    assert "stopped before the fit" in err.splitlines()[-1]


def test_fit_plain_sigma_warns(tmp_path, capsys, no_solve, stop_fit):
    """``--sigma height=0.02`` is 20 mm: said, and refused beside heights of at most 15 mm (an uncertainty above
    every datum of its column is no measurement's); ``height=0.00002`` (0.02 mm in m) is said and taken."""
    data = bulge_csv(tmp_path / "b.csv")
    lines = _refused(*_run([data, *SHEET, "--sigma", "height=0.02"], capsys), "--sigma height", "more than every")
    assert lines[:-1] == [f"pocket: warning: {w}" for w in plain_warnings("--sigma height", "0.02", "length")]
    _status, _, err = _run([data, *SHEET, "--sigma", "height=0.00002"], capsys)
    assert err.splitlines()[:-1] == [f"pocket: warning: {w}" for w in plain_warnings("--sigma height", "0.00002",
                                                                                   "length")]
    assert "stopped before the fit" in err.splitlines()[-1]


def test_fit_height_many_radii_refused(tmp_path, capsys, no_solve):
    """A height above ``MAX_STRETCH`` = 20 clamp radii is refused naming the file and the column (no rubber
    stretches that far: the bound is in ``pocket.apps.fit.checks``); just below the bound the data pass the
    check (the bound, not something else, refuses). On the command line: heights of 5 to 15 mm on a 0.5 mm clamp
    (30 R)."""
    data = bulge_csv(tmp_path / "b.csv")
    _refused(*_run([data, "--radius", "0.5 mm", "--thickness", "0.01 mm"], capsys), data, "height column",
             "above 20 R")
    test = read(data)
    top = float(np.max(test.responses["height"]))
    for factor, refused in ((1.01, True), (0.99, False)):
        setup = Setup((test,), top / (checks.MAX_STRETCH * factor), None)
        if refused:
            with pytest.raises(InputError, match="above 20 R"):
                checks.check(setup, slack=False)
        else:
            checks.check(setup, slack=False)  # the height bound alone (slack=False: no modulus bound)


def test_fit_volume_past_any_sphere_refused():
    """A volume column is bounded by the isoperimetric inequality: no closed surface of area (20^2 + 1) pi R^2 (the
    dome at 20 times stretch and the clamp disc) holds more than the sphere's (401 pi R^2)^(3/2) / (6 sqrt(pi)) =
    401^(3/2) pi R^3 / 6; 1 % past it is refused, 1 % inside it is not (a volume in m^3 for mL data is 1e6 past)."""
    bound = 401.0**1.5 * math.pi / 6.0 * R**3
    for factor, refused in ((1.01, True), (0.99, False)):
        test = Dataset("inflation", np.array([1e3, 2e3]), {"volume": np.array([0.5, 1.0]) * bound * factor},
                               None, "v.csv")
        if refused:
            with pytest.raises(InputError, match=r"v\.csv: the volume column"):
                checks.check(Setup((test,), R, T), slack=False)
        else:
            checks.check(Setup((test,), R, T), slack=False)


def test_fit_furlong_column_refused(tmp_path, capsys, no_solve):
    """pint knows the furlong (660 US survey feet of 1200/3937 m: 201.168 m), so ``height [furlong]`` makes the
    heights of a 20 mm clamp's dome 1000 m to 3 km: one line naming the file, the column and why, exit 2, before
    any solve (it was an internal error)."""
    assert quantity("furlong", "1 furlong", "length") == pytest.approx(660 * 1200 / 3937, rel=1e-12)
    text = pathlib.Path(bulge_csv(tmp_path / "b.csv")).read_text()
    (tmp_path / "f.csv").write_text(text.replace("height [mm]", "height [furlong]"))
    _refused(*_run([str(tmp_path / "f.csv"), *SHEET], capsys), str(tmp_path / "f.csv"), "height column",
             "no rubber stretches")


def test_fit_metre_column_for_mm_data_refused(tmp_path, capsys, no_solve):
    """``height [m]`` over millimetre numbers puts a 20 mm clamp's dome 5 to 15 m high (250 to 750 R): refused
    naming the file and the column, exit 2, before any solve (it was an exit-1 'no start has a state')."""
    text = pathlib.Path(bulge_csv(tmp_path / "b.csv")).read_text()
    (tmp_path / "m.csv").write_text(text.replace("height [mm]", "height [m]"))
    _refused(*_run([str(tmp_path / "m.csv"), *SHEET], capsys), str(tmp_path / "m.csv"), "height column", "R = 0.02 m")


@pytest.mark.slow
def test_fit_bom_reads_same_mu(tmp_path, capsys):
    """Excel's "CSV UTF-8" starts the file with a byte-order mark: the file is read as without it, and the fit
    gives the same mu_0 (to 1e-9: the same numbers, the same computation)."""
    truth = check("neo-hookean", {"mu": 200e3})
    data = bulge_csv(tmp_path / "b.csv", truth)
    (tmp_path / "bom.csv").write_bytes(b"\xef\xbb\xbf" + (tmp_path / "b.csv").read_bytes())
    fits = []
    for path in (data, str(tmp_path / "bom.csv")):
        status, out, _ = _run([path, *SHEET, "--law", "neo-hookean", "--json"], capsys)
        assert status == 0
        fits.append(json.loads(out)["mu0"]["value"])
    assert fits[1] == pytest.approx(fits[0], rel=1e-9)
    assert fits[0] == pytest.approx(truth.mu0, rel=1e-6)


def test_fit_semicolon_file(tmp_path, capsys, no_solve):
    """A European Excel writes ``;`` between cells and a decimal comma: the test read is the comma file's, value for
    value (the same decimal strings); a ``;`` file with decimal points is read too."""
    data = bulge_csv(tmp_path / "b.csv")
    text = (tmp_path / "b.csv").read_text()
    (tmp_path / "eu.csv").write_text(text.replace(",", ";").replace(".", ","))
    (tmp_path / "semi.csv").write_text(text.replace(",", ";"))
    expected = read(data)
    for name in ("eu.csv", "semi.csv"):
        got = read(tmp_path / name)
        assert np.array_equal(got.control, expected.control)
        assert np.array_equal(got.responses["height"], expected.responses["height"])


def test_case_file_bom_read(tmp_path):
    """A case file saved with a byte-order mark (TOML forbids one; Windows editors write it) is the same case as
    without: pocket run's case and fit's request."""
    from pocket.apps import cases
    from pocket.apps.fit import case

    bulge_csv(tmp_path / "b.csv")
    fit_case = '[sheet]\nthickness = "1 mm"\n[clamp]\nradius = "20 mm"\n[fit]\ndata = ["b.csv"]\n'
    run_case = ('[sheet]\nthickness = "1 mm"\nmaterial = "neo-hookean"\nmu = "200 kPa"\n[clamp]\nradius = "20 mm"\n'
                '[initial]\npressure = "5 kPa"\n[loads]\nforces = ["0.5 N"]\n')
    for text, load in ((fit_case, case.load), (run_case, cases.load)):
        (tmp_path / "plain.toml").write_text(text)
        (tmp_path / "bom.toml").write_bytes(b"\xef\xbb\xbf" + text.encode())
        plain, bom = load(tmp_path / "plain.toml"), load(tmp_path / "bom.toml")
        assert repr(plain).replace("plain.toml", "bom.toml") == repr(bom)


def test_profile_table_bom_and_semicolon_read(tmp_path):
    """An indenter's profile table saved by a spreadsheet (a byte-order mark, or ``;`` with decimal commas) is the
    table without them: the same rows, so the same spline (its digest)."""
    from pocket.core import profiles

    rows = "radius [mm],height [mm]\n0,0\n1,0.05\n2,0.2\n3,0.45\n"
    (tmp_path / "p.csv").write_text(rows)
    (tmp_path / "bom.csv").write_bytes(b"\xef\xbb\xbf" + rows.encode())
    (tmp_path / "eu.csv").write_text(rows.replace(",", ";").replace(".", ","))
    digest = profiles.read_csv(tmp_path / "p.csv", clamp_radius=0.02).digest
    for name in ("bom.csv", "eu.csv"):
        assert profiles.read_csv(tmp_path / name, clamp_radius=0.02).digest == digest


@pytest.mark.slow
def test_parameter_at_bound_says_so(tmp_path, capsys):
    """A sheet clamped without prestretch, fitted with ``--fit-prestretch``: the fit stops at the bound
    prestretch = 1 of the admissible set, and says so (its error is one-sided); its interval is cut at 1."""
    truth = check("neo-hookean", {"mu": 200e3})
    data = bulge_csv(tmp_path / "b.csv", truth)
    status, out, _err = _run([data, *SHEET, "--law", "neo-hookean", "--fit-prestretch", "--json"], capsys)
    result = json.loads(out)
    assert status == 0
    assert result["parameters"]["prestretch"]["value"] == pytest.approx(1.0, abs=1e-6)
    assert result["parameters"]["prestretch"]["interval_95"][0] >= 1.0
    assert any(w.startswith("prestretch = ") and "sits at 1, a bound of its admissible set" in w
               for w in result["warnings"]), result["warnings"]


def test_undetermined_parameter_has_no_zero_error():
    """A parameter the data do not see (its Jacobian column 0) gets a huge standard error and the warning, never
    0: (J^T J)^-1 from J's singular values floored, not a pseudo-inverse that drops the direction."""
    material = check("mooney-rivlin", {"c1": 160e3, "c2": 47e3})
    free = list(keys("mooney-rivlin")[:2])
    jac = np.array([[1.0, 0.0], [2.0, 0.0], [3.0, 0.0], [4.0, 0.0]])
    r = np.array([1e-3, -2e-3, 1e-3, 5e-4])
    s = stats.statistics(types.SimpleNamespace(thickness=T), material, free, np.diag([1e5, 1e5]), r, jac)
    assert s.standard_errors[1] > abs(s.values[1])
    assert math.isfinite(s.standard_errors[1])
    assert any(w.startswith("c2 = ") and "do not determine" in w for w in s.warnings)


@pytest.mark.slow
def test_fit_text_shows_correlations_and_mu0_interval(tmp_path, capsys):
    """The text report shows what the README promises: mu_0 with its 95 % interval, mu_0 +- t_(0.975, n-p) SE
    (Student's t from scipy.stats, independent of the report's), and the correlation matrix, as the JSON gives
    them. The data are rounded as a gauge reads them (kPa to 0.01, mm to 0.01), so the intervals have width."""
    from scipy.stats import t as student

    bulge_csv(tmp_path / "b.csv")
    lines = (tmp_path / "b.csv").read_text().splitlines()
    rounded = [",".join(f"{float(c):.2f}" for c in line.split(",")) for line in lines[1:]]
    (tmp_path / "r.csv").write_text("\n".join([lines[0], *rounded]) + "\n")
    status, out, _ = _run([str(tmp_path / "r.csv"), *SHEET, "--json"], capsys)
    result = json.loads(out)
    status, text, _ = _run([str(tmp_path / "r.csv"), *SHEET], capsys)
    assert status == 0
    mu0 = result["mu0"]
    half = student.ppf(0.975, result["degrees_of_freedom"]) * mu0["standard_error"]
    assert mu0["interval_95"] == pytest.approx([mu0["value"] - half, mu0["value"] + half], rel=1e-12)
    row = next(line for line in text.splitlines() if line.split()[:1] == ["mu_0"])
    lo, hi = (float(v) for v in row.split("[")[1].split("]")[0].split(","))
    assert [lo, hi] == pytest.approx([mu0["value"] - half, mu0["value"] + half], rel=1e-7)  # printed to 8 digits
    assert half > 1e-6 * mu0["value"]  # the interval has width at the printed digits
    table = text.split("correlation")[1].splitlines()
    assert table[0].split() == ["c1", "c2"]
    for line, expected in zip(table[1:3], result["correlation"]["matrix"], strict=True):
        assert [float(v) for v in line.split()[1:]] == pytest.approx(expected, abs=5e-5)  # printed to 4 decimals


def test_sigma_on_controlled_pressure_explained(tmp_path, capsys, no_solve):
    """``--sigma pressure`` on an inflation test: pressure is that test's controlled variable (the model is solved
    at each pressure given), so its uncertainty weights no residual; the message says so, not that there are no
    pressure data."""
    status, out, err = _run([bulge_csv(tmp_path / "b.csv"), *SHEET, "--sigma", "pressure=0.1 kPa"], capsys)
    lines = _refused(status, out, err, "--sigma pressure", "controlled variable of inflation tests")
    assert "no test has pressure data" not in err
    assert len(lines) == 1


def test_fitted_modulus_no_rubber_warns():
    """After the fit, E = 3 mu_0 outside rubbers' moduli (1 kPa to 1 GPa) is a warning; a rubber's (E = 3 * 414
    kPa, the test sheet's) is not; without a thickness, E >= 3 mu_0 T / R is checked against the top."""
    setup = Setup((), R, T)
    assert checks.modulus_warnings(setup, TRUTH.mu0) == []
    assert "no rubber's" in checks.modulus_warnings(setup, 1e10)[0]
    assert "no rubber's" in checks.modulus_warnings(setup, 100.0)[0]
    bare = Setup((), R, None)
    assert checks.modulus_warnings(bare, TRUTH.mu0 * T) == []
    assert "even for a sheet as thick" in checks.modulus_warnings(bare, 1e9 * R)[0]


def test_fit_prestretched_sheet_on_a_large_clamp_not_refused(tmp_path, capsys, stop_fit):
    """A prestretched sheet is taut: its dome at small pressure is P R^2 / (4 N_0), so millimetres on a 15 m clamp
    are no contradiction, and with the prestretch held the plain radius is said but the data are not refused (the
    slack sheet's modulus bound does not apply)."""
    status, _, err = _run([bulge_csv(tmp_path / "b.csv"), "--radius", "15", "--fix", "prestretch=1.1"], capsys)
    assert status == 2, err
    assert "stopped before the fit" in err.splitlines()[-1], err
    assert err.splitlines()[:-1] == [f"pocket: warning: {w}" for w in plain_warnings("--radius", "15", "length")]


def test_fit_case_file_plain_values_warn(tmp_path, capsys, stop_fit):
    """A fit's case file follows the same rule: ``radius = 0.02`` (a TOML number) and ``sigma = {height =
    0.00002}`` are read in SI and said, each named by its key (the plain_warnings lines, in the file's order)."""
    bulge_csv(tmp_path / "b.csv")
    (tmp_path / "case.toml").write_text('[sheet]\nthickness = "1 mm"\n[clamp]\nradius = 0.02\n[fit]\ndata = ["b.csv"]\n'
                                        "sigma = {height = 0.00002}\n")
    status, _, err = _run([str(tmp_path / "case.toml")], capsys)
    expected = [*plain_warnings("clamp.radius", 0.02, "length"), *plain_warnings("fit.sigma.height", 2e-5, "length")]
    assert status == 2, err
    assert err.splitlines()[:-1] == [f"pocket: warning: {w}" for w in expected], err
