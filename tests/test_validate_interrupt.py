"""Ctrl-C during ``pocket validate``: one line from the main process, status 130, no worker tracebacks.

The terminal sends SIGINT to the whole foreground process group, workers included. The
test makes the moment: in a child ``pocket validate``, every task the runner starts first
(the reference curves, the evidence) is replaced by one that marks that it started and
then waits for a file the test never creates before the interrupt; once every worker is
inside a task, the test sends SIGINT to the child's process group.
"""

import os
import signal
import subprocess
import sys
import time

import pytest
from pocket.validation.runner import WORKERS

pytestmark = pytest.mark.slow  # the slow lane (pytest -m slow)

CHILD = """
import os, pathlib, signal, sys, time
from pocket.validation import compute, evidence
from pocket.cli import main

folder = pathlib.Path(sys.argv[1])
# a test run started in the background passes SIGINT on ignored: the validation runs as a terminal's command would
signal.signal(signal.SIGINT, signal.default_int_handler)


def blocked(*args):
    (folder / f"started-{os.getpid()}").touch()
    while not (folder / "release").exists():
        time.sleep(0.01)
    raise AssertionError("released without an interrupt")


compute.reference = evidence.collect = blocked
sys.exit(main(["validate", "--quick", "--out", str(folder / "report")]))
"""
PATIENCE = 600.0  # seconds: only a bound on a hang (a condition is awaited, not a duration guessed)
EXIT = 120.0  # seconds: a bound on the exit after the interrupt (a few milliseconds of work; the tasks never end)


def _await(condition, what):
    end = time.monotonic() + PATIENCE
    while not condition():
        assert time.monotonic() < end, f"no {what} in {PATIENCE} s"
        time.sleep(0.01)


def _group_gone(group: int) -> bool:
    try:
        os.killpg(group, 0)
    except ProcessLookupError:
        return True
    return False


def test_ctrl_c_during_validate_is_one_line_130_and_no_worker_survives(tmp_path):
    """Exact answer: SIGINT to the process group while every worker is in a task: stderr is exactly
    `pocket: interrupted`, status 130, no report folder, and no process of the group is left."""
    proc = subprocess.Popen([sys.executable, "-c", CHILD, str(tmp_path)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        workers = min(WORKERS, 2)  # the runner starts at least two tasks (a reference curve and the evidence)
        _await(lambda: proc.poll() is not None or len(list(tmp_path.glob("started-*"))) >= workers,
               "worker inside a task")
        assert proc.poll() is None, proc.communicate()
        os.killpg(proc.pid, signal.SIGINT)
        out, err = proc.communicate(timeout=EXIT)
        assert (proc.returncode, out, err) == (130, "", "pocket: interrupted\n")
        assert not (tmp_path / "report").exists()
        _await(lambda: _group_gone(proc.pid), "end of every worker")
    finally:
        (tmp_path / "release").touch()
        if not _group_gone(proc.pid):  # what this test started, should the assertions above fail
            os.killpg(proc.pid, signal.SIGKILL)
