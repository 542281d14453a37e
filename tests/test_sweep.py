"""Sweeps: the same CSV on local processes and on a dask cluster; an interrupted sweep resumes."""

import csv
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pytest

from pocket import shooting
from pocket.apps.sweep import COLUMNS, run_sweep
from pocket.cli import main

ALPHAS, PRESSURES, FORCES = [0.2, 47 / 160], [0.1, 0.31], [0.0, 0.2, 1.0, 15.0]  # 15: out of range at 0.31
ARGV = ["--alpha", "0.2", "47/160", "--pressure", "0.1", "0.31", "--force", "0", "0.2", "1", "15"]


class CountingExecutor(ThreadPoolExecutor):
    """Counts the points submitted, to show which ones a resumed sweep recomputes."""

    def __init__(self):
        super().__init__(max_workers=2)
        self.points = []

    def submit(self, fn, *args, **kwargs):
        self.points.append(args[1:4])
        return super().submit(fn, *args, **kwargs)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The sweep on local processes (the command line's default executor)."""
    path = tmp_path_factory.mktemp("sweep") / "processes.csv"
    assert main(["sweep", *ARGV, "--out", str(path), "--workers", "2"]) == 0
    return path


def test_rows_are_the_solver(reference):
    """Exact: each row is the shooting solver's state at its point, written exactly (repr floats)."""
    rows = list(csv.DictReader(reference.open()))
    assert tuple(rows[0]) == COLUMNS and len(rows) == 16
    for row in rows:
        point = (float(row["alpha"]), float(row["pressure_initial"]), float(row["force"]))
        if row["status"] == "out_of_range":
            assert point[1:] == (0.31, 15.0) and "beyond the model's range" in row["message"]
            continue
        state = shooting.compress(*point)
        assert float(row["pressure_ratio"]) == state.pressure_ratio
        assert float(row["height"]) == state.height


def test_dask_cluster_same_csv(reference, tmp_path):
    """A local dask cluster of two worker processes, reached by --scheduler, writes the same bytes."""
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        path = tmp_path / "dask.csv"
        assert main(["sweep", *ARGV, "--out", str(path), "--scheduler", cluster.scheduler_address]) == 0
    assert path.read_bytes() == reference.read_bytes()


def test_interrupted_sweep_resumes(reference, tmp_path):
    """A sweep cut off mid-row keeps its finished rows, recomputes only the others, and ends with
    the same file as an uninterrupted one."""
    lines = reference.read_text().splitlines(keepends=True)
    path = tmp_path / "resumed.csv"
    path.write_text("".join(lines[:6]) + lines[6][:20])  # header, 5 rows, and half a row
    executor = CountingExecutor()
    with executor:
        computed, reused = run_sweep(path, ALPHAS, PRESSURES, FORCES, executor)
    assert (computed, reused) == (11, 5)
    finished = {tuple(float(x) for x in line.split(",")[:3]) for line in lines[1:6]}
    assert len(executor.points) == 11 and not finished & set(executor.points)
    assert path.read_bytes() == reference.read_bytes()
    with CountingExecutor() as again:  # all done: nothing to compute
        assert run_sweep(path, ALPHAS, PRESSURES, FORCES, again) == (0, 16) and again.points == []


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
    "argv, message",
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
    assert err.count("\n") == 1 and message in err, err
    assert not path.exists()


def test_not_a_sweep_file(tmp_path, capsys):
    path = tmp_path / "other.csv"
    path.write_text("a,b\n1,2\n")
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--out", str(path)]) == 2
    assert "is not a sweep file" in capsys.readouterr().err
    assert path.read_text() == "a,b\n1,2\n"
