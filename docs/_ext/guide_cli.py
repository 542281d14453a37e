"""The command line, from the parser ``pocket`` itself builds (``pocket.cli.main``): every subcommand, its
usage, each option as ``--help`` shows it (its default included), and the exit statuses.
"""

from __future__ import annotations

import argparse
import contextlib
import os

from guide_markdown import HEADER, cell, code, table

from pocket.cli.common import EXIT_CODES
from pocket.cli.main import _parser
from pocket.core import errors

#: the width usage lines and epilogs are wrapped to: the page's code blocks, whatever terminal builds the docs
WIDTH = "76"


@contextlib.contextmanager
def _columns():
    """argparse wraps to the terminal's width (COLUMNS): a fixed one while the page is written."""
    old = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = WIDTH
    try:
        yield
    finally:
        if old is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = old


def _commands(parser) -> list[tuple[str, str, argparse.ArgumentParser]]:
    """(name, one-line help, parser) of each subcommand, in ``pocket --help``'s order."""
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    helps = {choice.dest: choice.help for choice in action._choices_actions}
    return [(name, helps.get(name, ""), sub) for name, sub in action.choices.items()]


def _options(sub: argparse.ArgumentParser) -> str:
    """A table per argument group of ``sub``: each argument as ``--help`` spells it, and its help."""
    formatter = sub._get_formatter()
    out = []
    for group in sub._action_groups:
        actions = [a for a in group._group_actions if a.help is not argparse.SUPPRESS]
        if not actions:
            continue
        rows = [(code(formatter._format_action_invocation(a)), cell(formatter._expand_help(a) if a.help else ""))
                for a in actions]
        described = f": {cell(group.description)}" if group.description else ""
        out += [f"*{cell(group.title)}*{described}\n", table(("argument", "meaning"), rows)]
    return "\n".join(out)


def _exit_statuses() -> str:
    """Each error of ``pocket.core.errors`` with the status ``exit_status`` gives it."""
    kinds = (errors.InputError, errors.OutOfRangeError, errors.ConvergenceError, errors.OutputError,
             errors.ClusterError)
    rows = [(code(errors.exit_status(kind("x"))), code(kind.__name__), cell(kind.__doc__.splitlines()[0]))
            for kind in sorted(kinds, key=lambda k: errors.exit_status(k("x")))]
    return table(("status", "error", "when"), rows)


def exit_codes() -> str:
    """The exit statuses: ``--help``'s sentence, then the table of errors."""
    return HEADER + f"{EXIT_CODES[0].upper() + EXIT_CODES[1:]}.\n\n" + _exit_statuses()


def page() -> str:
    """Every subcommand under a heading: what it is for, its usage, its arguments, its epilog."""
    with _columns():
        parser = _parser()
        out = [HEADER, "`pocket --version` prints the version; every subcommand takes `-h` / `--help`.\n"]
        for name, summary, sub in _commands(parser):
            out.append(f"\n### `pocket {name}`\n")
            if summary and not (sub.description or "").startswith(summary):
                out.append(f"{cell(summary[0].upper() + summary[1:])}.\n")
            out.append(f"```text\n{sub.format_usage().strip()}\n```\n")
            if sub.description:
                out.append(f"{cell(sub.description[0].upper() + sub.description[1:])}\n")
            out.append(_options(sub))
            if sub.epilog:
                out.append(f"```text\n{sub._get_formatter()._fill_text(sub.epilog, int(WIDTH), '')}\n```\n")
    return "\n".join(out)


def solvers() -> str:
    """Each solver's record: its summary, what it computes (its entry points) and its options."""
    from pocket.apps.solvers import SOLVERS
    from pocket.core.solver import ENTRY_POINTS

    rows = [(code(s.name), cell(s.summary), cell("; ".join(ENTRY_POINTS[e] for e in s.entry_points)),
             ", ".join(code(f"--{o.name.replace('_', '-')}") for o in s.options) or "none")
            for s in SOLVERS.values()]
    return HEADER + table(("solver", "what it is", "what it computes", "options"), rows)


def ranges() -> str:
    """The input ranges checked before anything is solved, from the constants the checks use."""
    from pocket.apps.cases import MAX_LOADS
    from pocket.apps.sweep.grid import MAX_POINTS
    from pocket.core import inputs, sizes, units
    from pocket.core.fluids import GAMMA_RANGE
    from pocket.core.indenters import SPHERE_RADII
    from pocket.core.materials import EXPONENT_RANGE, JM_RANGE, PRESTRETCH_LIMIT

    def g(x: float) -> str:
        return f"{x:.3g}".replace("e+0", "e").replace("e+", "e").replace("e-0", "e-")

    low, high = inputs.MAGNITUDES
    rows = [
        ("a pressure Phat or Phat_atm, a penalty", f"{g(low)} to {g(high)}"),
        ("a force Fhat", f"0 to {g(high)}"),
        ("Mooney-Rivlin's alpha = C2 / C1", f"above -1, at most {g(high)}"),
        ("the prestretch lambda_p", f"1 to {PRESTRETCH_LIMIT:g}"),
        ("Gent's Jm", f"at least {g(JM_RANGE[0])}"),
        ("an Ogden exponent's \\|alpha_p\\|", f"{EXPONENT_RANGE[0]:g} to {EXPONENT_RANGE[1]:g}"),
        ("a gas's gamma", f"{GAMMA_RANGE[0]:g} to 5/3"),
        ("a sphere's K = R_s / R", f"{g(SPHERE_RADII[0])} to {g(SPHERE_RADII[1])}"),
        ("a volume V / R^3 (volume control)", f"at most {g(inputs.VOLUME_LIMIT)}"),
        ("a length in physical units", f"{g(sizes.SIZES[0])} m to {g(sizes.SIZES[1])} m"),
        ("any physical value, in SI", f"nonzero magnitudes {g(units.MAGNITUDES[0])} to {g(units.MAGNITUDES[1])}"),
        ("the sheet's T / R for a membrane solver", f"a warning above {sizes.THIN_WARNING:g}, refused from "
                                                   f"{sizes.THIN_LIMIT:g}"),
        ("the loads of a case file", f"at most {MAX_LOADS}"),
        ("the points of a sweep", f"at most {MAX_POINTS}"),
    ]
    return HEADER + table(("input", "range"), [(r[0], cell(r[1])) for r in rows])
