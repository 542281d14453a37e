"""Nothing of the user's is lost: every command that writes output refuses, with one line and exit
status 2 before any work, to replace or overwrite what pocket did not write; what pocket wrote
(a VTK series, a report, a results file) a rerun replaces.

Exact answers: the exit status, a message naming what was found, and the folder's bytes unchanged.
"""

import json
import pathlib
import shutil

import pytest
from pocket.validation import runner

import pocket
from pocket.apps.folders import MARKER, check_replaceable, staged
from pocket.apps.ledger import LEDGER
from pocket.apps.vtk import files
from pocket.cli import main
from pocket.core.errors import InputError

COMPRESS = ["compress", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1"]
INFLATE = ["inflate", "--alpha", "0.3", "--pressure", "0.1"]
SWEEP = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--workers", "1"]


@pytest.fixture
def no_work(monkeypatch):
    """Any solve or validation run fails the test: a refusal comes before the work."""
    import pocket.shooting.api as api

    def solved(*args, **kwargs):
        raise AssertionError("work started before the output was checked")

    for name in ("inflate", "inflate_volume", "compress", "compression_curve"):
        monkeypatch.setattr(api, name, solved)
    monkeypatch.setattr(runner, "run", solved)


@pytest.fixture
def mine(tmp_path, monkeypatch):
    """A folder of the user's files, the current folder: a thesis, a subfolder with a file, a folder
    holding the user's own report.md, the user's own sample1.csv, and an empty folder."""
    root = tmp_path / "mine"
    (root / "sub").mkdir(parents=True)
    (root / "thesis.tex").write_text("\\documentclass{article}\n")
    (root / "sub" / "notes.txt").write_text("my notes\n")
    (root / "old-report").mkdir()
    (root / "old-report" / "report.md").write_text("# my own report\n")
    (root / "sample1.csv").write_text("my,own\n1,2\n")
    (root / "empty").mkdir()
    monkeypatch.chdir(root)
    return root


def _starts(argv, capsys) -> bool:
    """The command passed its output checks and started the work (which ``no_work`` stops)."""
    status = main(argv)
    return status == 1 and "work started before the output was checked" in capsys.readouterr().err


def _tree(root: pathlib.Path) -> dict:
    return {str(p.relative_to(root)): (p.read_bytes() if p.is_file() else None) for p in sorted(root.rglob("*"))}


REFUSED = [
    ([*COMPRESS, "--vtk", "."], "--vtk .: is the current folder"),
    ([*COMPRESS, "--vtk", ".", "--overwrite"], "--vtk .: is the current folder"),
    ([*COMPRESS, "--vtk", "sub", "--overwrite"], "--vtk sub: holds notes.txt, which pocket did not write"),
    ([*COMPRESS, "--vtk", "old-report", "--overwrite"], "--vtk old-report: holds report.md, which pocket did not"),
    ([*COMPRESS, "--vtk", "..", "--overwrite"], "--vtk ..: is the current folder, pocket's install or a folder"),
    ([*INFLATE, "--vtk", "sub"], "--vtk sub: holds notes.txt, which pocket did not write"),
    ([*INFLATE, "--vtk", ".", "--overwrite"], "--vtk .: is the current folder"),
    (["validate", "--quick", "--out", "old-report"], "--out old-report: holds report.md, which pocket did not"),
    (["validate", "--quick", "--out", "."], "--out .: is the current folder"),
    (["validate", "--quick", "--out", "sub"], "--out sub: holds notes.txt, which pocket did not write"),
    (["converge", "--quick", "--out", "old-report"], "--out old-report: holds report.md, which pocket did not"),
    (["run", "--sample", "1", "--out", "."], "--out sample1.csv: the file exists and pocket did not write it"),
    ([*SWEEP, "--out", "thesis.tex"], "thesis.tex"),
    ([*SWEEP, "--out", "sample1.csv"], "sample1.csv"),
    (["sense", "--sample", "1", "--ratio", "1.2", "--table", "thesis.tex"],
     "--table thesis.tex: the file exists and pocket did not write it"),
]


@pytest.mark.parametrize(("argv", "message"), REFUSED)
def test_every_writer_refuses_the_users_files(argv, message, mine, capsys, no_work):
    """Exit 2, one line on stderr naming what was found, before any work, and the folder unchanged."""
    before = _tree(mine)
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert err.startswith("pocket: error: "), err
    assert message in err, err
    assert _tree(mine) == before


def test_an_empty_folder_is_filled(mine, capsys, no_work):
    """An empty folder is not refused: the check passes and the work starts (here: is stopped)."""
    assert _starts([*COMPRESS, "--vtk", "empty"], capsys)


def test_pockets_install_and_its_parents_are_never_replaced():
    """Exact answer: the folder of the pocket package and each folder above it are refused."""
    install = pathlib.Path(pocket.__file__).resolve().parent
    for folder in (install, *install.parents):
        with pytest.raises(InputError, match="pocket's install or a folder above"):
            check_replaceable(folder, files.KIND)


def test_a_series_pocket_wrote_is_replaced_by_a_rerun(tmp_path, monkeypatch, capsys):
    """The first run writes a series with its marker; without --overwrite a rerun is refused (exit 2,
    unchanged), with it the series is replaced (the times are the new forces); from inside the
    series, ``--vtk .`` is refused all the same."""
    monkeypatch.chdir(tmp_path)
    argv = ["compress", "--alpha", "0.3", "--pressure", "0.1", "--vtk", "series", "--force"]
    assert main([*argv, "0.1"]) == 0
    marker = json.loads((tmp_path / "series" / MARKER).read_text())
    assert marker["kind"] == files.KIND
    assert "surface.pvd" in marker["entries"]
    before = _tree(tmp_path)
    capsys.readouterr()
    assert main([*argv, "0.2"]) == 2
    assert "holds a previous VTK series (--overwrite replaces it)" in capsys.readouterr().err
    assert _tree(tmp_path) == before
    assert main([*argv, "0.05", "0.2", "--overwrite"]) == 0
    assert '"0.2"' in (tmp_path / "series" / "surface.pvd").read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["series"]
    monkeypatch.chdir(tmp_path / "series")
    capsys.readouterr()
    assert main([*argv[:-3], "--vtk", ".", "--overwrite", "--force", "0.1"]) == 2
    assert "is the current folder" in capsys.readouterr().err


def test_a_file_added_to_a_pocket_series_is_kept(tmp_path, capsys):
    """A series pocket wrote, plus the user's file in it (and one in a subfolder): refused even with
    --overwrite, naming the user's files."""
    argv = ["compress", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--vtk", str(tmp_path / "s")]
    assert main(argv) == 0
    (tmp_path / "s" / "notes.txt").write_text("mine\n")
    before = _tree(tmp_path)
    capsys.readouterr()
    assert main([*argv, "--overwrite"]) == 2
    assert "holds notes.txt, which pocket did not write, besides its VTK series" in capsys.readouterr().err
    assert _tree(tmp_path) == before


def _fake_report(target: pathlib.Path, kind: str) -> None:
    """A folder written as pocket writes a report of ``kind`` (through ``staged``), without the suite."""
    with staged(target, kind) as partial:
        (partial / "report.md").write_text(f"# pocket {kind}\n")


@pytest.mark.parametrize(("command", "kind", "other"), [("validate", "validation report", "convergence report"),
                                                  ("converge", "convergence report", "validation report")])
def test_a_report_of_the_other_kind_is_refused(command, kind, other, tmp_path, capsys, no_work):
    """``converge --out`` onto a validation report pocket wrote (and the reverse): exit 2, naming it."""
    _fake_report(tmp_path / "report", other)
    before = _tree(tmp_path)
    assert main([command, "--quick", "--out", str(tmp_path / "report")]) == 2
    err = capsys.readouterr().err
    assert f"holds a pocket {other}, not a {kind}" in err, err
    assert err.count("\n") == 1, err
    assert _tree(tmp_path) == before


@pytest.mark.parametrize(("command", "kind"), [("validate", "validation report"), ("converge", "convergence report")])
def test_a_report_of_the_same_kind_passes_the_check(command, kind, tmp_path, capsys, no_work):
    """A report of the command's own kind that pocket wrote is not refused: the run starts."""
    _fake_report(tmp_path / "report", kind)
    assert _starts([command, "--quick", "--out", str(tmp_path / "report")], capsys)


def test_run_replaces_its_own_results(tmp_path, capsys):
    """``run --out`` twice: the second replaces the files the first wrote (recorded in the folder's
    ledger), and nothing else is left."""
    for _ in range(2):
        assert main(["run", "--sample", "2", "--out", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == [LEDGER, "sample2.csv", "sample2.json"]


def test_sense_replaces_its_own_table(tmp_path, capsys):
    """``sense --table`` twice: the second replaces the table the first wrote; a copy the user made under
    another name is the user's file, refused (exit 2) and kept byte for byte."""
    argv = ["sense", "--sample", "1", "--ratio", "1.2", "--points", "3", "--table"]
    assert main([*argv, str(tmp_path / "t.csv")]) == 0
    assert main([*argv, str(tmp_path / "t.csv")]) == 0
    shutil.copy(tmp_path / "t.csv", tmp_path / "u.csv")
    before = _tree(tmp_path)
    capsys.readouterr()
    assert main([*argv, str(tmp_path / "u.csv")]) == 2
    assert "u.csv: the file exists and pocket did not write it" in capsys.readouterr().err
    assert _tree(tmp_path) == before
