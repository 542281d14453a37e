"""Force sensing: the force on a pocket from its measured pressure (``pocket sense``).

The paper's conclusion: the applied force can be inferred from the pressure
rise. The pressure ratio q = P/P_I grows monotonically with the force on the
model's first branch, so the force is the root Fhat of q(Fhat) = q_measured
(``pocket.apps.inverse.force_where``), solved on the forward solver to its
resolution: no fitted curve and no extrapolation. A pressure below P_I, or
above what the model reaches before the free part of the sheet meets the
clamp plane, is an OutOfRangeError quoting the pressure as given and the bound
in its unit.

With F = Fhat P_I pi R^2 and P = q P_I, the sensitivity is
dP/dF = (dq/dFhat) / (pi R^2) (reported in kPa/N, as sensor makers quote it) and its inverse
dF/dP (N/Pa), dq/dFhat by ``pocket.apps.slopes``. The contact area is the curved area in
contact (F / P on the flat plate), the travel H0 - H how far the indenter's lowest point has
gone down from the top of the inflated dome.

At rest (F -> 0) the sensitivity follows from the inflated pocket alone, by reciprocity
(Maxwell-Betti): the pressure P and the volume V, the force F and the indenter's descent -H,
are conjugate pairs, so dV/dF at fixed P equals -dH0/dP at fixed F, and keeping the fluid's
volume (V(P, F) = V_fluid(P)) gives

    dP/dF = (dH0/dP) / (dV0/dP + V / (gamma (P + P_atm)))

for any indenter touching at the pole; the second term, the gas's compliance, is absent for a
liquid (``sensitivity_at_rest``, dH0/dP and dV0/dP by central differences of inflations). A capsule is
pressed by two plates, each with F: the displacement conjugate to F is the gap's closing, twice each plate's
descent, so its dP/dF is twice that ratio (V0 the whole capsule's, H0 its pole's height above the equator).

The linearity over a force range is the largest deviation of P(F) from the best straight line
(the line that makes the largest deviation smallest, "independent linearity"), in % of the
full-scale output max P - min P over the range (``linearity``).

Pressures are gauge pressures, as P_I is: the pressure in the pocket above
the ambient pressure.

A gas-filled pocket (a case's ``[fluid]``) is the barometric touch sensor: its gas
is compressed as well, (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma, and the
forward solver holds that law, so the same inversion applies. Its pressure rise
also grows monotonically with the force (checked over the whole range in the
tests, isothermal and adiabatic); it is smaller than a liquid's at moderate
forces and, near the end of the range, larger (the liquid stretches the contact
zone more).
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np

from pocket.core.errors import InputError, OutOfRangeError, PocketError
from pocket.core.geometries import DISC, Symmetry
from pocket.core.inputs import check_count, check_finite, quote
from pocket.core.units import quantity, written_like

from .forcerange import check_force
from .inverse import force_where, range_end
from .physical import Pocket
from .slopes import curve_with_slopes
from .solvers import entry

__all__ = [
    "MAX_POINTS",
    "Reading",
    "calibration",
    "force_range",
    "linearity",
    "range_linearity",
    "sense",
    "sensitivity_at_rest",
]

#: most rows of a calibration table (a bound on the work it asks for)
MAX_POINTS = 10_000


@dataclasses.dataclass(frozen=True)
class Reading:
    """A force reading of a pocket: SI values carry their unit in the name.

    Attributes
    ----------
    force_N, pressure_Pa : float
        The force F and the (gauge) pressure P.
    pressure_ratio : float
        P / P_I.
    contact_area_m2 : float
        The curved area in contact (F / P on the flat plate).
    sensitivity_N_per_Pa, sensitivity_kPa_per_N : float
        dF/dP and dP/dF there.
    travel_m : float
        H0 - H, the indenter's descent from the top of the inflated dome.
    force : float
        Fhat = F / (P_I pi R^2).
    rubber : tuple
        The state's rubber and fluid as (key, value) pairs: material, its parameters (units of mu_0), fluid, a
        gas's ambient (Phat_atm) and gamma.

    Examples
    --------
    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.physical import resolve
    >>> from pocket.apps.sense import sense
    >>> row = sense(resolve(sample(1)), pressure="5 kPa").row()
    >>> print(list(row)[:4], row["material"])
    ['force_N', 'pressure_Pa', 'pressure_ratio', 'contact_area_m2'] mooney-rivlin
    """

    force_N: float
    pressure_Pa: float
    pressure_ratio: float  # P / P_I
    contact_area_m2: float
    sensitivity_N_per_Pa: float  # dF/dP
    sensitivity_kPa_per_N: float  # dP/dF
    travel_m: float  # H0 - H, the indenter's descent from the top of the inflated dome
    force: float
    rubber: tuple = ()  # the state's rubber and fluid as (key, value) pairs: material, its parameters
    # (units of mu_0), fluid, a gas's ambient (Phat_atm) and gamma

    def row(self) -> dict:
        """The reading as a flat dict (JSON- and CSV-ready): its numbers, then the rubber and the fluid."""
        out = {f.name: getattr(self, f.name) for f in dataclasses.fields(self) if f.name != "rubber"}
        return {**out, **dict(self.rubber)}


def _inflated(pocket: Pocket) -> None:
    """An InputError for an uninflated capsule (P_I = 0): the readings are in units of P_I, and its force of Fhat."""
    if pocket.uninflated:
        key = f"initial.{pocket.case.initial[0]}"
        raise InputError(f"{key} = {quote(pocket.case.as_given(key))} gives P_I = 0, an uninflated capsule: sensing "
                         "reads a pressure's rise over P_I (P / P_I) and a force in units of P_I pi R^2, which it "
                         "has not")


def _readings(pocket: Pocket, fhats) -> list[Reading]:
    states, slopes = curve_with_slopes(pocket.solver(), pocket.material, pocket.pressure_initial, fhats,
                                       ["pressure_ratio"], **pocket.options())
    area = math.pi * pocket.case.radius**2
    return [Reading(force_N=s.force * pocket.force_scale_N, pressure_Pa=s.pressure_ratio * pocket.pressure_initial_Pa,
                    pressure_ratio=s.pressure_ratio, contact_area_m2=s.contact_area * area,
                    sensitivity_N_per_Pa=float(area / slope),
                    sensitivity_kPa_per_N=float(slope * pocket.pressure_initial_Pa / pocket.force_scale_N / 1e3),
                    travel_m=float((s.inflated.height - s.height) * pocket.case.radius), force=s.force,
                    rubber=tuple({**s.material.describe(), **s.fluid.describe()}.items()))
            for s, slope in zip(states, slopes["pressure_ratio"], strict=True)]


def _beyond(pocket: Pocket, what: str, given) -> OutOfRangeError:
    """A measured pressure past the model's range, with the highest pressure it reaches (in the unit
    of ``given``) where the end of the range can be located."""
    top = ""
    try:
        solver, options = pocket.solver(), pocket.options()
        end = range_end(solver, pocket.material, pocket.pressure_initial, **options)
        q = entry(solver, "compress", what)(pocket.material, pocket.pressure_initial, end, **options).pressure_ratio
        top = f" (it reaches {written_like(q * pocket.pressure_initial_Pa, given, 'pressure')}, P/P_I = {q:.6g})"
    except PocketError:  # the reason stands without the number
        pass
    why = ("the free part of the sheet would fold onto the clamp plane first" if pocket.case.geometry == DISC else
           "the capsule's range ends first")
    return OutOfRangeError(f"{what} is beyond the model's range{top}: {why}")


def sense(pocket: Pocket, *, pressure=None, ratio=None) -> Reading:
    """The force on a pocket from its measured pressure, or pressure ratio.

    The root Fhat of P/P_I(Fhat) = the measured ratio, on the forward solver to its resolution: no fitted curve
    and no extrapolation.

    Parameters
    ----------
    pocket : Pocket
        The pocket (``pocket.apps.physical.resolve`` of a case).
    pressure : float or str, optional
        The measured gauge pressure P (Pa, or a string with unit).
    ratio : float, optional
        The measured P / P_I, instead of ``pressure``.

    Returns
    -------
    Reading

    Raises
    ------
    InputError
        For neither or both of ``pressure`` and ``ratio``, or a value that is not a pressure.
    OutOfRangeError
        For a pressure below P_I, or past the model's range, quoting it as given.

    Examples
    --------
    Sample 1 of the paper's Table 1, inflated at 4.81275 kPa, reads 5 kPa:

    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.physical import resolve
    >>> from pocket.apps.sense import sense
    >>> pocket = resolve(sample(1))
    >>> reading = sense(pocket, pressure="5 kPa")
    >>> print(f"F = {reading.force_N:.4f} N, travel {reading.travel_m * 1e3:.4f} mm")
    F = 0.1515 N, travel 0.5542 mm

    Pressed by that force, the pocket's pressure is 5 kPa:

    >>> from pocket import shooting
    >>> state = shooting.compress(pocket.material, pocket.pressure_initial, reading.force)
    >>> print(round(state.pressure * pocket.pressure_scale_Pa, 6))
    5000.0
    """
    _inflated(pocket)
    if (pressure is None) == (ratio is None):
        raise InputError("give either a pressure or a pressure ratio, not both or neither")
    if pressure is not None:
        q = quantity("pressure", pressure, "pressure") / pocket.pressure_initial_Pa
        what = f"pressure = {quote(pressure)}"
    else:
        q = check_finite("ratio", ratio)
        what = f"pressure ratio = {quote(ratio)}"
    if q < 1.0:
        raise OutOfRangeError(f"{what} is below its value with no force (P_I = "
                              f"{written_like(pocket.pressure_initial_Pa, pressure, 'pressure')}, ratio 1): "
                              "a plate can only push")
    try:
        fhat = force_where(pocket.solver(), pocket.material, pocket.pressure_initial, "pressure_ratio", q,
                           increasing=True, **pocket.options())
    except OutOfRangeError:
        raise _beyond(pocket, what, pressure) from None
    return _readings(pocket, [fhat])[0]


def calibration(pocket: Pocket, max_force, points: int = 21, *, key: str = "max_force") -> list[Reading]:
    """Readings at ``points`` forces evenly spaced from 0 to ``max_force``: a sensor's calibration table.

    Parameters
    ----------
    pocket : Pocket
        The pocket (``pocket.apps.physical.resolve`` of a case).
    max_force : float or str
        The largest force (N, or a string with unit).
    points : int, optional
        The number of readings, at least 2.
    key : str, optional
        The name of ``max_force`` in error messages.

    Returns
    -------
    list of Reading

    Raises
    ------
    InputError
        For an invalid force or count.
    OutOfRangeError
        For a ``max_force`` past the end of the model's range, naming ``key`` and quoting the end in the unit of
        ``max_force``.

    Examples
    --------
    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.physical import resolve
    >>> from pocket.apps.sense import calibration
    >>> table = calibration(resolve(sample(1)), "1 N", points=3)
    >>> print([(r.force_N, round(r.pressure_Pa)) for r in table])
    [(0.0, 4813), (0.5, 5435), (1.0, 6050)]
    """
    _inflated(pocket)
    points = check_count("points", points, 2, MAX_POINTS)
    top = quantity(key, max_force, "force")
    if not top > 0.0:
        raise InputError(f"{key} = {quote(max_force)}, but it must be > 0")
    return _readings(pocket, np.linspace(0.0, check_force(pocket, key, max_force, top / pocket.force_scale_N), points))


_INFLATION_STEP = 1e-4  # relative step of the central differences of sensitivity_at_rest (as slopes')


def sensitivity_at_rest(pocket: Pocket) -> float:
    """dP/dF at F -> 0, by reciprocity, from the inflated pocket alone.

    dP/dF = (dH0/dP) / (dV0/dP + V / (gamma (P + P_atm))) (``pocket.apps.sense``; the gas's compliance absent for
    a liquid), dH0/dP and dV0/dP by central differences of inflations at P_I (1 +- 1e-4): truncation ~1e-8 and
    round-off ~1e-7 relative for a solver resolving ~1e-11. The same for any indenter touching at the pole;
    twice it for a capsule, pressed by two plates that each descend by dH.

    Parameters
    ----------
    pocket : Pocket
        The pocket (``pocket.apps.physical.resolve`` of a case).

    Returns
    -------
    float
        dP/dF in kPa/N.

    Examples
    --------
    It is the slope of the pressure-force curve at its start, which the calibration computes from compressions:

    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.physical import resolve
    >>> from pocket.apps.sense import calibration, sensitivity_at_rest
    >>> pocket = resolve(sample(1))
    >>> at_rest = sensitivity_at_rest(pocket)
    >>> print(round(at_rest, 4), abs(at_rest / calibration(pocket, "1 N", 3)[0].sensitivity_kPa_per_N - 1) < 1e-5)
    1.2114 True
    """
    _inflated(pocket)
    solver = pocket.solver()
    inflate = entry(solver, "inflate", "the sensitivity at rest")
    phat, h = pocket.pressure_initial, _INFLATION_STEP * pocket.pressure_initial
    low, high = (inflate(pocket.material, p, **pocket.options("inflate")) for p in (phat - h, phat + h))
    dheight, dvolume = (high.height - low.height) / (2 * h), (high.volume - low.volume) / (2 * h)
    fluid = pocket.fluid
    if fluid.is_gas:  # the gas's compliance -dV_fluid/dP at P_I, in the same units (R^3 per Phat)
        volume = inflate(pocket.material, phat, **pocket.options("inflate")).volume
        dvolume += volume / (fluid.gamma * (phat + fluid.ambient))
    plates = 2.0 if isinstance(pocket.case.geometry.end, Symmetry) else 1.0  # a capsule's gap closes by 2 dH
    return float(plates * dheight / dvolume / pocket.case.radius**2 / 1e3)  # Pa/N: (R dHhat) / (R^3 dVhat)


def _hull(x, y, sign) -> list[int]:
    """Indices of the lower (``sign`` 1) or upper (-1) convex hull of the points (x sorted), left to right."""
    out: list[int] = []
    for i in range(len(x)):
        while len(out) >= 2:
            (a, b) = out[-2], out[-1]
            cross = (x[b] - x[a]) * (y[i] - y[a]) - (y[b] - y[a]) * (x[i] - x[a])
            if sign * cross > 0.0:
                break
            out.pop()
        out.append(i)
    return out


def linearity(forces, pressures) -> float:
    """The largest deviation of pressures from their best straight line in the forces, in % of the full scale.

    The best line makes the largest deviation smallest ("independent linearity"): its deviation is half the
    smallest vertical width of the points, max(P - b F) - min(P - b F) minimised over the slope b, a convex
    piecewise linear function of b whose corners are the slopes of the edges of the points' convex hull.

    Parameters
    ----------
    forces : array_like
        Shape (n,), n >= 2, any unit.
    pressures : array_like
        Shape (n,), any unit.

    Returns
    -------
    float
        The deviation in % of max - min of ``pressures``.

    Raises
    ------
    InputError
        For fewer than two points, arrays of different shapes, or values that are not finite.

    Examples
    --------
    A straight line deviates by nothing; a parabola by an eighth of its rise:

    >>> from pocket.apps.sense import linearity
    >>> print(linearity([0, 1, 2], [1, 3, 5]), linearity([0, 1, 2, 3, 4], [0, 1, 4, 9, 16]))
    0.0 12.5
    """
    x, y = (np.asarray(v, dtype=float) for v in (forces, pressures))
    order = np.argsort(x, kind="stable")
    x, y = x[order], y[order]
    scale = y.max() - y.min()
    if not scale > 0.0:
        raise InputError("the pressure does not change over the force range, so it has no full scale")
    slopes: set[float] = set()
    for sign in (1, -1):
        hull = _hull(x, y, sign)
        slopes.update((y[b] - y[a]) / (x[b] - x[a]) for a, b in itertools.pairwise(hull) if x[b] > x[a])
    width = min((np.ptp(y - b * x) for b in slopes), default=0.0)
    return float(100.0 * 0.5 * width / scale)


def force_range(low, high, key: str = "range") -> tuple[float, float]:
    """A force range in N, checked: 0 <= low < high.

    Parameters
    ----------
    low, high : float or str
        N, or strings with unit.
    key : str, optional
        The range's name in error messages.

    Returns
    -------
    tuple of float
        (low, high) in N.

    Raises
    ------
    InputError
        Otherwise, naming ``key``.

    Examples
    --------
    >>> from pocket.apps.sense import force_range
    >>> print(force_range("0 N", "500 mN"))
    (0.0, 0.5)
    >>> force_range("1 N", "0.5 N")
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: range = '1 N' '0.5 N', but it must go up from 0 or more
    """
    start, top = quantity(key, low, "force"), quantity(key, high, "force")
    if not 0.0 <= start < top:
        raise InputError(f"{key} = {quote(low)} {quote(high)}, but it must go up from 0 or more")
    return start, top


def range_linearity(pocket: Pocket, low, high, points: int = 21, *, key: str = "range") -> float:
    """The ``linearity`` of a pocket's pressure-force curve P(F) over a force range.

    Parameters
    ----------
    pocket : Pocket
        The pocket (``pocket.apps.physical.resolve`` of a case).
    low, high : float or str
        The range, N or strings with unit, 0 <= low < high.
    points : int, optional
        The forces evenly spaced from ``low`` to ``high``.
    key : str, optional
        The range's name in error messages.

    Returns
    -------
    float
        The deviation in % of the full-scale pressure rise.

    Raises
    ------
    InputError
        For an invalid range.
    OutOfRangeError
        For ``high`` past the end of the model's range, naming ``key``.

    Examples
    --------
    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.physical import resolve
    >>> from pocket.apps.sense import range_linearity
    >>> print(f"{range_linearity(resolve(sample(1)), '0 N', '1 N', points=5):.3f} %")
    0.170 %
    """
    _inflated(pocket)
    points = check_count("points", points, 2, MAX_POINTS)
    start, top = force_range(low, high, key)
    top = check_force(pocket, key, high, top / pocket.force_scale_N)
    forces = np.linspace(start / pocket.force_scale_N, top, points)
    curve = entry(pocket.solver(), "compression_curve", "the linearity over a force range")
    states = curve(pocket.material, pocket.pressure_initial, list(forces), **pocket.options())
    return linearity(forces, [s.pressure_ratio for s in states])
