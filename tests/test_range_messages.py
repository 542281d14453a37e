"""A force past the end of the model's range, refused in the user's unit and in one wording for every
solver (``pocket.core.errors.beyond_range``, ``pocket.apps.forcerange``)."""

import math

import pytest

from pocket import shooting
from pocket.cli import main

CASE = """
[sheet]
thickness = "0.25 mm"
c1 = "160 kPa"
c2 = "47 kPa"
[clamp]
radius = "20 mm"
[initial]
pressure = "4.81275 kPa"
[loads]
forces = ["1 N", "{force}"]
[solver]
name = "{solver}"
"""
ALPHA = 47 / 160
PHAT_I = 4812.75 * 0.02 / (6 * (160e3 + 47e3) * 0.25e-3)  # Phat_I = P_I R / (E T) = 0.31
SCALE = 4812.75 * math.pi * 0.02**2  # F = Fhat P_I pi R^2, N


def _expected(key, given, force_N, unit_per_N=1.0, unit="N"):
    """The message for ``key`` = ``given`` (``force_N`` newtons): the end by the shooting, in ``unit``."""
    end = shooting.range_end(ALPHA, PHAT_I)
    return (f"{key} = '{given}' (Fhat = {force_N / SCALE:.10g}) is beyond the model's range, which ends at "
            f"{end * SCALE * unit_per_N:.6g} {unit} (Fhat = {end:.10g}): there the free part of the sheet reaches "
            "the clamp plane")


@pytest.mark.parametrize("solver", ["shooting", "fem"])
@pytest.mark.parametrize(("given", "force_N", "unit_per_N", "unit"), [("61 N", 61.0, 1.0, "N"),
                                                                ("61000 mN", 61.0, 1e3, "mN")])
def test_a_case_force_past_the_end(tmp_path, capsys, solver, given, force_N, unit_per_N, unit):
    """``pocket run`` on a case whose only load is past the end: the load's key, its value as written, and
    the end in its unit, the same for both solvers (the FE is told the shooting's end), exit 2, nothing
    written (a case that reaches some of its loads writes those: test_user_files_safe)."""
    assert force_N / SCALE > shooting.range_end(ALPHA, PHAT_I)
    path = tmp_path / "case.toml"
    path.write_text(CASE.format(force=given, solver=solver).replace('"1 N", ', ""))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err == f"pocket: error: {_expected('loads.forces[0]', given, force_N, unit_per_N, unit)}\n"
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_sense_max_force_past_the_end(tmp_path, capsys):
    """``pocket sense --max-force '61 N'``: the flag, newtons, and the force asked, not a slope stencil's."""
    status = main(["sense", "--sample", "1", "--max-force", "61 N", "--table", str(tmp_path / "t.csv")])
    assert status == 2
    assert capsys.readouterr().err == f"pocket: error: {_expected('--max-force', '61 N', 61.0)}\n"
    assert not (tmp_path / "t.csv").exists()


def test_sense_table_up_to_a_case_load_past_the_end(tmp_path, capsys):
    """Without --max-force the table goes to the case's largest load: past the end, that load is named."""
    path = tmp_path / "case.toml"
    path.write_text(CASE.format(force="61 N", solver="shooting"))
    assert main(["sense", str(path), "--table", str(tmp_path / "t.csv")]) == 2
    assert capsys.readouterr().err == f"pocket: error: {_expected('loads.forces[1]', '61 N', 61.0)}\n"
