"""Parameter sweeps over (alpha, Phat_I, Fhat) on any ``concurrent.futures.Executor`` (``pocket sweep``).

The rubber is a Mooney-Rivlin alpha per grid point (the alpha axis), or one rubber of
another law for the whole sweep (``pocket.core.materials.Material``); the fluid is a
liquid or one gas, the indenter the flat plate or one sphere, and the membrane a pocket or a
capsule (``geometry``, given to the solver as it is), for the whole sweep.

Each grid point is one compressed state. The points of one curve (a rubber,
a fluid, Phat_I, the solver and its options) are solved in one task by
``solve_curve``, by continuation through their forces from one inflation
(``compression_curve``), which gives the states of ``solve_point`` (a point
from a fresh inflation) to the solver's tolerance at a fraction of the cost.
Both are top-level functions, so that they pickle to other processes and
machines. ``run_sweep`` takes the executor as an argument: local
processes (``pocket.apps.sweep.workers.local_executor``, the command line's default)
or a dask.distributed cluster (``Client(address).get_executor()``, with
``--scheduler ADDRESS``) run the same code.

The results are one tidy CSV, one row per point: the keys of a compressed
state (``CompressedState.KEYS``), the contact patch's deformed radius and contact
pressures (``pocket.apps.contactpatch``), the solver and its options, a ``status`` (``ok``;
``out_of_range`` past the model's range; ``failed`` when the solver did not
converge), a one-line ``message`` (the reason, or the state's warnings), the
rubber, the fluid and the smallest tensions with the wrinkling flag
(``pocket.apps.sweep.journal``). A row's ``alpha`` (or the parameters of another
law), ``pressure_initial``, ``force`` and fluid are the grid point as
asked, never the values a solver hands back, and every float is written
exactly (``repr``), so a point reads back equal to the number asked: that is
the key on which a rerun recognises the points already done.

A capsule's forces may be given as F / (E T R) instead (``force_unit="ETR"``; ``pocket sweep --force-etr``),
the same force for every Phat_I: the row's ``force_ETR`` is the force asked and its ``force`` the Fhat
F / (E T R) / (pi Phat_I) given to the solver. Only these take Phat_I = 0, the uninflated capsule, which has no
Fhat: its ``force`` and ``pressure_ratio`` cells are empty, and its forces go to the solver as F / (E T R).

The file's life:

1. Before any point is solved, an existing file must be a sweep file (its
   first line the columns above, every complete row well formed), or the sweep
   stops with an ``InputError`` and leaves it untouched. An empty file, or one
   holding only the start of the header, counts as new. One sweep at a time
   may write a file (an advisory POSIX lock, where the system has ``fcntl``).
2. While the sweep runs, the file is its journal: the points of each finished
   curve are appended, each as one complete row, and flushed.
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

from pocket.core.errors import UNINFLATED_CAPSULE, ConvergenceError, InputError, OutOfRangeError
from pocket.core.fluids import Fluid, as_fluid
from pocket.core.geometries import DISC, Geometry, as_geometry
from pocket.core.indenters import PLATE, Indenter, as_indenter
from pocket.core.inputs import FORCE_UNITS, check_choice, check_force, check_non_negative, check_positive
from pocket.core.materials import Material, as_material, mooney_rivlin
from pocket.core.states import CHECKS, UNINFLATED_UNDEFINED, CompressedState

from ..contactpatch import contact_patch
from ..folders import write_whole
from ..rubbers import prestretched
from ..solvers import entry, record
from .journal import CAPSULE, COLUMNS, STATUSES, Journal, identity, key, line, rows_csv

__all__ = ["COLUMNS", "MAX_POINTS", "STATUSES", "run_sweep", "solve_curve", "solve_point"]

#: most points of one sweep (a bound on the work and on the memory of its bookkeeping)
MAX_POINTS = 100_000


def _asked(pressure_initial: float, force: float, unit: str) -> dict:
    """The force cells of a point as asked: its Fhat (``unit`` "Fhat"); for a force F / (E T R) (``unit`` "ETR"),
    its ``force_ETR`` and the Fhat = F / (E T R) / (pi Phat_I) it is where P_I > 0 (none for an uninflated
    capsule)."""
    if unit == "Fhat":
        return {"force": force}
    return {"force": force / (math.pi * pressure_initial) if pressure_initial > 0.0 else "", "force_ETR": force}


def _loads(pressure_initial: float, forces: list[float], unit: str) -> tuple[list[float], dict]:
    """The forces of a curve as its solver takes them, and the keyword that says their unit: Fhat, or for an
    uninflated capsule F / (E T R) with ``force_unit="ETR"``."""
    if unit == "ETR" and pressure_initial == 0.0:
        return list(forces), {"force_unit": "ETR"}
    return [_asked(pressure_initial, f, unit)["force"] for f in forces], {}


def _row(solver: str, material, pressure_initial: float, force: float, options: dict, state=None,
         error: Exception | None = None, unit: str = "Fhat") -> dict:
    """The CSV row (dict of COLUMNS) of one point: its ``state``, or the ``error`` that stopped it; ``force`` in
    ``unit`` (``_asked``)."""
    row: dict[str, object] = dict.fromkeys(COLUMNS, "")
    if isinstance(error, OutOfRangeError):
        row.update(status="out_of_range", message=line(error))
    elif error is not None:
        row.update(status="failed", message=line(error))
    else:
        row.update({key: float(getattr(state, key)) for key in CompressedState.KEYS
                    if key != "alpha" and not (pressure_initial == 0.0 and key in UNINFLATED_UNDEFINED)})
        row.update(contact_patch(state))
        row.update({key: float(state.extra[key]) for key in CAPSULE if key in state.extra})
        row.update({key: float(getattr(state, key)) for key in CHECKS[:2]}, wrinkled=state.wrinkled)
        row.update(status="ok", message=line("; ".join(state.warnings)))
    row.update(identity(solver, options, material, as_fluid(options.get("fluid")),
                        as_indenter(options.get("indenter")), as_geometry(options.get("geometry"))))  # as asked
    row.update(alpha=_alpha_cell(material), pressure_initial=pressure_initial, **_asked(pressure_initial, force, unit))
    return row


def _alpha_cell(material: Material):
    """The ``alpha`` cell of a point: the alpha a Mooney-Rivlin rubber was given by, else empty."""
    return "" if material.exact_alpha is None else material.exact_alpha


def solve_point(solver: str, material, pressure_initial: float, force: float, options: dict,
                unit: str = "Fhat") -> dict:
    """One grid point, from a fresh inflation, as a CSV row; a model's failure becomes the row's status, not an error.

    Parameters
    ----------
    solver : str
        The solver by name.
    material : Material
        The rubber (``pocket.core.materials``; ``mooney_rivlin(alpha)`` for an alpha).
    pressure_initial : float
        Phat_I = P_I R / (E T).
    force : float
        Fhat = F / (P_I pi R^2), or F / (E T R) (``unit``).
    options : dict
        The solver's options, with the ``fluid`` (a ``Fluid``) if it is a gas and the ``indenter`` if it is not
        the flat plate.
    unit : {"Fhat", "ETR"}, optional
        The unit of ``force``: Fhat, or a capsule's F / (E T R) (at P_I = 0, an uninflated capsule's, the only unit
        it has).

    Returns
    -------
    dict
        The row: the state's keys (``COLUMNS``), ``status`` (``"ok"``, ``"out_of_range"``, ``"failed"``) and
        ``message``.

    Examples
    --------
    >>> from pocket.apps.sweep.grid import solve_point
    >>> from pocket.core.materials import mooney_rivlin
    >>> row = solve_point("shooting", mooney_rivlin(47 / 160), 0.31, 0.19, {})
    >>> print(row["status"], f"{row['pressure_ratio']:.4f}")
    ok 1.2944
    >>> print(solve_point("shooting", mooney_rivlin(47 / 160), 0.31, 20.0, {})["status"])
    out_of_range
    """
    (load,), extra = _loads(pressure_initial, [force], unit)
    try:
        state = entry(solver, "compress", "a sweep point")(material, pressure_initial, load, **options, **extra)
    except (OutOfRangeError, ConvergenceError) as err:
        return _row(solver, material, pressure_initial, force, options, error=err, unit=unit)
    return _row(solver, material, pressure_initial, force, options, state, unit=unit)


def solve_curve(solver: str, material, pressure_initial: float, forces, options: dict,
                unit: str = "Fhat") -> list[dict]:
    """The points of one curve (one rubber, fluid and Phat_I) as CSV rows, by continuation through the forces.

    The rows are those of ``solve_point`` to the solver's tolerance. Where the continuation fails at a force,
    that point is solved from a fresh inflation (its row is ``solve_point``'s), the forces before it are the
    curve up to it, and those after it a curve of their own; past a point out of the model's range, each point
    is solved alone (its row says why it is out of range).

    Parameters
    ----------
    solver : str
        The solver by name.
    material : Material
        The rubber.
    pressure_initial : float
        Phat_I = P_I R / (E T).
    forces : sequence of float
        Fhat (or F / (E T R), ``unit``), distinct, in increasing order.
    options, unit
        As for ``solve_point``.

    Returns
    -------
    list of dict
        The rows, in the order of ``forces``.

    Examples
    --------
    >>> from pocket.apps.sweep.grid import solve_curve, solve_point
    >>> from pocket.core.materials import mooney_rivlin
    >>> rows = solve_curve("shooting", mooney_rivlin(47 / 160), 0.31, [0.1, 0.19, 20.0], {})
    >>> print([row["status"] for row in rows])
    ['ok', 'ok', 'out_of_range']
    >>> alone = solve_point("shooting", mooney_rivlin(47 / 160), 0.31, 0.19, {})
    >>> print(abs(rows[1]["pressure_ratio"] - alone["pressure_ratio"]) < 1e-9)
    True
    """
    done = [0]
    loads, extra = _loads(pressure_initial, list(forces), unit)
    try:
        states = entry(solver, "compression_curve", "a sweep curve")(
            material, pressure_initial, loads, progress=lambda count, _: done.append(count), **options, **extra)
    except (OutOfRangeError, ConvergenceError):
        k = done[-1]
        rows = solve_curve(solver, material, pressure_initial, forces[:k], options, unit) if k else []
        rows.append(solve_point(solver, material, pressure_initial, forces[k], options, unit))
        rest = forces[k + 1:]
        if rows[-1]["status"] == "out_of_range":
            return rows + [solve_point(solver, material, pressure_initial, f, options, unit) for f in rest]
        return rows + (solve_curve(solver, material, pressure_initial, rest, options, unit) if rest else [])
    return [_row(solver, material, pressure_initial, f, options, state, unit=unit)
            for f, state in zip(forces, states, strict=True)]


def _grid(materials, pressures, forces, unit: str, geometry: Geometry) -> list[tuple]:
    if geometry != DISC and any(p == 0.0 for p in pressures) and unit == "Fhat":
        raise InputError(f"pressure = 0: {UNINFLATED_CAPSULE}")
    if geometry == DISC and unit == "ETR":
        raise InputError("forces F / (E T R) (--force-etr) are a capsule's (--geometry capsule); a pocket's are Fhat")
    uninflated = unit == "ETR"  # a capsule's forces F / (E T R) are defined at P_I = 0
    pressures = [check_non_negative("pressure", p) if uninflated else check_positive("pressure", p)
                 for p in pressures]
    forces = [check_force(f) for f in forces]
    if not (materials and pressures and forces):
        raise InputError("a sweep needs at least one alpha (or a rubber), one pressure and one force")
    size = math.prod(map(len, (materials, pressures, forces)))
    if size > MAX_POINTS:
        raise InputError(f"the grid has {size} points, but a sweep takes at most {MAX_POINTS}")
    return list(dict.fromkeys(itertools.product(materials, pressures, forces)))


def _curves(points) -> dict:
    """(material, Phat_I) -> the distinct forces of ``points`` (material, Phat_I, Fhat) there, increasing."""
    curves: dict = {}
    for material, pressure, force in points:
        curves.setdefault((material, pressure), set()).add(force)
    return {curve: sorted(forces) for curve, forces in curves.items()}


def run_sweep(path, alphas, pressures, forces, executor, *, solver="shooting", options=None,
              progress: Callable[[int, int], None] | None = None, material: Material | None = None,
              fluid: Fluid | None = None, indenter: Indenter | None = None, prestretch: float = 1.0,
              geometry: Geometry | str | None = None, force_unit: str = "Fhat") -> tuple[int, int]:
    """Solve every (alpha, Phat_I, Fhat) of a grid not already in the sweep file, on an executor.

    Each curve (a rubber and Phat_I) missing points is one task (``solve_curve``) through the grid's forces up
    to the last one missing, so that a point's row does not depend on which points an earlier run on the file
    had finished. The file's life, when the sweep finishes and when it stops early, is in ``pocket.apps.sweep.grid``:
    one CSV row per point, appended as the sweep runs; a rerun resumes it.

    Parameters
    ----------
    path : str or path
        The sweep's CSV file (``pocket.apps.sweep.journal``).
    alphas : sequence of float or None
        Mooney-Rivlin alphas = C2/C1; empty or None with ``material``.
    pressures : sequence of float
        Phat_I = P_I R / (E T).
    forces : sequence of float
        Fhat = F / (P_I pi R^2), or F / (E T R) (``force_unit``).
    executor : concurrent.futures.Executor
        Where the curves are solved (``pocket.apps.sweep.workers.local_executor``, a dask cluster's,
        ``pocket.apps.sweep.cluster.connect``). A sweep that stops early leaves the curves not yet solved in it:
        its owner ends them (``pocket.apps.sweep.workers.stop``).
    solver : str, optional
        The solver by name; ``options`` its options (checked against its record). Both are part of each point:
        a file may hold the points of several solvers.
    progress : callable, optional
        ``progress(done, total)``, called after each curve, ``done`` counting points.
    material : Material, optional
        Another law, for every point (instead of ``alphas``).
    fluid : Fluid, optional
        None (a liquid) or a gas, its ambient pressure as Phat_atm = P_atm R / (E T).
    indenter : Indenter, optional
        None (the flat plate), a sphere or a profile table (``pocket.core.indenters``), part of each point.
    prestretch : float, optional
        The sheets' lambda_p (``Material.prestretch``), for every rubber of the grid.
    geometry : Geometry or str, optional
        The membrane (``pocket.core.geometries``): None or "pocket" the flat clamped sheet, "capsule" the closed
        capsule between two plates (its Fhat's F on each plate), part of each point.
    force_unit : {"Fhat", "ETR"}, optional
        The unit of ``forces``: Fhat, or a capsule's F / (E T R), the same force for every Phat_I (each point's
        ``force_ETR``, and its Fhat where P_I > 0); only these take Phat_I = 0, an uninflated capsule.

    Returns
    -------
    tuple of int
        (computed, reused) points.

    Raises
    ------
    InputError
        For an invalid grid, solver or option, or a file that is not a sweep's, before the file is touched.

    Examples
    --------
    A grid of two rubbers, one pressure and two forces, then the same grid with a third force: the second run
    reuses the four points it has.

    >>> import csv, pathlib, tempfile
    >>> from concurrent.futures import ThreadPoolExecutor
    >>> from pocket.apps.sweep.grid import run_sweep
    >>> with tempfile.TemporaryDirectory() as folder, ThreadPoolExecutor(1) as executor:
    ...     path = pathlib.Path(folder) / "grid.csv"
    ...     first = run_sweep(path, [0.0, 47 / 160], [0.31], [0.1, 0.19], executor)
    ...     second = run_sweep(path, [0.0, 47 / 160], [0.31], [0.1, 0.19, 0.3], executor)
    ...     rows = list(csv.DictReader(path.open()))
    >>> print(first, second, len(rows), {row["status"] for row in rows})
    (4, 0) (2, 4) 6 {'ok'}
    """
    if material is not None and alphas:
        raise InputError("give either alphas (a Mooney-Rivlin rubber) or another law's material, not both")
    materials = [mooney_rivlin(a) for a in alphas or ()] if material is None else [as_material(material)]
    if prestretch != 1.0:  # every alpha's sheet clamped with it
        materials = [prestretched(m, prestretch, "prestretch") for m in materials]
    unit = check_choice("force_unit", force_unit, FORCE_UNITS)
    geometry = as_geometry(geometry)
    grid = _grid(materials, pressures, forces, unit, geometry)
    options = record(solver).checked(dict(options or {}), "compress")
    for name in ("compress", "compression_curve"):  # refused here, before the file is touched
        entry(solver, name, "a sweep")
    fluid = as_fluid(fluid)
    if fluid.is_gas:
        options["fluid"] = fluid
    indenter = as_indenter(indenter)
    if indenter != PLATE:
        options["indenter"] = indenter
    if geometry != DISC:
        options["geometry"] = geometry
    cells = {m: identity(solver, options, m, fluid, indenter, geometry) for m in materials}
    keys = [key({**cells[m], "alpha": _alpha_cell(m), "pressure_initial": p, **_asked(p, f, unit)})
            for m, p, f in grid]
    journal = Journal(pathlib.Path(path))
    failed = True
    try:
        todo = {k: point for point, k in zip(grid, keys, strict=True) if k not in journal.rows}
        curves = _curves(grid)
        futures = [executor.submit(solve_curve, solver, m, p, [f for f in curves[m, p] if f <= fs[-1]], options,
                                   unit=unit)
                   for (m, p), fs in _curves(todo.values()).items()]
        done = 0
        for future in as_completed(futures):
            curve = [row for row in future.result() if key(row) in todo]
            for row in curve:
                journal.append(row)
            done += len(curve)
            if progress is not None:
                progress(done, len(todo))
        rows = journal.rows
        ordered = [rows[k] for k in keys] + [rows[k] for k in sorted(set(rows) - set(keys), key=_order)]
        write_whole(journal.path, rows_csv(ordered, header=True).decode("utf-8"), record=False)  # kept by rows
        failed = False
    finally:
        journal.close(failed=failed)
    return len(todo), len(grid) - len(todo)


def _order(point: tuple) -> tuple:
    """A sort key for the points of other sweeps in one file: text first, None (no alpha) before numbers."""
    return tuple((0, "") if v is None else (1, v) if isinstance(v, str) else (2, "", v) for v in point)
