"""Parameter sweeps over (alpha, Phat_I, Fhat) on any ``concurrent.futures.Executor`` (``pocket sweep``).

Each grid point is one compressed state, solved in a task of its own by
``solve_point`` (a top-level function, so that it pickles to other processes
and machines). ``run_sweep`` takes the executor as an argument: local
processes (``pocket.apps.workers.local_executor``, the command line's default)
or a dask.distributed cluster (``Client(address).get_executor()``, with
``--scheduler ADDRESS``) run the same code.

The results are one tidy CSV, one row per point: the keys of a compressed
state (``CompressedState.KEYS``), the solver, a ``status`` (``ok``;
``out_of_range`` past the model's range; ``failed`` when the solver did not
converge) and a one-line ``message`` (the reason, or the state's warnings).
A row's ``alpha``, ``pressure_initial`` and ``force`` are the grid point as
asked, never the values a solver hands back, and every float is written
exactly (``repr``), so a point reads back equal to the number asked: that is
the key on which a rerun recognises the points already done.

The file's life:

1. Before any point is solved, an existing file must be a sweep file (its
   first line the columns above, every complete row well formed), or the sweep
   stops with an ``InputError`` and leaves it untouched. An empty file, or one
   holding only the start of the header, counts as new. One sweep at a time
   may write a file (an advisory POSIX lock, where the system has ``fcntl``).
2. While the sweep runs, the file is its journal: each finished point is
   appended as one complete row and flushed.
3. Once every point is in, the file is rewritten in grid order (then any other
   points it held), through a sibling renamed onto it
   (``pocket.apps.folders.write_whole``), so that the result does not depend on
   the executor or on interruptions.

If the sweep stops early (an interrupt, a failure, or an ``OutputError`` when
the file cannot be written, e.g. a full disk), the file holds the header and
complete rows only: a row being written is cut off again. A sweep that created
the file and finished no point removes it. Only a sudden end of the process
(``kill -9``, a power cut) can leave a cut last line, which the next run on the
file ignores and writes over. Rerunning the same command resumes the sweep.
"""

from __future__ import annotations

import csv
import errno
import io
import itertools
import math
import os
import pathlib
import stat
from collections.abc import Callable
from concurrent.futures import as_completed

from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError, OutputError
from pocket.core.inputs import check_alpha, check_force, check_positive
from pocket.core.states import CompressedState

from .folders import created_parents, remove_created, write_whole
from .solvers import get_solver, record

try:
    import fcntl
except ImportError:  # not a POSIX system: no lock
    fcntl = None

__all__ = ["COLUMNS", "STATUSES", "MAX_POINTS", "solve_point", "run_sweep"]

COLUMNS = (*CompressedState.KEYS, "solver", "status", "message")
STATUSES = ("ok", "out_of_range", "failed")
#: most points of one sweep (a bound on the work and on the memory of its bookkeeping)
MAX_POINTS = 100_000
_PARAMETERS = ("alpha", "pressure_initial", "force")


def _line(text) -> str:
    """``text`` on one line (a CSV cell that never spans lines)."""
    return " ".join(str(text).split())


def solve_point(solver: str, alpha: float, pressure_initial: float, force: float, options: dict) -> dict:
    """One grid point as a CSV row (dict of COLUMNS); model failures become a status, not an error."""
    row = dict.fromkeys(COLUMNS, "")
    try:
        state = get_solver(solver).compress(alpha, pressure_initial, force, **options)
    except OutOfRangeError as err:
        row.update(status="out_of_range", message=_line(err))
    except ConvergenceError as err:
        row.update(status="failed", message=_line(err))
    else:
        row.update({key: float(getattr(state, key)) for key in CompressedState.KEYS})
        row.update(status="ok", message=_line("; ".join(state.warnings)))
    row.update(alpha=alpha, pressure_initial=pressure_initial, force=force, solver=solver)  # the point as asked
    return row


def _key(row) -> tuple[float, float, float]:
    return tuple(float(row[k]) for k in _PARAMETERS)


def _csv(rows, *, header=False) -> bytes:
    text = io.StringIO(newline="")
    writer = csv.DictWriter(text, COLUMNS, lineterminator="\n")
    if header:
        writer.writeheader()
    writer.writerows(rows)
    return text.getvalue().encode("utf-8")


_HEADER = _csv([], header=True)


def _not_a_sweep(path, why) -> InputError:
    return InputError(f"{path} exists but is not a sweep file ({why}); give another --out file")


def _parse(data: bytes, path) -> tuple[dict, int]:
    """The complete rows of the sweep file ``data`` by point, and their length in bytes.

    An empty file, or the start of the header alone, has no rows; a cut last line is left out.
    """
    if _HEADER.startswith(data):
        return {}, 0
    end = data.rfind(b"\n") + 1
    try:
        text = data[:end].decode("utf-8")
    except UnicodeDecodeError:
        raise _not_a_sweep(path, "it is not UTF-8 text") from None
    lines = csv.reader(io.StringIO(text, newline=""))
    next(lines)  # the header, checked by _Journal
    rows = {}
    for number, values in enumerate(lines, start=2):
        row = dict(zip(COLUMNS, values, strict=False))
        try:
            if len(values) != len(COLUMNS) or row["status"] not in STATUSES:
                raise ValueError
            key = _key(row)
        except ValueError:
            raise _not_a_sweep(path, f"line {number} is not a row of one") from None
        rows[key] = row
    return rows, end


class _Journal:
    """The sweep file, locked and opened for appending rows (module docstring, 1 and 2).

    Unbuffered (``io.FileIO``): what a failed write leaves is on the disk, where
    ``close`` cuts it off, never in a buffer that a later flush would retry.
    """

    def __init__(self, path: pathlib.Path):
        self.path, self.made, self.end, self.locked = path, created_parents(path), None, False
        try:
            for folder in self.made:
                folder.mkdir(exist_ok=True)
            try:
                fd, self.created = os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666), True
            except FileExistsError:
                fd, self.created = os.open(path, os.O_RDWR), False
        except OSError as err:
            remove_created(self.made)
            raise OutputError(f"cannot write {path}: {err.strerror or err}") from None
        self.file = io.FileIO(fd, "r+")
        try:
            if not stat.S_ISREG(os.fstat(fd).st_mode):
                raise InputError(f"{path} is not a regular file, so not a sweep file; give another --out file")
            self._lock()
            self.rows, self.end = _parse(self._read(), path)
        except BaseException:
            self.close(failed=True)
            raise
        self.count = len(self.rows)

    def _read(self) -> bytes:
        """The file's bytes, once its start is known to be (a prefix of) the header."""
        start = self.file.read(len(_HEADER))
        if not (_HEADER.startswith(start) if len(start) < len(_HEADER) else start == _HEADER):
            first = start.split(b"\n", 1)[0][:80].decode("utf-8", errors="replace")
            raise _not_a_sweep(self.path, f"its first line starts {_line(first)!r}")
        return start + self.file.readall()

    def _lock(self) -> None:
        if fcntl is not None:
            try:  # a POSIX record lock: held by this process only, not by the workers it forks
                fcntl.lockf(self.file.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError as err:
                if err.errno not in (errno.EACCES, errno.EAGAIN):
                    raise OutputError(f"cannot lock {self.path}: {err.strerror or err}") from None
                raise InputError(f"{self.path}: another pocket sweep is writing this file; wait for it to "
                                 "finish or give another --out file") from None
            if os.fstat(self.file.fileno()).st_ino != os.stat(self.path).st_ino:
                raise InputError(f"{self.path}: another pocket sweep has just rewritten this file; run again")
        self.locked = True

    def _write(self, data: bytes) -> None:
        try:
            self.file.truncate(self.end)  # a line cut by an earlier run
            self.file.seek(self.end)
            view = memoryview(data)
            while view:
                view = view[self.file.write(view):]
        except OSError as err:
            raise OutputError(f"cannot write {self.path}: {err.strerror or err}; it keeps the {self.count} points "
                              "finished before, and the same command resumes the sweep") from None
        self.end += len(data)

    def append(self, row: dict) -> None:
        """Add one finished point (the header first if the file is new)."""
        self._write((_HEADER if self.end == 0 else b"") + _csv([row]))
        self.rows[_key(row)] = row
        self.count += 1

    def close(self, *, failed: bool) -> None:
        """Close the file; after a failure cut it back to its complete rows, or remove it if this
        sweep created it and finished no point (only if the lock was ours: the file is then this sweep's)."""
        try:
            if failed and self.end is not None:
                self.file.truncate(self.end)
        except OSError:
            pass  # the rows written stay complete; a cut line is ignored by the next run
        finally:
            self.file.close()
        if failed and self.created and self.locked and not self.end:
            self.path.unlink(missing_ok=True)
            remove_created(self.made)


def _grid(alphas, pressures, forces) -> list[tuple[float, float, float]]:
    alphas = [check_alpha(a) for a in alphas]
    pressures = [check_positive("pressure", p) for p in pressures]
    forces = [check_force(f) for f in forces]
    if not (alphas and pressures and forces):
        raise InputError("a sweep needs at least one alpha, one pressure and one force")
    size = math.prod(map(len, (alphas, pressures, forces)))
    if size > MAX_POINTS:
        raise InputError(f"the grid has {size} points, but a sweep takes at most {MAX_POINTS}")
    return list(dict.fromkeys(itertools.product(alphas, pressures, forces)))


def run_sweep(path, alphas, pressures, forces, executor, *, solver="shooting", options=None,
              progress: Callable[[int, int], None] | None = None) -> tuple[int, int]:
    """Solve every (alpha, Phat_I, Fhat) of the grid not already in the CSV ``path``.

    Returns (computed, reused). ``options`` are the solver's (checked against its
    record); ``progress(done, total)`` is called after each point. The file's life,
    when the sweep finishes and when it stops early, is in the module docstring.
    A sweep that stops early leaves the points not yet solved in ``executor``: its
    owner ends them (``pocket.apps.workers.stop``; a ``ProcessPoolExecutor`` whose
    futures were cancelled cannot be stopped by killing its workers before Python
    3.12, its manager thread then fails on the cancelled futures).
    """
    grid = _grid(alphas, pressures, forces)
    options = record(solver).checked(dict(options or {}), "compress")
    journal = _Journal(pathlib.Path(path))
    failed = True
    try:
        todo = [point for point in grid if point not in journal.rows]
        futures = [executor.submit(solve_point, solver, *point, options) for point in todo]
        for done, future in enumerate(as_completed(futures), start=1):
            journal.append(future.result())
            if progress is not None:
                progress(done, len(todo))
        rows = journal.rows
        ordered = [rows[point] for point in grid] + [rows[k] for k in sorted(set(rows) - set(grid))]
        write_whole(journal.path, _csv(ordered, header=True).decode("utf-8"))
        failed = False
    finally:
        journal.close(failed=failed)
    return len(todo), len(grid) - len(todo)
