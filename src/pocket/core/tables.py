"""CSV tables whose header names each column with its unit: ``radius [mm],height [mm]``.

The one reader of such files (an indenter's profile, a bulge test's data): ``rows`` reads the file
(UTF-8, at most ``MAX_BYTES``, blank lines skipped) into lists of cells; ``heading`` splits a header
cell ``name [unit]`` into its name and unit, refusing a cell without a unit in one line. Converting
the unit is the caller's (``pocket.core.units.quantity``), which knows the quantity it expects.

Files as spreadsheets write them are read as meant: a UTF-8 byte-order mark (Excel's "CSV UTF-8"
starts the file with one) is dropped; the separator is the one of ``SEPARATORS`` the header line
uses most (a European Excel writes ``;``, a copied table tabs), and with a separator other than a
comma, a number's decimal comma (``1,5``) is its decimal point: there a comma can separate nothing else.
"""

from __future__ import annotations

import csv
import io
import pathlib
import re

from .errors import InputError

__all__ = ["MAX_BYTES", "SEPARATORS", "heading", "rows"]

#: largest table file read (bytes): a bound on the work a file can ask for
MAX_BYTES = 1_000_000

#: the cell separators read, the comma first (it wins a tie)
SEPARATORS = (",", ";", "\t")
_DECIMAL_COMMA = re.compile(r"^\s*[+-]?\d*,\d+(?:[eE][+-]?\d+)?\s*$")
_HEADING = re.compile(r"^\s*(?P<name>[^\[\]]*?)\s*\[(?P<unit>[^\[\]]*)\]\s*$")


def rows(path, what: str) -> list[list[str]]:
    """The non-blank rows of the CSV file ``path`` as lists of cells, read as a spreadsheet saves it (module
    docstring: a byte-order mark dropped, the header's separator, decimal commas); an unreadable, oversized or
    non-UTF-8 file is an InputError naming ``path`` and ``what`` the file should be ("a profile table")."""
    path = pathlib.Path(path)
    try:
        if path.stat().st_size > MAX_BYTES:
            raise InputError(f"{path}: larger than {MAX_BYTES} bytes, too large for {what}")
        text = path.read_bytes().decode("utf-8").removeprefix("\ufeff")  # a byte-order mark says nothing here
    except OSError as err:
        raise InputError(f"{path}: cannot read {what} ({err.strerror})") from None
    except UnicodeDecodeError as err:
        raise InputError(f"{path}: not a UTF-8 text file (byte {err.start}), so not {what}") from None
    header = next((line for line in text.splitlines() if line.strip()), "")
    separator = max(SEPARATORS, key=header.count)  # the first of the most used: a comma unless another is used more
    table = [r for r in csv.reader(io.StringIO(text), delimiter=separator) if any(cell.strip() for cell in r)]
    if separator == ",":
        return table
    return [[cell.replace(",", ".") if _DECIMAL_COMMA.match(cell) else cell for cell in r] for r in table]


def heading(where: str, text: str, example: str) -> tuple[str, str]:
    """(name, unit) of the header cell ``text``, ``"height [mm]"`` -> ("height", "mm"); a cell without a
    unit in brackets is an InputError naming ``where`` and showing ``example`` (a header to write)."""
    match = _HEADING.match(text)
    if match is None or not match["unit"].strip():
        raise InputError(f"{where} has no unit: write the header like {example!r}")
    return match["name"].strip(), match["unit"].strip()
