"""Local worker processes that never outlive the process that started them (``pocket sweep``).

A ``ProcessPoolExecutor``'s workers are ordinary child processes: if their
parent is killed (``kill -9``, an out-of-memory kill) they go on computing and
keep the terminal's pipes open, so that ``pocket sweep ... | tee log`` never
ends. ``local_executor`` starts each worker with ``_init``, which

- on Linux asks the kernel to send the worker SIGKILL when its parent dies
  (``prctl(PR_SET_PDEATHSIG)``, through ctypes: immediate, even while the worker
  is inside compiled code);
- everywhere, starts a watchdog thread that waits on the parent's sentinel
  (``multiprocessing.parent_process()``: a pipe that reaches end-of-file when the
  parent is gone, whatever the start method) and then ends the worker; a worker
  whose parent died before it started ends at once;
- ignores SIGINT: Ctrl-C reaches the whole foreground process group, and only
  the parent should answer it (once, with one line), not every worker with a
  traceback.

``stop`` ends the workers of an executor at once (an interrupted sweep does not
wait for the points under way).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import multiprocessing
import os
import signal
import sys
import threading
from concurrent.futures import Executor, ProcessPoolExecutor

from pocket.core.inputs import check_count

from ..provenance import cpus

__all__ = ["local_executor", "max_workers", "stop"]

_PR_SET_PDEATHSIG = 1  # linux/prctl.h


def max_workers() -> int:
    """Most local workers a sweep may start: 4 per usable CPU (more only cost memory).

    Returns
    -------
    int

    Examples
    --------
    >>> import os
    >>> from pocket.apps.sweep.workers import max_workers
    >>> print(max_workers() % 4, 4 <= max_workers() <= 4 * os.cpu_count())
    0 True
    """
    return 4 * cpus()


def _die_with_parent_linux() -> None:
    """Ask the kernel for SIGKILL when the parent dies (Linux only; elsewhere a no-op)."""
    if not sys.platform.startswith("linux"):
        return
    libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
    libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


def _watch_parent() -> None:
    """End this process when its multiprocessing parent ends (portable: waits on its sentinel)."""
    parent = multiprocessing.parent_process()
    if parent is None:
        return

    def watch():
        parent.join()
        os._exit(1)

    threading.Thread(target=watch, name="pocket-parent-watchdog", daemon=True).start()


def _init() -> None:
    """Initializer of every local worker (module docstring)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _die_with_parent_linux()
    _watch_parent()


def local_executor(workers: int | None = None) -> ProcessPoolExecutor:
    """A process pool whose workers die with this process: a sweep's local executor.

    Parameters
    ----------
    workers : int, optional
        The number of processes, 1 to ``max_workers()`` (default: one per usable CPU).

    Returns
    -------
    concurrent.futures.ProcessPoolExecutor

    Raises
    ------
    InputError
        For a number of workers out of range.

    Examples
    --------
    >>> from pocket.apps.sweep.workers import local_executor, stop
    >>> executor = local_executor(1)
    >>> print(executor.submit(pow, 2, 10).result())
    1024
    >>> stop(executor)
    """
    count = cpus() if workers is None else check_count("workers", workers, 1, max_workers())
    return ProcessPoolExecutor(max_workers=count, initializer=_init)


def stop(executor: Executor) -> None:
    """Shut an executor down without waiting for the tasks under way (cancel the others first).

    A ``ProcessPoolExecutor``'s workers are killed through its process table (``_processes``, there since
    Python 3.2): ``shutdown`` would wait for the tasks under way, and so would the interpreter's exit. Any
    other executor (a dask cluster's) is only shut down.

    Parameters
    ----------
    executor : concurrent.futures.Executor
        The executor.

    Examples
    --------
    >>> from concurrent.futures import ThreadPoolExecutor
    >>> from pocket.apps.sweep.workers import stop
    >>> executor = ThreadPoolExecutor(1)
    >>> stop(executor)
    >>> executor.submit(print, "late")
    Traceback (most recent call last):
        ...
    RuntimeError: cannot schedule new futures after shutdown
    """
    processes = list((getattr(executor, "_processes", None) or {}).values())
    executor.shutdown(wait=False)
    for process in processes:
        process.kill()
