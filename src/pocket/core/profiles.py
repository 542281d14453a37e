r"""A user's indenter profile z(rho): a table of heights, or functions, with a slope and a curvature.

The profile is convex and axisymmetric, z(rho) >= 0 with z(0) = 0 and z'(0) = 0 (flat on the axis),
lengths in units of the clamp radius R. It is defined for 0 <= rho <= ``extent``; beyond it its
height, slope and second derivative are NaN (as a sphere's past its equator).

Interpolating a table
---------------------
A profile flat on the axis and smooth is an even function of rho, so it is a smooth function of
s = rho^2: z(rho) = g(rho^2). The table (rho_i, z_i) is interpolated by the cubic spline g through
(s_i, z_i) (not-a-knot ends), and

    z(rho) = g(s),   z'(rho) = 2 rho g'(s),   z''(rho) = 2 g'(s) + 4 s g''(s).

Interpolating in s rather than rho makes z even: z'(0) = 0 exactly, whatever the table, and z''
exists everywhere (a spline in rho would need an end condition to be flat at the axis, and would
be flat only to the spline's accuracy). A fitted even polynomial would be as smooth, but a sphere's
g(s) = R_s - sqrt(R_s^2 - s) has a branch point at s = R_s^2, so a polynomial of fixed degree
converges slowly near the equator, and its error depends on the degree chosen, not on the table.

Its error: for g with a bounded fourth derivative, a cubic spline's error on rows spaced at most
h apart in s is (Hall & Meyer, J. Approx. Theory 16, 1976, for the complete spline)

    |g - S| <= 5/384 h^4 M,   |g' - S'| <= 1/24 h^3 M,   |g'' - S''| <= 3/8 h^2 M,   M = max|g''''|,

and the not-a-knot spline has the same orders, its end intervals at most a few times those constants
(measured on a sphere: 2.1 times): the height is exact to O(h^4), the slope z' = 2 rho g' to O(h^3)
and the curvature to O(h^2). A table of n rows evenly spaced in rho up to rho_max has
h ~ 2 rho_max^2 / n: 40 rows of a fingertip sphere (R_s = 0.4 R) up to rho = 0.3 R give heights to
1e-7 R, slopes to 1e-4 and curvatures to 0.5 %.

The checks
----------
A table must have at least ``MIN_ROWS`` rows, radii increasing from 0, heights z >= 0 with z = 0 on
the first row, convex (the slopes of successive chords do not decrease, to ``CONVEX_TOLERANCE``
of the largest), and flat on the axis: the tip slope b of the curve z = b rho + c rho^2 through
the first three rows must stay within ``FLAT_TOLERANCE`` of the mean slope z_2 / rho_2 (a cone's tip
has b = z_2 / rho_2, a smooth profile's b = O(rho_1 rho_2)). The interpolated profile is then
checked convex on a fine grid. A CSV table has a header naming its columns with their units,
``radius [mm],height [mm]`` (pint units; ``[R]`` for units of the clamp radius), and one row of
numbers per line.
"""

from __future__ import annotations

import dataclasses
import hashlib
import pathlib
from collections.abc import Callable

import numpy as np

from .errors import InputError
from .tables import MAX_BYTES, heading
from .tables import rows as _rows
from .units import is_plain, quantity

__all__ = [
    "CONVEX_TOLERANCE",
    "FLAT_TOLERANCE",
    "MAX_BYTES",
    "MIN_ROWS",
    "Shape",
    "functions",
    "read_csv",
    "table",
]

#: fewest rows of a table: the three of the flatness check and one more for the cubic spline's ends
MIN_ROWS = 4
#: a chord slope may fall below the one before by this fraction of the largest slope (rounded tables)
CONVEX_TOLERANCE = 1e-6
#: the tip slope b may be this fraction of the mean slope z_2/rho_2 (a cone's is 1, a smooth tip's O(rho_1))
FLAT_TOLERANCE = 0.05
#: points per row on which the interpolated profile is checked convex
_CHECKS = 8


@dataclasses.dataclass(frozen=True, eq=False)
class Shape:
    """A profile: ``height``, ``slope`` and ``second`` map radii rho (float array of any shape, units R)
    to z, dz/drho and d2z/drho2 of the same shape, NaN past ``extent`` (units R). ``source`` names it
    in messages (a file, or "a function"). ``knots``: the radii (units R, increasing) where d3z/drho3
    jumps, a table's rows (an ODE integrator keeps its order by stopping there); none for functions.
    ``digest``: a table's content, the SHA-256 (hex) of its radii and heights in units of R as float64
    bytes, so that two tables of the same numbers are recognised as one profile wherever they were read
    from (a sweep's record); empty for functions, whose content cannot be read. ``pieces``: a table's
    spline g(s) as (breakpoints s_i = rho_i^2, shape (n,); coefficients c, shape (4, n - 1)), so that on
    s_i <= s <= s_(i+1) g(s) = sum_k c[k, i] (s - s_i)^(3 - k) (scipy's ``PPoly`` layout): compiled code
    evaluates the same spline from them; None for functions. Compared by identity (a cache key)."""

    height: Callable[[np.ndarray], np.ndarray]
    slope: Callable[[np.ndarray], np.ndarray]
    second: Callable[[np.ndarray], np.ndarray]
    extent: float
    source: str
    knots: tuple[float, ...] = ()
    digest: str = ""
    pieces: tuple[np.ndarray, np.ndarray] | None = None

    def __repr__(self) -> str:
        return f"Shape({self.source}, extent {self.extent:g} R)"


def _outside(extent: float, rho: np.ndarray, values: np.ndarray) -> np.ndarray:
    return np.where((rho >= 0.0) & (rho <= extent), values, np.nan)


def _check_convex(source: str, rho: np.ndarray, second: np.ndarray, slope: np.ndarray) -> None:
    """Refuse a profile whose second derivative is negative anywhere on the radii ``rho``."""
    scale = max(float(np.max(np.abs(slope))), 1e-300)
    bad = np.flatnonzero(second * max(float(rho[-1]), 1e-300) < -CONVEX_TOLERANCE * scale)
    if bad.size:
        raise InputError(f"{source}: the profile is not convex near radius {rho[bad[0]]:.6g} R "
                         f"(z'' = {second[bad[0]]:.3g}): an indenter must be convex")


@dataclasses.dataclass(frozen=True)
class _Spline:
    """z(rho) = g(rho^2) of the cubic spline ``g`` (module docstring), up to ``extent``; picklable, so that a
    case holding a profile table can go to a worker process."""

    g: object
    extent: float

    def height(self, r):
        return _outside(self.extent, r, self.g(np.square(r)))

    def slope(self, r):
        return _outside(self.extent, r, 2.0 * r * self.g(np.square(r), 1))

    def second(self, r):
        s = np.square(r)
        return _outside(self.extent, r, 2.0 * self.g(s, 1) + 4.0 * s * self.g(s, 2))


def table(radii, heights, source: str = "the profile table", written=None) -> Shape:
    """The profile interpolating a table of rows (radius, height), in units of R.

    A cubic spline in rho^2 (``pocket.core.profiles``), checked to be a profile: z(0) = 0, flat on the axis, convex.

    Parameters
    ----------
    radii, heights : sequence of float
        The rows, of equal length (at least ``MIN_ROWS``), radii increasing from 0, units R.
    source : str, optional
        The table's name in error messages.
    written : sequence of str, optional
        Each row's text as the file has it, quoted in error messages (else the row in units of R).

    Returns
    -------
    Shape

    Raises
    ------
    InputError
        For a table that is no profile, naming ``source`` and the row.

    Examples
    --------
    The paraboloid z = rho^2, tabulated, is interpolated within 1e-6 R:

    >>> import numpy as np
    >>> from pocket.core.profiles import table
    >>> rho = np.linspace(0.0, 0.5, 11)
    >>> shape = table(rho, rho**2)
    >>> print(shape.extent, abs(float(shape.height(0.33)) - 0.33**2) < 1e-6)
    0.5 True
    >>> table([0.0, 0.1, 0.2, 0.3], [0.0, 0.01, 0.0, 0.09])
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: the profile table: ...
    """
    from scipy.interpolate import CubicSpline

    rho, z = np.asarray(radii, dtype=float), np.asarray(heights, dtype=float)
    if rho.shape != z.shape or rho.ndim != 1:
        raise InputError(f"{source}: radii and heights must be two lists of the same length")

    def row(i: int) -> str:
        """Row ``i`` (from 0) as its message names it."""
        text = f"{rho[i]:g} R,{z[i]:g} R" if written is None else written[i]
        return f"row {i + 1} ({text!r})"

    if rho.size < MIN_ROWS:
        raise InputError(f"{source}: {rho.size} rows, but a profile needs at least {MIN_ROWS}")
    if not (np.all(np.isfinite(rho)) and np.all(np.isfinite(z))):
        raise InputError(f"{source}: {row(int(np.flatnonzero(~np.isfinite(rho + z))[0]))} is not finite")
    if rho[0] != 0.0:
        raise InputError(f"{source}: {row(0)} has a radius that is not 0, but a profile starts on the axis")
    if z[0] != 0.0:
        raise InputError(f"{source}: {row(0)} has a height that is not 0, but z(0) must be 0 (heights are from "
                         "the indenter's lowest point, on the axis)")
    steps = np.diff(rho)
    if np.any(steps <= 0.0):
        raise InputError(f"{source}: {row(int(np.flatnonzero(steps <= 0.0)[0]) + 1)}: the radii must increase")
    if np.any(z < 0.0):
        raise InputError(f"{source}: {row(int(np.flatnonzero(z < 0.0)[0]))} has a negative height, but "
                         "z >= 0 (the lowest point is on the axis)")
    chords = np.diff(z) / steps
    drops = np.flatnonzero(np.diff(chords) < -CONVEX_TOLERANCE * max(float(np.max(np.abs(chords))), 1e-300))
    if drops.size:
        raise InputError(f"{source}: not convex at {row(int(drops[0]) + 1)} (the slope falls from "
                         f"{chords[drops[0]]:.6g} to {chords[drops[0] + 1]:.6g}): an indenter must be convex")
    r1, r2, z1, z2 = rho[1], rho[2], z[1], z[2]
    tip = (z1 * r2**2 - z2 * r1**2) / (r1 * r2 * (r2 - r1))
    if tip > FLAT_TOLERANCE * z2 / r2:
        raise InputError(f"{source}: does not start flat on the axis (the first rows have a tip slope "
                         f"{tip:.3g}, {tip / (z2 / r2):.0%} of their mean slope): a profile must have z'(0) = 0")
    g = CubicSpline(rho**2, z)
    spline = _Spline(g, float(rho[-1]))
    extent = spline.extent
    height, slope, curve = spline.height, spline.slope, spline.second
    fine = np.linspace(0.0, extent, _CHECKS * rho.size)
    _check_convex(source + " (interpolated)", fine, curve(fine), slope(fine))
    digest = hashlib.sha256(np.ascontiguousarray([rho, z], dtype=np.float64).tobytes()).hexdigest()
    pieces = (np.asarray(g.x, dtype=np.float64), np.asarray(g.c, dtype=np.float64))
    return Shape(height, slope, curve, extent, source, tuple(map(float, rho)), digest, pieces)


def functions(height, slope, curvature, extent: float, source: str = "the profile function") -> Shape:
    """The profile of a user's functions z(rho), dz/drho and the meridional curvature, in units of R.

    Parameters
    ----------
    height, slope, curvature : callable
        z(rho), dz/drho and z'' / (1 + z'^2)^(3/2); each maps a float array of radii (units R) to an array of
        the same shape.
    extent : float
        The largest radius they are defined at, units R, > 0.
    source : str, optional
        The profile's name in error messages.

    Returns
    -------
    Shape

    Raises
    ------
    InputError
        Unless, checked on a grid, they are finite, z(0) = 0, z'(0) = 0, z >= 0 and convex.

    Examples
    --------
    The paraboloid z = rho^2:

    >>> import numpy as np
    >>> from pocket.core.profiles import functions
    >>> shape = functions(lambda r: r**2, lambda r: 2 * r, lambda r: 2 / (1 + 4 * r**2) ** 1.5, 0.5)
    >>> print(float(shape.height(0.3)), float(shape.second(0.3)))
    0.09 2.0
    """
    extent = float(extent)
    if not np.isfinite(extent) or extent <= 0.0:
        raise InputError(f"{source}: extent = {extent:g}, but it must be a positive radius (units R)")
    grid = np.linspace(0.0, extent, 257)
    z, dz, k = (np.asarray(fn(grid), dtype=float) for fn in (height, slope, curvature))
    if not all(v.shape == grid.shape and np.all(np.isfinite(v)) for v in (z, dz, k)):
        raise InputError(f"{source}: height, slope and curvature must give finite arrays of the radii's shape")
    if z[0] != 0.0 or dz[0] != 0.0:
        raise InputError(f"{source}: z(0) = {z[0]:g} and z'(0) = {dz[0]:g}, but a profile starts flat at 0")
    if np.any(z < 0.0):
        raise InputError(f"{source}: negative height at radius {grid[np.flatnonzero(z < 0.0)[0]]:.6g}")
    _check_convex(source, grid, k, dz)

    def second(r):
        return np.asarray(curvature(r), dtype=float) * (1.0 + np.square(slope(r))) ** 1.5

    return Shape(lambda r: _outside(extent, r, height(r)), lambda r: _outside(extent, r, slope(r)),
                 lambda r: _outside(extent, r, second(r)), extent, source)


def _unit(path, column: int, text: str, clamp_radius: float | None) -> float:
    """The factor turning column ``column``'s numbers into units of R, from its header ``text``."""
    where = f"{path}: column {column} ({text.strip()!r})"
    _, unit = heading(where, text, "radius [mm],height [mm]")
    if unit == "R":
        return 1.0
    key = f"{where} unit"
    one = f"1 {unit}"
    factor = quantity(key, one, "length")
    if is_plain(one):
        raise InputError(f"{where} has no length unit: write the header like 'radius [mm],height [mm]'")
    if clamp_radius is None:
        raise InputError(f"{where} is in {unit}, but a dimensionless command takes the profile in units of the "
                         "clamp radius: write the header like 'radius [R],height [R]'")
    return factor / clamp_radius


def read_csv(path, clamp_radius: float | None = None) -> Shape:
    r"""The profile of a CSV file: a header ``radius [unit],height [unit]`` and a row of two numbers per line.

    Parameters
    ----------
    path : str or path
        The file.
    clamp_radius : float, optional
        R in m, which makes the lengths dimensionless; units are pint lengths, or ``[R]`` for units of the clamp
        radius (then ``clamp_radius`` may be None).

    Returns
    -------
    Shape

    Raises
    ------
    InputError
        For an unreadable file, a missing unit, a row that is not two numbers, or a table that is no profile
        (``table``), naming the file, the row or the column.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.core.profiles import read_csv
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "cap.csv"
    ...     _ = path.write_text("radius [mm],height [mm]\n0,0\n1,0.05\n2,0.2\n3,0.45\n4,0.8\n")
    ...     shape = read_csv(path, clamp_radius=0.010)
    >>> print(shape.extent)
    0.4
    """
    path = pathlib.Path(path)
    rows = _rows(path, "the profile file")
    if not rows or len(rows[0]) != 2:
        raise InputError(f"{path}: the first line must name two columns with units, like 'radius [mm],height [mm]'")
    factors = [_unit(path, i + 1, cell, clamp_radius) for i, cell in enumerate(rows[0])]
    values, written = [], []
    for number, row in enumerate(rows[1:], start=1):
        try:
            if len(row) != 2:
                raise ValueError
            values.append([float(cell) * f for cell, f in zip(row, factors, strict=True)])
            written.append(",".join(row))
        except ValueError:
            raise InputError(f"{path}: row {number} is {','.join(row)!r}, but each row must be two numbers") from None
    data = np.array(values, dtype=float).reshape(-1, 2)
    return table(data[:, 0], data[:, 1], source=str(path), written=written)
