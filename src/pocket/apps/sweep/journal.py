"""The sweep file: one CSV row per grid point, appended while a sweep runs (``pocket.apps.sweep.grid``).

Columns (``COLUMNS``), named as ``pocket.apps.columns`` says (all dimensionless): the keys of a
compressed state (``CompressedState.KEYS``; ``contact_radius`` the Lagrangian a_c / R), the contact
patch (``CONTACT``: ``contact_radius_deformed`` rho_c / R, the contact edge's distance from the axis
in the deformed sheet, and the contact pressure at the pole and at the edge, ``contact_pressure_pole``
and ``contact_pressure_edge`` in units of Phat, P on the flat plate; ``pocket.apps.contactpatch``), the
solver and its options (``solver_options``: ``name=value`` separated by spaces, in name order, as
given; empty for the solver's defaults), a ``status`` (``STATUSES``) and a one-line ``message``; then
the rubber (``material``, the law's name, and a column per parameter of every law, empty where the
law has no such parameter, its stresses in units of mu_0: ``c1_per_mu0``, ``mu_per_mu0``, ...;
Mooney-Rivlin's is ``alpha``, so its rows leave ``c1_per_mu0`` and ``c2_per_mu0`` empty; Ogden's
lists are numbers separated by spaces; a sheet clamped with a prestretch lambda_p != 1 has
``material`` = ``<law> prestretch=<lambda_p>``, so the files of sheets without one keep their
columns and cells), the fluid (``fluid``, and a gas's ``ambient`` Phat_atm and ``gamma``), the
indenter (``indenter``: ``plate``, ``sphere K=...`` with K = R_s / R, or ``profile sha256=...`` for
a profile table), the membrane's checks (``tension_1_min``, ``tension_2_min``, ``wrinkled``), and the membrane
(``geometry``: ``pocket``, the flat clamped sheet, or ``capsule``). A capsule's point also fills its own keys
(``CAPSULE``: ``stretch_pole``, ``radius_equator`` in units of its radius R, ``force_ETR`` = F / (E T R), after the
contact patch; empty for a pocket), and its other keys are a capsule's (``pocket.core.reported``: F on each plate,
``height`` each plate's distance from the equatorial plane, ``volume`` the whole capsule's).
Floats are written exactly (``repr``), so a point reads back equal to the number asked.

A point is its solver and options, rubber, fluid, indenter, geometry, Phat_I and Fhat (``key``; an uninflated
capsule's, at Phat_I = 0, has no Fhat, and its ``force`` and ``pressure_ratio`` cells are empty: its force is
``force_ETR``): a file
may hold points of several sweeps, of several solvers and indenters, and a rerun recognises its own
and keeps every row it reads, so nothing of the file is lost: a line that is not a row of one, or a
second row of one point, is refused before any work. A file of an earlier pocket, whose rows lack
some of these columns, is refused, saying what it holds.

``Journal`` opens a sweep file for a sweep: it refuses, untouched, a file that
is not a sweep file (``InputError``), takes an advisory POSIX lock so that one
sweep at a time writes it, reads back its complete rows (a line cut off by a
sudden end of an earlier run is left out, and written over), and appends one
complete row per finished point. Writes are unbuffered: what a failed write
leaves is on the disk, where ``close(failed=True)`` cuts it off again, never in
a buffer that a later flush would retry. A write that fails is an
``OutputError`` saying how many points the file keeps.
"""

from __future__ import annotations

import collections
import csv
import errno
import io
import os
import pathlib
import stat

from pocket.core.errors import InputError, OutputError
from pocket.core.fluids import Fluid
from pocket.core.geometries import DISC, Geometry
from pocket.core.indenters import PLATE, Indenter
from pocket.core.materials import Material
from pocket.core.states import CHECKS, CompressedState

from ..columns import documented, in_mu0, parameter_column
from ..contactpatch import KEYS
from ..folders import created_parents, remove_created
from ..rubbers import PARAMETERS

try:
    import fcntl
except ImportError:  # not a POSIX system: no lock
    fcntl = None  # type: ignore[assignment]

__all__ = ["CAPSULE", "COLUMNS", "CONTACT", "IDENTITY", "STATUSES", "Journal", "identity", "key", "line",
           "options_text", "rows_csv"]

#: what identifies a point besides alpha, Phat_I and Fhat: its solver, rubber, fluid and indenter
IDENTITY = ("solver", "solver_options", "material", *map(parameter_column, PARAMETERS), "fluid", "ambient", "gamma",
            "indenter", "geometry")
#: the contact patch of a point: its deformed radius and contact pressures (``pocket.apps.contactpatch``)
CONTACT = ("contact_radius_deformed", *KEYS)
#: a capsule's own keys (its states' ``extra``, ``pocket.core.reported``'s group capsule), empty for a pocket
CAPSULE = ("stretch_pole", "radius_equator", "force_ETR")
COLUMNS = (*CompressedState.KEYS, *CONTACT, *CAPSULE, "solver", "solver_options", "status", "message", *IDENTITY[2:],
           *CHECKS)
STATUSES = ("ok", "out_of_range", "failed")
_NUMBERS = ("alpha", "pressure_initial", "force")


def line(text) -> str:
    """``text`` on one line (a CSV cell that never spans lines)."""
    return " ".join(str(text).split())


def _cell(value) -> str:
    """A number exactly (``repr``), a list of numbers separated by spaces."""
    return " ".join(map(repr, value)) if isinstance(value, tuple) else repr(float(value))


def _option(name: str, value) -> str:
    if isinstance(value, bool):
        return f"{name}={str(value).lower()}"
    if isinstance(value, (int, float, str)):
        return f"{name}={value!r}" if isinstance(value, float) else f"{name}={value}"
    raise InputError(f"a sweep records its solver's options as text: give {name} as a number or a file name")


def options_text(options: dict) -> str:
    """The ``solver_options`` cell of a sweep's solver ``options`` (checked; the fluid, the indenter and the
    geometry are not ones)."""
    return " ".join(_option(name, options[name]) for name in sorted(options)
                    if name not in ("fluid", "indenter", "geometry"))


def identity(solver: str, options: dict, material: Material, fluid: Fluid, indenter: Indenter = PLATE,
             geometry: Geometry = DISC) -> dict:
    """The IDENTITY cells (text) of a point: ``solver`` its name and ``options`` its options (as
    ``options_text``), ``material`` a ``Material`` (its stresses written in units of mu_0, ``in_mu0``; a
    Mooney-Rivlin rubber given by its alpha: that alpha has its own column, and the parameters' cells stay
    empty), ``fluid`` a ``Fluid``, ``indenter`` as its ``journal`` (``pocket.core.indenters``), ``geometry`` by
    its name."""
    cells = dict.fromkeys(IDENTITY, "")
    law = material.law if material.prestretch == 1.0 else f"{material.law} prestretch={material.prestretch!r}"
    cells.update(solver=solver, solver_options=options_text(options), material=law, indenter=indenter.journal(),
                 geometry=geometry.name)
    if material.exact_alpha is None:
        cells.update({parameter_column(name): _cell(value) for name, value in in_mu0(material).params})
    cells.update({k: v if isinstance(v, str) else repr(v) for k, v in fluid.describe().items()})
    return cells


def key(row) -> tuple:
    """The point of a row: its IDENTITY cells (solver, options, rubber, fluid, indenter, geometry), then alpha (None for
    another law), Phat_I and Fhat; an uninflated capsule's (Phat_I = 0, no Fhat) F / (E T R), ``force_ETR``."""
    alpha, pressure, force = (row[k] for k in _NUMBERS)
    if float(pressure) == 0.0:
        force = row["force_ETR"]
    return (*(row[k] for k in IDENTITY), None if alpha in ("", None) else float(alpha), float(pressure),
            float(force))


def rows_csv(rows, *, header=False) -> bytes:
    """``rows`` (dicts of COLUMNS) as CSV bytes, after the header if ``header``; every column is one of pocket's
    documented columns (``pocket.apps.columns.documented``)."""
    documented(COLUMNS)
    text = io.StringIO(newline="")
    writer = csv.DictWriter(text, COLUMNS, lineterminator="\n")
    if header:
        writer.writeheader()
    writer.writerows(rows)
    return text.getvalue().encode("utf-8")


_HEADER = rows_csv([], header=True)
_RUBBER_FLUID = ("material", *PARAMETERS, "fluid", "ambient", "gamma")  # as earlier pockets named them
#: headers of earlier pockets, and what their rows lack
_EARLIER = {
    ",".join((*CompressedState.KEYS, "solver", "status", "message")).encode() + b"\n":
        "the solver's options, the rubber and the fluid",
    ",".join((*CompressedState.KEYS, "solver", "status", "message", *_RUBBER_FLUID, *CHECKS)).encode() + b"\n":
        "the solver's options and the indenter",
    ",".join((*CompressedState.KEYS, "solver", "solver_options", "status", "message", *_RUBBER_FLUID,
              *CHECKS)).encode() + b"\n": "the indenter (they were all pressed by the flat plate)",
    ",".join((*CompressedState.KEYS, "solver", "solver_options", "status", "message", *_RUBBER_FLUID, "indenter",
              *CHECKS)).encode() + b"\n": "the contact patch's deformed radius and contact pressures",
    ",".join((*CompressedState.KEYS, *CONTACT, "solver", "solver_options", "status", "message", *IDENTITY[2:-1],
              *CHECKS)).encode() + b"\n": "the membrane's geometry (they are all pockets) and a capsule's keys",
}


def _not_a_sweep(path, why) -> InputError:
    return InputError(f"{path} exists but is not a sweep file ({why}); give another --out file")


def _parse(data: bytes, path) -> tuple[dict, int]:
    """The complete rows of the sweep file ``data`` by point, and their length in bytes.

    An empty file, or the start of the header alone, has no rows; a cut last line is left out.
    """
    if _HEADER.startswith(data):
        return {}, 0
    end = data.rfind(b"\n") + 1
    try:
        text = data[:end].decode("utf-8")
    except UnicodeDecodeError:
        raise _not_a_sweep(path, "it is not UTF-8 text") from None
    lines = csv.reader(io.StringIO(text, newline=""))
    next(lines)  # the header, checked by Journal
    rows: dict = {}
    lines_of: dict = {}
    for number, values in enumerate(lines, start=2):
        row = dict(zip(COLUMNS, values, strict=False))
        try:
            if len(values) != len(COLUMNS) or row["status"] not in STATUSES:
                raise ValueError
            point = key(row)
        except ValueError:
            raise _not_a_sweep(path, f"line {number} is not a row of one") from None
        if point in rows:
            raise InputError(f"{path}: line {number} repeats the point of line {lines_of[point]} (pocket writes each "
                             "point once, and a rerun would keep one of them only); give another --out file")
        rows[point], lines_of[point] = row, number
    return rows, end


def _holds(path) -> str:
    """What the sweep file ``path`` of an earlier pocket holds: its complete rows by solver."""
    with open(path, newline="", encoding="utf-8", errors="replace") as file:
        data = file.read()
    rows = list(csv.DictReader(io.StringIO(data[: data.rfind("\n") + 1], newline="")))
    solvers = collections.Counter(row.get("solver") or "?" for row in rows)
    points = ", ".join(f"{n} of solver {name}" for name, n in sorted(solvers.items()))
    return f"{len(rows)} points" + (f": {points}" if points else "")


class Journal:
    """A sweep file, locked and opened for appending rows (module docstring); ``rows`` maps each
    point to its row, ``path`` is the file."""

    def __init__(self, path: pathlib.Path):
        self.path, self.made, self.locked = path, created_parents(path), False
        self.end: int | None = None  # bytes of complete rows, once the file is read (then never None)
        try:
            for folder in self.made:
                folder.mkdir(exist_ok=True)
            try:
                fd, self.created = os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666), True
            except FileExistsError:
                fd, self.created = os.open(path, os.O_RDWR), False
        except OSError as err:
            remove_created(self.made)
            raise OutputError(f"cannot write {path}: {err.strerror or err}") from None
        self.file = io.FileIO(fd, "r+")
        try:
            if not stat.S_ISREG(os.fstat(fd).st_mode):
                raise InputError(f"{path} is not a regular file, so not a sweep file; give another --out file")
            self._lock()
            self.rows, self.end = _parse(self._read(), path)
        except BaseException:
            self.close(failed=True)
            raise

    def _read(self) -> bytes:
        """The file's bytes, once its start is known to be (a prefix of) the header."""
        start = self.file.read(len(_HEADER))
        if not (_HEADER.startswith(start) if len(start) < len(_HEADER) else start == _HEADER):
            for header, lacks in _EARLIER.items():
                if start.startswith(header):  # each shorter than today's header
                    raise InputError(f"{self.path} is a sweep file of an earlier pocket ({_holds(self.path)}), "
                                     f"whose rows do not record {lacks}, so this sweep cannot resume it; give "
                                     "another --out file")
            first = start.split(b"\n", 1)[0][:80].decode("utf-8", errors="replace")
            raise _not_a_sweep(self.path, f"its first line starts {line(first)!r}")
        return start + self.file.readall()

    def _lock(self) -> None:
        if fcntl is not None:
            try:  # a POSIX record lock: held by this process only, not by the workers it forks
                fcntl.lockf(self.file.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError as err:
                if err.errno not in (errno.EACCES, errno.EAGAIN):
                    raise OutputError(f"cannot lock {self.path}: {err.strerror or err}") from None
                raise InputError(f"{self.path}: another pocket sweep is writing this file; wait for it to "
                                 "finish or give another --out file") from None
            if os.fstat(self.file.fileno()).st_ino != os.stat(self.path).st_ino:
                raise InputError(f"{self.path}: another pocket sweep has just rewritten this file; run again")
        self.locked = True

    def _write(self, data: bytes) -> None:
        assert self.end is not None  # the file was read when it was opened
        try:
            self.file.truncate(self.end)  # a line cut by an earlier run
            self.file.seek(self.end)
            view = memoryview(data)
            while view:
                view = view[self.file.write(view):]
        except OSError as err:
            raise OutputError(f"cannot write {self.path}: {err.strerror or err}; it keeps the {len(self.rows)} "
                              "points finished before, and the same command resumes the sweep") from None
        self.end += len(data)

    def append(self, row: dict) -> None:
        """Add one finished point (the header first if the file is new)."""
        self._write((_HEADER if self.end == 0 else b"") + rows_csv([row]))
        self.rows[key(row)] = row

    def close(self, *, failed: bool) -> None:
        """Close the file; after a failure cut it back to its complete rows, or remove it if this
        sweep created it and finished no point (only if the lock was ours: the file is then this sweep's)."""
        try:
            if failed and self.end is not None:
                self.file.truncate(self.end)
        except OSError:
            pass  # the rows written stay complete; a cut line is ignored by the next run
        finally:
            self.file.close()
        if failed and self.created and self.locked and not self.end:
            self.path.unlink(missing_ok=True)
            remove_created(self.made)
