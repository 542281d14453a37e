"""``pocket run CASE.toml | --sample N | --example NAME [--out DIR] [--vtk DIR]``: solve a case file in physical
units (a pocket's, or a capsule's: ``pocket.apps.cases``)."""

from __future__ import annotations

import pathlib
import sys

from pocket.apps.casefile import results_paths, solved, write
from pocket.apps.cases import EXAMPLES, Case, example, load, sample
from pocket.apps.folders import check_output_dir, check_output_file, check_replaceable
from pocket.core.errors import InputError

from .common import path_name, progress_bar, solvers_epilog

__all__ = ["add_case_arguments", "case_from_args", "case_source", "register", "warn_case"]

_SHOWN = ("load", "force_N", "pressure_Pa", "contact_area_m2", "height_m", "force", "pressure_ratio",
          "height_ratio")


def add_case_arguments(parser) -> None:
    """The pocket to use: a case file or a built-in sample of Table 1."""
    parser.add_argument("case", nargs="?", type=path_name, metavar="CASE.toml",
                        help="case file in physical units (its tables and keys: the user guide's page on case files)")
    parser.add_argument("--sample", type=int, metavar="N", help="built-in sample N (1-4) of the paper's Table 1")
    parser.add_argument("--example", choices=tuple(EXAMPLES),
                        help="a built-in example case: capsule, a 50 um microcapsule with a 0.5 um neo-Hookean wall "
                        "squeezed between two plates (forces on each plate, up to 20 uN); uninflated-capsule, the "
                        "same capsule full of liquid at no pressure (up to 40 uN, by the finite elements)")


def case_from_args(args) -> tuple[Case, str]:
    """The case of the command line and a file stem for it."""
    given = [args.case is not None, args.sample is not None, getattr(args, "example", None) is not None]
    if sum(given) != 1:
        raise InputError("give one of a case file, --sample N or --example NAME, not "
                         + ("several" if sum(given) else "none"))
    if args.sample is not None:
        return sample(args.sample), f"sample{args.sample}"
    if args.case is None:
        return example(args.example), f"example_{args.example}"
    return load(args.case), pathlib.Path(args.case).stem


def case_source(args) -> str:
    """What the outputs of the command line's case are of, as pocket's records of them name it: the case file
    (its absolute path) or the built-in sample."""
    if args.sample is not None:
        return f"built-in sample {args.sample}"
    if getattr(args, "example", None) is not None:
        return f"built-in example {args.example}"
    return f"case file {pathlib.Path(args.case).resolve()}"


def warn_case(case: Case) -> None:
    """Print the case's warnings on its inputs on stderr, before any solve: they may explain why one fails."""
    for text in case.warnings:
        print(f"pocket: warning: {text}", file=sys.stderr)


def _write_vtk(directory, pocket, states: list, of: str) -> None:
    """The compressed ``states`` as a ParaView series in ``directory`` (``pocket.apps.vtk.files``), a step per
    force in increasing order (one for loads of equal force), the time of each its force in newtons, with the
    case's scales in every file's field data."""
    from pocket.apps.vtk.files import write_series

    steps = list({pocket.force_N(s): s for s in sorted(states, key=pocket.force_N)}.values())
    scales = {"length_scale_m": pocket.case.radius, "pressure_scale_Pa": pocket.pressure_scale_Pa,
              **({} if pocket.uninflated else {"force_scale_N": pocket.force_scale_N})}
    write_series(directory, steps, times=[pocket.force_N(s) for s in steps], overwrite=True, fields=scales, of=of)


def _main(args) -> int:
    case, stem = case_from_args(args)
    of = case_source(args)
    warn_case(case)
    out = check_output_dir(args.out, "--out").resolve()
    paths = [check_output_file(path, "--out", of=of) for path in results_paths(args.out, stem)]
    if args.vtk is not None:
        from pocket.apps.vtk.files import KIND

        vtk = check_replaceable(args.vtk, KIND, "--vtk", of=of)
        if out == vtk or vtk in out.parents:
            raise InputError(f"--vtk {args.vtk}: holds the --out folder {args.out}, but a series is written as a "
                             "folder of its own; give --vtk another folder, e.g. OUT/vtk")
    with progress_bar(case.name, " loads") as progress:
        result, pocket, states = solved(case, progress)
    if args.vtk is not None:
        _write_vtk(args.vtk, pocket, states, of)
    write(result, paths, of)
    # an uninflated capsule's inflated state is the unstressed sphere, tension-free by definition: not a warning
    inflated = () if pocket.uninflated else (result["inflated"],)
    for text in dict.fromkeys(w for row in (*inflated, *result["states"]) for w in row["warnings"]
                              if w not in case.warnings):
        print(f"pocket: warning: {text}", file=sys.stderr)
    missed = result["unreachable"]
    if missed:
        print(f"pocket: warning: {missed[0]['warnings'][0]}; the results hold the {len(result['states'])} of "
              f"{len(case.loads)} loads the model reaches, and list the others with the reason", file=sys.stderr)
    rows = result["states"]
    fluid = case.fluid.kind if not case.fluid.is_gas else \
        f"gas (ambient {case.fluid.ambient:.6g} Pa, gamma {case.fluid.gamma:g})"
    capsule = "gap_m" in rows[0]
    print(f"# {case.name}: {'a capsule, ' if capsule else ''}solver {case.solver}, {case.material.law} rubber (E = "
          f"{case.modulus:.6g} Pa), {fluid}, Phat_I = {rows[0]['pressure_initial']:.10g}, H0 = "
          f"{result['inflated']['height_m']:.6g} m" + (", the force F on each plate" if capsule else ""))
    # a capsule's gap; an uninflated capsule's force in E T R, its P / P_I undefined
    swap = {"height_m": "gap_m" if capsule else "height_m", "force": "force_ETR" if pocket.uninflated else "force"}
    shown = tuple(swap.get(k, k) for k in _SHOWN if not (pocket.uninflated and k == "pressure_ratio"))
    print("  ".join(f"{k:>15}" for k in shown))
    for row in rows:
        print("  ".join(f"{row[k]:>15.8g}" if isinstance(row[k], float) else f"{row[k]!s:>15}" for k in shown))
    print("wrote " + ", ".join(map(str, paths)) + ("" if args.vtk is None else f", {args.vtk}"))
    return 0


def register(subparsers) -> None:
    """Add ``pocket run``."""
    text = "solve a case file (physical units): inflate, compress at each load, write JSON and CSV"
    p = subparsers.add_parser("run", help=text, description=f"{text}. The results are DIR/STEM.json (the case, "
                              "the inflated state, every compressed state, SI and dimensionless, and the "
                              "provenance) and DIR/STEM.csv (one row per load). A rerun replaces only results "
                              "pocket wrote for the same case file and no one changed since (it keeps checksums "
                              "in DIR/.pocket-files.json); anything else is refused before any work (exit 2). "
                              "Loads the model does not reach (a force past the end of its range) are left "
                              "out: a warning names the first, the results list each with the reason, and the "
                              "exit status is 0; if no load is reached, exit 2.",
                              epilog=solvers_epilog(chosen_by="a case file's [solver] name; default shooting"))
    add_case_arguments(p)
    p.add_argument("--out", default=".", type=path_name, metavar="DIR",
                   help="folder for the results (default: ., the current folder)")
    p.add_argument("--vtk", type=path_name, metavar="DIR",
                   help="also write the compressed states as a ParaView series (as "
                   "compress --vtk does: surface.pvd, profile.pvd, indenter.pvd), the time of each step its "
                   "force in N; lengths are in units of the clamp radius, and every file's field data holds "
                   "length_scale_m (R), pressure_scale_Pa (E T / R) and force_scale_N (P_I pi R^2; not for an "
                   "uninflated capsule, which has no Fhat) to turn them into SI")
    p.set_defaults(handler=_main)
