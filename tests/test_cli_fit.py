"""``pocket fit``: bad data refused in one line before any solve; the JSON; the folder and its case file."""

import json

import numpy as np
import pytest

from pocket import shooting
from pocket.cli import main
from pocket.core.materials import check

R, T = 0.02, 1e-3
TRUTH = check("mooney-rivlin", {"c1": 160e3, "c2": 47e3})


def bulge_csv(path, truth=TRUTH):
    """A noise-free bulge test of ``truth`` in kPa and mm, 8 pressures."""
    phats = np.linspace(0.05, 0.6, 8)
    tension = 3.0 * truth.mu0 * T
    heights = [shooting.inflate(truth.scaled(), p).height * R for p in phats]
    rows = [f"{float(p * tension / R / 1e3)!r},{float(h * 1e3)!r}" for p, h in zip(phats, heights, strict=True)]
    path.write_text("pressure [kPa],height [mm]\n" + "\n".join(rows) + "\n")
    return str(path)


BAD = {
    "missing unit": ("pressure,height [mm]\n1,2\n2,3\n3,4\n", "has no unit"),
    "non-numeric cell": ("pressure [kPa],height [mm]\n1,2\n2,abc\n3,4\n",
                         "row 2, height = 'abc' is not a finite number"),
    "negative pressure": ("pressure [kPa],height [mm]\n-1,2\n2,3\n3,4\n",
                          "row 1, pressure = -1000 (SI), but it must be > 0"),
    "non-monotone pressures": ("pressure [kPa],height [mm]\n1,2\n3,3\n2,4\n",
                               "row 3, pressure = 2000 Pa is not above"),
    "fewer points than parameters": ("pressure [kPa],height [mm]\n1,2\n2,3\n", "2 data, but fitting 2 parameters"),
    "unusable column": ("pressure [kPa],temperature [K]\n1,2\n2,3\n3,4\n", "the fit cannot use a column 'temperature'"),
    "volume in compression": ("force [N],pressure [kPa],volume [mL]\n0,1,2\n1,2,2\n2,3,2\n", "cannot use a volume"),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_data_one_line_exit_2_before_solving(case, tmp_path, capsys, monkeypatch):
    """Each defect is one line on stderr naming it, exit status 2, and no solve (the model is not called)."""
    import pocket.apps.fit.model as model

    monkeypatch.setattr(model, "entry", lambda *a: pytest.fail("solved"))
    text, message = BAD[case]
    (tmp_path / "data.csv").write_text(text)
    status = main(["fit", str(tmp_path / "data.csv"), "--radius", "20 mm", "--thickness", "1 mm"])
    out, err = capsys.readouterr()
    assert status == 2, err
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err


def test_json_parameters_in_si(tmp_path, capsys):
    """Exact answer: the truth's C1 and C2 in Pa (noise-free data; 1e-6 as in the library's recovery test),
    with standard errors, the correlation matrix and the counts."""
    status = main(["fit", bulge_csv(tmp_path / "b.csv"), "--radius", "20 mm", "--thickness", "1 mm", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert status == 0
    for key in ("c1", "c2"):
        assert out["parameters"][key]["value"] == pytest.approx(TRUTH[key], rel=1e-6)
        assert out["parameters"][key]["unit"] == "Pa"
        assert out["parameters"][key]["standard_error"] >= 0.0
    assert out["correlation"]["keys"] == ["c1", "c2"]
    assert out["solver_calls"] > 0
    assert out["data"] == 8


def test_without_thickness_reports_products(tmp_path, capsys):
    """The model sees mu_0 T only: without --thickness the parameters are stress * T in N/m (truth times T)."""
    status = main(["fit", bulge_csv(tmp_path / "b.csv"), "--radius", "20 mm", "--json", "--fix", "c2=0.047 N/m"])
    assert status == 2  # a held stress needs a thickness
    capsys.readouterr()
    status = main(["fit", bulge_csv(tmp_path / "b.csv"), "--radius", "20 mm", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert status == 0
    assert out["parameters"]["c1"]["unit"] == "N/m"
    assert out["parameters"]["c1"]["value"] == pytest.approx(TRUTH["c1"] * T, rel=1e-6)


@pytest.mark.slow
def test_out_folder_case_file_round_trip(tmp_path, capsys):
    """The fitted sheet's case file runs, and its inflated height at its initial pressure is the fitted
    curve's (the data's, noise-free) there; a folder pocket did not write is refused before solving."""
    from pocket.apps.casefile import solve
    from pocket.apps.cases import load

    data = bulge_csv(tmp_path / "b.csv")
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("mine")
    assert main(["fit", data, "--radius", "20 mm", "--thickness", "1 mm", "--out", str(tmp_path / "mine")]) == 2
    assert main(["fit", data, "--radius", "20 mm", "--thickness", "1 mm", "--out", str(tmp_path / "res")]) == 0
    capsys.readouterr()
    assert (tmp_path / "res" / "fit.png").stat().st_size > 0
    case = load(tmp_path / "res" / "fitted.toml")
    result = solve(case)
    pressure = result["inflated"]["pressure_Pa"]
    expected = shooting.inflate(TRUTH.scaled(), pressure * R / (3.0 * TRUTH.mu0 * T)).height * R
    assert result["inflated"]["height_m"] == pytest.approx(expected, rel=1e-6)  # the fit's 1e-6


@pytest.mark.slow
def test_prestretch_held_or_fitted(tmp_path, capsys):
    """Exact answer: the truth, a Mooney-Rivlin sheet clamped with a prestretch of 1.1 (noise-free data; 1e-6 as
    above). --fix prestretch=1.1 holds it (reported as fixed, written to the fitted case file) and recovers C1 and
    C2; --fit-prestretch fits it too; both at once, or a prestretch below 1, is one line and exit 2."""
    import dataclasses

    truth = dataclasses.replace(TRUTH, prestretch=1.1)
    data = bulge_csv(tmp_path / "b.csv", truth)
    base = ["fit", data, "--radius", "20 mm", "--thickness", "1 mm"]
    assert main([*base, "--json", "--fix", "prestretch=1.1", "--out", str(tmp_path / "held")]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["fixed"] == {"prestretch": {"value": 1.1, "unit": "1"}}
    for key in ("c1", "c2"):
        assert out["parameters"][key]["value"] == pytest.approx(truth[key], rel=1e-6)
    assert "prestretch = 1.1\n" in (tmp_path / "held" / "fitted.toml").read_text()
    assert main([*base, "--json", "--fit-prestretch"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["parameters"]["prestretch"]["value"] == pytest.approx(1.1, rel=1e-6)
    for bad, message in ((["--fit-prestretch", "--fix", "prestretch=1.1"], "give one of them"),
                         (["--fix", "prestretch=0.9"], "--fix prestretch = 0.9, but a prestretch")):
        assert main([*base, *bad]) == 2
        out, err = capsys.readouterr()
        assert out == "", err
        assert err.count("\n") == 1, err
        assert message in err, err


CASE = """[sheet]
material = "mooney-rivlin"
thickness = "1 mm"
[clamp]
radius = "20 mm"
[fit]
data = ["b.csv"]
"""


@pytest.mark.slow
def test_case_file_names_the_data(tmp_path, capsys):
    """A case file with a [fit] table gives the same fit as the flags it replaces (the same computation: the same
    numbers to the last bit), the data file relative to the case file's folder, run from elsewhere."""
    bulge_csv(tmp_path / "b.csv")
    assert main(["fit", str(tmp_path / "b.csv"), "--radius", "20 mm", "--thickness", "1 mm", "--json"]) == 0
    flags = json.loads(capsys.readouterr().out)
    (tmp_path / "case.toml").write_text(CASE)
    assert main(["fit", str(tmp_path / "case.toml"), "--json"]) == 0
    case = json.loads(capsys.readouterr().out)
    assert case["parameters"] == flags["parameters"]
    assert case["solver_calls"] == flags["solver_calls"]


CASE_BAD = {
    "no [fit] table": (CASE.split("[fit]")[0], [], "no [fit] table"),
    "a flag the case gives": (CASE, ["--radius", "20 mm"], "--radius: the case file"),
    "data not a list": (CASE.replace('["b.csv"]', '"b.csv"'), [], "fit.data = 'b.csv', but it must be a non-empty"),
    "a parameter in [sheet]": (CASE.replace('thickness = "1 mm"', 'thickness = "1 mm"\nc1 = "1 kPa"'), [],
                               "unknown key 'sheet.c1'"),
    "an unknown key to hold": (CASE + 'fix = {c3 = "1 kPa"}\n', [], "fit.fix = 'c3', but the law's keys are"),
    "a bad uncertainty": (CASE + 'sigma = {height = "-1 mm"}\n', [], "fit.sigma.height"),
    "a prestretch held and fitted": (CASE.replace("[clamp]", "prestretch = 1.1\n[clamp]") + "prestretch = true\n", [],
                                     "give one of them"),
    "a missing data file": (CASE.replace("b.csv", "nothere.csv"), [], "nothere.csv"),
}


@pytest.mark.parametrize("case", list(CASE_BAD))
def test_bad_case_file_one_line_exit_2_before_solving(case, tmp_path, capsys, monkeypatch):
    """Each defect of a fit's case file is one line on stderr naming the key, exit 2, and no solve."""
    import pocket.apps.fit.model as model

    monkeypatch.setattr(model, "entry", lambda *a: pytest.fail("solved"))
    text, flags, message = CASE_BAD[case]
    (tmp_path / "b.csv").write_text("pressure [kPa],height [mm]\n1,2\n2,3\n3,4\n")
    (tmp_path / "case.toml").write_text(text)
    status = main(["fit", str(tmp_path / "case.toml"), *flags])
    out, err = capsys.readouterr()
    assert status == 2, err
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err
