"""Work that waits for the test: a ``pocket`` command in a subprocess whose solve (or compiler) stops at a
chosen place, tells the test it is there, and stays there until the test releases it, so that a signal
lands where the test means it to, however fast the machine or the solver is.

``Hold(folder, patch)`` writes a driver script into ``folder``: it gives SIGINT Python's own handler (as a
terminal's foreground command has it, even where the test run ignores SIGINT), runs ``patch`` (Python
source that replaces an entry point by one calling ``arrived()`` and then ``wait()``, or a function made by
``compiled_wait()``), then the ``pocket`` command line. The test and the held process talk through two
pipes: ``arrived()`` writes a byte that ``Hold.arrived`` reads (an event, not a guess of time);
``wait()`` blocks in Python reading a byte that ``Hold.release`` writes (a SIGINT ends it at once); a
``compiled_wait()`` function blocks the same way inside numba-compiled code (a SIGINT is acted on once
the compiled code returns).
"""

import os
import select
import subprocess
import sys
import time

DRIVER = """
import os, signal, sys

ARRIVED, RELEASE = {arrived}, {release}

# A held command is the foreground command of a terminal, whose Ctrl-C the test sends: SIGINT at Python's own
# handler, also where the test run itself ignores it (started in the background: `pytest &`, nohup, a runner
# without a terminal), which its processes inherit and pocket, rightly, leaves alone (pocket.core.interrupts).
signal.signal(signal.SIGINT, signal.default_int_handler)


def arrived():
    os.write(ARRIVED, b"x")


def wait():
    os.read(RELEASE, 1)


def compiled_wait():
    # a function blocking inside numba-compiled code until released (compiled here, before any hold)
    import ctypes
    import numpy as np
    from numba import njit

    read = ctypes.CDLL(None).read
    read.argtypes, read.restype = [ctypes.c_int, ctypes.c_void_p, ctypes.c_size_t], ctypes.c_ssize_t

    @njit
    def until_released(fd, byte):
        while read(fd, byte.ctypes.data, 1) != 1:  # a signal interrupts read (EINTR): read again
            pass

    byte = np.zeros(1, np.uint8)
    until_released.compile("(int64, uint8[::1])")
    return lambda: until_released(RELEASE, byte)


{patch}

from pocket.cli.main import main

sys.exit(main(sys.argv[1:]))
"""

#: every FE point after a curve's first (``pocket.fem.curves._next_fitted``, a Newton solve per force) first
#: says it arrived, then waits inside compiled code for the release
FE_NEXT_POINT = """
import pocket.fem.curves as curves

_solve = curves._next_fitted
_wait = compiled_wait()


def _held(*args, **kwargs):
    arrived()
    _wait()
    return _solve(*args, **kwargs)


curves._next_fitted = _held
"""

#: the shooting solver's inflation (``pocket.shooting.api.inflate``, what ``pocket inflate`` solves) says it
#: arrived, then waits; released without an interrupt, it fails
SHOOTING_INFLATE = """
import pocket.shooting.api as api


def _held(*args, **kwargs):
    arrived()
    wait()
    raise AssertionError("released without an interrupt")


api.inflate = _held
"""

#: every curve of a sweep (``pocket.apps.sweep.grid.solve_curve``, run by the workers) says it arrived, then
#: waits; a forked worker inherits the patch and the pipes
SWEEP_CURVE = """
import pocket.apps.sweep.grid as sweep

_solve = sweep.solve_curve


def _held(*args, **kwargs):
    arrived()
    wait()
    return _solve(*args, **kwargs)


sweep.solve_curve = _held
"""

#: the first object code numba emits waits inside llvmlite's object-cache callback, whose exceptions
#: llvmlite ignores (a KeyboardInterrupt raised there is printed and dropped), for the test's SIGINT
IN_COMPILER = """
from numba.core import codegen

_hook = codegen.CPUCodeLibrary._object_compiled_hook.__func__
_seen = []


def _held(cls, ll_module, buf):
    _hook(cls, ll_module, buf)
    if not _seen:
        _seen.append(ll_module)
        arrived()
        wait()


codegen.CPUCodeLibrary._object_compiled_hook = classmethod(_held)
"""


class Hold:
    """A held ``pocket`` command (module docstring); use as a context manager (closes the pipes)."""

    def __init__(self, folder, patch: str):
        self._arrived, arrived = os.pipe()
        release, self._release = os.pipe()
        self._child = (arrived, release)
        self.script = folder / "held_pocket.py"
        self.script.write_text(DRIVER.format(arrived=arrived, release=release, patch=patch))

    def popen(self, argv, **options) -> subprocess.Popen:
        """Start ``pocket argv`` held (``options`` as ``subprocess.Popen``'s)."""
        proc = subprocess.Popen([sys.executable, str(self.script), *argv], pass_fds=self._child, **options)
        for fd in self._child:  # the child holds them now: end-of-file once it (and its workers) end
            os.close(fd)
        self._child = ()
        return proc

    def arrived(self, count: int = 1, timeout: float = 600.0) -> bool:
        """Whether ``count`` held places were reached; False if the process ended first (or after
        ``timeout`` seconds: a bound for a broken test, never reached by a working one)."""
        end = time.monotonic() + timeout
        while count > 0:
            ready, _, _ = select.select([self._arrived], [], [], max(0.0, end - time.monotonic()))
            if not ready:
                return False
            got = os.read(self._arrived, count)
            if not got:
                return False
            count -= len(got)
        return True

    def release(self, count: int = 1) -> None:
        """Let ``count`` held places go on."""
        os.write(self._release, b"x" * count)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        for fd in (self._arrived, self._release, *self._child):
            os.close(fd)
