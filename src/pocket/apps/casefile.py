"""Solve a case file and write its results as JSON and CSV (``pocket run``).

The case (``pocket.apps.cases``) is resolved to the dimensionless model
(``pocket.apps.physical``), inflated and compressed at each load by its solver (forces along one compression
curve; heights each where the solver holds it, ``compress_height``, else at the force a search finds), and
written as ``DIR/<stem>.json`` (the case: SI values and, under ``given``, every
input as the file wrote it; the inflated state, the compressed states, and the
provenance: pocket's and its libraries' versions) and ``DIR/<stem>.csv`` (one row
per load), both or neither. A column's name says its unit (``pocket.apps.columns``): SI values
end in their unit, names without one are dimensionless, and the rubber's stresses in units of mu_0
end in ``_per_mu0``. Each row holds the load as written (``load``: ``"0.2 N"``),
the SI values (``force_N``, for a force load the force as parsed; ``pressure_Pa``,
``pressure_rise_Pa``, ``contact_pressure_pole_Pa`` and ``contact_pressure_edge_Pa`` (P on the flat
plate, ``pocket.apps.contactpatch``), ``contact_area_m2`` (the curved area in contact under a sphere),
``contact_radius_deformed_m`` (the contact patch's radius as a camera or a print measures it: the
contact edge's distance from the axis in the deformed sheet, sqrt(A_c / pi) on the plate),
``contact_radius_lagrangian_m`` (where the contact edge was in the flat sheet, a_c R: smaller by the
hoop stretch there), ``height_m``, ``travel_m`` = H0 - H, ``volume_m3``, and for a membrane solver
``volume_lower_m3``: the fluid's volume under the sheet's lower surface, ``pocket.core.offset``), the
dimensionless keys of ``CompressedState.KEYS`` (the inputs as asked, not a solver's echo; ``alpha``
only for a Mooney-Rivlin rubber; ``contact_radius`` the Lagrangian a_c / R), then
``contact_radius_deformed`` (rho_c / R), ``contact_pressure_pole`` and ``contact_pressure_edge``
(Phat), the smallest tensions ``tension_1_min``, ``tension_2_min`` (units E T) and ``wrinkled``,
the rubber (``material`` and its law's parameters: ``c1_per_mu0``, ``mu_per_mu0``, ... in units of
mu_0, Gent's ``jm`` and Ogden's ``exponents`` as numbers), the fluid (``fluid``, and a gas's
``ambient`` as Phat_atm = P_atm R / (E T) and ``gamma``), the solver and the state's ``warnings``
(a list in JSON, joined by "; " in CSV, as are Ogden's lists). The JSON's inflated state has the
same names, and its case holds the rubber and the fluid in SI (``c10_Pa``, ``ambient_Pa``, ...).

A load the model does not reach (a force past the end of its range, a height below the lowest it
reaches, ``pocket.apps.physical.load_forces``) is left out of the solve: the JSON's ``unreachable``
lists each such load as the case gives it, with its SI value and the reason (``warnings``), and the CSV
ends with a row for each, holding those cells only. A case none of whose loads is reached is refused
(the first load's ``OutOfRangeError``).

``results_paths`` names both files; whether existing ones may be replaced is
``pocket.apps.folders.check_output_file``'s rule: only results pocket wrote for the same case, unchanged.
"""

from __future__ import annotations

import csv
import io
import json
import pathlib

from pocket.core.errors import OutOfRangeError

from .cases import Case
from .columns import documented
from .folders import write_files
from .physical import Pocket, compressed_row, inflated_row, load_forces, resolve
from .provenance import environment
from .solvers import entry

__all__ = ["results_paths", "solve", "solved", "write"]


def results_paths(directory, stem: str) -> tuple[pathlib.Path, pathlib.Path]:
    """The results' files of ``pocket run``: ``stem.json`` and ``stem.csv`` in ``directory``.

    Parameters
    ----------
    directory : str or path
        The folder.
    stem : str
        The files' name without its suffix.

    Returns
    -------
    tuple of pathlib.Path
        The JSON file and the CSV file.

    Examples
    --------
    >>> from pocket.apps.casefile import results_paths
    >>> print([path.name for path in results_paths("out", "sample1")])
    ['sample1.json', 'sample1.csv']
    """
    directory = pathlib.Path(directory)
    return directory / f"{stem}.json", directory / f"{stem}.csv"


def _unreached(case: Case, index: int, error: OutOfRangeError) -> dict:
    """The row of load ``index``, which the model does not reach: the load as given, its SI value, the reason."""
    kind = case.load_kind
    return {"load": case.as_given(f"loads.{kind}[{index}]"), "force_N" if kind == "forces" else "height_m":
            case.loads[index], "warnings": [str(error)]}


def solved(case: Case, progress=None) -> tuple[dict, Pocket, list]:
    """The case solved: its results, the case resolved to the model, and the compressed states.

    The case is resolved to the dimensionless model (``pocket.apps.physical.resolve``), inflated and compressed
    at each load it reaches by its solver; a load the model does not reach is listed under ``unreachable``
    with the reason.

    Parameters
    ----------
    case : Case
        The case (``pocket.apps.cases``).
    progress : callable, optional
        ``progress(done, total)``, passed to the solver's compression curve.

    Returns
    -------
    result : dict
        JSON-ready: ``case`` (SI inputs, and under ``given`` every input as written), ``inflated`` (a row),
        ``states`` (a row per reached load: SI values named with their unit, then the dimensionless keys),
        ``unreachable`` and ``provenance`` (pocket's and its libraries' versions).
    pocket : Pocket
        The case resolved (``pocket.apps.physical.Pocket``: its scales).
    states : list of CompressedState
        Of the reached loads.

    Raises
    ------
    OutOfRangeError
        If no load is reached (the first load's), or the initial state is not.
    ConvergenceError
        If a solve fails.

    Examples
    --------
    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.casefile import solved
    >>> result, pocket, states = solved(sample(1))
    >>> row = result["states"][2]
    >>> print(row["load"], row["force_N"], round(row["pressure_Pa"]), round(row["travel_m"] * 1e3, 3))
    1 N 1.0 6050 1.724

    The SI values are the dimensionless state's times the case's scales:

    >>> print(abs(states[2].force * pocket.force_scale_N - 1.0) < 1e-12)
    True
    """
    pocket = resolve(case)
    held: dict = {}  # the states of heights the solver held itself
    loads = load_forces(pocket, held)
    reached = [i for i, load in enumerate(loads) if not isinstance(load, OutOfRangeError)]
    if not reached:
        first = loads[0]
        assert isinstance(first, OutOfRangeError)  # no load reached: each is its error
        raise first
    if set(held) == set(reached):  # heights, each solved where it is: not again at its force
        states = [held[i] for i in reached]
        if progress is not None:
            progress(len(states), len(states))
    else:
        extra = {} if progress is None else {"progress": progress}
        curve = entry(pocket.solver(), "compression_curve", f"the loads of case {case.name}")
        states = curve(pocket.material, pocket.pressure_initial,
                       [load for load in loads if not isinstance(load, OutOfRangeError)], **pocket.curve_options(),
                       **extra)
    result = {"case": case.fields(), "inflated": inflated_row(pocket, states[0].inflated),
              "states": [compressed_row(pocket, s, i) for i, s in zip(reached, states, strict=True)],
              "unreachable": [_unreached(case, i, e) for i, e in enumerate(loads) if isinstance(e, OutOfRangeError)],
              "provenance": environment()}
    return result, pocket, states


def solve(case: Case, progress=None) -> dict:
    """The results of a case, as ``pocket run`` writes them: the first part of ``solved``.

    Parameters
    ----------
    case : Case
        The case (``pocket.apps.cases``).
    progress : callable, optional
        ``progress(done, total)``, passed to the solver's compression curve.

    Returns
    -------
    dict
        JSON-ready: ``case``, ``inflated``, ``states``, ``unreachable``, ``provenance`` (``solved``).

    Raises
    ------
    OutOfRangeError
        If no load is reached.
    ConvergenceError
        If a solve fails.

    Examples
    --------
    A load past the end of the model's range is listed with the reason, in the user's unit:

    >>> from pocket.apps.cases import parse
    >>> from pocket.apps.casefile import solve
    >>> result = solve(parse({"sheet": {"thickness": "0.25 mm", "c1": "160 kPa", "c2": "47 kPa"},
    ...                       "clamp": {"radius": "20 mm"}, "initial": {"pressure": "4.81275 kPa"},
    ...                       "loads": {"forces": ["0.5 N", "100 N"]}}))
    >>> print([row["load"] for row in result["states"]], [row["load"] for row in result["unreachable"]])
    ['0.5 N'] ['100 N']
    >>> print(result["unreachable"][0]["warnings"][0])
    loads.forces[1] = '100 N' (Fhat = 16.53471956) is beyond the model's range, which ends at 60.1223 N ...
    """
    return solved(case, progress)[0]


def write(result: dict, paths, of: str | None = None) -> None:
    """Write a case's results as JSON and CSV, both or neither.

    The files are recorded as pocket's results for ``of``: existing ones may be replaced only if pocket wrote
    them for the same case, unchanged (``pocket.apps.folders.write_files``). Every column of the rows (the
    CSV's, and the JSON's inflated state's) is one of pocket's documented columns
    (``pocket.apps.columns.documented``).

    Parameters
    ----------
    result : dict
        The results (``solve``).
    paths : tuple of path
        The JSON and the CSV file (``results_paths``).
    of : str, optional
        What the results are of (the case file), recorded with them.

    Raises
    ------
    OutputError
        If a file cannot be written (nothing half-written is left); an ``InputError`` for existing files pocket
        may not replace.
    KeyError
        For a column that is not documented, before anything is written.

    Examples
    --------
    >>> import csv, pathlib, tempfile
    >>> from pocket.apps.cases import parse
    >>> from pocket.apps.casefile import results_paths, solve, write
    >>> result = solve(parse({"sheet": {"thickness": "0.25 mm", "c1": "160 kPa", "c2": "47 kPa"},
    ...                       "clamp": {"radius": "20 mm"}, "initial": {"pressure": "4.81275 kPa"},
    ...                       "loads": {"forces": ["0.5 N", "1 N"]}}))
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     json_path, csv_path = results_paths(folder, "button")
    ...     write(result, (json_path, csv_path))
    ...     rows = list(csv.DictReader(csv_path.open()))
    >>> print([row["load"] for row in rows], rows[0]["force_N"])
    ['0.5 N', '1 N'] 0.5
    """
    json_path, csv_path = paths
    rows = [*result["states"], *result["unreachable"]]
    fields = list(dict.fromkeys(k for row in rows for k in row))
    documented([*fields, *result["inflated"]])
    text = io.StringIO(newline="")
    writer = csv.DictWriter(text, fields, restval="")
    writer.writeheader()
    writer.writerows({k: "; ".join(map(str, v)) if isinstance(v, list) else v for k, v in row.items()} for row in rows)
    write_files({json_path: json.dumps(result, indent=2) + "\n", csv_path: text.getvalue()}, of=of)
