"""Local sweep workers die with the sweep: real process trees, killed the way users kill them.

The sweeps here solve FE points of 20000 elements (about a minute each on this machine), so the
workers are busy in compiled code when their parent goes.
"""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads the process tree in /proc")

SLOW_SWEEP = [sys.executable, "-m", "pocket.cli", "sweep", "--alpha", "0.3", "--pressure", "0.3",
              "--force", "0.1", "0.2", "0.3", "0.4", "--solver", "fem", "--elements", "20000", "--workers", "2"]


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


def test_kill_9_of_a_sweep_ends_its_workers(tmp_path):
    """Exact answer: after SIGKILL to `pocket sweep` (its output piped, as into `| tee`), its two
    busy workers are gone within 10 s and the pipe reaches end-of-file (nobody holds it)."""
    proc = subprocess.Popen([*SLOW_SWEEP, "--out", str(tmp_path / "s.csv")], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    workers = set()
    try:
        assert _wait(lambda: len(_children(proc.pid)) == 2, 60), "the sweep did not start two workers"
        workers = _children(proc.pid)
        time.sleep(1.0)  # the workers are now solving
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        assert _wait(lambda: not any(map(_alive, workers)), 10), "workers outlived their parent"
        os.set_blocking(proc.stdout.fileno(), False)
        assert _wait(lambda: proc.stdout.read() == b"", 10)  # end-of-file, not None (no data yet)
    finally:
        _kill(workers | _children(proc.pid))


def test_portable_watchdog_alone(tmp_path):
    """The fallback without prctl: workers started with only the parent watchdog still end when
    their parent is killed (here a script owning a pool whose workers sleep)."""
    script = tmp_path / "pool.py"
    script.write_text(textwrap.dedent("""
        import time
        from concurrent.futures import ProcessPoolExecutor
        from pocket.apps.workers import _watch_parent
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


def test_ctrl_c_ends_the_sweep_at_once_with_one_line(tmp_path):
    """Exact answer: SIGINT to the sweep's process group (what Ctrl-C does) ends it within 10 s,
    though its points take a minute each: status 130, stderr exactly one line, no worker left,
    and (no point finished) no file left."""
    path = tmp_path / "s.csv"
    proc = subprocess.Popen([*SLOW_SWEEP, "--out", str(path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)
    workers = set()
    try:
        assert _wait(lambda: len(_children(proc.pid)) == 2, 60), "the sweep did not start two workers"
        workers = _children(proc.pid)
        time.sleep(1.0)
        start = time.monotonic()
        os.killpg(proc.pid, signal.SIGINT)
        out, err = proc.communicate(timeout=30)
        assert time.monotonic() - start < 10
        assert proc.returncode == 130 and err == b"pocket: interrupted\n" and out == b"", err
        assert _wait(lambda: not any(map(_alive, workers)), 10)
        assert list(tmp_path.iterdir()) == []
    finally:
        proc.kill()
        _kill(workers | _children(proc.pid))
