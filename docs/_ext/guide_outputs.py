"""The reported keys and columns, from the one table pocket's writers look them up in.

``pocket.core.reported`` holds the model's keys by group, ``pocket.apps.columns`` the columns the applications
add (SI values, a case's load, a sweep's record) and the rule for a rubber's stresses in units of mu_0.
"""

from __future__ import annotations

from guide_markdown import HEADER, cell, code, table

from pocket.apps import columns
from pocket.apps.sweep.journal import COLUMNS as SWEEP_COLUMNS
from pocket.core import reported


def _rows(entries: dict) -> list[tuple[str, str, str]]:
    return [(code(key), code(entry.unit), cell(entry.meaning)) for key, entry in entries.items()]


def units() -> str:
    """The units every key and column is given in."""
    return HEADER + table(("unit", "what it is"), [(code(u), cell(text)) for u, text in columns.UNITS.items()])


def model_keys() -> str:
    """The model's keys, one table per group, under a heading each."""
    out = [HEADER]
    for group, entries in reported.GROUPS.items():
        out += [f"### The {group}\n", table(("key", "unit", "meaning"), _rows(entries))]
    return "\n".join(out)


def si_columns() -> str:
    """The applications' columns, then the rubber's stresses in units of mu_0."""
    stresses = {name: columns.column(columns.parameter_column(name))
                for name in reported.REPORTED if name in columns.STRESSES}
    return (HEADER + table(("column", "unit", "meaning"), _rows(columns.COLUMNS)) + "\n"
            + "The rubber's stresses, in units of its small-strain shear modulus mu_0 (Gent's `jm`, Ogden's "
              "`exponents` and the `prestretch` are plain numbers under their own names):\n\n"
            + table(("column", "unit", "meaning"),
                    [(code(columns.parameter_column(n)), code(e.unit), cell(e.meaning)) for n, e in stresses.items()]))


def sweep_columns() -> str:
    """A sweep file's header, in order, each column with its unit."""
    return HEADER + table(("column", "unit", "meaning"),
                          [(code(c), code(columns.column(c).unit), cell(columns.column(c).meaning))
                           for c in SWEEP_COLUMNS])


def vtk_codes() -> str:
    """The codes a VTK file's field data gives the names of its solver, rubber law and fluid."""
    from pocket.apps.vtk.files import CODES

    rows = [(code(field), cell(", ".join(f"{i} {name}" for i, name in enumerate(names)))) for field, names in
            CODES.items()]
    return HEADER + table(("field", "code: name"), rows)
