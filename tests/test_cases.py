"""Case files and ``pocket run``: Table 1 samples, the three initial states, and one-line errors."""

import csv
import json
import math
import tomllib

import pytest
import scipy

from pocket import shooting
from pocket.apps.cases import SAMPLES, load, parse, sample
from pocket.cli import main

BUTTON = """
name = "button"
[sheet]
thickness = "0.25 mm"
modulus = "1 MPa"
alpha = 0.3
[clamp]
radius = "20 mm"
[initial]
height = "10 mm"
[loads]
heights = ["9 mm", "8 mm"]
"""


def _write(tmp_path, text, name="case.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


@pytest.mark.parametrize("number", sorted(SAMPLES))
def test_every_sample_runs(number, tmp_path, capsys):
    """Each Table 1 sample: the SI rows equal the dimensionless shooting solve scaled by the paper's
    definitions Phat = P R/(E T), Fhat = F/(P_I pi R^2), E = 6 (C1 + C2)."""
    assert main(["run", "--sample", str(number), "--out", str(tmp_path)]) == 0
    result = json.loads((tmp_path / f"sample{number}.json").read_text())
    rows = list(csv.DictReader((tmp_path / f"sample{number}.csv").open()))
    thickness = {1: 0.25e-3, 2: 0.5e-3, 3: 0.8e-3, 4: 1.6e-3}[number]
    modulus, radius, p_i = 6 * (160e3 + 47e3), 0.02, 4812.75
    phat_i = p_i * radius / (modulus * thickness)
    forces = [0, 0.5, 1, 2, 3, 4.5, 6]
    expected = shooting.compression_curve(47 / 160, phat_i, [f / (p_i * math.pi * radius**2) for f in forces])
    assert [float(r["force_N"]) for r in rows] == pytest.approx(forces, rel=1e-14)
    assert result["provenance"]["scipy"] == scipy.__version__  # the versions that ran
    assert not list(tmp_path.glob(".*partial"))
    for row, state, saved in zip(rows, expected, result["states"], strict=True):
        # the same solve: equal to the solver's resolution (~1e-10)
        assert float(row["pressure_Pa"]) == pytest.approx(state.pressure * modulus * thickness / radius, rel=1e-9)
        assert float(row["height_m"]) == pytest.approx(state.height * radius, rel=1e-9)
        assert float(row["contact_area_m2"]) == pytest.approx(state.contact_area * math.pi * radius**2,
                                                             rel=1e-9, abs=1e-15)
        assert float(row["pressure_ratio"]) == saved["pressure_ratio"]  # CSV and JSON agree exactly
    assert result["case"]["thickness_m"] == pytest.approx(thickness, rel=1e-15)


def test_initial_height_and_plate_heights(tmp_path):
    """A case given by H0 and plate heights: the solved states sit at exactly those heights."""
    result_dir = tmp_path / "out"
    assert main(["run", str(_write(tmp_path, BUTTON)), "--out", str(result_dir)]) == 0
    result = json.loads((result_dir / "case.json").read_text())
    assert result["inflated"]["height_m"] == pytest.approx(0.010, rel=1e-9)
    assert [s["height_m"] for s in result["states"]] == pytest.approx([0.009, 0.008], rel=1e-9)
    assert [s["height_ratio"] for s in result["states"]] == pytest.approx([0.9, 0.8], rel=1e-9)


def test_initial_volume(tmp_path):
    """A case given by its volume: the inflated volume is that volume."""
    text = BUTTON.replace('height = "10 mm"', 'volume = "7 mL"')
    assert main(["run", str(_write(tmp_path, text)), "--out", str(tmp_path)]) == 0
    result = json.loads((tmp_path / "case.json").read_text())
    assert result["inflated"]["volume_m3"] == pytest.approx(7e-6, rel=1e-9)
    assert all(s["volume_m3"] == pytest.approx(7e-6, rel=1e-9) for s in result["states"])


def test_c1_c2_equals_modulus_alpha(tmp_path):
    """E = 6 (C1 + C2), alpha = C2/C1: the two ways of giving the sheet are the same sheet."""
    a = load(_write(tmp_path, BUTTON))
    b = load(_write(tmp_path, BUTTON.replace('modulus = "1 MPa"\nalpha = 0.3',
                                             f'c1 = "{1e6 / 7.8} Pa"\nc2 = "{0.3e6 / 7.8} Pa"'), "b.toml"))
    assert (b.modulus, b.alpha) == pytest.approx((a.modulus, a.alpha), rel=1e-14)


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ('radius = "20 mm"', 'radius = "20 mm"\ncolour = "red"', "unknown key 'clamp.colour'"),
        ('name = "button"', 'name = "button"\n[plate]\nx = 1', "unknown key 'plate'"),
        ('radius = "20 mm"', "", "missing key 'clamp.radius'"),
        ('[initial]\nheight = "10 mm"', "[initial]", "missing key 'initial.pressure' or 'initial.height'"),
        ('height = "10 mm"', 'pressure = "4 mm"', "initial.pressure = '4 mm' has dimension [length], but a pressure"),
        ('thickness = "0.25 mm"', 'thickness = "-0.25 mm"', "sheet.thickness = '-0.25 mm', but it must be > 0"),
        ("alpha = 0.3", "alpha = -1.5", "sheet.alpha = -1.5, but the Mooney-Rivlin model needs alpha > -1"),
        ('"8 mm"]', '"-8 mm"]', "loads.heights[1] = '-8 mm', but it must be > 0"),
        ('height = "10 mm"', 'height = "10 mm"\nvolume = "1 mL"', "give one of"),
        ("alpha = 0.3", 'alpha = 0.3\nc1 = "1 MPa"', "give either sheet.c1 and sheet.c2 or sheet.modulus"),
        ('heights = ["9 mm", "8 mm"]', 'heights = ["9 mm"]\n[solver]\nelements = 10', "solver.elements does not apply"),
        ('radius = "20 mm"', 'radius = 20 mm', "not valid TOML"),
        ('heights = ["9 mm", "8 mm"]', 'heights = ["9 mm"]\n[solver]\nname = "solid"\nthickness_ratio = 0.01',
         "solver.thickness_ratio = 0.01, but a case's thickness ratio is sheet.thickness / clamp.radius"),
    ],
)
def test_bad_case_file(old, new, message, tmp_path, capsys):
    """Each kind of bad case: exit 2, one line on stderr naming the key, no traceback, no output."""
    assert old in BUTTON
    path = _write(tmp_path, BUTTON.replace(old, new))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert "Traceback" not in err, err
    assert not (tmp_path / "out").exists()


def test_sample_number_checked(capsys):
    assert main(["run", "--sample", "7"]) == 2
    assert "sample = 7, but Table 1 has samples 1, 2, 3, 4" in capsys.readouterr().err
    assert sample(1).thickness == pytest.approx(0.25e-3, rel=1e-15)


def _run_case(tmp_path, capsys, text: bytes | str, name="case.toml"):
    """Run the case file ``text``: (status, the one stderr line); nothing may be written."""
    path = tmp_path / name
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    status = main(["run", str(path), "--out", str(tmp_path / "out")])
    out, err = capsys.readouterr()
    assert not (tmp_path / "out").exists()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert "Traceback" not in err, err
    assert len(err) < 400, err
    return status, err


def _with(key_line: str, section: str = "[clamp]") -> str:
    """BUTTON with ``key_line`` added to ``section`` (a value of the wrong kind or size)."""
    return BUTTON.replace(section, f"{section}\n{key_line}", 1)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (b"\xff\xfe[sheet]\n", "not a UTF-8 text file (byte 0)"),
        (bytes(range(256)) * 4, "not a UTF-8 text file"),
        (b"\x00" * 100, "not valid TOML"),
        ("label = " + "[" * 5000 + "]" * 5000 + "\n" + BUTTON, "nested too deeply"),
        ("label = " + "{a = " * 2000 + "1" + "}" * 2000 + "\n" + BUTTON, "nested too deeply"),
        ("label = " + "[" * 200 + "1" + "]" * 200 + "\n" + BUTTON, "label = [[[...]]], but it must be a string"),
        ('name = ["a", "b"]\n' + BUTTON.replace('name = "button"', ""), "name = ['a', 'b'], but it must be a string"),
        ("tags = [[" + ", ".join(['"x"'] * 5000) + "]]\n" + BUTTON, "tags = [['x', 'x', 'x', 'x', ...]], but"),
        (BUTTON + '[solver]\nname = ["fem"]\n', "solver.name = ['fem'], but it must be one of"),
        (BUTTON + "[solver]\nname = {a = 1}\n", "solver.name = {'a': 1}, but it must be one of"),
        (BUTTON.replace('radius = "20 mm"', 'radius = ["20 mm"]'), "clamp.radius = ['20 mm'] is not a length"),
        (BUTTON.replace('radius = "20 mm"', 'radius = "1e300 m"'), "clamp.radius = '1e300 m' is outside the"),
        (BUTTON.replace('radius = "20 mm"', "radius = 1e300"), "clamp.radius = 1e+300 is outside the magnitudes"),
        (BUTTON.replace('radius = "20 mm"', 'radius = "1e-300 mm"'), "outside the magnitudes"),
        (BUTTON.replace('height = "10 mm"', 'pressure = "1e-15 Pa"'),  # Phat_I = 1e-15 0.02 / (1e6 2.5e-4)
         "initial.pressure = '1e-15 Pa' with sheet.thickness = '0.25 mm', clamp.radius = '20 mm' (E = 1e+06 Pa) "
         "gives Phat_I = P_I R / (E T) = 8e-20, outside the magnitudes"),
        (BUTTON.replace('height = "10 mm"', 'pressure = "4 kPa"').replace('heights = ["9 mm", "8 mm"]',
                                                                          'forces = ["1 N", "1e-15 N"]'),
         # Fhat = 1e-15 / (4e3 pi 0.02^2)
         "loads.forces[1] = '1e-15 N' gives Fhat = F / (P_I pi R^2) = 1.99e-16, outside the magnitudes"),
        (BUTTON.replace('radius = "20 mm"', 'radius = "1' + "0" * 400 + ' m"'), "is not finite"),
        (BUTTON.replace("alpha = 0.3", "alpha = 1e300"), "sheet.alpha = 1e+300 is outside the magnitudes"),
        (BUTTON + "[solver]\nrtol = 1e-20\n", "solver.rtol = 1e-20, but it must lie in [1e-14, 0.0001]"),
        (BUTTON + "[solver]\nrtol = 2\n", "solver.rtol = 2, but it must lie in [1e-14, 0.0001]"),
        (BUTTON + '[solver]\nname = "fem"\ntol = 1e-300\n', "solver.tol = 1e-300, but it must lie in [1e-14"),
        (BUTTON + '[solver]\nname = "fem"\nelements = 1000000\n', "solver.elements = 1000000, but it must lie in [4,"),
        (BUTTON + '[solver]\nname = "fem"\nelements = 10.5\n', "solver.elements = 10.5 is not an integer"),
        (BUTTON + '[solver]\nname = "fem"\nmesh = [0, 0.5, 1]\n', "solver.mesh = [0, 0.5, 1], but it must be a file"),
        (BUTTON + '[solver]\nname = "fem"\nmesh = "missing.vtu"\n', "missing.vtu': cannot read it (No such file"),
        (BUTTON + '[solver]\nname = "fem"\nmesh = "/dev/zero"\n', "solver.mesh = '/dev/zero' is not a regular file"),
        (BUTTON + '[solver]\nname = "fem"\npenalty = 1e300\n', "solver.penalty = 1e+300 is outside the magnitudes"),
        (BUTTON + '[solver]\nname = "analytical"\norder = 2\n', "solver.order does not apply to solver analytical"),
        (BUTTON.replace('heights = ["9 mm", "8 mm"]', "heights = [" + ", ".join(['"9 mm"'] * 10_001) + "]"),
         "loads.heights has 10001 values, but a case takes at most 10000"),
        ("# " + "x" * 1_000_001 + "\n" + BUTTON, "bytes, but a case file has at most 1000000"),
    ],
)
def test_hostile_case_files(tmp_path, capsys, text, message):
    """Each file: one line of at most a few hundred characters naming the problem, exit 2, no output,
    before any solve (the work a case can ask for is bounded: elements, loads, file sizes)."""
    status, err = _run_case(tmp_path, capsys, text)
    assert status == 2, err
    assert message in err, err


def test_a_mesh_file_is_relative_to_the_case_file(tmp_path, monkeypatch, capsys):
    """Exact answer: `mesh = "fine.vtu"` in cases/c.toml names cases/fine.vtu whatever the current
    folder; the FE states then report that mesh's element count."""
    from pocket import meshes

    (tmp_path / "cases").mkdir()
    meshes.write(tmp_path / "cases" / "fine.vtu", meshes.uniform(40))
    path = _write(tmp_path / "cases", BUTTON.replace('heights = ["9 mm", "8 mm"]', 'heights = ["9 mm"]')
                  + '[solver]\nname = "fem"\nmesh = "fine.vtu"\n', "c.toml")
    monkeypatch.chdir(tmp_path)
    assert load(path).options == (("mesh", str(tmp_path / "cases" / "fine.vtu")),)
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    result = json.loads((tmp_path / "out" / "c.json").read_text())
    assert result["states"][0]["elements"] == 40
    assert result["case"]["given"]["solver.mesh"] == "fine.vtu"


@pytest.mark.parametrize(
    ("heights", "message"),
    [
        ('["20 mm", "1 mm"]', "loads.heights[0] = '20 mm' is above the inflated pocket (H0 = 10 mm): the plate "
                              "would not touch it"),
        ('["2 cm"]', "loads.heights[0] = '2 cm' is above the inflated pocket (H0 = 1 cm)"),
        ('["1 mm"]', "loads.heights[0] = '1 mm' is below the lowest plate height the model reaches (4.7"),
    ],
)
def test_plate_height_errors_quote_the_case(tmp_path, capsys, heights, message):
    """A case none of whose plate heights the model has a state for: exit 2, the first height as written and
    the bound in its unit (H0 = 10 mm is the case's own initial height; the lowest height is the model's
    range end). A case reaching some of its loads writes those (test_user_files_safe)."""
    text = BUTTON.replace('heights = ["9 mm", "8 mm"]', f"heights = {heights}")
    status, err = _run_case(tmp_path, capsys, text)
    assert status == 2, err
    assert message in err, err
    assert "height = 1 " not in err, err


def test_lowest_plate_height_is_the_range_end(tmp_path):
    """Exact answer: the lowest plate height the message quotes is the height of the state at the end
    of the model's range, compressed by the forward solver (inverse.range_end), in mm."""
    from pocket.apps.inverse import range_end
    from pocket.apps.physical import forces, resolve
    from pocket.core.errors import OutOfRangeError

    pocket = resolve(load(_write(tmp_path, BUTTON.replace('"8 mm"]', '"1 mm"]'))))
    end = range_end(shooting.SOLVER, pocket.alpha, pocket.pressure_initial)
    lowest = shooting.compress(pocket.alpha, pocket.pressure_initial, end).height * 20.0  # mm
    with pytest.raises(OutOfRangeError, match=rf"\({lowest:.6g} mm; the inflated height is 10 mm\)"):
        forces(pocket)


def test_rows_carry_the_loads_as_written(tmp_path):
    """Exact answer: force loads written "0.2 N", "0.67 N" and 0.1 appear in the CSV and JSON as written,
    force_N is the force as parsed (0.2, not 0.19999999999999998 from Fhat P_I pi R^2), and force
    is the Fhat the solver was given, F / (P_I pi R^2)."""
    from pocket.apps.physical import resolve

    text = BUTTON.replace('heights = ["9 mm", "8 mm"]', 'forces = ["0.2 N", "0.67 N", 0.1]')
    path = _write(tmp_path, text)
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    result = json.loads((tmp_path / "out" / "case.json").read_text())
    rows = list(csv.DictReader((tmp_path / "out" / "case.csv").open()))
    assert [r["load"] for r in rows] == ["0.2 N", "0.67 N", "0.1"]
    assert [s["load"] for s in result["states"]] == ["0.2 N", "0.67 N", 0.1]
    assert [s["force_N"] for s in result["states"]] == [0.2, 0.67, 0.1]
    assert [r["force_N"] for r in rows] == ["0.2", "0.67", "0.1"]
    scale = resolve(load(path)).force_scale_N
    assert [s["force"] for s in result["states"]] == [0.2 / scale, 0.67 / scale, 0.1 / scale]
    assert result["case"]["given"] == {"sheet.thickness": "0.25 mm", "sheet.modulus": "1 MPa", "sheet.alpha": 0.3,
                                       "clamp.radius": "20 mm", "initial.height": "10 mm",
                                       "loads.forces[0]": "0.2 N", "loads.forces[1]": "0.67 N",
                                       "loads.forces[2]": 0.1}
    # the plain force is read as newtons and said so, in every row (pocket.core.units.plain_warnings)
    plain = "loads.forces[2] = 0.1 has no unit and is read as 0.1 N; write it with its unit ('0.1 N') to say so"
    assert all(s["warnings"] == [plain] for s in result["states"])
    assert {r["warnings"] for r in rows} == {plain}


def test_solver_options_are_given_as_written(tmp_path):
    """The case's solver section appears in the JSON's given values as the file wrote it."""
    text = BUTTON.replace('heights = ["9 mm", "8 mm"]', 'heights = ["9 mm"]') + "[solver]\nrtol = 1e-9\n"
    assert main(["run", str(_write(tmp_path, text)), "--out", str(tmp_path)]) == 0
    given = json.loads((tmp_path / "case.json").read_text())["case"]["given"]
    assert given["solver.rtol"] == 1e-9
    assert "solver.name" not in given


@pytest.mark.parametrize("number", sorted(SAMPLES))
def test_the_solid_takes_its_thickness_ratio_from_the_sheet(number):
    """A case solved as a solid gets T/R = sheet.thickness / clamp.radius (not the record's default); the
    membrane solvers, which have no thickness, get no such option."""
    case = sample(number)
    assert "thickness_ratio" not in dict(case.options)
    text = BUTTON.replace('thickness = "0.25 mm"', f'thickness = "{SAMPLES[number]}"') + '[solver]\nname = "solid"\n'
    solid_case = parse(tomllib.loads(text))
    assert dict(solid_case.options)["thickness_ratio"] == pytest.approx(solid_case.thickness / solid_case.radius,
                                                                        rel=1e-15)
