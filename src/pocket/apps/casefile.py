"""Solve a case file and write its results as JSON and CSV (``pocket run``).

The case (``pocket.apps.cases``) is resolved to the dimensionless model
(``pocket.apps.physical``), inflated and compressed at each load by its solver, and
written as ``DIR/<stem>.json`` (the case: SI values and, under ``given``, every
input as the file wrote it; the inflated state, the compressed states, and the
provenance: pocket's and its libraries' versions) and ``DIR/<stem>.csv`` (one row
per load), both or neither. A column's name says its unit (``pocket.apps.columns``): SI values
end in their unit, names without one are dimensionless, and the rubber's stresses in units of mu_0
end in ``_per_mu0``. Each row holds the load as written (``load``: ``"0.2 N"``),
the SI values (``force_N``, for a force load the force as parsed; ``pressure_Pa``,
``pressure_rise_Pa``, ``contact_pressure_pole_Pa`` and ``contact_pressure_edge_Pa`` (P on the flat
plate, ``pocket.apps.contact``), ``contact_area_m2`` (the curved area in contact under a sphere),
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

``results_paths`` names both files and says which existing ones a rerun may replace:
a JSON file only if it is pocket's results (its keys and its provenance naming pocket),
a CSV file only beside such a JSON file (the two are written together).
"""

from __future__ import annotations

import csv
import io
import json
import pathlib

from .cases import Case
from .folders import write_files
from .physical import compressed_row, forces, inflated_row, resolve
from .provenance import environment
from .solvers import entry

__all__ = ["solve", "write", "results_paths"]

_KEYS = {"case", "inflated", "states", "provenance"}


def _is_results(path: pathlib.Path) -> bool:
    """``path`` is a results JSON file that pocket wrote."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(data, dict) and set(data) == _KEYS and "pocket" in data["provenance"]


def results_paths(directory, stem: str) -> dict:
    """{path: ours} for ``stem.json`` and ``stem.csv`` in ``directory``: ``ours(path)`` is true if
    ``path`` holds results that pocket wrote (for ``pocket.apps.folders.check_output_file``)."""
    directory = pathlib.Path(directory)
    json_path = directory / f"{stem}.json"
    return {json_path: _is_results, directory / f"{stem}.csv": lambda path: _is_results(json_path)}


def solve(case: Case, progress=None) -> dict:
    """The case solved: {"case": SI inputs, "inflated": row, "states": [rows], "provenance": {...}}
    (JSON-ready). ``progress(done, total)``, if given, goes to the solver's compression curve."""
    pocket = resolve(case)
    loads = forces(pocket)
    extra = {} if progress is None else {"progress": progress}
    curve = entry(pocket.solver(), "compression_curve", f"the loads of case {case.name}")
    states = curve(pocket.material, pocket.pressure_initial, loads,
                                               **pocket.options(), **extra)
    return {"case": case.fields(), "inflated": inflated_row(pocket, states[0].inflated),
            "states": [compressed_row(pocket, s, i) for i, s in enumerate(states)], "provenance": environment()}


def write(result: dict, directory, stem: str) -> tuple[pathlib.Path, pathlib.Path]:
    """Write ``stem.json`` and ``stem.csv`` into ``directory``, both or neither; returns their paths."""
    json_path, csv_path = results_paths(directory, stem)
    fields = list(dict.fromkeys(k for row in result["states"] for k in row))
    text = io.StringIO(newline="")
    writer = csv.DictWriter(text, fields, restval="")
    writer.writeheader()
    writer.writerows({k: "; ".join(map(str, v)) if isinstance(v, list) else v for k, v in row.items()}
                     for row in result["states"])
    write_files({json_path: json.dumps(result, indent=2) + "\n", csv_path: text.getvalue()})
    return json_path, csv_path
