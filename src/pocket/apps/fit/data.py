"""A user's test data for a fit: CSV files read, checked and turned into SI arrays, before any solve.

Each file is one test of the clamped sheet, its header naming each column's quantity and unit
(``pocket.core.tables``):

- an **inflation** (bulge) test: ``pressure`` with ``height`` (the pole's rise above the clamp plane)
  and/or ``volume`` (the enclosed volume); the pressure is the control, strictly increasing and > 0;
- a **compression** test by the flat plate: ``force`` with ``pressure`` and optionally ``height`` (of
  the plate, the sheet's top); the force is the control (>= 0, no force twice), at the initial
  pressure P_I given (``initial_pressure``), or else read from the row at zero force.

The file is read as a spreadsheet saves it (``pocket.core.tables``: a byte-order mark ignored, ``;``
with decimal commas). Any other column, a column without a unit or of the wrong dimension, a cell
that is not a finite number, or a response that is not > 0 (a relative residual divides by it) is a
one-line ``InputError`` naming the file, the row or the column. The fluid is a liquid (the volume is fixed
under compression, so a volume column there says nothing and is refused).
"""

from __future__ import annotations

import dataclasses
import math
import pathlib

import numpy as np

from pocket.core.errors import InputError
from pocket.core.inputs import quote
from pocket.core.tables import heading, rows
from pocket.core.units import is_plain, quantity

__all__ = ["CONTROLS", "QUANTITIES", "Dataset", "check_forces", "columns", "read"]

#: column name -> the kind of quantity it holds (``pocket.core.units.KINDS``)
QUANTITIES = {"pressure": "pressure", "height": "length", "volume": "volume", "force": "force"}
#: test kind -> its control column (a capsule's compression: ``pocket.apps.fit.capsuledata``)
CONTROLS = {"inflation": "pressure", "compression": "force", "capsule": "force"}
_EXAMPLE = "pressure [kPa],height [mm]"


@dataclasses.dataclass(frozen=True)
class Dataset:
    r"""One test of the clamped sheet, in SI units (``read``).

    Attributes
    ----------
    kind : {"inflation", "compression", "capsule"}
        A bulge test (pressure controlled), a compression by the flat plate (force controlled), or a closed
        capsule's compression between two plates (force controlled, ``pocket.apps.fit.capsuledata``).
    control : numpy.ndarray
        The pressures in Pa or the forces in N, shape (n,).
    responses : dict
        Column name -> SI values of shape (n,), NaN where a row has no datum (the zero-force pressure that
        defines P_I).
    initial_pressure : float or None
        P_I in Pa; None for an inflation (and a capsule's test: its P_I is the fit's, given or fitted).
    source : str
        The file, for messages.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.apps.fit.data import read
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "press.csv"
    ...     _ = path.write_text("force [N],pressure [kPa]\n0,5\n0.5,5.6\n1,6.3\n")
    ...     test = read(path)
    >>> print(test.kind, test.control, test.initial_pressure, test.count)
    compression [0.  0.5 1. ] 5000.0 2
    """

    kind: str
    control: np.ndarray
    responses: dict[str, np.ndarray]
    initial_pressure: float | None
    source: str

    @property
    def count(self) -> int:
        """The number of data (finite responses) the test gives the fit."""
        return int(sum(np.count_nonzero(np.isfinite(v)) for v in self.responses.values()))


def _columns(path: pathlib.Path, header: list[str], quantities: dict, example: str) -> list[tuple[str, float]]:
    """(name, SI factor) of each header cell."""
    out: list[tuple[str, float]] = []
    for i, text in enumerate(header, start=1):
        where = f"{path}: column {i} ({text.strip()!r})"
        name, unit = heading(where, text, example)
        if name not in quantities:
            raise InputError(f"{where}: the fit cannot use a column {name!r} (it uses {', '.join(quantities)})")
        if name in (n for n, _ in out):
            raise InputError(f"{where}: a second {name!r} column")
        one = f"1 {unit}"
        factor = quantity(f"{where} unit", one, quantities[name])
        if is_plain(one):
            raise InputError(f"{where} has no {quantities[name]} unit: write the header like {example!r}")
        out.append((name, factor))
    return out


def _numbers(path: pathlib.Path, body: list[list[str]], columns) -> np.ndarray:
    values = np.empty((len(body), len(columns)))
    for number, row in enumerate(body, start=1):
        if len(row) != len(columns):
            raise InputError(f"{path}: row {number} is {','.join(row)!r}, but the header names {len(columns)} columns")
        for j, (cell, (name, factor)) in enumerate(zip(row, columns, strict=True)):
            try:
                value = float(cell)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise InputError(f"{path}: row {number}, {name} = {quote(cell.strip())} is not a finite number")
            values[number - 1, j] = value * factor
    return values


def _positive(path, name, values) -> None:
    bad = np.flatnonzero(~(values > 0.0))
    if bad.size:
        raise InputError(f"{path}: row {bad[0] + 1}, {name} = {values[bad[0]]:.6g} (SI), but it must be > 0")


def read(path, initial_pressure: float | None = None) -> Dataset:
    r"""A test of the clamped sheet from its CSV file, checked, in SI units.

    The header names each column's quantity and unit (``pressure [kPa],height [mm]``). An inflation (bulge)
    test has ``pressure`` with ``height`` and/or ``volume``; a compression test by the flat plate ``force`` with
    ``pressure`` and optionally ``height``.

    Parameters
    ----------
    path : str or path
        The CSV file, read as a spreadsheet saves it (a byte-order mark ignored, ``;`` with decimal commas).
    initial_pressure : float, optional
        P_I in Pa of a compression test (None: from its row at zero force); ignored for an inflation test.

    Returns
    -------
    Dataset

    Raises
    ------
    InputError
        For any other column, a column without a unit or of the wrong dimension, a cell that is not a finite
        number, a response that is not > 0, a control that does not increase; one line naming the file, the row
        or the column.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.apps.fit.data import read
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "bulge.csv"
    ...     _ = path.write_text("pressure [kPa],height [mm]\n6,6.04\n12,8.13\n18,10.0\n")
    ...     test = read(path)
    >>> print(test.kind, test.control, test.responses["height"])
    inflation [ 6000. 12000. 18000.] [0.00604 0.00813 0.01   ]
    """
    path = pathlib.Path(path)
    data = columns(path, QUANTITIES, _EXAMPLE)
    if "force" in data:
        return _compression(path, data, initial_pressure)
    return _inflation(path, data)


def columns(path, quantities: dict, example: str) -> dict[str, np.ndarray]:
    """The columns of a test's CSV file ``path``: name -> its values in SI, shape (n,), in the header's order.

    ``quantities`` maps each column name the test may have to its kind (``pocket.core.units.KINDS``);
    ``example`` is a header to show in errors. A missing header or unit, a column not in ``quantities`` or
    given twice, a unit of another kind, a row of another length or a cell that is not a finite number is an
    InputError naming the file and the column or row (``read``)."""
    path = pathlib.Path(path)
    table = rows(path, "a test's CSV data")
    if not table:
        raise InputError(f"{path}: empty, but the first line must name the columns with units, like {example!r}")
    named = _columns(path, table[0], quantities, example)
    if len(table) < 2:
        raise InputError(f"{path}: a header and no rows of data")
    values = _numbers(path, table[1:], named)
    return {name: values[:, j] for j, (name, _) in enumerate(named)}


def _inflation(path, data) -> Dataset:
    if "pressure" not in data or not ({"height", "volume"} & set(data)):
        raise InputError(f"{path}: an inflation test needs a pressure column and a height or volume column "
                         f"(a compression test a force column): write the header like {_EXAMPLE!r}")
    pressure = data.pop("pressure")
    _positive(path, "pressure", pressure)
    steps = np.flatnonzero(np.diff(pressure) <= 0.0)
    if steps.size:
        raise InputError(f"{path}: row {steps[0] + 2}, pressure = {pressure[steps[0] + 1]:.6g} Pa is not above the "
                         f"row before ({pressure[steps[0]]:.6g} Pa): an inflation test's pressures must increase")
    for name, v in data.items():
        _positive(path, name, v)
    return Dataset("inflation", pressure, data, None, str(path))


def check_forces(path, force: np.ndarray, test: str) -> None:
    """Refuse the forces (N) of a force-controlled ``test`` ("a compression test") in ``path`` that are not >= 0 or
    not each its own: an InputError naming the row."""
    bad = np.flatnonzero(~(force >= 0.0))
    if bad.size:
        raise InputError(f"{path}: row {bad[0] + 1}, force = {force[bad[0]]:.6g} N, but it must be >= 0")
    if np.unique(force).size != force.size:
        raise InputError(f"{path}: a force given twice, but each row of {test} needs its own force")


def _compression(path, data, initial_pressure) -> Dataset:
    if "pressure" not in data:
        raise InputError(f"{path}: a compression test (a force column) needs a pressure column, like "
                         "'force [N],pressure [kPa]'")
    if "volume" in data:
        raise InputError(f"{path}: the fit cannot use a volume column in a compression test (the liquid's "
                         "volume is fixed while the plate presses)")
    force = data.pop("force")
    check_forces(path, force, "a compression test")
    for name, v in data.items():
        _positive(path, name, v)
    zero = np.flatnonzero(force == 0.0)
    pressure = data["pressure"].copy()
    if initial_pressure is None:
        if not zero.size:
            raise InputError(f"{path}: a compression test needs its initial pressure: give --initial-pressure or "
                             "a row at zero force")
        initial_pressure = float(pressure[zero[0]])
        pressure[zero[0]] = math.nan  # it defines P_I: not a datum
    elif not initial_pressure > 0.0:
        raise InputError(f"initial pressure = {quote(initial_pressure)} Pa, but it must be > 0")
    return Dataset("compression", force, {**data, "pressure": pressure}, float(initial_pressure), str(path))
