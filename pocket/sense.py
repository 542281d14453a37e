"""Force sensing: the force on a pocket from its measured pressure (``pocket sense``).

The paper's conclusion: the applied force can be inferred from the pressure
rise. The pressure ratio q = P/P_I grows monotonically with the force on the
model's first branch, so the force is the root Fhat of q(Fhat) = q_measured
(``pocket.inverse.force_where``), solved on the forward solver to its
resolution: no fitted curve and no extrapolation. A pressure below P_I, or
above what the model reaches before the free part of the sheet meets the
clamp plane, is an OutOfRangeError.

With F = Fhat P_I pi R^2 and P = q P_I, the sensitivity is
dF/dP = pi R^2 / (dq/dFhat) (units m^2 = N/Pa), dq/dFhat by ``pocket.slopes``.
The contact area is A_c = F / P (frictionless flat plate).

Pressures are gauge pressures, as P_I is: the pressure in the pocket above
the ambient pressure.
"""

from __future__ import annotations

import csv
import dataclasses
import json
import math
import pathlib

import numpy as np

from .checks import check_finite
from .errors import InputError
from .inverse import force_where
from .physical import Pocket, forces, resolve
from .run import add_case_arguments, case_from_args
from .slopes import curve_with_slopes
from .units import quantity

__all__ = ["Reading", "sense", "calibration", "register"]


@dataclasses.dataclass(frozen=True)
class Reading:
    """A force reading, SI units, with its dimensionless force and pressure ratio."""

    force: float  # F, N
    pressure: float  # P, Pa
    pressure_ratio: float  # P / P_I
    contact_area: float  # A_c, m^2
    sensitivity: float  # dF/dP, m^2
    force_hat: float  # F / (P_I pi R^2)

    def row(self) -> dict:
        return {"force_N": self.force, "pressure_Pa": self.pressure, "pressure_ratio": self.pressure_ratio,
                "contact_area_m2": self.contact_area, "sensitivity_N_per_Pa": self.sensitivity,
                "force": self.force_hat}


def _readings(pocket: Pocket, fhats) -> list[Reading]:
    states, slopes = curve_with_slopes(pocket.solver(), pocket.alpha, pocket.pressure_initial, fhats,
                                       ["pressure_ratio"], **pocket.options())
    area = math.pi * pocket.case.radius**2
    return [Reading(force=s.force * pocket.force_scale, pressure=s.pressure_ratio * pocket.initial_pressure,
                    pressure_ratio=s.pressure_ratio, contact_area=s.contact_area * area,
                    sensitivity=area / slope, force_hat=s.force)
            for s, slope in zip(states, slopes["pressure_ratio"], strict=True)]


def sense(pocket: Pocket, *, pressure=None, ratio=None) -> Reading:
    """The force at the measured ``pressure`` (Pa, or a string with unit) or pressure ``ratio`` P/P_I."""
    if (pressure is None) == (ratio is None):
        raise InputError("give either a pressure or a pressure ratio, not both or neither")
    if pressure is not None:
        q = quantity("pressure", pressure, "pressure") / pocket.initial_pressure
    else:
        q = check_finite("ratio", ratio)
    fhat = force_where(pocket.solver(), pocket.alpha, pocket.pressure_initial, "pressure_ratio", q,
                       increasing=True, **pocket.options())
    return _readings(pocket, [fhat])[0]


def calibration(pocket: Pocket, max_force: float, points: int = 21) -> list[Reading]:
    """Readings at ``points`` forces evenly spaced from 0 to ``max_force`` (N)."""
    if points < 2:
        raise InputError(f"points = {points}, but a table needs >= 2")
    if not (math.isfinite(max_force) and max_force > 0.0):
        raise InputError(f"max_force = {max_force!r}, but it must be > 0")
    return _readings(pocket, np.linspace(0.0, max_force / pocket.force_scale, points))


def _main(args) -> int:
    case, _ = case_from_args(args)
    if args.pressure is None and args.ratio is None and args.table is None:
        raise InputError("give a measured --pressure or --ratio, or --table FILE.csv")
    pocket = resolve(case)
    out = {}
    if args.pressure is not None or args.ratio is not None:
        out = sense(pocket, pressure=args.pressure, ratio=args.ratio).row()
    if args.table is not None:
        top = (quantity("max-force", args.max_force, "force") if args.max_force is not None
               else max(forces(pocket)) * pocket.force_scale)
        rows = [r.row() for r in calibration(pocket, top, args.points)]
        path = pathlib.Path(args.table)
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("w", newline="") as stream:
            writer = csv.DictWriter(stream, list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
        out["table"] = str(path)
    if args.json:
        print(json.dumps(out))
    else:
        for key, value in out.items():
            print(f"{key:<22}{value:.10g}" if isinstance(value, float) else f"{key:<22}{value}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket sense``."""
    from .cli import number

    p = subparsers.add_parser("sense", help="force sensing: force, contact area and dF/dP from a pressure")
    add_case_arguments(p)
    p.add_argument("--pressure", help="measured gauge pressure P ('5.2 kPa', SI if plain)")
    p.add_argument("--ratio", type=number, help="measured pressure rise P/P_I")
    p.add_argument("--table", metavar="FILE.csv", help="write a calibration table over the force range")
    p.add_argument("--max-force", help="top of the table's force range (default: the case's largest load)")
    p.add_argument("--points", type=int, default=21, help="rows of the table (default 21)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(handler=_main)
