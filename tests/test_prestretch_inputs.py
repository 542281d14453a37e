"""A prestretch as users give it: the case file's ``sheet.prestretch``, ``--prestretch`` on the command line,
a sweep's point; every bad value one line, exit 2, before any solve."""

import csv
import dataclasses
import json

import pytest
from test_cases_laws import by_hand, case_text, load_text, run_case

from pocket import shooting
from pocket.apps.physical import resolve
from pocket.cli import main
from pocket.core.materials import mooney_rivlin


def test_a_case_file_takes_the_prestretch_and_its_rows_are_that_solve(tmp_path):
    """Exact: the case hands the solvers its rubber (in units of mu_0) clamped with lambda_p, and its rows
    are that solve to the last bit, with a prestretch column."""
    text = case_text("yeoh").replace('[clamp]', 'prestretch = 1.1\n[clamp]')
    pocket = resolve(load_text(tmp_path, text))
    assert pocket.material == dataclasses.replace(by_hand("yeoh"), prestretch=1.1)
    result, rows = run_case(tmp_path, text)
    states = shooting.compression_curve(pocket.material, pocket.pressure_initial,
                                        [s["force"] for s in result["states"]])
    for row, state in zip(result["states"], states, strict=True):
        assert all(row[k] == getattr(state, k) for k in state.KEYS if k != "alpha")
        assert row["prestretch"] == 1.1
    assert all(float(row["prestretch"]) == 1.1 for row in rows)


def test_a_mooney_rivlin_case_keeps_its_alpha_and_takes_the_prestretch(tmp_path):
    text = case_text("mooney-rivlin").replace('[clamp]', 'prestretch = 1.2\n[clamp]')
    pocket = resolve(load_text(tmp_path, text))
    assert pocket.material == dataclasses.replace(mooney_rivlin(47e3 / 160e3), prestretch=1.2)


@pytest.mark.parametrize(("value", "message"), [
    ("0.9", "sheet.prestretch = 0.9, but a prestretch of the clamped sheet must be >= 1"),
    ("nan", "sheet.prestretch = nan is not finite"),
    ('"1.1"', "sheet.prestretch = '1.1' is not a number"),
    ('"10 %"', "sheet.prestretch = '10 %' is not a number"),
])
def test_a_bad_case_prestretch_is_one_line(value, message, tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text(case_text("yeoh").replace('[clamp]', f'prestretch = {value}\n[clamp]'))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    out, err = capsys.readouterr()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert "Traceback" not in err, err
    assert not (tmp_path / "out").exists()


def _exit(argv) -> int:
    """The exit status of ``pocket argv``: main's return, or argparse's exit for a flag it refuses."""
    try:
        return main(argv)
    except SystemExit as stop:
        return stop.code


@pytest.mark.parametrize(("value", "message"), [
    ("0.5", "--prestretch = 0.5, but a prestretch of the clamped sheet must be >= 1"),
    ("nan", "--prestretch = nan is not finite"),
    ("abc", "argument --prestretch: 'abc' is not a number"),
])
def test_a_bad_flag_is_one_line(value, message, capsys):
    assert _exit(["inflate", "--law", "neo-hookean", "--mu", "1", "--prestretch", value, "--pressure", "0.3"]) == 2
    out, err = capsys.readouterr()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err


def test_gent_past_locking_on_the_command_line(capsys):
    argv = ["inflate", "--law", "gent", "--mu", "1", "--jm", "0.3", "--prestretch", "1.2", "--pressure", "0.3"]
    assert _exit(argv) == 2
    assert "--prestretch = 1.2 puts the clamped flat sheet at I1 - 3 = 0.362253" in capsys.readouterr().err


def test_the_flag_reaches_the_solver_and_the_json(capsys):
    assert main(["inflate", "--alpha", "0.1", "--prestretch", "1.1", "--pressure", "0.3", "--json"]) == 0
    state = json.loads(capsys.readouterr().out)
    expected = shooting.inflate(dataclasses.replace(mooney_rivlin(0.1), prestretch=1.1), 0.3)
    assert state["prestretch"] == 1.1
    assert state["height"] == expected.height
    assert main(["inflate", "--alpha", "0.1", "--pressure", "0.3", "--json"]) == 0
    assert "prestretch" not in json.loads(capsys.readouterr().out)  # none given: today's keys


def test_a_sweep_point_is_identified_by_its_prestretch(tmp_path, capsys):
    out = tmp_path / "sweep.csv"
    common = ["sweep", "--alpha", "0.1", "--pressure", "0.3", "--force", "0.5", "--workers", "1", "--out", str(out)]
    assert main(common) == 0
    assert main([*common, "--prestretch", "1.1"]) == 0
    assert "1 points computed, 0 reused" in capsys.readouterr().out  # the stretched point is a new one
    rows = {row["material"]: row for row in csv.DictReader(out.open())}  # the last sweep's points first
    assert sorted(rows) == ["mooney-rivlin", "mooney-rivlin prestretch=1.1"]
    expected = shooting.compress(dataclasses.replace(mooney_rivlin(0.1), prestretch=1.1), 0.3, 0.5)
    assert float(rows["mooney-rivlin prestretch=1.1"]["height"]) == expected.height
    assert float(rows["mooney-rivlin"]["height"]) != expected.height
