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
liquid (``sensitivity_at_rest``, dH0/dP and dV0/dP by central differences of inflations).

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
    """A force reading: SI values carry their unit in the name, ``force`` is Fhat = F / (P_I pi R^2)."""

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
    return OutOfRangeError(f"{what} is beyond the model's range{top}: the free part of the sheet would fold onto "
                           "the clamp plane first")


def sense(pocket: Pocket, *, pressure=None, ratio=None) -> Reading:
    """The force at the measured ``pressure`` (Pa, or a string with unit) or pressure ``ratio`` P/P_I.

    A pressure below P_I, or past the model's range, is an ``OutOfRangeError`` quoting it as given.
    """
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
    """Readings at ``points`` forces evenly spaced from 0 to ``max_force`` (N, or a string with unit).

    A ``max_force`` past the end of the model's range is an ``OutOfRangeError`` naming ``key`` and quoting
    the end in the unit of ``max_force`` (``pocket.apps.forcerange``).
    """
    points = check_count("points", points, 2, MAX_POINTS)
    top = quantity(key, max_force, "force")
    if not top > 0.0:
        raise InputError(f"{key} = {quote(max_force)}, but it must be > 0")
    return _readings(pocket, np.linspace(0.0, check_force(pocket, key, max_force, top / pocket.force_scale_N), points))


_INFLATION_STEP = 1e-4  # relative step of the central differences of sensitivity_at_rest (as slopes')


def sensitivity_at_rest(pocket: Pocket) -> float:
    """dP/dF at F -> 0 (kPa/N) by reciprocity (module docstring), from inflations at P_I (1 +- 1e-4):
    truncation ~1e-8 and round-off ~1e-7 relative for a solver resolving ~1e-11."""
    solver = pocket.solver()
    inflate = entry(solver, "inflate", "the sensitivity at rest")
    phat, h = pocket.pressure_initial, _INFLATION_STEP * pocket.pressure_initial
    low, high = (inflate(pocket.material, p, **pocket.options("inflate")) for p in (phat - h, phat + h))
    dheight, dvolume = (high.height - low.height) / (2 * h), (high.volume - low.volume) / (2 * h)
    fluid = pocket.fluid
    if fluid.is_gas:  # the gas's compliance -dV_fluid/dP at P_I, in the same units (R^3 per Phat)
        volume = inflate(pocket.material, phat, **pocket.options("inflate")).volume
        dvolume += volume / (fluid.gamma * (phat + fluid.ambient))
    return float(dheight / dvolume / pocket.case.radius**2 / 1e3)  # Pa/N: (R dHhat) / (R^3 dVhat), the scales cancel


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
    """The largest deviation of ``pressures`` (shape (n,), any unit) from their best straight line in
    ``forces`` (shape (n,), any unit; n >= 2), in % of the full scale max - min of ``pressures``.

    The best line makes the largest deviation smallest: its deviation is half the smallest vertical
    width of the points, max(P - b F) - min(P - b F) minimised over the slope b, a convex piecewise
    linear function of b whose corners are the slopes of the edges of the points' convex hull.
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
    """``low`` and ``high`` (N, or strings with unit) in N, checked: 0 <= low < high (an ``InputError`` naming
    ``key`` otherwise)."""
    start, top = quantity(key, low, "force"), quantity(key, high, "force")
    if not 0.0 <= start < top:
        raise InputError(f"{key} = {quote(low)} {quote(high)}, but it must go up from 0 or more")
    return start, top


def range_linearity(pocket: Pocket, low, high, points: int = 21, *, key: str = "range") -> float:
    """``linearity`` of P(F) at ``points`` forces evenly from ``low`` to ``high`` (N, or strings with unit),
    0 <= low < high, ``high`` within the model's range (else an ``OutOfRangeError`` naming ``key``)."""
    points = check_count("points", points, 2, MAX_POINTS)
    start, top = force_range(low, high, key)
    top = check_force(pocket, key, high, top / pocket.force_scale_N)
    forces = np.linspace(start / pocket.force_scale_N, top, points)
    curve = entry(pocket.solver(), "compression_curve", "the linearity over a force range")
    states = curve(pocket.material, pocket.pressure_initial, list(forces), **pocket.options())
    return linearity(forces, [s.pressure_ratio for s in states])
