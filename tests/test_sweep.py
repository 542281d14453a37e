"""Sweeps: the same CSV on local processes and on a dask cluster; an interrupted sweep resumes."""

import csv
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pytest

from pocket import analytical, shooting
from pocket.apps.rubbers import PARAMETERS
from pocket.apps.sweep.grid import run_sweep
from pocket.apps.sweep.journal import COLUMNS
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.materials import mooney_rivlin
from pocket.core.states import CHECKS, CompressedState

ALPHAS, PRESSURES, FORCES = [0.2, 47 / 160], [0.1, 0.31], [0.0, 0.2, 1.0, 15.0]  # 15: out of range at 0.31
ARGV = ["--alpha", "0.2", "47/160", "--pressure", "0.1", "0.31", "--force", "0", "0.2", "1", "15"]


class CountingExecutor(ThreadPoolExecutor):
    """Counts the tasks (curves) and the points submitted, to show which ones a resumed sweep recomputes."""

    def __init__(self):
        super().__init__(max_workers=2)
        self.points, self.tasks = [], 0

    def submit(self, fn, *args, **kwargs):
        _solver, material, pressure, forces, _options = args
        self.points += [(material.alpha, pressure, force) for force in forces]
        self.tasks += 1
        return super().submit(fn, *args, **kwargs)


def _entry_of(compress):
    """``pocket.apps.solvers.entry`` of a solver whose entry points are ``compress`` and its curve, point by
    point."""

    def compression_curve(material, pressure_initial, forces, *, progress=None, **options):
        states = []
        for force in forces:
            states.append(compress(material, pressure_initial, force, **options))
            if progress is not None:
                progress(len(states), len(forces))
        return states

    return lambda solver, name, purpose: {"compress": compress, "compression_curve": compression_curve}[name]


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The sweep on local processes (the command line's default executor)."""
    path = tmp_path_factory.mktemp("sweep") / "processes.csv"
    assert main(["sweep", *ARGV, "--out", str(path), "--workers", "2"]) == 0
    return path


def test_rows_are_the_solver(reference):
    """Exact: each row is the shooting solver's state on its curve (``compression_curve`` through the
    forces in range), written exactly (repr floats); past the range, the row says so."""
    rows = list(csv.DictReader(reference.open()))
    assert tuple(rows[0]) == COLUMNS
    assert len(rows) == 16
    for alpha in ALPHAS:
        for pressure in PRESSURES:
            curve = [r for r in rows if (float(r["alpha"]), float(r["pressure_initial"])) == (alpha, pressure)]
            assert [float(r["force"]) for r in curve] == FORCES
            ok = [r for r in curve if r["status"] == "ok"]
            for row in curve[len(ok):]:
                assert (pressure, row["force"]) == (0.31, "15.0")
                assert "beyond the model's range" in row["message"]
            states = shooting.compression_curve(alpha, pressure, FORCES[: len(ok)])
            assert [float(r["pressure_ratio"]) for r in ok] == [s.pressure_ratio for s in states]
            assert [float(r["height"]) for r in ok] == [s.height for s in states]


#: (solver, options) of the curve-against-points test: every solver, fem with P1 on a small mesh (fast)
CURVE_SOLVERS = [("shooting", {}), ("analytical", {}), ("fem", {"order": 1, "elements": 64})]


@pytest.mark.parametrize(("solver", "options"), CURVE_SOLVERS)
def test_a_curve_task_gives_the_points(solver, options):
    """A curve solved by continuation (one task) gives each point's row as solved alone from a fresh
    inflation: the same statuses and messages, the numbers to the solver's tolerance. Each solve is
    within its tolerance of the exact state (shooting: the ODE's rtol; fem: Newton's tol on a
    residual of order 1; analytical: closed form, solved to round-off), so two solves of one
    point differ by a few of it: 100 times it bounds that, and is far below any physical digit."""
    from pocket.apps.solvers import record
    from pocket.apps.sweep.grid import solve_curve, solve_point

    tolerance = {"shooting": "rtol", "fem": "tol"}
    rel = 100 * (record(solver).option(tolerance[solver]).default if solver in tolerance else 1e-12)
    for alpha in ALPHAS:
        for pressure in PRESSURES:
            curve = solve_curve(solver, mooney_rivlin(alpha), pressure, FORCES, options)
            points = [solve_point(solver, mooney_rivlin(alpha), pressure, force, options) for force in FORCES]
            assert [r["status"] for r in curve] == [r["status"] for r in points]
            assert "out_of_range" in {r["status"] for r in curve} or pressure == 0.1
            for row, alone in zip(curve, points, strict=True):
                assert {k: v for k, v in row.items() if not isinstance(v, float)} == {
                    k: v for k, v in alone.items() if not isinstance(v, float)}
                for name, value in alone.items():
                    if isinstance(value, float):
                        assert row[name] == pytest.approx(value, rel=rel, abs=rel), (name, row[name], value)


@pytest.mark.slow
def test_dask_cluster_same_csv(reference, tmp_path):
    """A local dask cluster of two worker processes, reached by --scheduler, writes the same bytes."""
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        path = tmp_path / "dask.csv"
        assert main(["sweep", *ARGV, "--out", str(path), "--scheduler", cluster.scheduler_address]) == 0
    assert path.read_bytes() == reference.read_bytes()


def test_interrupted_sweep_resumes(reference, tmp_path):
    """A sweep cut off mid-row keeps its finished rows, computes only the others (on the curves they
    belong to), and ends with the same file as an uninterrupted one."""
    lines = reference.read_text().splitlines(keepends=True)
    path = tmp_path / "resumed.csv"
    path.write_text("".join(lines[:6]) + lines[6][:20])  # header, 5 rows, and half a row
    executor = CountingExecutor()
    with executor:
        computed, reused = run_sweep(path, ALPHAS, PRESSURES, FORCES, executor)
    assert (computed, reused) == (11, 5)
    assert executor.tasks == 3  # the curve finished (4 rows of the first curve) is not solved again
    assert path.read_bytes() == reference.read_bytes()
    with CountingExecutor() as again:  # all done: nothing to compute
        assert run_sweep(path, ALPHAS, PRESSURES, FORCES, again) == (0, 16)
        assert again.points == []


def test_partial_grid_then_full(tmp_path):
    """A smaller sweep first, then the full grid on the same file: only the new points are computed."""
    path = tmp_path / "grown.csv"
    with ProcessPoolExecutor(2) as executor:
        assert run_sweep(path, [0.2], [0.1], [0.2, 1.0], executor) == (2, 0)
    with CountingExecutor() as executor:
        assert run_sweep(path, [0.2], [0.1], [0.0, 0.2, 1.0], executor) == (1, 2)
    assert executor.points == [(0.2, 0.1, 0.0)]
    assert [row["force"] for row in csv.DictReader(path.open())] == ["0.0", "0.2", "1.0"]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--alpha", "-1.5", "--pressure", "0.3", "--force", "0.1"], "alpha = -1.5"),
        (["--alpha", "0.3", "--pressure", "0", "--force", "0.1"], "pressure = 0.0, but it must be > 0"),
        (["--alpha", "0.3", "--pressure", "0.3", "--force", "-1"], "force = -1.0, but a plate can only push"),
    ],
)
def test_bad_grid(argv, message, tmp_path, capsys):
    """Checked before any work: exit 2, one line, no file written."""
    path = tmp_path / "bad.csv"
    assert main(["sweep", *argv, "--out", str(path), "--workers", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert not path.exists()


def test_not_a_sweep_file(tmp_path, capsys):
    path = tmp_path / "other.csv"
    path.write_text("a,b\n1,2\n")
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--out", str(path)]) == 2
    assert "is not a sweep file" in capsys.readouterr().err
    assert path.read_text() == "a,b\n1,2\n"


def test_rows_record_the_grid_as_asked(tmp_path, monkeypatch):
    """Exact answer: a solver whose states echo each input one ulp off (0.1 -> 0.10000000000000002)
    still gives rows holding the numbers asked, written so that they read back equal; a rerun on
    the file finds every point and adds no row."""
    import dataclasses
    import math

    import pocket.apps.sweep.grid as sweep

    def compress(material, pressure_initial, force, **options):
        state = shooting.compress(material, pressure_initial, force, **options)
        return dataclasses.replace(state, material=mooney_rivlin(math.nextafter(material.alpha, 2.0)),
                                   force=math.nextafter(force, 2.0),
                                   pressure_initial=math.nextafter(pressure_initial, 2.0))

    monkeypatch.setattr(sweep, "entry", _entry_of(compress))
    path = tmp_path / "echo.csv"
    grid = ([0.3, 1.2], [0.05, 0.1], [0.05, 0.1])
    with CountingExecutor() as executor:
        assert run_sweep(path, *grid, executor) == (8, 0)
    rows = list(csv.DictReader(path.open()))
    assert [(float(r["alpha"]), float(r["pressure_initial"]), float(r["force"])) for r in rows] == [
        (a, p, f) for a in grid[0] for p in grid[1] for f in grid[2]]
    before = path.read_bytes()
    with CountingExecutor() as executor:
        assert run_sweep(path, *grid, executor) == (0, 8)
        assert executor.points == []
    assert path.read_bytes() == before


def test_readme_example_runs_and_reruns(tmp_path, capsys):
    """The README's sweep, on local processes: 2 x 4 x 5 = 40 rows holding exactly the grid asked;
    run again on the same file it computes nothing and leaves the same bytes."""
    argv = ["sweep", "--alpha", "0.3", "1.2", "--pressure", "0.05", "0.1", "0.2", "0.32",
            "--force", "0.05", "0.1", "0.2", "0.5", "1", "--out", str(tmp_path / "s.csv"), "--workers", "2"]
    assert main(argv) == 0
    assert "40 points computed, 0 reused" in capsys.readouterr().out
    text = (tmp_path / "s.csv").read_text()
    rows = list(csv.DictReader(text.splitlines()))
    assert {(r["alpha"], r["pressure_initial"]) for r in rows} == {
        (a, p) for a in ("0.3", "1.2") for p in ("0.05", "0.1", "0.2", "0.32")}
    assert len(rows) == 40
    assert {r["status"] for r in rows} == {"ok"}
    assert main(argv) == 0
    assert "0 points computed, 40 reused" in capsys.readouterr().out
    assert (tmp_path / "s.csv").read_text() == text


@pytest.mark.parametrize("content", [b"my notes\nthe last line, no newline at its end",
                                     b"my notes without any newline",
                                     ",".join(COLUMNS).encode() + b"\n0.3,0.1\n",  # a short row
                                     b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR"])
def test_a_file_that_is_not_a_sweep_is_left_untouched(tmp_path, capsys, content):
    """Checked before anything is written: exit 2, one line, the file's bytes unchanged."""
    path = tmp_path / "notes.csv"
    path.write_bytes(content)
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--out", str(path),
                 "--workers", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert "is not a sweep file" in err, err
    assert path.read_bytes() == content


def test_the_start_of_a_header_is_a_new_sweep(tmp_path):
    """A sweep killed while writing its header left a prefix of it: that file is a new sweep."""
    path = tmp_path / "cut.csv"
    path.write_text(",".join(COLUMNS)[:30])
    with CountingExecutor() as executor:
        assert run_sweep(path, [0.3], [0.1], [0.1], executor) == (1, 0)
    assert [r["force"] for r in csv.DictReader(path.open())] == ["0.1"]


def test_interrupted_sweep_keeps_complete_rows_and_resumes(reference, tmp_path):
    """An interrupt after the first curve (4 points): the file holds the header and exactly its 4
    complete rows of the reference; the rerun computes the other 12 and ends with the reference's bytes."""
    path = tmp_path / "stopped.csv"

    def progress(done, total):
        if done == len(FORCES):
            raise KeyboardInterrupt

    with CountingExecutor() as executor, pytest.raises(KeyboardInterrupt):
        run_sweep(path, ALPHAS, PRESSURES, FORCES, executor, progress=progress)
    lines = path.read_text().splitlines(keepends=True)
    assert len(lines) == 1 + len(FORCES)
    assert lines[0] == reference.read_text().splitlines(keepends=True)[0]
    assert set(lines[1:]) <= set(reference.read_text().splitlines(keepends=True))
    with CountingExecutor() as executor:
        assert run_sweep(path, ALPHAS, PRESSURES, FORCES, executor) == (16 - len(FORCES), len(FORCES))
    assert path.read_bytes() == reference.read_bytes()


def test_a_new_sweep_stopped_before_any_point_leaves_nothing(tmp_path):
    """Nothing finished: neither the file nor the folders made for it remain."""

    class Refusing(CountingExecutor):
        def submit(self, fn, *args, **kwargs):
            raise KeyboardInterrupt

    with Refusing() as executor, pytest.raises(KeyboardInterrupt):
        run_sweep(tmp_path / "new" / "deeper" / "s.csv", [0.3], [0.1], [0.1], executor)
    assert list(tmp_path.iterdir()) == []


class _FullDisk:
    """A file whose writes stop at ``room`` bytes: the write that reaches it is short, the next
    fails with ENOSPC (what write(2) does on a full disk)."""

    def __init__(self, file, room):
        self._file, self._room = file, room

    def write(self, data):
        import errno

        if not self._room:
            raise OSError(errno.ENOSPC, "No space left on device")
        written = self._file.write(data[: self._room])
        self._room -= written
        return written

    def __getattr__(self, name):
        return getattr(self._file, name)


def test_full_disk_while_appending_keeps_complete_rows(reference, tmp_path, monkeypatch, capsys):
    """ENOSPC in the middle of a row (the disk fills after the bytes of the header and 3.5 rows): exit
    1, one line naming the file, the file cut back to the header and the complete rows that fitted;
    freed, the rerun resumes and ends with the reference's bytes."""
    import io

    lines = reference.read_bytes().splitlines(keepends=True)
    room = sum(map(len, lines[:4])) + len(lines[4]) // 2
    real = io.FileIO
    monkeypatch.setattr(io, "FileIO", lambda *args: _FullDisk(real(*args), room))
    path = tmp_path / "full.csv"
    assert main(["sweep", *ARGV, "--out", str(path), "--workers", "2"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert f"cannot write {path}: No space left on device" in err, err
    kept = path.read_bytes().splitlines(keepends=True)  # rows finish in any order, of different lengths
    assert len(kept) >= 2
    assert kept[0] == lines[0]
    assert set(kept[1:]) <= set(lines[1:])
    assert path.stat().st_size <= room
    monkeypatch.undo()
    assert main(["sweep", *ARGV, "--out", str(path), "--workers", "2"]) == 0
    assert path.read_bytes() == reference.read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["full.csv"]


def test_full_disk_at_the_final_rewrite_keeps_the_journal(reference, tmp_path, monkeypatch, capsys):
    """ENOSPC while the finished file is rewritten in grid order: exit 1, no hidden sibling left, and
    the file still holds all 16 points (in the order they finished), so a rerun only reorders it."""
    import errno
    import pathlib

    def full(self, *args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(pathlib.Path, "write_text", full)
    path = tmp_path / "last.csv"
    assert main(["sweep", *ARGV, "--out", str(path), "--workers", "2"]) == 1
    assert "No space left on device" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["last.csv"]
    assert sorted(path.read_bytes().splitlines()) == sorted(reference.read_bytes().splitlines())
    monkeypatch.undo()
    with CountingExecutor() as executor:
        assert run_sweep(path, ALPHAS, PRESSURES, FORCES, executor) == (0, 16)
    assert path.read_bytes() == reference.read_bytes()


@pytest.mark.slow
def test_file_size_limit_in_a_real_process(reference, tmp_path):
    """A real write failure (RLIMIT_FSIZE: writes past it fail with EFBIG, as on a full disk) in the
    installed command: exit 1, one line, no traceback, complete rows only, within the limit; the
    rerun without the limit resumes and ends with the reference's bytes."""
    import resource
    import subprocess
    import sys

    lines = reference.read_bytes().splitlines(keepends=True)
    limit = sum(map(len, lines[:7])) + 10

    def small_files():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    path = tmp_path / "limited.csv"
    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "sweep", *ARGV, "--out", str(path), "--workers", "2"],
                          capture_output=True, text=True, preexec_fn=small_files)
    assert proc.returncode == 1, proc.stderr
    assert proc.stderr.count("\n") == 1, proc.stderr
    assert "File too large" in proc.stderr, proc.stderr
    kept = path.read_bytes().splitlines(keepends=True)  # rows finish in any order, of different lengths
    assert len(kept) >= 2
    assert kept[0] == lines[0]
    assert set(kept[1:]) <= set(lines[1:])
    assert path.stat().st_size <= limit
    assert sorted(p.name for p in tmp_path.iterdir()) == ["limited.csv"]
    assert main(["sweep", *ARGV, "--out", str(path), "--workers", "2"]) == 0
    assert path.read_bytes() == reference.read_bytes()


def test_one_writer_at_a_time(tmp_path, capsys):
    """While another process holds the file's lock (as a running sweep does), a sweep on it is
    refused: exit 2, one line, the file unchanged."""
    import subprocess
    import sys

    pytest.importorskip("fcntl")
    path = tmp_path / "busy.csv"
    path.write_text(",".join(COLUMNS) + "\n")
    holder = subprocess.Popen([sys.executable, "-c", "import fcntl, sys; f = open(sys.argv[1], 'r+b'); "
                               "fcntl.lockf(f.fileno(), fcntl.LOCK_EX); print('locked', flush=True); sys.stdin.read()",
                               str(path)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline() == "locked\n"
        assert main(["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--out", str(path)]) == 2
    finally:
        holder.communicate("")
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert "another pocket sweep is writing this file" in err, err
    assert path.read_text() == ",".join(COLUMNS) + "\n"


@pytest.mark.slow
@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--workers", "0"], "workers = 0, but it must lie in [1, "),
        (["--workers", "100000"], "workers = 100000, but it must lie in [1, "),
        (["--rtol", "2"], "--rtol = 2.0, but it must lie in [1e-14, 0.0001]"),
        (["--solver", "fem", "--rtol", "1e-8"], "--rtol does not apply to solver fem"),
        (["--force", *map(str, range(200_000))], "the grid has 200000 points, but a sweep takes at most 100000"),
    ],
)
def test_bad_sweep_options(tmp_path, capsys, extra, message):
    """Checked before any work: exit 2, one line, no file."""
    path = tmp_path / "s.csv"
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--out", str(path), *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert not path.exists()


def test_warnings_go_to_the_message_column(tmp_path, monkeypatch):
    """An ok point's message is its state's warnings, joined by '; ' on one line."""
    import dataclasses

    import pocket.apps.sweep.grid as sweep

    def compress(*args, **options):
        return dataclasses.replace(shooting.compress(*args, **options), warnings=("first\nnote", "second"))

    monkeypatch.setattr(sweep, "entry", _entry_of(compress))
    path = tmp_path / "w.csv"
    with CountingExecutor() as executor:
        run_sweep(path, [0.3], [0.3], [0.1], executor)
    (row,) = csv.DictReader(path.open())
    assert row["status"] == "ok"
    assert row["message"] == "first note; second"


def test_a_bad_scheduler_address_is_input(tmp_path, capsys):
    """A malformed dask address: exit 2, one line naming it, no file."""
    pytest.importorskip("dask.distributed")
    path = tmp_path / "s.csv"
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--out", str(path),
                 "--scheduler", "not an address"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert "--scheduler not an address: cannot connect" in err, err
    assert not path.exists()


@pytest.mark.slow
def test_another_solver_or_options_computes_its_own_points(tmp_path, capsys):
    """The solver and its options are part of a point: the same grid with another solver, or other
    options, computes its points and keeps the others' rows; each rerun reuses its own."""
    path = tmp_path / "mix.csv"
    argv = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "0.2", "--out", str(path),
            "--workers", "1"]
    runs = [[], ["--solver", "analytical"], ["--solver", "fem", "--order", "1", "--elements", "64"],
            ["--solver", "fem", "--order", "2", "--elements", "64"], ["--rtol", "1e-8"]]
    for number, extra in enumerate(runs, start=1):
        assert main([*argv, *extra]) == 0
        assert "2 points computed, 0 reused" in capsys.readouterr().out
        rows = list(csv.DictReader(path.open()))
        assert len(rows) == 2 * number
    assert sorted((r["solver"], r["solver_options"]) for r in rows[::2]) == [
        ("analytical", ""), ("fem", "elements=64 order=1"), ("fem", "elements=64 order=2"), ("shooting", ""),
        ("shooting", "rtol=1e-08")]
    approximate = [r for r in rows if r["solver"] == "analytical"]
    assert [float(r["height"]) for r in approximate] == [
        s.height for s in analytical.compression_curve(0.3, 0.1, [0.1, 0.2])]
    for extra in runs:
        assert main([*argv, *extra]) == 0
        assert "0 points computed, 2 reused" in capsys.readouterr().out


OLD_RUBBER_FLUID = ("material", *PARAMETERS, "fluid", "ambient", "gamma")  # the parameters' names before _per_mu0


@pytest.mark.parametrize(("columns", "lacks"), [
    ((*CompressedState.KEYS, "solver", "solver_options", "status", "message", *OLD_RUBBER_FLUID, "indenter",
      *CHECKS), "the contact patch's deformed radius and contact pressures"),
    ((*CompressedState.KEYS, "solver", "solver_options", "status", "message", *OLD_RUBBER_FLUID, *CHECKS),
     "the indenter (they were all pressed by the flat plate)"),
    ((*CompressedState.KEYS, "solver", "status", "message", *OLD_RUBBER_FLUID, *CHECKS),
     "the solver's options and the indenter"),
    ((*CompressedState.KEYS, "solver", "status", "message"), "the solver's options, the rubber and the fluid")])
def test_a_sweep_file_of_an_earlier_pocket_is_refused_saying_what_it_holds(tmp_path, capsys, columns, lacks):
    """A file whose rows do not say all of what a point is: exit 2, one line saying so and how many points
    of which solver it holds, the file untouched."""
    path = tmp_path / "old.csv"
    row = dict.fromkeys(columns, "")
    lines = [",".join(columns)] + [",".join({**row, "alpha": "0.3", "pressure_initial": "0.1", "force": str(f),
                                               "solver": "shooting", "status": "ok"}.values()) for f in (0.1, 0.2)]
    text = "\n".join(lines) + "\n"
    path.write_text(text)
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--out", str(path),
                 "--solver", "analytical"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert f"{path} is a sweep file of an earlier pocket (2 points: 2 of solver shooting), whose rows do not " \
           f"record {lacks}" in err, err
    assert path.read_text() == text


def test_indenters_share_a_file(tmp_path, capsys):
    """The indenter is part of a point: the plate's sweep, then the same grid under a sphere K = 0.4, keep both
    in one file, each row saying what pressed it; the sphere's rows are the solver's sphere curve exactly, not
    the plate's; each rerun reuses its own points."""
    from pocket.core.indenters import Sphere

    path = tmp_path / "fingers.csv"
    argv = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "0.2", "--out", str(path),
            "--workers", "1"]
    runs = [[], ["--indenter", "sphere", "--indenter-radius", "0.4"]]
    for extra in runs:
        assert main([*argv, *extra]) == 0
        assert "2 points computed, 0 reused" in capsys.readouterr().out
    rows = list(csv.DictReader(path.open()))  # the last sweep's grid first, then the other points
    assert [r["indenter"] for r in rows] == ["sphere K=0.4", "sphere K=0.4", "plate", "plate"]
    assert [float(r["height"]) for r in rows[:2]] == [
        s.height for s in shooting.compression_curve(0.3, 0.1, [0.1, 0.2], indenter=Sphere(0.4))]
    assert [float(r["height"]) for r in rows[2:]] == [
        s.height for s in shooting.compression_curve(0.3, 0.1, [0.1, 0.2])]
    assert rows[2]["height"] != rows[0]["height"]
    for extra in runs:
        assert main([*argv, *extra]) == 0
        assert "0 points computed, 2 reused" in capsys.readouterr().out


@pytest.mark.parametrize(("extra", "message"), [
    (["--indenter", "sphere"], "--indenter sphere needs --indenter-radius"),
    (["--indenter", "sphere", "--indenter-radius", "-1"], "--indenter-radius = -1, but a sphere's radius must be > 0"),
    (["--indenter", "profile", "--indenter-file", "{tip}"], "tip.csv: not convex at row 3")])
def test_bad_sweep_indenter(tmp_path, capsys, extra, message):
    """A missing or bad radius, or an indenter a row cannot name: exit 2, one line, no file written."""
    tip = tmp_path / "tip.csv"
    tip.write_text("radius [R],height [R]\n0,0\n0.1,0.005\n0.2,0.02\n0.3,0.03\n")
    path = tmp_path / "s.csv"
    extra = [e.format(tip=tip) for e in extra]
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1", "--out", str(path),
                 "--workers", "1", *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert not path.exists()


def test_a_profile_table_is_recorded_by_its_content(tmp_path, capsys):
    """A profile table presses in a sweep; its rows name it by the SHA-256 of its numbers (units R), so the same
    table copied to another folder reuses every point, a different table is another indenter, and the rows are
    the solver's own curve under that profile exactly. A profile given as functions has no content to record:
    one line, before any solving."""
    from pocket.core import profiles
    from pocket.core.indenters import Profile

    tip = "radius [R],height [R]\n0,0\n0.1,0.005\n0.2,0.02\n0.3,0.045\n0.4,0.08\n"
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    (tmp_path / "a" / "tip.csv").write_text(tip)
    (tmp_path / "b" / "tip.csv").write_text(tip)
    (tmp_path / "b" / "blunt.csv").write_text(tip.replace("0.08", "0.081"))
    path = tmp_path / "tips.csv"
    argv = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.05", "0.1", "--out", str(path),
            "--workers", "1", "--indenter", "profile", "--indenter-file"]
    for where, message in (("a/tip.csv", "2 points computed, 0 reused"), ("b/tip.csv", "0 points computed, 2 reused"),
                           ("b/blunt.csv", "2 points computed, 0 reused")):
        assert main([*argv, str(tmp_path / where)]) == 0
        assert message in capsys.readouterr().out
    rows = list(csv.DictReader(path.open()))
    shape = profiles.read_csv(tmp_path / "a" / "tip.csv")
    assert {r["indenter"] for r in rows[2:]} == {f"profile sha256={shape.digest}"}
    assert [float(r["height"]) for r in rows[2:]] == [
        s.height for s in shooting.compression_curve(0.3, 0.1, [0.05, 0.1], indenter=Profile(shape))]
    assert rows[0]["indenter"] != rows[2]["indenter"]
    functions = profiles.functions(lambda r: r * r, lambda r: 2 * r, lambda r: 2 + 0 * r, 0.5)
    with pytest.raises(InputError, match="not a profile given as functions"), ThreadPoolExecutor(1) as executor:
        run_sweep(tmp_path / "f.csv", [0.3], [0.1], [0.1], executor, indenter=Profile(functions))
    assert not (tmp_path / "f.csv").exists()


def test_two_alphas_with_one_c1_c2_are_two_rows(tmp_path):
    """Exact answer: a sweep over two neighbouring alphas whose C1, C2 round alike (found by searching up from
    alpha = 1.5) solves both, each row holding its own alpha."""
    import math

    alpha = 1.5
    while mooney_rivlin(alpha).params != mooney_rivlin(math.nextafter(alpha, 2.0)).params:
        alpha = math.nextafter(alpha, 2.0)
    alphas = [alpha, math.nextafter(alpha, 2.0)]
    path = tmp_path / "ulp.csv"
    with CountingExecutor() as executor:
        assert run_sweep(path, alphas, [0.1], [0.2], executor, solver="analytical") == (2, 0)
    assert [float(r["alpha"]) for r in csv.DictReader(path.open())] == alphas
