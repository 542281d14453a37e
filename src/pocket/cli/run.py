"""``pocket run CASE.toml | --sample N [--out DIR]``: solve a case file in physical units."""

from __future__ import annotations

import pathlib
import sys

from pocket.apps.casefile import results_paths, solve, write
from pocket.apps.cases import Case, load, sample
from pocket.apps.folders import check_output_dir, check_output_file
from pocket.core.errors import InputError

from .common import EXIT_CODES, progress_bar

__all__ = ["register", "add_case_arguments", "case_from_args", "warn_case"]

_SHOWN = ("load", "force_N", "pressure_Pa", "contact_area_m2", "height_m", "force", "pressure_ratio",
          "height_ratio")


def add_case_arguments(parser) -> None:
    """The pocket to use: a case file or a built-in sample of Table 1."""
    parser.add_argument("case", nargs="?", metavar="CASE.toml",
                        help="case file in physical units (the format is in the README)")
    parser.add_argument("--sample", type=int, metavar="N", help="built-in sample N (1-4) of the paper's Table 1")


def case_from_args(args) -> tuple[Case, str]:
    """The case of the command line and a file stem for it."""
    if (args.case is None) == (args.sample is None):
        raise InputError("give either a case file or --sample N, not both or neither")
    if args.sample is not None:
        return sample(args.sample), f"sample{args.sample}"
    return load(args.case), pathlib.Path(args.case).stem


def warn_case(case: Case) -> None:
    """Print the case's warnings on its inputs on stderr, before any solve: they may explain why one fails."""
    for text in case.warnings:
        print(f"pocket: warning: {text}", file=sys.stderr)


def _main(args) -> int:
    case, stem = case_from_args(args)
    warn_case(case)
    check_output_dir(args.out, "--out")
    for path, ours in results_paths(args.out, stem).items():
        check_output_file(path, "--out", ours=ours)
    with progress_bar(case.name, " loads") as progress:
        result = solve(case, progress)
    paths = write(result, args.out, stem)
    for text in dict.fromkeys(w for row in (result["inflated"], *result["states"]) for w in row["warnings"]
                              if w not in case.warnings):
        print(f"pocket: warning: {text}", file=sys.stderr)
    rows = result["states"]
    fluid = case.fluid.kind if not case.fluid.is_gas else \
        f"gas (ambient {case.fluid.ambient:.6g} Pa, gamma {case.fluid.gamma:g})"
    print(f"# {case.name}: solver {case.solver}, {case.material.law} rubber (E = {case.modulus:.6g} Pa), {fluid}, "
          f"Phat_I = {rows[0]['pressure_initial']:.10g}, H0 = {result['inflated']['height_m']:.6g} m")
    print("  ".join(f"{k:>15}" for k in _SHOWN))
    for row in rows:
        print("  ".join(f"{row[k]:>15.8g}" if isinstance(row[k], float) else f"{row[k]!s:>15}" for k in _SHOWN))
    print("wrote " + ", ".join(map(str, paths)))
    return 0


def register(subparsers) -> None:
    """Add ``pocket run``."""
    text = "solve a case file (physical units): inflate, compress at each load, write JSON and CSV"
    p = subparsers.add_parser("run", help=text, description=f"{text}. The results are DIR/STEM.json (the case, "
                              "the inflated state, every compressed state, SI and dimensionless, and the "
                              "provenance) and DIR/STEM.csv (one row per load).", epilog=EXIT_CODES)
    add_case_arguments(p)
    p.add_argument("--out", default=".", metavar="DIR", help="folder for the results (default: ., the current folder)")
    p.set_defaults(handler=_main)
