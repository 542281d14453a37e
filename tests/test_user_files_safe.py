"""Nothing of the user's is lost on a rerun, a case is written in metres for ParaView, and a case with a
force past the end of the model's range keeps the part the model reaches.

Exact answers: exit statuses, messages naming the file, bytes unchanged after a refusal, the ledger's
checksums against ``hashlib`` on the bytes written, the series' times and heights against the run's own
results (F in N, H in m: the scales written beside the files), and the end of the range by the shooting's
``range_end`` (as in test_range_messages).
"""

import csv
import hashlib
import json
import math
import pathlib
import re

import meshio
import pytest

from pocket import shooting
from pocket.apps.folders import MARKER
from pocket.apps.ledger import LEDGER
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
forces = [{forces}]
"""
ALPHA = 47 / 160
PHAT_I = 4812.75 * 0.02 / (6 * (160e3 + 47e3) * 0.25e-3)  # Phat_I = P_I R / (E T)
SCALE = 4812.75 * math.pi * 0.02**2  # F = Fhat P_I pi R^2, N


def _tree(root: pathlib.Path) -> dict:
    return {str(p.relative_to(root)): (p.read_bytes() if p.is_file() else None) for p in sorted(root.rglob("*"))}


def _case(path: pathlib.Path, forces: str) -> pathlib.Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(CASE.format(forces=forces))
    return path


@pytest.fixture
def no_solve(monkeypatch):
    """Once applied, solving a case fails the test: a refusal must come before any work."""
    import pocket.cli.run as run

    def solved(*args, **kwargs):
        raise AssertionError("a case was solved before its output was checked")

    def apply():
        monkeypatch.setattr(run, "solved", solved)

    return apply


def _refused(argv, root, capsys, *needles) -> str:
    """``argv`` exits 2 with one line on stderr holding every needle, and leaves ``root`` as it was."""
    before = _tree(root)
    capsys.readouterr()
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert err.startswith("pocket: error: "), err
    for needle in needles:
        assert needle in err, err
    assert _tree(root) == before
    return err


def test_two_same_named_cases_keep_both_results(tmp_path, capsys, no_solve):
    """``vA/sensor.toml`` then ``vB/sensor.toml`` into one --out folder: the second is refused before any
    solve (exit 2), naming the results file and both case files, and the first case's results stay."""
    first, second = _case(tmp_path / "vA" / "sensor.toml", '"1 N"'), _case(tmp_path / "vB" / "sensor.toml", '"2 N"')
    out = tmp_path / "D"
    assert main(["run", str(first), "--out", str(out)]) == 0
    no_solve()
    _refused(["run", str(second), "--out", str(out)], tmp_path, capsys, f"{out / 'sensor.json'}: holds pocket's output "
             f"for case file {first.resolve()}, not for case file {second.resolve()}")


def test_appended_csv_row_refuses_rerun(tmp_path, capsys, no_solve):
    """A row the user appended to the results CSV: the rerun is refused (exit 2, naming the CSV) and the
    file keeps the row; the JSON, untouched, is not what stops it."""
    case = _case(tmp_path / "sensor.toml", '"1 N"')
    assert main(["run", str(case), "--out", str(tmp_path)]) == 0
    with open(tmp_path / "sensor.csv", "a", encoding="utf-8") as file:
        file.write("my measurement,1.02\n")
    no_solve()
    _refused(["run", str(case), "--out", str(tmp_path)], tmp_path, capsys,
             f"--out {tmp_path / 'sensor.csv'}: the file was changed after pocket wrote it")


def test_added_table_line_refuses_rerun(tmp_path, capsys):
    """A line added to a ``sense --table`` file: the rerun is refused before any work, the line kept."""
    argv = ["sense", "--sample", "1", "--ratio", "1.2", "--points", "3", "--table", str(tmp_path / "t.csv")]
    assert main(argv) == 0
    with open(tmp_path / "t.csv", "a", encoding="utf-8") as file:
        file.write("# checked against the bench on Monday\n")
    _refused(argv, tmp_path, capsys, f"--table {tmp_path / 't.csv'}: the file was changed after pocket wrote it")


def test_repeated_sweep_row_refuses_rerun(tmp_path, capsys):
    """A sweep file whose last row the user copied (to edit it): a rerun would keep one row per point, so
    it is refused naming both lines (2 and 3: the header is line 1), the file unchanged."""
    path = tmp_path / "s.csv"
    argv = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--workers", "1", "--out", str(path)]
    assert main(argv) == 0
    lines = path.read_text().splitlines(keepends=True)
    assert len(lines) == 2
    path.write_text(lines[0] + lines[1] + lines[1])
    _refused(argv, tmp_path, capsys, f"{path}: line 3 repeats the point of line 2")


def test_edited_file_in_a_series_refuses_rerun(tmp_path, capsys):
    """A file of a VTK series edited after pocket wrote it: even with --overwrite the series is refused,
    naming the file."""
    argv = ["compress", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--vtk", str(tmp_path / "s"),
            "--overwrite"]
    assert main(argv) == 0
    with open(tmp_path / "s" / "surface.pvd", "a", encoding="utf-8") as file:
        file.write("<!-- my camera settings -->\n")
    _refused(argv, tmp_path, capsys, "surface.pvd changed after pocket wrote its VTK series")


def test_users_file_named_like_the_ledger_is_kept(tmp_path, capsys, no_solve):
    """A file of the user's that has the ledger's name is never replaced by one: the run is refused."""
    (tmp_path / LEDGER).write_text("my own notes\n")
    no_solve()
    _refused(["run", "--sample", "1", "--out", str(tmp_path)], tmp_path, capsys, f"{tmp_path / LEDGER} is not a "
             "record pocket wrote")


def test_rerun_replaces_untouched_results(tmp_path, capsys):
    """Results no one changed are replaced by a rerun of the same case file, edited to a new force: the
    CSV then holds that force, and the ledger records the SHA-256 (by hashlib) of each file's bytes."""
    case = _case(tmp_path / "sensor.toml", '"1 N"')
    out = tmp_path / "D"
    assert main(["run", str(case), "--out", str(out)]) == 0
    _case(case, '"2 N"')
    assert main(["run", str(case), "--out", str(out)]) == 0
    with open(out / "sensor.csv", encoding="utf-8", newline="") as file:
        assert [row["load"] for row in csv.DictReader(file)] == ["2 N"]
    files = json.loads((out / LEDGER).read_text())["files"]
    assert sorted(files) == ["sensor.csv", "sensor.json"]
    for name, entry in files.items():
        assert entry == {"sha256": hashlib.sha256((out / name).read_bytes()).hexdigest(),
                         "of": f"case file {case.resolve()}"}


def test_run_vtk_writes_surface_series(tmp_path, capsys):
    """``run --sample 1 --out D --vtk V`` writes V/surface.pvd (and profile.pvd, indenter.pvd): a step per
    load, its time the load's force_N in the results; every file states length_scale_m = R = 0.02 m, and the
    plate's lowest point (z of the indenter, units R) times it is the results' height_m of that load."""
    out, vtk = tmp_path / "D", tmp_path / "V"
    assert main(["run", "--sample", "1", "--out", str(out), "--vtk", str(vtk)]) == 0
    assert {"surface.pvd", "profile.pvd", "indenter.pvd", MARKER} <= {p.name for p in vtk.iterdir()}
    rows = json.loads((out / "sample1.json").read_text())["states"]
    pvd = (vtk / "surface.pvd").read_text()
    times = [float(t) for t in re.findall(r'timestep="([^"]+)"', pvd)]
    assert times == pytest.approx(sorted(r["force_N"] for r in rows), rel=1e-12, abs=0.0)  # F = Fhat * (P_I pi R^2)
    steps = sorted(rows, key=lambda r: r["force_N"])
    for k, row in enumerate(steps):
        plate = meshio.read(vtk / f"step_{k:04d}_indenter.vtu")
        surface = meshio.read(vtk / f"step_{k:04d}_surface.vtu")
        for mesh in (plate, surface):
            assert float(mesh.field_data["length_scale_m"][0]) == 0.02
            assert float(mesh.field_data["force_scale_N"][0]) * row["force"] == pytest.approx(row["force_N"],
                                                                                              rel=1e-12)
        assert plate.points[:, 2].min() * 0.02 == pytest.approx(row["height_m"], rel=1e-12)


@pytest.mark.parametrize(("out", "vtk"), [("D", "D"), ("V/D", "V")])
def test_run_vtk_into_its_out_folder_is_refused(out, vtk, tmp_path, capsys, no_solve, monkeypatch):
    """``--vtk`` the --out folder (or a folder holding it): the series, written as a folder of its own, would
    mix with the results; refused before any solve, exit 2, nothing written."""
    monkeypatch.chdir(tmp_path)
    no_solve()
    _refused(["run", "--sample", "1", "--out", out, "--vtk", vtk], tmp_path, capsys,
             f"--vtk {vtk}: holds the --out folder {out}")


def test_case_past_range_end_writes_reachable_part(tmp_path, capsys):
    """Forces 1 N and 61 N, the range ending at about 60 N: exit 0, the 1 N state written; stderr warns
    with the one message of a force past the end (the end by the shooting, in N); the JSON lists 61 N as
    unreachable with that message, and the CSV's second row holds the load, its force and the message
    only."""
    end = shooting.range_end(ALPHA, PHAT_I)
    assert 1.0 / SCALE < end < 61.0 / SCALE
    message = (f"loads.forces[1] = '61 N' (Fhat = {61.0 / SCALE:.10g}) is beyond the model's range, which ends at "
               f"{end * SCALE:.6g} N (Fhat = {end:.10g}): there the free part of the sheet reaches the clamp plane")
    case = _case(tmp_path / "sensor.toml", '"1 N", "61 N"')
    assert main(["run", str(case), "--out", str(tmp_path)]) == 0
    err = capsys.readouterr().err
    assert f"pocket: warning: {message}; the results hold the 1 of 2 loads the model reaches, and list the " \
           "others with the reason\n" in err, err
    result = json.loads((tmp_path / "sensor.json").read_text())
    assert [r["force_N"] for r in result["states"]] == [1.0]
    assert result["unreachable"] == [{"load": "61 N", "force_N": 61.0, "warnings": [message]}]
    with open(tmp_path / "sensor.csv", encoding="utf-8", newline="") as file:
        rows = list(csv.DictReader(file))
    assert [r["load"] for r in rows] == ["1 N", "61 N"]
    assert {k: v for k, v in rows[1].items() if v} == {"load": "61 N", "force_N": "61.0", "warnings": message}
