"""A dask.distributed cluster as a sweep's executor, which says when the cluster cannot run the sweep
(``pocket sweep --scheduler``).

A dask cluster's executor waits for ever when no worker is left, and reports a lost
scheduler as a cancelled task (after tracebacks in dask's log). ``connect`` checks the
cluster before any task is sent: a worker must join within ``patience`` seconds, and every
worker must run this version of pocket (a worker imports pocket to answer). ``ClusterExecutor``
then watches the cluster while the sweep runs, and fails the tasks not finished with a
one-line ``ClusterError`` when the connection to the scheduler is lost, when no worker has
been connected for ``patience`` seconds, or when a worker cannot import pocket. dask's own
log is silenced while the sweep runs: its errors are these lines.
"""

from __future__ import annotations

import contextlib
import logging
import threading
import time
from concurrent.futures import Executor, Future

from pocket.core.errors import ClusterError, InputError

from ..provenance import version

__all__ = ["PATIENCE", "ClusterExecutor", "connect"]

#: how long (s) a sweep waits, by default, for a worker to join a cluster that has none
PATIENCE = 60.0
#: how often (s) the cluster is looked at while the sweep runs
_POLL = 0.5

_RESUME = "the file keeps the points finished, and the same command resumes the sweep"


def connect(address: str, patience: float = PATIENCE) -> ClusterExecutor:
    """The executor of the dask scheduler at ``address``, once a worker of this pocket's version has
    joined (within ``patience`` seconds). An address that cannot be reached is an ``InputError``;
    no worker, or a worker without this pocket, a ``ClusterError``."""
    try:
        from dask.distributed import Client
    except ImportError:
        raise InputError("--scheduler needs dask.distributed: pip install 'pocket-mechanics[sweep]'") from None
    try:
        client = Client(address, timeout="10s")
    except (OSError, ValueError, TypeError) as err:
        raise InputError(f"--scheduler {address}: cannot connect ({' '.join(str(err).split())})") from None
    try:
        try:
            client.wait_for_workers(1, timeout=patience)
        except TimeoutError:
            raise ClusterError(f"no dask worker joined the scheduler at {address} within {patience:g} s: start "
                               f"workers (dask worker {address}), with this pocket installed") from None
        for worker, answer in client.run(version, on_error="return").items():
            if isinstance(answer, BaseException):
                raise ClusterError(f"dask worker {worker} cannot run pocket ({_line(answer)}): the workers need "
                                   f"this pocket ({version()}) installed")
            if answer != version():
                raise ClusterError(f"dask worker {worker} runs pocket {answer}, but this command pocket {version()}: "
                                   "the workers need the same pocket installed")
    except BaseException:
        client.close()
        raise
    return ClusterExecutor(client, address, patience)


def _line(err: BaseException) -> str:
    """``err`` on one line with its type (dask hands a worker's error that could not travel back as an
    ``Exception`` holding its repr, which already says it)."""
    text = " ".join(str(err).split())
    return text if type(err) is Exception else f"{type(err).__name__}: {text}"


class ClusterExecutor(Executor):
    """The executor of a connected dask ``client`` (scheduler ``address``) whose futures fail with a
    ``ClusterError`` when the cluster cannot run them (module docstring); ``shutdown`` closes the client."""

    def __init__(self, client, address: str, patience: float = PATIENCE):
        self.client, self.address, self.patience = client, address, patience
        self._executor = client.get_executor()
        self._pending: set[Future] = set()
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._quiet = contextlib.ExitStack()
        self._quiet.enter_context(_dask_log_silenced())
        self._watcher = threading.Thread(target=self._watch, name="pocket-cluster-watch", daemon=True)
        self._watcher.start()

    def submit(self, fn, /, *args, **kwargs) -> Future:
        outer: Future = Future()
        with self._lock:
            self._pending.add(outer)
        self._executor.submit(fn, *args, **kwargs).add_done_callback(lambda inner: self._settle(outer, inner))
        return outer

    def _settle(self, outer: Future, inner: Future) -> None:
        """Hand ``inner``'s outcome to ``outer``, in the words of this module."""
        error = None if inner.cancelled() else inner.exception()
        if inner.cancelled():
            self._fail(outer, self._lost() if self.client.status != "running" else
                       ClusterError(f"the dask scheduler at {self.address} cancelled a task; {_RESUME}"))
        elif isinstance(error, ImportError):
            self._fail(outer, ClusterError(f"a dask worker cannot run pocket ({_line(error)}): the "
                                           f"workers need this pocket ({version()}) installed; {_RESUME}"))
        elif error is not None:
            self._fail(outer, error)
        else:
            with self._lock:
                if outer not in self._pending:
                    return
                self._pending.discard(outer)
            outer.set_result(inner.result())

    def _fail(self, outer: Future, err: BaseException) -> None:
        with self._lock:
            if outer not in self._pending:
                return
            self._pending.discard(outer)
        outer.set_exception(err)

    def _fail_all(self, err: ClusterError) -> None:
        with self._lock:
            pending, self._pending = self._pending, set()
        for future in pending:
            future.set_exception(err)

    def _lost(self) -> ClusterError:
        return ClusterError(f"lost the connection to the dask scheduler at {self.address}; {_RESUME}")

    def _watch(self) -> None:
        """Fail the pending tasks when the scheduler is lost or no worker has been there for ``patience``."""
        alone_since = None
        while not self._stop.wait(_POLL):
            try:
                if self.client.status != "running":
                    raise OSError
                workers = self.client.scheduler_info()["workers"]
            except Exception:
                self._fail_all(self._lost())
                continue
            if workers:
                alone_since = None
            elif alone_since is None:
                alone_since = time.monotonic()
            elif time.monotonic() - alone_since >= self.patience:
                self._fail_all(ClusterError(f"no dask worker has been connected to the scheduler at {self.address} "
                                            f"for {self.patience:g} s; start workers (with this pocket installed): "
                                            f"{_RESUME}"))

    def shutdown(self, wait: bool = True, *, cancel_futures: bool = False) -> None:
        """Stop watching, wait for the tasks if ``wait`` (and the cluster is there), and close the client;
        the client's closing ends the tasks left."""
        self._stop.set()
        try:
            self._executor.shutdown(wait=wait and self.client.status == "running")
        except Exception:  # a cluster already lost has nothing left to shut down
            pass
        finally:
            self.client.close()
            self._quiet.close()


@contextlib.contextmanager
def _dask_log_silenced():
    """dask's log handlers (set on the ``distributed`` logger) quiet: its errors here become one line."""
    handlers = logging.getLogger("distributed").handlers
    levels = [handler.level for handler in handlers]
    for handler in handlers:
        handler.setLevel(logging.CRITICAL + 1)
    try:
        yield
    finally:
        for handler, level in zip(handlers, levels, strict=True):
            handler.setLevel(level)
