"""The ``pocket`` command line.

    pocket inflate  --alpha A --pressure PHAT   [--solver S] [--json]
    pocket compress --alpha A --pressure PHAT_I --force FHAT [FHAT ...] [--solver S] [--json]

Further subcommands live in the modules of ``COMMAND_MODULES``: each has
``register(subparsers)``, adding its parsers with ``set_defaults(handler=f)``
where ``f(args) -> int`` is the exit status. They share the error handling below.

Quantities are dimensionless (DESIGN.md): Phat = P R / (E T), Fhat = F / (P_I pi R^2).
Exit status: 0 success, 2 bad input or a state outside the model, 1 solver failure.
Errors are one line on stderr.
"""

from __future__ import annotations

import argparse
import importlib
import itertools
import json
import math
import os
import sys
from fractions import Fraction

from .checks import check_positive
from .errors import ConvergenceError, InputError, PocketError
from .provenance import version
from .solvers import SOLVERS, get_solver

__all__ = ["main", "number", "COMMAND_MODULES"]

_FEM_OPTIONS = ("elements", "order", "penalty", "mesh")

#: modules adding subcommands (imported when the parser is built)
COMMAND_MODULES: tuple[str, ...] = ("validation.cli", "pocket.run", "pocket.design", "pocket.sense", "pocket.sweep")


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2 (argparse prints the usage too)
        self.exit(2, f"{self.prog}: error: {message}\n")


def number(text: str) -> float:
    """A float or a fraction such as 47/160."""
    try:
        return float(Fraction(text)) if "/" in text else float(text)
    except (ValueError, ZeroDivisionError):
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="pocket", description="Mechanics of pressurised elastic pockets.")
    parser.add_argument("--version", action="version", version=f"pocket {version()}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    common = _Parser(add_help=False)
    common.add_argument("--alpha", type=number, required=True, help="C2/C1, > -1 (fractions allowed: 47/160)")
    common.add_argument("--solver", choices=sorted(SOLVERS), default="shooting")
    common.add_argument("--json", action="store_true", help="print JSON instead of a table")
    common.add_argument("--rtol", type=number, help="ODE tolerance of the shooting solver (default 1e-10)")
    fem = common.add_argument_group("finite elements (--solver fem)")
    fem.add_argument("--elements", type=int, help="number of elements of a uniform mesh")
    fem.add_argument("--order", type=int, help="element order, 1 or 2")
    fem.add_argument("--penalty", type=number, help="contact penalty stiffness")
    fem.add_argument("--mesh", help="mesh file of [0, 1] (any meshio format)")
    common.add_argument("--vtk", metavar="DIR", help="write the states as VTK files for ParaView")
    common.add_argument("--overwrite", action="store_true", help="replace an existing --vtk DIR")

    p = sub.add_parser("inflate", parents=[common], help="step 1: inflate at pressure Phat")
    p.add_argument("--pressure", type=number, required=True, help="Phat = P R / (E T)")
    c = sub.add_parser("compress", parents=[common], help="step 2: compress at fixed volume")
    c.add_argument("--pressure", type=number, required=True, help="initial Phat_I = P_I R / (E T)")
    c.add_argument("--force", type=number, nargs="+", required=True,
                   help="Fhat = F / (P_I pi R^2); several give a curve (continuation)")
    for name in COMMAND_MODULES:
        importlib.import_module(name).register(sub)
    return parser


def _options(args) -> dict:
    given = {k: getattr(args, k) for k in _FEM_OPTIONS if getattr(args, k) is not None}
    if args.solver == "fem":
        if "mesh" in given and "elements" in given:
            raise InputError("give either --mesh or --elements, not both")
        if "mesh" in given:
            import meshes

            given["mesh"] = meshes.read(given["mesh"])
        if "elements" in given:
            import meshes

            given["mesh"] = meshes.uniform(given.pop("elements"))
        return given
    if given:
        raise InputError(f"--{next(iter(given))} applies to --solver fem only")
    if args.rtol is None:
        return {}
    if args.solver != "shooting":
        raise InputError("--rtol applies to --solver shooting only")
    return {"rtol": check_positive("rtol", args.rtol)}


def _table(rows: list[dict]) -> str:
    keys = [k for k in rows[0] if k != "solver"]
    if len(rows) == 1:
        width = max(map(len, keys))
        return "\n".join(f"{k:<{width}}  {_fmt(rows[0][k])}" for k in keys)
    cols = [[k] + [_fmt(r[k]) for r in rows] for k in keys]
    widths = [max(map(len, col)) for col in cols]
    lines = ["  ".join(col[i].rjust(w) for col, w in zip(cols, widths, strict=True)) for i in range(len(rows) + 1)]
    return "\n".join(lines)


def _fmt(value) -> str:
    return f"{value:.10g}" if isinstance(value, float) else str(value)


def _run(args) -> tuple[list, bool]:
    solver = get_solver(args.solver)
    options = _options(args)
    if args.command == "inflate":
        return [solver.inflate(args.alpha, args.pressure, **options)], False
    states = solver.compression_curve(args.alpha, args.pressure, args.force, **options)
    return states, len(args.force) > 1


def _fail(err: PocketError) -> int:
    """One line on stderr; exit 1 for a solver failure, 2 for input outside the model."""
    print(f"pocket: error: {err}", file=sys.stderr)
    return 1 if isinstance(err, ConvergenceError) else 2


def main(argv=None) -> int:
    """Run the command line; returns the exit status.

    Output cut short by the reader (``pocket ... | head``) ends quietly with status 1
    (Python's documented recipe for SIGPIPE), an interrupt with one line and 130.
    """
    try:
        status = _main(argv)
        sys.stdout.flush()
        return status
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except KeyboardInterrupt:
        print("pocket: interrupted", file=sys.stderr)
        return 130


def _main(argv) -> int:
    args = _parser().parse_args(argv)
    if hasattr(args, "handler"):
        try:
            return args.handler(args)
        except PocketError as err:
            return _fail(err)
    try:
        states, curve = _run(args)
        if args.vtk:
            from .vtkfiles import write_series

            forces = [getattr(s, "force", 0.0) for s in states]
            increasing = all(a < b for a, b in itertools.pairwise(forces))
            write_series(args.vtk, states, times=forces if increasing else None,
                         overwrite=args.overwrite)
    except PocketError as err:
        return _fail(err)
    rows = [s.scalars() for s in states]
    if any(isinstance(v, float) and not math.isfinite(v) for row in rows for v in row.values()):
        print("pocket: error: a solver returned a non-finite value", file=sys.stderr)
        return 1
    if args.json:
        print(json.dumps(rows if curve else rows[0]))
    else:
        print(f"# solver: {rows[0]['solver']}")
        print(_table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
