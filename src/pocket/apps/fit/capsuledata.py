r"""A micromanipulation test of a closed capsule: its CSV file read, checked and turned into SI arrays.

The test squeezes a closed capsule (undeformed radius R) between two parallel plates and records the force F
on each plate with the plates' position, as one of two columns:

- ``gap``: the distance between the plates, 2 H R (H the plate's height above the capsule's equatorial plane
  in units of R, as the solvers report it); at zero force the untouched capsule's, 2 lambda_I R;
- ``displacement``: how far the plates have come together since first touch (the probe's travel against the
  fixed base of a micromanipulation rig, which is the gap's fall): 2 lambda_I R - gap. It is 0 at first touch,
  so a row at zero force must have 0 (it defines the origin and is not a datum) and every other is >= 0.

The header names each column's quantity and unit (``force [uN],gap [um]``), read as for the tests of the
clamped sheet (``pocket.apps.fit.data.columns``: any unit pint knows, a spreadsheet's ``;`` and decimal
commas). The force is the control (>= 0, no force twice); the gap (or displacement) is the response, the fit's
datum. Any other column, both a gap and a displacement, no row above zero force, a gap that is not > 0 or a
displacement < 0 is a one-line ``InputError`` naming the file, the row or the column.

Units gone wrong (``check``), from the radius R alone, before any solve. No rubber stretches ``MAX_STRETCH``
times (``pocket.apps.fit.checks``). The gap is at most the length of the deformed meridian from one plate's
contact to the other's, at most ``MAX_STRETCH`` times the reference half circle pi R: gap <= pi MAX_STRETCH R,
and a displacement is less than that gap. At least: the liquid's volume V = 4/3 pi lambda_I^3 R^3 >= 4/3 pi R^3
(an inflated capsule, lambda_I >= 1) lies between the plates, and any closed surface of area A between two
planes a gap g apart encloses at most g A / 2 (V = the flux of (0, 0, z) through it, |z| <= g / 2 from the
mid-plane), with A <= MAX_STRETCH^2 4 pi R^2 (no area element stretches more): gap >= 2 R / (3 MAX_STRETCH^2).
A gap outside these bounds is in the wrong unit, or R is.
"""

from __future__ import annotations

import math
import pathlib

import numpy as np

from pocket.core.errors import InputError

from . import checks
from .checks import MAX_STRETCH
from .data import Dataset, check_forces, columns
from .model import Setup

__all__ = ["COLUMNS", "EXAMPLE", "QUANTITIES", "check", "read"]

#: column name -> the kind of quantity it holds (``pocket.core.units.KINDS``)
QUANTITIES = {"force": "force", "gap": "length", "displacement": "length"}
#: the response columns, of which a test has one
COLUMNS = ("gap", "displacement")
#: a header to show in errors
EXAMPLE = "force [uN],gap [um]"
#: the gap's bounds in units of R (module docstring)
_WIDEST, _NARROWEST = math.pi * MAX_STRETCH, 2.0 / (3.0 * MAX_STRETCH**2)


def read(path) -> Dataset:
    r"""A capsule's micromanipulation test from its CSV file, checked, in SI units.

    Parameters
    ----------
    path : str or path
        The CSV file: a ``force`` column and a ``gap`` or ``displacement`` column, each with its unit in the header
        (module docstring).

    Returns
    -------
    Dataset
        ``kind`` "capsule", ``control`` the forces in N, ``responses`` {"gap": m} or {"displacement": m} (NaN in a
        displacement's zero-force rows: they define its origin), ``initial_pressure`` None.

    Raises
    ------
    InputError
        For a missing or extra column, a cell that is not a finite number, a negative force or one given twice,
        no force above zero, a gap not > 0, a displacement < 0 or not 0 at zero force; one line naming the file,
        the row or the column.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.apps.fit.capsuledata import read
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "squeeze.csv"
    ...     _ = path.write_text("force [uN],gap [um]\n0,101.2\n2,96.5\n5,90.1\n")
    ...     test = read(path)
    >>> print(test.kind, test.control * 1e6, test.responses["gap"] * 1e6)
    capsule [0. 2. 5.] [101.2  96.5  90.1]
    """
    path = pathlib.Path(path)
    data = columns(path, QUANTITIES, EXAMPLE)
    given = [name for name in COLUMNS if name in data]
    if "force" not in data or len(given) != 1:
        what = "both a gap and a displacement column" if len(given) > 1 else \
            "no force column" if "force" not in data else "no gap or displacement column"
        raise InputError(f"{path}: {what}, but a capsule's test has a force column and a gap (or displacement) "
                         f"column, like {EXAMPLE!r}")
    force, name = data["force"], given[0]
    values = data[name].copy()
    check_forces(path, force, "a capsule's test")
    if not np.any(force > 0.0):
        raise InputError(f"{path}: no row with a force above 0, so nothing is squeezed")
    if name == "gap":
        bad = np.flatnonzero(~(values > 0.0))
        if bad.size:
            raise InputError(f"{path}: row {bad[0] + 1}, gap = {values[bad[0]]:.6g} m, but it must be > 0")
    else:
        bad = np.flatnonzero(~(values >= 0.0) | ((force == 0.0) & (values != 0.0)))
        if bad.size:
            i = bad[0]
            raise InputError(f"{path}: row {i + 1}, displacement = {values[i]:.6g} m at force = {force[i]:.6g} N, "
                             "but it is counted from first touch, where the force is 0: it must be 0 there and "
                             ">= 0 beyond")
        values[force == 0.0] = math.nan  # the origin, not a datum
    return Dataset("capsule", force, {name: values}, None, str(path))


def check(setup: Setup, spell=lambda name: f"--sigma {name}") -> None:
    """Refuse ``setup``'s capsule tests where a gap or displacement beside the radius R, or a stated uncertainty,
    can only be in a wrong unit (module docstring): an InputError naming the file and column, or the uncertainty
    (named by ``spell(column)``, as ``pocket.apps.fit.checks.check``)."""
    radius = setup.radius
    for test in setup.tests:
        for name, values in test.responses.items():
            top, bottom = float(np.nanmax(values)), float(np.nanmin(values))
            if top > _WIDEST * radius:
                raise InputError(f"{test.source}: the {name} column reaches {top:.4g} m, {top / radius:.3g} R on a "
                                 f"capsule of radius R = {radius:.4g} m, but no rubber stretches far enough for a "
                                 f"{name} above pi {MAX_STRETCH:g} R = {_WIDEST:.4g} R: its unit (or the radius's) "
                                 "is wrong")
            if name == "gap" and bottom < _NARROWEST * radius:
                raise InputError(f"{test.source}: the gap column falls to {bottom:.4g} m, {bottom / radius:.3g} R on "
                                 f"a capsule of radius R = {radius:.4g} m, but no rubber stretches far enough to hold "
                                 f"its liquid in a gap below 2 R / (3 x {MAX_STRETCH:g}^2) = {_NARROWEST:.3g} R: its "
                                 "unit (or the radius's) is wrong")
    checks.check(setup, spell, slack=False, quantities=QUANTITIES)
