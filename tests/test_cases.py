"""Case files and ``pocket run``: Table 1 samples, the three initial states, and one-line errors."""

import csv
import json
import math

import pytest
import scipy

from pocket import shooting
from pocket.apps.cases import SAMPLES, load, sample
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
    "old, new, message",
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
    ],
)
def test_bad_case_file(old, new, message, tmp_path, capsys):
    """Each kind of bad case: exit 2, one line on stderr naming the key, no traceback, no output."""
    assert old in BUTTON
    path = _write(tmp_path, BUTTON.replace(old, new))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err and "Traceback" not in err, err
    assert not (tmp_path / "out").exists()


def test_sample_number_checked(capsys):
    assert main(["run", "--sample", "7"]) == 2
    assert "sample = 7, but Table 1 has samples 1, 2, 3, 4" in capsys.readouterr().err
    assert sample(1).thickness == pytest.approx(0.25e-3, rel=1e-15)
