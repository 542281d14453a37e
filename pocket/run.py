"""``pocket run CASE.toml | --sample N [--out DIR]``: solve a case file, write JSON and CSV.

The case (``pocket.cases``) is resolved to the dimensionless model
(``pocket.physical``), inflated and compressed at each load by its solver, and
written as ``DIR/<stem>.json`` (the case in SI, the inflated state, the
compressed states, and the provenance: pocket's and its libraries' versions)
and ``DIR/<stem>.csv`` (one row per load). Each row holds
the SI values (``force_N``, ``pressure_Pa``, ``pressure_rise_Pa``,
``contact_area_m2``, ``contact_radius_m``, ``height_m``, ``travel_m`` = H0 - H,
``volume_m3``) followed by the dimensionless keys of DESIGN.md.
"""

from __future__ import annotations

import csv
import io
import json
import pathlib

from .cases import Case, load, sample
from .errors import InputError
from .folders import write_whole
from .physical import compressed_row, forces, inflated_row, resolve
from .provenance import environment

__all__ = ["solve", "write", "add_case_arguments", "case_from_args", "register"]

_SHOWN = ("force_N", "pressure_Pa", "contact_area_m2", "height_m", "force", "pressure_ratio", "height_ratio")


def solve(case: Case) -> dict:
    """The case solved: {"case": SI inputs, "inflated": row, "states": [rows], "provenance": {...}}
    (JSON-ready)."""
    pocket = resolve(case)
    loads = forces(pocket)
    states = pocket.solver().compression_curve(pocket.alpha, pocket.pressure_initial, loads,
                                               **pocket.options())
    return {"case": case.fields(), "inflated": inflated_row(pocket, states[0].inflated),
            "states": [compressed_row(pocket, s) for s in states], "provenance": environment()}


def write(result: dict, directory, stem: str) -> tuple[pathlib.Path, pathlib.Path]:
    """Write ``stem.json`` and ``stem.csv`` into ``directory``; returns their paths."""
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    json_path, csv_path = directory / f"{stem}.json", directory / f"{stem}.csv"
    fields = list(dict.fromkeys(k for row in result["states"] for k in row))
    text = io.StringIO(newline="")
    writer = csv.DictWriter(text, fields, restval="")
    writer.writeheader()
    writer.writerows(result["states"])
    write_whole(json_path, json.dumps(result, indent=2) + "\n")
    write_whole(csv_path, text.getvalue())
    return json_path, csv_path


def add_case_arguments(parser) -> None:
    """The pocket to use: a case file or a built-in sample of Table 1."""
    parser.add_argument("case", nargs="?", metavar="CASE.toml", help="case file (see pocket.cases)")
    parser.add_argument("--sample", type=int, metavar="N", help="built-in sample N (1-4) of the paper's Table 1")


def case_from_args(args) -> tuple[Case, str]:
    """The case of the command line and a file stem for it."""
    if (args.case is None) == (args.sample is None):
        raise InputError("give either a case file or --sample N, not both or neither")
    if args.sample is not None:
        return sample(args.sample), f"sample{args.sample}"
    return load(args.case), pathlib.Path(args.case).stem


def _main(args) -> int:
    case, stem = case_from_args(args)
    result = solve(case)
    paths = write(result, args.out, stem)
    rows = result["states"]
    print(f"# {case.name}: solver {case.solver}, Phat_I = {rows[0]['pressure_initial']:.10g}, "
          f"H0 = {result['inflated']['height_m']:.6g} m")
    print("  ".join(f"{k:>15}" for k in _SHOWN))
    for row in rows:
        print("  ".join(f"{row[k]:>15.8g}" for k in _SHOWN))
    print("wrote " + ", ".join(map(str, paths)))
    return 0


def register(subparsers) -> None:
    """Add ``pocket run``."""
    p = subparsers.add_parser("run", help="solve a case file (physical units), write JSON and CSV")
    add_case_arguments(p)
    p.add_argument("--out", default=".", metavar="DIR", help="directory for the results (default: .)")
    p.set_defaults(handler=_main)
