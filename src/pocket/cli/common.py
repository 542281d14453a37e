"""What every ``pocket`` subcommand shares: the parser class, number parsing, solver flags, exit codes.

Exit status: 0 success; 1 a solver failed (the message says where) or output
could not be written; 2 bad input, or a state outside the model (past the end
of its range, above a pressure maximum). Errors are one line on stderr.
"""

from __future__ import annotations

import argparse
from fractions import Fraction

from pocket.apps.solvers import all_options, solver_options

__all__ = ["EXIT_CODES", "Parser", "number", "add_solver_flags", "solver_flags", "flag"]

EXIT_CODES = ("exit status: 0 success; 1 a solver failed (the message says where) or output could not be "
              "written; 2 bad input or a state outside the model (one line on stderr, nothing written)")


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors and exit status 2 (argparse would print the usage too)."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


def number(text: str) -> float:
    """A float or a fraction such as 47/160."""
    try:
        return float(Fraction(text)) if "/" in text else float(text)
    except (ValueError, ZeroDivisionError):
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None


def flag(name: str) -> str:
    """The command-line spelling of an option name: ``--name``."""
    return f"--{name}"


_TYPES = {"float": number, "int": int, "path": str, "choice": str}


def add_solver_flags(parser, step: str) -> None:
    """A flag per solver option (``pocket.apps.solvers``) that ``step`` uses, in one group per solver."""
    groups = {}
    for name, owners in all_options().items():
        owners = [(solver, option) for solver, option in owners if step in option.steps]
        if not owners:
            continue
        solver, option = owners[0]
        if solver not in groups:
            groups[solver] = parser.add_argument_group(f"{solver} options (with --solver {solver})")
        text = f"{option.help}" + ("" if len(owners) == 1 else f" (also {', '.join(s for s, _ in owners[1:])})")
        if option.kind == "bool":
            groups[solver].add_argument(flag(name), action=argparse.BooleanOptionalAction, default=None,
                                        help=text)
        else:
            groups[solver].add_argument(flag(name), type=_TYPES[option.kind], default=None, help=text,
                                        metavar=option.kind.upper())


def solver_flags(args, solver: str, step: str) -> dict:
    """The solver options given on the command line, checked against ``solver`` for ``step``."""
    given = {name: getattr(args, name) for name in all_options() if getattr(args, name, None) is not None}
    return solver_options(solver, given, step, flag)
