"""Local sweep workers die with the sweep: real process trees, killed the way users kill them.

The local sweeps here run two curves on two workers, each of which waits inside its task for the test
(``holds.SWEEP_CURVE``; a forked worker inherits the patch): the workers are busy when their parent
goes, however fast the machine or the solver is, and would never end by themselves.
"""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest
from holds import SWEEP_CURVE, Hold

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads the process tree in /proc")

#: two curves (one task each) on two workers
HELD_SWEEP = ["sweep", "--alpha", "0.3", "--pressure", "0.3", "0.31", "--force", "0.1", "0.2", "--workers", "2"]


def _children(pid: int) -> set[int]:
    """The live (not zombie) processes whose parent is ``pid``."""
    out = set()
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as stat:
                    fields = stat.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid and fields[0] != "Z":
                out.add(int(entry))
    return out


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def _kill(pids) -> None:
    for pid in pids:
        if _alive(pid):
            os.kill(pid, signal.SIGKILL)


def _wait(condition, timeout: float) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.05)
    return condition()


@pytest.mark.slow
def test_kill_9_of_a_sweep_ends_its_workers(tmp_path):
    """Exact answer: after SIGKILL to `pocket sweep` (its output piped, as into `| tee`), its two
    busy workers (each inside its task, never released) are gone and the pipe reaches end-of-file
    (nobody holds it). The waits are bounds for a broken test, not guesses of speed."""
    with Hold(tmp_path, SWEEP_CURVE) as hold:
        proc = hold.popen([*HELD_SWEEP, "--out", str(tmp_path / "s.csv")], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE)
        workers = set()
        try:
            assert hold.arrived(2), "the two workers did not start their tasks"
            workers = _children(proc.pid)
            assert len(workers) == 2
            os.kill(proc.pid, signal.SIGKILL)
            proc.wait()
            assert _wait(lambda: not any(map(_alive, workers)), 60), "workers outlived their parent"
            os.set_blocking(proc.stdout.fileno(), False)
            assert _wait(lambda: proc.stdout.read() == b"", 60)  # end-of-file, not None (no data yet)
        finally:
            _kill(workers | _children(proc.pid))


@pytest.mark.slow
def test_portable_watchdog_alone(tmp_path):
    """The fallback without prctl: workers started with only the parent watchdog still end when
    their parent is killed (here a script owning a pool whose workers sleep)."""
    script = tmp_path / "pool.py"
    script.write_text(textwrap.dedent("""
        import time
        from concurrent.futures import ProcessPoolExecutor
        from pocket.apps.sweep.workers import _watch_parent
        pool = ProcessPoolExecutor(2, initializer=_watch_parent)
        futures = [pool.submit(time.sleep, 600) for _ in range(2)]
        print("started", flush=True)
        time.sleep(600)
    """))
    proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE)
    workers = set()
    try:
        assert proc.stdout.readline() == b"started\n"
        assert _wait(lambda: len(_children(proc.pid)) == 2, 30)
        workers = _children(proc.pid)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        assert _wait(lambda: not any(map(_alive, workers)), 10), "workers outlived their parent"
    finally:
        _kill(workers | _children(proc.pid))


@pytest.mark.slow
def test_ctrl_c_ends_the_sweep_at_once_with_one_line(tmp_path):
    """Exact answer: SIGINT to the sweep's process group (what Ctrl-C does) while both workers are
    inside their tasks, which never end by themselves (so a sweep that waited for them would never
    end): status 130, stderr exactly one line, no worker left, and (no point finished) no file left."""
    path = tmp_path / "s.csv"
    with Hold(tmp_path, SWEEP_CURVE) as hold:
        proc = hold.popen([*HELD_SWEEP, "--out", str(path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          start_new_session=True)
        workers = set()
        try:
            assert hold.arrived(2), "the two workers did not start their tasks"
            workers = _children(proc.pid)
            os.killpg(proc.pid, signal.SIGINT)
            out, err = proc.communicate(timeout=600)
            assert proc.returncode == 130, err
            assert err == b"pocket: interrupted\n", err
            assert out == b"", err
            assert _wait(lambda: not any(map(_alive, workers)), 60)
            assert [p.name for p in tmp_path.iterdir()] == [hold.script.name]  # no output left
        finally:
            proc.kill()
            _kill(workers | _children(proc.pid))


# A dask cluster that cannot run the sweep: real scheduler and worker processes on 127.0.0.1, the
# sweep a `pocket sweep --scheduler` process. Its task waits for the test (a file the test writes)
# before solving, so that what the test does happens while the sweep runs, whatever the machine's speed.

DASK_SWEEP = [sys.executable, "-m", "pocket.cli", "sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.1",
              "0.2"]
#: a dask --preload module: every curve task says it started (a file), then waits for the test's release file
HOLD = """
import os, pathlib, time
import pocket.apps.sweep.grid as sweep

FOLDER = pathlib.Path({folder!r})
solve = sweep.solve_curve


def held(*args, **kwargs):
    (FOLDER / "started").touch()
    while not (FOLDER / "release").exists():
        time.sleep(0.05)
    return solve(*args, **kwargs)


sweep.solve_curve = held
"""


def _scheduler(folder):
    """A dask scheduler process on 127.0.0.1 and its address."""
    file = folder / "scheduler.json"
    proc = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                             "--port", "0", "--no-dashboard", "--scheduler-file", str(file)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    import json

    assert _wait(lambda: file.exists() and file.read_text().strip().endswith("}"), 60), "no scheduler"
    return proc, json.loads(file.read_text())["address"]


#: a dask worker on a machine without pocket: an import of pocket fails as it does where it is not installed
NO_POCKET = """
import runpy, sys


class NoPocket:
    def find_spec(self, name, path=None, target=None):
        if name == "pocket" or name.startswith("pocket."):
            raise ModuleNotFoundError("No module named 'pocket'", name="pocket")


sys.meta_path.insert(0, NoPocket())
sys.argv = ["dask-worker", *sys.argv[1:]]
runpy.run_module("distributed.cli.dask_worker", run_name="__main__", alter_sys=True)
"""


def _worker(address, folder, *, without_pocket=False):
    """A dask worker process (no nanny: killing it kills the worker) whose tasks wait for ``folder``'s
    release file; ``without_pocket``: started so that it cannot import pocket."""
    preload = folder / "hold.py"
    preload.write_text(HOLD.format(folder=str(folder)))
    argv = ["-m", "distributed.cli.dask_worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard"]
    if without_pocket:  # however pocket is installed (regular or editable), this worker cannot import it
        argv = ["-c", NO_POCKET, *argv[2:]]
    else:
        argv += ["--preload", str(preload)]
    return subprocess.Popen([sys.executable, *argv], cwd=folder, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)


@pytest.fixture
def cluster(tmp_path):
    """(scheduler process, its address, started processes to end after the test)."""
    pytest.importorskip("dask.distributed")
    scheduler, address = _scheduler(tmp_path)
    started = [scheduler]
    yield scheduler, address, started
    (tmp_path / "release").touch()
    for proc in started:
        proc.kill()
        proc.wait()


def _sweep(folder, address, *extra):
    return subprocess.Popen([*DASK_SWEEP, "--out", str(folder / "s.csv"), "--scheduler", address, *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


@pytest.mark.slow
def test_a_lost_scheduler_is_one_line(cluster, tmp_path):
    """The scheduler killed while the sweep's task runs: exit 1, stderr one line saying the connection
    was lost and that the same command resumes, no traceback, and (no point finished) no file."""
    scheduler, address, started = cluster
    started.append(_worker(address, tmp_path))
    sweep = _sweep(tmp_path, address)
    started.append(sweep)
    assert _wait(lambda: (tmp_path / "started").exists(), 120), "the task did not start"
    scheduler.kill()
    _out, err = sweep.communicate(timeout=120)
    assert sweep.returncode == 1, err
    assert err.count("\n") == 1, err
    assert f"lost the connection to the dask scheduler at {address}" in err, err
    assert "resumes the sweep" in err, err
    assert not (tmp_path / "s.csv").exists()


@pytest.mark.slow
def test_all_workers_gone_is_one_line(cluster, tmp_path):
    """The only worker killed while it runs the sweep's task: with --patience 1 the sweep stops (it
    used to wait for ever): exit 1, one line saying no worker is connected."""
    _, address, started = cluster
    worker = _worker(address, tmp_path)
    started.append(worker)
    sweep = _sweep(tmp_path, address, "--patience", "1")
    started.append(sweep)
    assert _wait(lambda: (tmp_path / "started").exists(), 120), "the task did not start"
    worker.kill()
    _out, err = sweep.communicate(timeout=120)
    assert sweep.returncode == 1, err
    assert err.count("\n") == 1, err
    assert f"no dask worker has been connected to the scheduler at {address} for 1 s" in err, err


@pytest.mark.slow
def test_no_worker_at_all_is_one_line(cluster, tmp_path):
    """A scheduler without workers: the sweep waits --patience seconds, then exit 1, one line, no file."""
    _, address, started = cluster
    sweep = _sweep(tmp_path, address, "--patience", "1")
    started.append(sweep)
    _out, err = sweep.communicate(timeout=120)
    assert sweep.returncode == 1, err
    assert err.count("\n") == 1, err
    assert f"no dask worker joined the scheduler at {address} within 1 s" in err, err
    assert not (tmp_path / "s.csv").exists()


@pytest.mark.slow
def test_a_worker_without_pocket_is_one_line(cluster, tmp_path):
    """A worker that cannot import pocket: refused before any task, exit 1, one line naming the worker
    and the missing module, no file."""
    _, address, started = cluster
    started.append(_worker(address, tmp_path, without_pocket=True))
    sweep = _sweep(tmp_path, address)
    started.append(sweep)
    _out, err = sweep.communicate(timeout=120)
    assert sweep.returncode == 1, err
    assert err.count("\n") == 1, err
    assert "cannot run pocket (ModuleNotFoundError" in err, err
    assert "No module named 'pocket'" in err, err
    assert not (tmp_path / "s.csv").exists()
