"""``pocket sense``: the force on a pocket from its measured pressure, and a calibration table."""

from __future__ import annotations

import csv
import io
import json
import sys

from pocket.apps.folders import check_output_file, write_whole
from pocket.apps.physical import forces, resolve
from pocket.apps.sense import (
    MAX_POINTS,
    calibration,
    force_range,
    range_linearity,
    sense,
    sensitivity_at_rest,
)
from pocket.core.errors import InputError
from pocket.core.inputs import check_count
from pocket.core.units import plain_warnings, positive, quantity

from .common import EXIT_CODES, PHYSICAL_UNITS, number, path_name, physical_help
from .run import add_case_arguments, case_from_args, case_source, warn_case

__all__ = ["register"]


def _main(args) -> int:
    case, _ = case_from_args(args)
    warn_case(case)
    if args.pressure is None and args.ratio is None and args.table is None:
        raise InputError("give a measured --pressure or --ratio, or --table FILE.csv")
    table = None if args.table is None else check_output_file(args.table, "--table", of=case_source(args))
    if args.max_force is not None:
        positive("--max-force", args.max_force, "force")
    points = check_count("--points", args.points, 2, MAX_POINTS)
    if args.pressure is not None:
        quantity("--pressure", args.pressure, "pressure")
    if args.range is not None:
        low, high = args.range
        span = list(force_range(low, high, key="--range"))
    _warn_plain(args)
    pocket = resolve(case)
    out = {}
    if args.pressure is not None or args.ratio is not None:
        out = sense(pocket, pressure=args.pressure, ratio=args.ratio).row()
    out["sensitivity_at_rest_kPa_per_N"] = sensitivity_at_rest(pocket)
    if args.range is not None:
        out["linearity_percent_fs"] = range_linearity(pocket, low, high, points, key="--range")
        out["linearity_range_N"] = span
    if table is not None:
        if args.max_force is None:
            rows = [r.row() for r in calibration(pocket, max(forces(pocket)) * pocket.force_scale_N, points)]
        else:
            rows = [r.row() for r in calibration(pocket, args.max_force, points, key="--max-force")]
        text = io.StringIO(newline="")
        writer = csv.DictWriter(text, list(rows[0]))
        writer.writeheader()
        writer.writerows({k: "; ".join(map(str, v)) if isinstance(v, list) else v for k, v in row.items()}
                         for row in rows)
        write_whole(table, text.getvalue(), of=case_source(args))
        out["table"] = args.table
    if args.json:
        print(json.dumps(out))
    else:
        for key, value in out.items():
            print(f"{key:<31}{value:.10g}" if isinstance(value, float) else f"{key:<31}{value}")
    return 0


def _warn_plain(args) -> None:
    """A ``pocket: warning:`` line on stderr for each value given without a unit (read as SI)."""
    given = [("--pressure", args.pressure, "pressure"), ("--max-force", args.max_force, "force"),
             *((f"--range[{i}]", v, "force") for i, v in enumerate(args.range or ()))]
    for key, value, kind in given:
        for text in [] if value is None else plain_warnings(key, value, kind):
            print(f"pocket: warning: {text}", file=sys.stderr)


def register(subparsers) -> None:
    """Add ``pocket sense``."""
    text = "force sensing: force, contact area, travel and sensitivity from a measured pressure"
    p = subparsers.add_parser("sense", help=text, description=f"{text} (gauge, like P_I), by inverting the "
                              "full model (no extrapolation: a pressure below P_I or past the model's range is "
                              "an error); --table writes a calibration table over the force range. The case's "
                              "rubber and fluid are used: with a gas ([fluid] kind = \"gas\") it is the "
                              "barometric touch sensor, the gas compressed by (P + P_atm) V^gamma fixed; the case's "
                              "[indenter] presses. Reported: sensitivity_kPa_per_N (dP/dF) and sensitivity_N_per_Pa "
                              "(dF/dP) at the reading and at each row of the table, travel_m (H0 - H, the indenter's "
                              "descent from the top of the inflated dome), sensitivity_at_rest_kPa_per_N (dP/dF as "
                              "F -> 0, from the inflated pocket by reciprocity) and, with --range, "
                              "linearity_percent_fs: the largest deviation of P(F) from its best straight line over "
                              f"the range, in % of the full-scale pressure change. {PHYSICAL_UNITS}",
                              epilog=EXIT_CODES)
    add_case_arguments(p)
    p.add_argument("--pressure", metavar="PRESSURE", help="measured gauge pressure P: "
                   f"{physical_help('pressure', '5.2 kPa')}")
    p.add_argument("--ratio", type=number, metavar="P/P_I", help="measured pressure rise P/P_I, a number")
    p.add_argument("--table", type=path_name, metavar="FILE.csv", help="write a calibration table over the force range")
    p.add_argument("--max-force", metavar="FORCE", help="top of the table's force range (default: the case's "
                   f"largest load): {physical_help('force', '2 N')}")
    p.add_argument("--points", type=int, default=21, help=f"rows of the table, and forces of --range's curve "
                   f"(2 to {MAX_POINTS})")
    p.add_argument("--range", nargs=2, metavar=("LOW", "HIGH"), help="report the linearity of P(F) over this "
                   f"force range, LOW and HIGH each {physical_help('force', '2 N')}")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(handler=_main)
