"""The ``pocket`` command: ``main(argv)`` builds the parser and maps errors to exit codes.

Each subcommand lives in a module of ``COMMANDS`` with ``register(subparsers)``,
which adds its parser with ``set_defaults(handler=f)``, ``f(args) -> int`` the
exit status. They share the error handling here: a ``PocketError`` is one line
on stderr, status 1 for a solver failure (``ConvergenceError``) or output that
cannot be written (``OutputError``), 2 for bad input or a state outside the
model (``pocket.cli.common.EXIT_CODES``). Any other exception is a bug in pocket:
one line (``pocket: internal error: ...``) and status 1, or its traceback when
the environment sets ``POCKET_TRACEBACK``.
"""

from __future__ import annotations

import importlib
import os
import sys

from pocket.apps.provenance import described
from pocket.core import interrupts
from pocket.core.errors import PocketError, exit_status

from .common import EXIT_CODES, Parser

__all__ = ["COMMANDS", "main"]

#: modules adding subcommands, in the order of ``pocket --help``
COMMANDS = ("pocket.cli.solve", "pocket.cli.run", "pocket.cli.fit", "pocket.cli.design", "pocket.cli.sense",
            "pocket.cli.sweep",
            "pocket.cli.validate")


def _parser() -> Parser:
    parser = Parser(prog="pocket", description="Mechanics of pressurised elastic pockets: a clamped rubber "
                    "sheet inflated by a fluid and pressed by a flat plate (Bouremel et al., 'Compression of "
                    "pressurised elastic pockets').", epilog=EXIT_CODES)
    parser.add_argument("--version", action="version", version=f"pocket {described()}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=Parser, metavar="COMMAND")
    for name in COMMANDS:
        importlib.import_module(name).register(sub)
    return parser


def _interrupted(err: BaseException | None) -> bool:
    """Whether ``err`` wraps a KeyboardInterrupt: a signal that arrives while numba's compiled code runs
    surfaces as "SystemError: ... returned a result with an exception set", caused by the interrupt."""
    seen = set()
    while err is not None and id(err) not in seen:
        if isinstance(err, KeyboardInterrupt):
            return True
        seen.add(id(err))
        err = err.__cause__ or err.__context__
    return False


def main(argv=None) -> int:
    """Run the command line; returns the exit status (also for ``--help``, ``--version`` and usage
    errors, which argparse ends with SystemExit).

    Output cut short by the reader (``pocket ... | head``) ends quietly with status 0, as a command
    whose reader has all it wanted (Python's documented recipe for SIGPIPE, without its status 1,
    which would fail a passing run under ``set -o pipefail``); an interrupt ends with one line and 130,
    also one that Python could not raise where it landed (``pocket.core.interrupts``), at the latest
    when the command returns.
    """
    with interrupts.remembered():
        return _run(argv)


def _run(argv) -> int:
    """``main`` within ``interrupts.remembered()``."""
    try:
        try:
            args = _parser().parse_args(argv)
        except SystemExit as stop:
            sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's last flush
            return stop.code if isinstance(stop.code, int) else 2
        try:
            status = args.handler(args)
            interrupts.check()
        except PocketError as err:
            print(f"pocket: error: {err}", file=sys.stderr)
            return exit_status(err)
        except (BrokenPipeError, KeyboardInterrupt):
            raise
        except Exception as err:  # a bug: one line, unless its traceback is asked for
            if _interrupted(err):  # Ctrl-C inside compiled code comes back wrapped in a SystemError
                raise KeyboardInterrupt from err
            interrupts.check()  # a failure that followed an interrupt Python could not raise
            if os.environ.get("POCKET_TRACEBACK"):
                raise
            print(f"pocket: internal error: {type(err).__name__}: {' '.join(str(err).split())} (a bug in pocket: "
                  "please report it with the command; POCKET_TRACEBACK=1 shows where)", file=sys.stderr)
            return 1
        sys.stdout.flush()
        return status
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # the interpreter's last flush
        return 0
    except KeyboardInterrupt:
        print("pocket: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
