"""Outputs: checked before any work, written whole or not at all, one line and a status when they cannot be.

Read-only folders are made with chmod, or, when the tests run as root (whom chmod does not stop),
with the immutable attribute (chattr +i), which stops root too; where neither works the tests skip.
"""

import contextlib
import errno
import json
import os
import pathlib
import shutil
import subprocess
import sys
import threading

import pytest

from pocket.apps import folders
from pocket.apps.folders import check_output_dir, check_output_file, staged, write_files, write_whole
from pocket.apps.ledger import LEDGER
from pocket.cli import main
from pocket.core.errors import InputError, OutputError

SWEEP = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--workers", "1"]
SENSE = ["sense", "--sample", "1", "--ratio", "1.2"]
COMPRESS = ["compress", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1"]


@pytest.fixture
def no_solver(monkeypatch):
    """Any solve fails the test: the output checks must come before the work."""
    import pocket.shooting.api as api

    def solved(*args, **kwargs):
        raise AssertionError("a solver ran before the output was checked")

    for name in ("inflate", "inflate_volume", "compress", "compression_curve"):
        monkeypatch.setattr(api, name, solved)


def _tree(root: pathlib.Path) -> dict:
    return {str(p.relative_to(root)): (p.read_bytes() if p.is_file() else None) for p in sorted(root.rglob("*"))}


def _one_line(capsys) -> str:
    out, err = capsys.readouterr()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert "Traceback" not in err, err
    return err


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["run", "--sample", "1", "--out", "FILE"], "--out FILE: is a file, not a folder"),
        ([*SWEEP, "--out", "FILE/x.csv"], "--out FILE/x.csv: "),
        ([*COMPRESS, "--vtk", "FILE/sub"], "--vtk FILE/sub: "),
        ([*SENSE, "--table", "FILE/x.csv"], "--table FILE/x.csv: "),
        ([*SENSE, "--table", "."], "--table .: is a folder, not a file"),
        ([*SENSE, "--table", "/dev/null"], "--table /dev/null: is not a regular file"),
        ([*SWEEP, "--out", "/dev/null"], "--out /dev/null: is not a regular file"),
        (["run", "--sample", "1", "--out", "results"], "--out results/sample1.json: is a folder, not a file"),
        ([*COMPRESS, "--vtk", "full"], "--vtk full: holds old.vtu, which pocket did not write"),
        ([*SWEEP, "--out", "dangling.csv"], "--out dangling.csv: is a broken link"),
    ],
)
def test_bad_output_path_before_any_work(argv, message, tmp_path, monkeypatch, capsys, no_solver):
    """Each bad output path: exit 2, one line naming it, nothing written, and no solver called."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "FILE").write_text("a file\n")
    (tmp_path / "results" / "sample1.json").mkdir(parents=True)
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "old.vtu").write_text("old\n")
    (tmp_path / "dangling.csv").symlink_to(tmp_path / "nowhere")
    before = _tree(tmp_path)
    assert main(argv) == 2
    err = _one_line(capsys)
    assert message in err, err
    assert "is a file, not a folder" in err or "FILE" not in message, err
    assert _tree(tmp_path) == before


def test_a_link_to_a_file_is_followed(tmp_path):
    """The file a link names (one pocket wrote) is the one replaced; the link stays a link."""
    write_whole(tmp_path / "real.csv", "old\n")
    (tmp_path / "link.csv").symlink_to(tmp_path / "real.csv")
    target = check_output_file(tmp_path / "link.csv")
    write_whole(target, "new\n")
    assert (tmp_path / "link.csv").is_symlink()
    assert (tmp_path / "real.csv").read_text() == "new\n"


@contextlib.contextmanager
def read_only(folder: pathlib.Path):
    """``folder`` made read-only for this process: chmod, or as root the immutable attribute."""
    folder.mkdir(parents=True, exist_ok=True)
    if os.geteuid() != 0:
        folder.chmod(0o555)
        undo = [lambda: folder.chmod(0o755)]
    elif shutil.which("chattr") and subprocess.run(["chattr", "+i", str(folder)], capture_output=True).returncode == 0:
        undo = [lambda: subprocess.run(["chattr", "-i", str(folder)], check=True)]
    else:
        pytest.skip("running as root without chattr: no way to make a folder read-only")
    try:
        probe = folder / "probe"
        try:
            probe.write_text("")
        except OSError:
            pass
        else:
            probe.unlink()
            pytest.skip("this file system lets the process write into a read-only folder")
        yield folder
    finally:
        for step in undo:
            step()


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["run", "--sample", "1", "--out", "ro/new"], "--out ro/new: the folder"),
        (["run", "--sample", "1", "--out", "ro"], "--out ro: the folder is not writable"),
        ([*SWEEP, "--out", "ro/s.csv"], "--out ro/s.csv: the folder"),
        ([*SENSE, "--table", "ro/t.csv"], "--table ro/t.csv: the folder"),
        ([*COMPRESS, "--vtk", "ro/vtk"], "--vtk ro/vtk: the folder"),
    ],
)
def test_read_only_folder_before_any_work(argv, message, tmp_path, monkeypatch, capsys, no_solver):
    """A real read-only folder: exit 2, one line, before any solve; the folder stays empty."""
    monkeypatch.chdir(tmp_path)
    with read_only(tmp_path / "ro"):
        assert main(argv) == 2
    err = _one_line(capsys)
    assert message in err, err
    assert "not writable" in err, err
    assert list((tmp_path / "ro").iterdir()) == []


def test_folder_made_read_only_during_the_solve(tmp_path, monkeypatch, capsys):
    """The folder passes the check, then becomes read-only while the case is solved: the write
    fails for real, exit 1, one line, nothing left in it."""
    import pocket.cli.run as run

    out = tmp_path / "out"
    out.mkdir()
    state = contextlib.ExitStack()
    real = run.solved

    def solve_then_lock(case, progress=None):
        result = real(case, progress)
        state.enter_context(read_only(out))
        return result

    monkeypatch.setattr(run, "solved", solve_then_lock)
    with state:
        assert main(["run", "--sample", "1", "--out", str(out)]) == 1
    err = _one_line(capsys)
    assert f"cannot write {out}" in err, err
    assert list(out.iterdir()) == []


def _full_disk(monkeypatch, after: int = 0):
    """pathlib.Path.write_text fails with ENOSPC on every call after the first ``after``, having
    written half its text (what a disk filling up mid-file leaves)."""
    real, calls = pathlib.Path.write_text, []

    def write_text(self, text, *args, **kwargs):
        calls.append(self)
        if len(calls) <= after:
            return real(self, text, *args, **kwargs)
        real(self, text[: len(text) // 2], *args, **kwargs)
        raise OSError(errno.ENOSPC, "No space left on device", str(self))

    monkeypatch.setattr(pathlib.Path, "write_text", write_text)
    return calls


@pytest.mark.parametrize("after", [0, 1])
def test_run_on_a_full_disk_writes_neither_file(after, tmp_path, monkeypatch, capsys):
    """ENOSPC writing the JSON (after = 0) or the CSV (after = 1): exit 1, one line naming the file,
    neither file, no hidden partial, not even the results folder it would have made."""
    _full_disk(monkeypatch, after)
    assert main(["run", "--sample", "1", "--out", str(tmp_path / "new" / "results")]) == 1
    err = _one_line(capsys)
    name = ("sample1.json", "sample1.csv")[after]
    assert f"cannot write {tmp_path / 'new' / 'results' / name}: No space left on device" in err, err
    assert list(tmp_path.iterdir()) == []


def test_run_on_a_full_disk_keeps_the_previous_results(tmp_path, monkeypatch, capsys):
    """Results of an earlier run stay as they were when the new ones cannot be written."""
    assert main(["run", "--sample", "1", "--out", str(tmp_path)]) == 0
    capsys.readouterr()
    before = _tree(tmp_path)
    _full_disk(monkeypatch, 1)
    assert main(["run", "--sample", "1", "--out", str(tmp_path)]) == 1
    _one_line(capsys)
    assert _tree(tmp_path) == before


def test_sense_table_on_a_full_disk(tmp_path, monkeypatch, capsys):
    """The calibration table is written whole or not at all: exit 1, one line, no file, no partial."""
    _full_disk(monkeypatch)
    assert main([*SENSE, "--table", str(tmp_path / "t.csv"), "--points", "3"]) == 1
    assert "No space left on device" in _one_line(capsys)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_file_size_limit_in_a_real_process(tmp_path):
    """A real write failure (RLIMIT_FSIZE: writes past 2000 bytes fail with EFBIG, as on a full
    disk) in the installed command: exit 1, one line, no traceback, nothing left."""
    resource = pytest.importorskip("resource")

    def small_files():
        resource.setrlimit(resource.RLIMIT_FSIZE, (2000, 2000))

    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "run", "--sample", "1", "--out", str(tmp_path / "r")],
                          capture_output=True, text=True, preexec_fn=small_files)
    assert proc.returncode == 1, proc.stderr
    assert proc.stderr.count("\n") == 1, proc.stderr
    assert "File too large" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert list(tmp_path.iterdir()) == []


def test_write_files_is_all_or_nothing(tmp_path, monkeypatch):
    """Two files, the second cannot be written: neither exists afterwards, the first keeps its old
    content, no sibling and no folder made for them remains; the error names the second."""
    (tmp_path / "a.txt").write_text("old a\n")
    _full_disk(monkeypatch, 1)
    with pytest.raises(OutputError, match=r"cannot write .*b\.txt: No space left on device"):
        write_files({tmp_path / "a.txt": "new a\n", tmp_path / "sub" / "b.txt": "new b\n"})
    assert _tree(tmp_path) == {"a.txt": b"old a\n"}


def test_staged_folder_failure_leaves_nothing(tmp_path):
    """An error while a staged folder is filled removes it and the folders made for it."""
    target = tmp_path / "new" / "report"

    def fill_then_fail():
        with staged(target, "validation report") as partial:
            (partial / "index.html").write_text("half")
            raise RuntimeError("stop")

    with pytest.raises(RuntimeError, match="stop"):
        fill_then_fail()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("fixed", [False, True])
def test_two_writers_of_one_file(fixed, tmp_path, monkeypatch):
    """Four threads write 1 MB texts of their own to one file, 20 times each. With random temporary
    names every write succeeds and the file ends as one writer's whole text, with no temporary
    left. The control (fixed = True) gives every writer one fixed temporary name, as before: then
    the writers collide (a rename finds its temporary gone, or a file mixes two texts)."""
    if fixed:
        monkeypatch.setattr(folders, "_partial", lambda target: target.with_name(f".{target.name}.partial"))
    target = tmp_path / "shared.csv"
    texts = [str(i) * 1_000_000 for i in range(4)]
    errors = []

    def writer(text):
        for _ in range(20):
            try:
                write_whole(target, text)
            except OutputError as err:
                errors.append(err)

    threads = [threading.Thread(target=writer, args=(text,)) for text in texts]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    whole = target.read_text() in texts and sorted(p.name for p in tmp_path.iterdir()) == [LEDGER, "shared.csv"]
    assert (not errors and whole) != fixed, (len(errors), whole)


def test_checks_return_absolute_paths(tmp_path, monkeypatch):
    """Exact answer: the checked path is the absolute path of the one given (relative to the cwd)."""
    monkeypatch.chdir(tmp_path)
    assert check_output_file("a/b.csv") == tmp_path / "a" / "b.csv"
    assert check_output_dir("out") == tmp_path / "out"
    with pytest.raises(InputError, match="is a folder"):
        check_output_file(".")


def test_run_json_is_valid_after_a_rerun(tmp_path, capsys):
    """A second run over the first replaces both files whole (valid JSON, same keys)."""
    for _ in range(2):
        assert main(["run", "--sample", "2", "--out", str(tmp_path)]) == 0
    assert set(json.loads((tmp_path / "sample2.json").read_text())) == {"case", "inflated", "states", "unreachable",
                                                                        "provenance"}
    assert sorted(p.name for p in tmp_path.iterdir()) == [LEDGER, "sample2.csv", "sample2.json"]
