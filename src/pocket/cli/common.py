"""What every ``pocket`` subcommand shares: the parser class, number parsing, solver flags, exit codes.

Exit status: 0 success; 1 a solver failed (the message says where), output
could not be written, or an internal error (a bug); 2 bad input, or a state
outside the model (past the end of its range, above a pressure maximum); 130
interrupted. Errors are one line on stderr.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import textwrap
from fractions import Fraction

from pocket.apps.solvers import SOLVERS, all_options, solver_options
from pocket.core.inputs import quote
from pocket.core.reported import reported
from pocket.core.units import KINDS, has_unit

__all__ = [
    "EXIT_CODES",
    "MODEL_UNITS",
    "PHYSICAL_UNITS",
    "HelpFormatter",
    "Parser",
    "add_solver_flags",
    "flag",
    "model_value",
    "number",
    "path_name",
    "physical_help",
    "progress_bar",
    "report",
    "solver_flags",
    "solvers_epilog",
    "warn",
]

EXIT_CODES = ("exit status: 0 success (also when the reader of the output stops early, as `| head` does); "
              "1 a solver failed (the message says where), output could not be "
              "written, or an internal error (a bug); 2 bad input or a state outside the model (one line on "
              "stderr, nothing written); 130 interrupted (Ctrl-C)")


class HelpFormatter(argparse.HelpFormatter):
    """Each option's help ends with its default, unless it names it already or has none to name; lines
    break at spaces only (never inside mooney-rivlin or neo-hookean)."""

    def _split_lines(self, text, width):
        return textwrap.wrap(" ".join(text.split()), width, break_on_hyphens=False)

    def _fill_text(self, text, width, indent):
        """Each line of ``text`` filled on its own (a list such as ``solvers_epilog``'s keeps its lines), an
        indented line's continuation indented further."""
        out = []
        for line in text.split("\n"):
            lead = indent + line[:len(line) - len(line.lstrip())]
            out.append(textwrap.fill(" ".join(line.split()), width, initial_indent=lead,
                                     subsequent_indent=lead + ("    " if lead != indent else ""),
                                     break_on_hyphens=False))
        return "\n".join(out)

    def _get_help_string(self, action):
        text = action.help or ""
        if action.default in (None, False, argparse.SUPPRESS) or "default" in text or action.nargs == 0:
            return text
        return f"{text} (default: %(default)s)"


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors and exit status 2 (argparse would print the usage too), and
    help that shows the defaults (``HelpFormatter``)."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", HelpFormatter)
        super().__init__(*args, **kwargs)

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


#: what the help of a command in physical units says of its values
PHYSICAL_UNITS = ("Dimensional values carry their unit ('20 mm', '1 MPa', '0.67 N'); a plain number is read as SI "
                  "(m, Pa, N) and a warning naming the option says so.")
#: what the help of a command in the model's units says of its values
MODEL_UNITS = ("Every value is a number in the model's units (each option names its own); a value with a unit "
               "('8 mm') is refused: pocket run, design and sense take physical values.")

#: kind -> an example with its unit, for the help of an option in physical units
_EXAMPLES = {"length": "20 mm", "pressure": "1 MPa", "force": "0.67 N"}


def number(text: str) -> float:
    """A float or a fraction such as 47/160 (one too large for a double is no number); text with a unit is
    refused as such (the option is a plain number)."""
    try:
        return float(Fraction(text)) if "/" in text else float(text)
    except (ValueError, ZeroDivisionError, OverflowError):
        if has_unit(text):
            raise argparse.ArgumentTypeError(f"{quote(text)} has a unit, but this option is a plain number") from None
        raise argparse.ArgumentTypeError(f"{quote(text)} is not a number") from None


def path_name(text: str) -> str:
    """A file or folder name as given (the argparse type of every option that names one): empty or blank text
    names nothing (as a path it would be the current folder, which no option means) and is refused."""
    if not text.strip():
        raise argparse.ArgumentTypeError(f"{quote(text)} is empty, but it must name a file or folder")
    return text


def model_value(command: str, wants: str):
    """The argparse type of a dimensional option of ``pocket command``, which works in the model's units:
    a ``number`` in the unit ``wants`` names (``"R_s/R"``); a value with a unit (``"8 mm"``) is refused in one
    line naming ``wants`` and the command that takes physical values."""

    def parse(text: str) -> float:
        if has_unit(text):
            raise argparse.ArgumentTypeError(f"{quote(text)} has a unit, but pocket {command} works in the model's "
                                             f"units: give {wants} (a number); pocket run takes physical values in "
                                             "a case file")
        return number(text)

    return parse


def physical_help(kind: str, example: str | None = None, noun: str | None = None) -> str:
    """The end of the help of an option in physical units, a quantity of ``kind`` (``noun``: another name for
    it, "stress"): ``"a length, e.g. '20 mm' (plain: m, with a warning)"``."""
    unit = KINDS[kind][1]
    return f"a {noun or kind}, e.g. '{example or _EXAMPLES[kind]}' (plain: {unit}, with a warning)"


def solvers_epilog(names=None, chosen_by: str = "--solver") -> str:
    """A command's epilog: what each solver of ``names`` (default all of ``SOLVERS``) is for, one line each from
    its record's summary, then ``EXIT_CODES``; ``chosen_by`` says how a user picks one."""
    names = tuple(names or SOLVERS)
    return "\n".join([f"solvers ({chosen_by}):", *(f"  {n}: {SOLVERS[n].summary}" for n in names), "", EXIT_CODES])


def flag(name: str) -> str:
    """The command-line spelling of an option name: ``--name``, its underscores as hyphens
    (``thickness_ratio``: ``--thickness-ratio``; argparse stores it under the name again)."""
    return "--" + name.replace("_", "-")


_TYPES = {"float": number, "int": int, "path": path_name}


def _shown(value) -> str:
    """A record's default as the help shows it (``1e-10``, ``1000``, ``true``)."""
    if isinstance(value, bool):
        return str(value).lower()
    return f"{value:g}" if isinstance(value, float) else str(value)


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
        text = option.help + ("" if len(owners) == 1 else f" (also {', '.join(s for s, _ in owners[1:])})")
        if option.default is not None and "default" not in text:  # argparse's default stays None: "not given"
            text += f" (default: {_shown(option.default)})"
        if option.kind == "bool":
            groups[solver].add_argument(flag(name), action=argparse.BooleanOptionalAction, default=None,
                                        help=text)
        elif option.kind == "choice":
            groups[solver].add_argument(flag(name), choices=option.choices, default=None, help=text)
        else:
            groups[solver].add_argument(flag(name), type=_TYPES[option.kind], default=None, help=text,
                                        metavar=option.kind.upper())


def solver_flags(args, solver: str, step: str) -> dict:
    """The solver options given on the command line, checked against ``solver`` for ``step``."""
    given = {name: getattr(args, name) for name in all_options() if getattr(args, name, None) is not None}
    return solver_options(solver, given, step, flag)


@contextlib.contextmanager
def progress_bar(what: str, unit: str):
    """A ``progress(done, total)`` callback drawing a bar (tqdm) on stderr if it is a terminal, else None."""
    if not sys.stderr.isatty():
        yield None
        return
    from tqdm import tqdm

    with tqdm(desc=what, unit=unit, file=sys.stderr, leave=False, dynamic_ncols=True) as bar:

        def progress(done: int, total: int) -> None:
            bar.total = total
            bar.update(done - bar.n)
            if done == total:
                bar.refresh()  # the last count is shown even if it came within tqdm's refresh interval

        yield progress


def report(state) -> dict:
    """A state as JSON and tables show it: its scalars, then its ``warnings`` (a list); each key one of
    ``pocket.core.reported``'s (a ``KeyError`` for one that is not)."""
    out = {**state.scalars(), "warnings": list(state.warnings)}
    for key in out:
        reported(key)
    return out


def warn(states) -> None:
    """Print the warnings of ``states`` (and of the inflated states they start from, but an uninflated capsule's
    unstressed sphere) on stderr, each once, as ``pocket: warning: ...`` lines."""
    seen = []
    for state in states:
        # an uninflated capsule's inflated state is the unstressed sphere, tension-free by definition: not a warning
        inflated = getattr(state, "inflated", None) if getattr(state, "pressure_initial", None) != 0.0 else None
        for text in (*getattr(inflated, "warnings", ()), *state.warnings):
            if text not in seen:
                seen.append(text)
    for text in seen:
        print(f"pocket: warning: {text}", file=sys.stderr)
