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

import itertools
import math
import pathlib
from collections.abc import Callable
from concurrent.futures import as_completed

from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError
from pocket.core.inputs import check_alpha, check_force, check_positive
from pocket.core.states import CompressedState

from .folders import write_whole
from .solvers import get_solver, record
from .sweepfile import COLUMNS, STATUSES, Journal, line, rows_csv

__all__ = ["COLUMNS", "STATUSES", "MAX_POINTS", "solve_point", "run_sweep"]

#: most points of one sweep (a bound on the work and on the memory of its bookkeeping)
MAX_POINTS = 100_000


def solve_point(solver: str, alpha: float, pressure_initial: float, force: float, options: dict) -> dict:
    """One grid point as a CSV row (dict of COLUMNS); model failures become a status, not an error."""
    row = dict.fromkeys(COLUMNS, "")
    try:
        state = get_solver(solver).compress(alpha, pressure_initial, force, **options)
    except OutOfRangeError as err:
        row.update(status="out_of_range", message=line(err))
    except ConvergenceError as err:
        row.update(status="failed", message=line(err))
    else:
        row.update({key: float(getattr(state, key)) for key in CompressedState.KEYS})
        row.update(status="ok", message=line("; ".join(state.warnings)))
    row.update(alpha=alpha, pressure_initial=pressure_initial, force=force, solver=solver)  # the point as asked
    return row


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
    journal = Journal(pathlib.Path(path))
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
        write_whole(journal.path, rows_csv(ordered, header=True).decode("utf-8"))
        failed = False
    finally:
        journal.close(failed=failed)
    return len(todo), len(grid) - len(todo)
