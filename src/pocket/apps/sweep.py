"""Parameter sweeps over (alpha, Phat_I, Fhat) on any ``concurrent.futures.Executor`` (``pocket sweep``).

Each grid point is one compressed state, solved in a task of its own by
``solve_point`` (a top-level function, so that it pickles to other processes
and machines). ``run_sweep`` takes the executor as an argument: local
processes (``ProcessPoolExecutor``, the command line's default) or a
dask.distributed cluster (``Client(address).get_executor()``, with
``--scheduler ADDRESS``) run the same code.

The results are one tidy CSV, one row per point: the DESIGN.md keys of a
compressed state, the solver, a ``status`` (``ok``; ``out_of_range`` past the
model's range; ``failed`` when the solver did not converge) and its
``message``. Rows are appended and flushed as points finish, floats written
exactly (``repr``). A sweep rerun on the same file reads the points already
there (an interrupted last line is dropped) and computes only the others; once
every point is in, the file is rewritten in grid order, so that the result
does not depend on the executor or on the interruptions.
"""

from __future__ import annotations

import csv
import io
import itertools
import pathlib
import sys
from concurrent.futures import as_completed

from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError
from pocket.core.inputs import check_alpha, check_force, check_positive
from pocket.core.states import CompressedState

from .folders import write_whole
from .solvers import SOLVERS, get_solver

__all__ = ["COLUMNS", "solve_point", "run_sweep"]

COLUMNS = (*CompressedState.KEYS, "solver", "status", "message")
_PARAMETERS = ("alpha", "pressure_initial", "force")


def solve_point(solver: str, alpha: float, pressure_initial: float, force: float, options: dict) -> dict:
    """One grid point as a CSV row (dict of COLUMNS); model failures become a status, not an error."""
    row = dict.fromkeys(COLUMNS, "")
    row.update(alpha=alpha, pressure_initial=pressure_initial, force=force, solver=solver, status="ok")
    try:
        state = get_solver(solver).compress(alpha, pressure_initial, force, **options)
    except OutOfRangeError as err:
        return {**row, "status": "out_of_range", "message": str(err)}
    except ConvergenceError as err:
        return {**row, "status": "failed", "message": str(err)}
    row.update({key: float(getattr(state, key)) for key in CompressedState.KEYS})
    return row


def _key(row) -> tuple[float, float, float]:
    return tuple(float(row[k]) for k in _PARAMETERS)


def _read(path: pathlib.Path) -> list[dict]:
    """The complete rows of an earlier run; an unfinished last line is cut off the file."""
    if not path.exists() or path.stat().st_size == 0:
        return []
    text = path.read_text()
    if not text.endswith("\n"):
        text = text[: text.rfind("\n") + 1]
        path.write_text(text)
    rows = list(csv.DictReader(text.splitlines()))
    header = text.split("\n", 1)[0].split(",")
    if tuple(header) != COLUMNS:
        raise InputError(f"{path} exists but is not a sweep file (its columns are {','.join(header)!r})")
    return rows


def _progress(done: int, total: int) -> None:
    if sys.stderr.isatty():
        width = 30
        bar = "#" * (width * done // max(total, 1))
        print(f"\rsweep [{bar:<{width}}] {done}/{total}", end="\n" if done == total else "",
              file=sys.stderr, flush=True)


def run_sweep(path, alphas, pressures, forces, executor, *, solver="shooting", options=None) -> tuple[int, int]:
    """Solve every (alpha, Phat_I, Fhat) of the grid not already in the CSV ``path``.

    Returns (computed, reused). Rows go to ``path`` as they finish; at the end
    the file holds the grid in order (then any other points it held before).
    """
    alphas = [check_alpha(a) for a in alphas]
    pressures = [check_positive("pressure", p) for p in pressures]
    forces = [check_force(f) for f in forces]
    if not (alphas and pressures and forces):
        raise InputError("a sweep needs at least one alpha, one pressure and one force")
    if solver not in SOLVERS:
        raise InputError(f"solver = {solver!r}, but it must be one of {', '.join(sorted(SOLVERS))}")
    options = dict(options or {})
    grid = list(dict.fromkeys(itertools.product(alphas, pressures, forces)))
    path = pathlib.Path(path)
    rows = {_key(row): row for row in _read(path)}
    todo = [point for point in grid if point not in rows]
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("a", newline="") as stream:
        writer = csv.DictWriter(stream, COLUMNS)
        if stream.tell() == 0:
            writer.writeheader()
        futures = [executor.submit(solve_point, solver, *point, options) for point in todo]
        try:
            for done, future in enumerate(as_completed(futures), start=1):
                row = future.result()
                writer.writerow(row)
                stream.flush()
                rows[_key(row)] = row
                _progress(done, len(todo))
        except BaseException:
            for future in futures:
                future.cancel()
            raise
    ordered = [rows[point] for point in grid] + [rows[k] for k in sorted(set(rows) - set(grid))]
    text = io.StringIO(newline="")
    writer = csv.DictWriter(text, COLUMNS)
    writer.writeheader()
    writer.writerows(ordered)
    write_whole(path, text.getvalue())
    return len(todo), len(grid) - len(todo)
