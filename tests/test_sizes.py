"""Sizes the membrane model is meant for (``pocket.core.sizes``): lengths a pocket can have, plain numbers
that look like millimetres, and a sheet thin beside its clamp; each message names the user's key."""

import json

import pytest

from pocket.apps.cases import SAMPLES, parse, sample
from pocket.apps.design import design
from pocket.cli import main
from pocket.core.sizes import SIZES, THIN_LIMIT, THIN_WARNING
from pocket.core.units import is_plain, quantity

CASE = """
[sheet]
thickness = "0.25 mm"
c1 = "160 kPa"
c2 = "47 kPa"
[clamp]
radius = "20 mm"
[initial]
pressure = "4.8 kPa"
[loads]
forces = ["0.5 N"]
"""


def _run(tmp_path, capsys, text, *extra):
    path = tmp_path / "case.toml"
    path.write_text(text)
    status = main(["run", str(path), "--out", str(tmp_path), *extra])
    return status, capsys.readouterr().err


def test_plain_means_no_unit():
    """A number, or text pint reads as dimensionless, has no unit; text with a unit has one."""
    assert is_plain(20)
    assert is_plain(0.25)
    assert is_plain("20")
    assert not is_plain("20 mm")
    assert not is_plain("1 km")


def test_the_papers_samples_draw_no_warning():
    """Table 1: T/R = 0.25/20 to 1.6/20 mm, all below the warning threshold, all lengths with units."""
    for number, thickness in SAMPLES.items():
        ratio = quantity("t", thickness, "length") / 0.02
        assert ratio < THIN_WARNING
        assert sample(number).warnings == ()


def test_a_radius_in_kilometres_is_refused_naming_the_radius(tmp_path, capsys):
    """20 km is beyond the largest pocket (SIZES): the radius is blamed, not a pressure derived from it."""
    assert SIZES[1] < 20e3
    status, err = _run(tmp_path, capsys, CASE.replace('radius = "20 mm"', 'radius = "20 km"'))
    assert status == 2, err
    assert err.startswith("pocket: error: clamp.radius = '20 km' is 20000 m, outside"), err
    assert not list(tmp_path.glob("case.*[jc]s[vo]*"))


def test_a_plain_thickness_in_metres_on_a_radius_in_mm_is_refused(tmp_path, capsys):
    """thickness = 0.25 is 0.25 m: on a 20 mm clamp T/R = 12.5 >= THIN_LIMIT, a plate, not a membrane."""
    ratio = 0.25 / 0.02
    assert ratio >= THIN_LIMIT
    status, err = _run(tmp_path, capsys, CASE.replace('thickness = "0.25 mm"', "thickness = 0.25"))
    assert status == 2, err
    assert f"sheet.thickness = 0.25 on clamp.radius = '20 mm': the sheet's thickness is {ratio:.3g} times" in err
    assert err.count("\n") == 1


def test_a_thick_sheet_warns_on_stderr_and_in_every_row(tmp_path, capsys):
    """T/R = 3/20 = 0.15, above THIN_WARNING and below THIN_LIMIT: solved, with one warning line on stderr
    and the warning in the JSON's case and rows and in the CSV."""
    ratio = 3 / 20
    assert THIN_WARNING < ratio < THIN_LIMIT
    status, err = _run(tmp_path, capsys, CASE.replace('thickness = "0.25 mm"', 'thickness = "3 mm"'))
    expected = f"sheet.thickness = '3 mm' on clamp.radius = '20 mm': the sheet's thickness is {ratio:.3g} times"
    assert status == 0, err
    assert err.count(expected) == 1, err
    assert err.count("\n") == 1, err
    result = json.loads((tmp_path / "case.json").read_text())
    assert any(expected in w for w in result["case"]["warnings"])
    assert all(any(expected in w for w in row["warnings"]) for row in (result["inflated"], *result["states"]))
    assert expected in (tmp_path / "case.csv").read_text()


def test_a_plain_radius_warns_and_the_failure_names_it(tmp_path, capsys):
    """radius = 20 is 20 m (20000 mm: most likely meant in mm): a warning first, then the pressure it makes too
    large (Phat_I = P_I R / (E T) = 4800 * 20 / (1.242e6 * 2.5e-4)) is an error naming the radius."""
    status, err = _run(tmp_path, capsys, CASE.replace('radius = "20 mm"', "radius = 20"))
    lines = err.splitlines()
    assert status == 2, err
    assert len(lines) == 2, err
    assert lines[0] == ("pocket: warning: clamp.radius = 20 has no unit and is read as 20 m; write '20 mm' if "
                        "millimetres were meant")
    phat = 4800 * 20 / (6 * (160e3 + 47e3) * 0.25e-3)
    assert lines[1].startswith(f"pocket: error: initial.pressure = '4.8 kPa' with sheet.thickness = '0.25 mm', "
                               f"clamp.radius = 20 (E = 1.242e+06 Pa) gives Phat_I = P_I R / (E T) = {phat:.6g}: ")


def test_plain_metres_and_pascals_in_a_case_warn_whatever_their_size():
    """A plain number where a unit is expected is SI and always said so, also when it is plausible in SI
    (0.02 m, 4800 Pa, 0.5 N): each key named once, with the value written in the usual unit; with units, none."""
    import tomllib

    text = (CASE.replace('radius = "20 mm"', "radius = 0.02").replace('pressure = "4.8 kPa"', "pressure = 4800")
            .replace('forces = ["0.5 N"]', 'forces = [0, 0.5]').replace('c2 = "47 kPa"', "c2 = 47e3"))
    case = parse(tomllib.loads(text))
    assert case.warnings == (
        "clamp.radius = 0.02 has no unit and is read as 0.02 m; write it with its unit ('20 mm') to say so",
        "sheet.c2 = 47000.0 has no unit and is read as 47000 Pa; write it with its unit ('47 kPa') to say so",
        "initial.pressure = 4800 has no unit and is read as 4800 Pa; write it with its unit ('4.8 kPa') to say so",
        "loads.forces[1] = 0.5 has no unit and is read as 0.5 N; write it with its unit ('0.5 N') to say so")
    assert parse(tomllib.loads(CASE)).warnings == ()


def test_plain_plate_heights_warn_each_key():
    """Every length key is checked: a plain plate height of 9 (m) draws a warning naming it."""
    text = CASE.replace('forces = ["0.5 N"]', 'heights = ["9 mm", 9]').replace('pressure = "4.8 kPa"',
                                                                              'height = "10 mm"')
    import tomllib

    case = parse(tomllib.loads(text))
    assert [w.split(" = ")[0] for w in case.warnings] == ["loads.heights[1]"]


def test_sense_prints_the_case_warning(tmp_path, capsys):
    """``pocket sense`` on a thick-sheet case: the same warning line on stderr."""
    path = tmp_path / "case.toml"
    path.write_text(CASE.replace('thickness = "0.25 mm"', 'thickness = "3 mm"'))
    assert main(["sense", str(path), "--ratio", "1.1"]) == 0
    assert "pocket: warning: sheet.thickness = '3 mm' on clamp.radius = '20 mm'" in capsys.readouterr().err


def test_design_in_plain_metres_warns_naming_radius_and_height(capsys):
    """``pocket design --radius 20 --height 10``: a 20 m button, with one warning per plain length."""
    args = ["design", "--alpha", "0.3", "--modulus", "1 MPa", "--force", "0.67 N", "--json"]
    assert main([*args, "--radius", "20", "--height", "10"]) == 0
    out, err = capsys.readouterr()
    assert err.splitlines() == [f"pocket: warning: {key} = '{v}' has no unit and is read as {v} m; write '{v} mm' if "
                                "millimetres were meant" for key, v in (("--radius", 20), ("--height", 10))]
    assert len(json.loads(out)["warnings"]) == 2
    assert main([*args, "--radius", "20 mm", "--height", "10 mm"]) == 0
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize(("modulus", "factor"), [("40 kPa", 25), ("10 kPa", 100)])
def test_design_of_a_thick_sheet(capsys, modulus, factor):
    """P_I does not depend on E, so T scales as 1/E: T at ``modulus`` is ``factor`` times T at 1 MPa.
    T/R above THIN_WARNING warns, at THIN_LIMIT or above is refused (exit 2), naming the inputs."""
    base = design("20 mm", "10 mm", "1 MPa", 0.3, "0.67 N")
    ratio = factor * base.thickness_m / 0.02
    status = main(["design", "--alpha", "0.3", "--radius", "20 mm", "--height", "10 mm", "--modulus", modulus,
                   "--force", "0.67 N"])
    err = capsys.readouterr().err
    assert f"--radius = '20 mm', --height = '10 mm', --modulus = '{modulus}', --force = '0.67 N' give T = " in err
    assert f"the sheet's thickness is {ratio:.3g} times the clamp radius" in err
    assert err.count("\n") == 1
    if ratio >= THIN_LIMIT:
        assert status == 2
        assert err.startswith("pocket: error: ")
    else:
        assert ratio > THIN_WARNING
        assert status == 0
        assert err.startswith("pocket: warning: ")


def test_a_plain_fingertip_radius_warns_in_a_case_and_in_design(capsys):
    """A sphere's radius is a length like the others: ``indenter.radius = 8`` (8 m, a plate to a 20 mm pocket)
    draws the plain-length warning in a case file, and ``--indenter-radius 8`` the same, named by its flag, in
    ``pocket design``; '8 mm' draws none."""
    import tomllib

    sphere = '\n[indenter]\nshape = "sphere"\nradius = {}\n'
    case = parse(tomllib.loads(CASE + sphere.format("8")))
    assert [w.split(" = ")[0] for w in case.warnings] == ["indenter.radius"]
    assert parse(tomllib.loads(CASE + sphere.format('"8 mm"'))).warnings == ()
    args = ["design", "--alpha", "0.3", "--modulus", "1 MPa", "--force", "0.67 N", "--radius", "20 mm", "--height",
            "10 mm", "--indenter", "sphere", "--json", "--indenter-radius"]
    assert main([*args, "8"]) == 0
    assert capsys.readouterr().err.splitlines() == ["pocket: warning: --indenter-radius = '8' has no unit and is read "
                                                    "as 8 m; write '8 mm' if millimetres were meant"]
